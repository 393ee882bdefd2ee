#include "hedge/algorithms/mass_properties.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// The unit cube scaled to a x b x c and moved by `offset`, triangulated.
SurfaceMesh box(float a, float b, float c, Vec3 offset = {0, 0, 0}) {
  IndexedMesh in = test::cube();
  for (Vec3& p : in.positions) p = Vec3{p.x * a, p.y * b, p.z * c} + offset;
  return build(to_indexed(build(in), {.triangulation = Triangulation::fan}));
}

void expect_tensor(const MassProperties& m, const double (&expected)[3][3], double tol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m.inertia[3 * i + j], expected[i][j], tol) << "entry " << i << j;
}

TEST(MassProperties, UnitCube) {
  const MassProperties m = mass_properties(box(1, 1, 1), 2.0);
  EXPECT_NEAR(m.volume, 1, 1e-12);
  EXPECT_NEAR(m.mass, 2, 1e-12);
  EXPECT_NEAR(norm(m.centre_of_mass - Vec3d{0.5, 0.5, 0.5}), 0, 1e-12);
  const double d = 2.0 / 6;  // m / 6
  expect_tensor(m, {{d, 0, 0}, {0, d, 0}, {0, 0, d}}, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.principal_moments[std::size_t(k)], d, 1e-12);
}

TEST(MassProperties, BoxOfSidesABC) {
  const double a = 1, b = 2, c = 3, density = 0.5;
  const MassProperties m = mass_properties(box(float(a), float(b), float(c)), density);
  const double mass = density * a * b * c;
  EXPECT_NEAR(m.mass, mass, 1e-12);
  EXPECT_NEAR(norm(m.centre_of_mass - Vec3d{a / 2, b / 2, c / 2}), 0, 1e-12);
  expect_tensor(m,
                {{mass * (b * b + c * c) / 12, 0, 0},
                 {0, mass * (a * a + c * c) / 12, 0},
                 {0, 0, mass * (a * a + b * b) / 12}},
                1e-12);
  // Ascending moments: about z (the short sides a, b), y, then x (the long sides b, c).
  EXPECT_NEAR(m.principal_moments[0], mass * (a * a + b * b) / 12, 1e-12);
  EXPECT_NEAR(m.principal_moments[1], mass * (a * a + c * c) / 12, 1e-12);
  EXPECT_NEAR(m.principal_moments[2], mass * (b * b + c * c) / 12, 1e-12);
  EXPECT_NEAR(std::abs(m.principal_axes[2].x), 1, 1e-9);
  EXPECT_NEAR(std::abs(m.principal_axes[0].z), 1, 1e-9);
  EXPECT_NEAR(dot(cross(m.principal_axes[0], m.principal_axes[1]), m.principal_axes[2]), 1, 1e-12);
}

TEST(MassProperties, ACubeFarFromTheOriginKeepsItsDigits) {
  const MassProperties m = mass_properties(box(2, 2, 2, {1e5f, -2e5f, 3e5f}));
  EXPECT_NEAR(m.volume, 8, 1e-9);
  EXPECT_NEAR(norm(m.centre_of_mass - Vec3d{1e5 + 1, -2e5 + 1, 3e5 + 1}), 0, 1e-9);
  const double d = 8.0 * 8 / 12;  // m (s^2 + s^2) / 12, s = 2
  expect_tensor(m, {{d, 0, 0}, {0, d, 0}, {0, 0, d}}, 1e-9);
}

TEST(MassProperties, ARotatedBoxHasTheRotatedTensor) {
  const double a = 1, b = 2, c = 4;
  IndexedMesh in =
      to_indexed(box(float(a), float(b), float(c), {-0.5f, -1, -2}), {.triangulation = Triangulation::fan});
  // A rotation by 30 degrees about z, then by 45 about x: R = Rx Rz.
  const double cz = std::cos(M_PI / 6), sz = std::sin(M_PI / 6), cx = std::cos(M_PI / 4),
               sx = std::sin(M_PI / 4);
  const double rz[3][3] = {{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}};
  const double rx[3][3] = {{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}};
  double r[3][3] = {};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += rx[i][k] * rz[k][j];
  for (Vec3& p : in.positions) {
    const Vec3d q = to_double(p);
    p = to_float({r[0][0] * q.x + r[0][1] * q.y + r[0][2] * q.z,
                  r[1][0] * q.x + r[1][1] * q.y + r[1][2] * q.z,
                  r[2][0] * q.x + r[2][1] * q.y + r[2][2] * q.z});
  }
  const MassProperties m = mass_properties(build(in));
  const double mass = a * b * c;
  const double body[3] = {mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12,
                          mass * (a * a + b * b) / 12};
  double expected[3][3] = {};  // R diag(body) R^T
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) expected[i][j] += r[i][k] * body[k] * r[j][k];
  EXPECT_NEAR(m.volume, mass, 1e-5);
  EXPECT_NEAR(norm(m.centre_of_mass), 0, 1e-6);
  expect_tensor(m, expected, 1e-5);
  // The principal moments are the body's, and the largest axis is R's first column (the box's x).
  EXPECT_NEAR(m.principal_moments[0], body[2], 1e-5);
  EXPECT_NEAR(m.principal_moments[1], body[1], 1e-5);
  EXPECT_NEAR(m.principal_moments[2], body[0], 1e-5);
  EXPECT_NEAR(std::abs(dot(m.principal_axes[2], Vec3d{r[0][0], r[1][0], r[2][0]})), 1, 1e-6);
}

TEST(MassProperties, UnitCornerTetrahedron) {
  // Vertices 0, x, y, z: V = 1/6, centroid (1/4, 1/4, 1/4); about the origin the second moments are
  // V/10 (x^2) and V/20 (x y); moved to the centroid: 1/60 - V/16 = 1/160 and 1/120 - V/16 = -1/480.
  const MassProperties m = mass_properties(build(test::tetrahedron()), 3.0);
  EXPECT_NEAR(m.volume, 1.0 / 6, 1e-15);
  EXPECT_NEAR(m.mass, 0.5, 1e-15);
  EXPECT_NEAR(norm(m.centre_of_mass - Vec3d{0.25, 0.25, 0.25}), 0, 1e-15);
  const double d = 3.0 * 2 / 160, o = 3.0 / 480;
  expect_tensor(m, {{d, o, o}, {o, d, o}, {o, o, d}}, 1e-15);
  // Symmetric about (1,1,1): the moment d + 2 o along it, two of d - o across.
  EXPECT_NEAR(m.principal_moments[0], d - o, 1e-15);
  EXPECT_NEAR(m.principal_moments[1], d - o, 1e-15);
  EXPECT_NEAR(m.principal_moments[2], d + 2 * o, 1e-15);
  EXPECT_NEAR(std::abs(dot(m.principal_axes[2], normalize(Vec3d{1, 1, 1}))), 1, 1e-12);
}

TEST(MassProperties, SpotsVolumeIsTheGeometryVolume) {
  const SurfaceMesh spot = read_mesh(test::data_path("spot_triangulated.obj"));
  const MassProperties m = mass_properties(spot, 1.0);
  EXPECT_NEAR(m.volume, volume(spot), 1e-12 * volume(spot));
  EXPECT_GT(m.principal_moments[0], 0);
  // The inertia tensor of a solid satisfies the triangle inequality of its principal moments.
  EXPECT_LE(m.principal_moments[2], m.principal_moments[0] + m.principal_moments[1] + 1e-12);
  EXPECT_NEAR(m.inertia[1], m.inertia[3], 1e-15);  // symmetric
}

TEST(MassProperties, BadInputIsRefusedWithAReason) {
  auto message = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const InvalidInputError& e) {
      return e.what();
    }
    return "no error";
  };
  const SurfaceMesh cube = box(1, 1, 1);
  EXPECT_NE(message([&] { mass_properties(cube, -1); }).find("density must be finite and positive, got -1"),
            std::string::npos);
  EXPECT_NE(message([&] { mass_properties(cube, 0); }).find("density"), std::string::npos);
  EXPECT_NE(message([&] { mass_properties(cube, std::nan("")); }).find("density"), std::string::npos);
  EXPECT_NE(message([&] { mass_properties(build(test::grid(2, true))); }).find("8 boundary half-edges"),
            std::string::npos);
  EXPECT_NE(message([&] { mass_properties(build(test::cube())); }).find("face 0 has 4 corners"),
            std::string::npos);
  IndexedMesh inside_out = test::tetrahedron();
  std::swap(inside_out.indices[1], inside_out.indices[2]);
  std::swap(inside_out.indices[4], inside_out.indices[5]);
  std::swap(inside_out.indices[7], inside_out.indices[8]);
  std::swap(inside_out.indices[10], inside_out.indices[11]);
  EXPECT_NE(message([&] { mass_properties(build(inside_out)); }).find("not a positive one"),
            std::string::npos);
  EXPECT_NE(message([&] { mass_properties(SurfaceMesh()); }).find("volume of 0,"), std::string::npos);
}

TEST(MassProperties, RefusesANonFinitePosition) {
  SurfaceMesh m = build(test::tetrahedron());
  test::expect_refuses_non_finite(m, Vertex(3), "mass_properties", [&] { mass_properties(m); });
}

// A unit square plate (grid of 2 x 2 squares of side 0.5) t thick: the slab's textbook inertia.
TEST(ShellMassProperties, FlatPlateIsASlab) {
  IndexedMesh in = test::grid(2, true);
  for (Vec3& p : in.positions) p = p * 0.5f + Vec3{3, 4, 5};
  const double t = 0.1, density = 2;
  const MassProperties m = shell_mass_properties(build(in), density, t);
  EXPECT_NEAR(m.volume, t, 1e-12);
  EXPECT_NEAR(m.mass, density * t, 1e-12);
  EXPECT_NEAR(norm(m.centre_of_mass - Vec3d{3.5, 4.5, 5}), 0, 1e-12);
  const double in_plane = m.mass * (1 + t * t) / 12, normal = m.mass / 6;
  expect_tensor(m, {{in_plane, 0, 0}, {0, in_plane, 0}, {0, 0, normal}}, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_GT(m.principal_moments[std::size_t(k)], 0);
}

// A thin-walled cube of side 1: (5/18) m a^2 for the surface, plus the thickness term of the four
// walls parallel to each axis (m / 6 t^2 / 12 each).
TEST(ShellMassProperties, HollowCube) {
  const double t = 0.01;
  const MassProperties m = shell_mass_properties(box(1, 1, 1), 1, t);
  EXPECT_NEAR(m.mass, 6 * t, 1e-12);
  const double d = m.mass * (5.0 / 18 + t * t / 18);
  expect_tensor(m, {{d, 0, 0}, {0, d, 0}, {0, 0, d}}, 1e-12);
}

TEST(ShellMassProperties, BadInputIsRefusedWithAReason) {
  auto expect_refused = [](auto&& call, const std::string& part) {
    std::string what = "no error";
    try {
      call();
    } catch (const InvalidInputError& e) {
      what = e.what();
    }
    EXPECT_NE(what.find(part), std::string::npos) << what;
  };
  const SurfaceMesh plate = build(test::grid(2, true));
  expect_refused([&] { shell_mass_properties(plate, 0, 1); },
                 "shell_mass_properties: density must be finite");
  expect_refused([&] { shell_mass_properties(plate, 1, -1); },
                 "thickness must be finite and positive, got -1");
  expect_refused([&] { shell_mass_properties(plate, 1, std::nan("")); }, "thickness");
  expect_refused([&] { shell_mass_properties(build(test::grid(2, false)), 1, 1); }, "face 0 has 4 corners");
  expect_refused([&] { shell_mass_properties(SurfaceMesh(), 1, 1); }, "an area of 0,");
  SurfaceMesh poisoned = build(test::tetrahedron());
  test::expect_refuses_non_finite(poisoned, Vertex(3), "shell_mass_properties",
                                  [&] { shell_mass_properties(poisoned, 1, 1); });
}

}  // namespace
}  // namespace hedge

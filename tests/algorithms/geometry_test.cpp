#include "hedge/algorithms/geometry.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

IndexedMesh reversed(IndexedMesh m) {
  std::size_t at = 0;
  for (std::size_t f = 0; f < m.face_count(); ++f) {
    const std::size_t n = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    std::reverse(m.indices.begin() + std::ptrdiff_t(at), m.indices.begin() + std::ptrdiff_t(at + n));
    at += n;
  }
  return m;
}

TEST(Geometry, UnitCubeHasAreaSixAndVolumeOne) {
  const SurfaceMesh m = build(test::cube());
  EXPECT_NEAR(surface_area(m), 6, 1e-12);
  EXPECT_NEAR(volume(m), 1, 1e-12);
  for (Face f : m.faces()) EXPECT_NEAR(face_area(m, f), 1, 1e-12);
  const BoundingBox box = bounding_box(m);
  EXPECT_FALSE(box.empty);
  EXPECT_EQ(box.min, (Vec3{0, 0, 0}));
  EXPECT_EQ(box.max, (Vec3{1, 1, 1}));
  EXPECT_EQ(box.centre(), (Vec3{0.5f, 0.5f, 0.5f}));
  // Triangulated, the same measures.
  const SurfaceMesh t = build(to_indexed(m, {.triangulation = Triangulation::fan}));
  EXPECT_EQ(t.n_faces(), 12u);
  EXPECT_NEAR(surface_area(t), 6, 1e-12);
  EXPECT_NEAR(volume(t), 1, 1e-12);
}

TEST(Geometry, VolumeIsSignedByOrientation) {
  EXPECT_NEAR(volume(build(test::tetrahedron())), 1.0 / 6, 1e-12);
  EXPECT_NEAR(volume(build(reversed(test::tetrahedron()))), -1.0 / 6, 1e-12);
  EXPECT_NEAR(volume(build(reversed(test::cube()))), -1, 1e-12);
}

TEST(Geometry, VolumeFarFromTheOriginKeepsItsDigits) {
  IndexedMesh in = test::cube();
  for (Vec3& p : in.positions) p += Vec3{10000, -20000, 5000};
  const SurfaceMesh m = build(in);
  EXPECT_NEAR(volume(m), 1, 1e-9);
  EXPECT_NEAR(surface_area(m), 6, 1e-6);
}

TEST(Geometry, PolygonAreasAndTheGrid) {
  // A right triangle of legs 2 and 3, and a regular hexagon of side 1.
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}};
  for (int i = 0; i < 6; ++i)
    in.positions.push_back({float(10 + std::cos(i * M_PI / 3)), float(std::sin(i * M_PI / 3)), 0});
  in.indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  in.face_sizes = {3, 6};
  const SurfaceMesh m = build(in);
  EXPECT_NEAR(face_area(m, Face(0)), 3, 1e-12);
  EXPECT_NEAR(face_area(m, Face(1)), 1.5 * std::sqrt(3.0), 1e-6);
  const SurfaceMesh grid = build(test::grid(4, false));
  EXPECT_NEAR(surface_area(grid), 16, 1e-12);
}

TEST(Geometry, AnOpenSurfaceHasNoVolume) {
  const SurfaceMesh grid = build(test::grid(3, true));
  try {
    volume(grid);
    FAIL() << "an open grid has a volume";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("12 boundary half-edges"), std::string::npos) << e.what();
  }
}

TEST(Geometry, TheEmptyMesh) {
  const SurfaceMesh m;
  EXPECT_TRUE(bounding_box(m).empty);
  EXPECT_EQ(bounding_box(m).size(), (Vec3{0, 0, 0}));
  EXPECT_EQ(surface_area(m), 0);
  EXPECT_EQ(volume(m), 0);
}

TEST(Geometry, ARealClosedMeshHasAPositiveVolumeBelowItsBox) {
  const SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  const BoundingBox box = bounding_box(m);
  const double v = volume(m);
  EXPECT_GT(v, 0);
  EXPECT_LT(v, double(box.size().x) * box.size().y * box.size().z);
  // The quad control mesh and the triangulated mesh of spot differ, but not by much.
  EXPECT_GT(surface_area(m), 0);
}

TEST(Geometry, VolumeSplitsPolygonsAsTheirExportedFan) {
  // Spot's control mesh has non-planar quads whose first-corner fan folds: volume() sums the fan of
  // fan_start(), the triangles export's fan writes (and the picking tree and solid fracture use).
  const SurfaceMesh m = read_mesh(test::data_path("spot_control_mesh.obj"));
  ExportOptions o;
  o.triangulation = Triangulation::fan;
  const SurfaceMesh tri = build(to_indexed(m, o));
  EXPECT_NEAR(volume(m), volume(tri), 1e-12 * volume(tri));
}

TEST(Geometry, EdgeLengthsAndCentroidsOfAFace) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}};
  in.indices = {0, 1, 2, 3};
  in.face_sizes = {4};
  const SurfaceMesh m = build(in);
  const Face f(0);
  EXPECT_DOUBLE_EQ(longest_edge(m, f), 4);
  EXPECT_DOUBLE_EQ(mean_edge_length(m, f), 3.5);
  for (Halfedge h : m.halfedges(f)) {
    const double l = edge_length(m, h);
    EXPECT_TRUE(l == 3 || l == 4) << l;
    EXPECT_EQ(l, edge_length(m, SurfaceMesh::twin(h)));
  }
  EXPECT_EQ(centroid(m, f), (Vec3d{1.5, 2, 0}));
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Geometry, CornerAnglesAndCotangents) {
  const Vec3d o{0, 0, 0}, x{2, 0, 0}, y{0, 5, 0};
  EXPECT_NEAR(corner_angle(o, x, y), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(corner_angle(o, x, x * -1.0), std::numbers::pi, 1e-15);
  EXPECT_EQ(corner_angle(o, o, y), 0);  // a side of zero length
  EXPECT_DOUBLE_EQ(triangle_area(o, x, y), 5);
  // The right angle at corner 0 has cotangent 0; the others are adjacent over opposite.
  const std::array<double, 3> cot = triangle_cotangents(o, x, y);
  EXPECT_NEAR(cot[0], 0, 1e-15);
  EXPECT_NEAR(cot[1], 2.0 / 5.0, 1e-15);
  EXPECT_NEAR(cot[2], 5.0 / 2.0, 1e-15);
  EXPECT_EQ(triangle_cotangents(o, x, x * 3.0), (std::array<double, 3>{0, 0, 0}));  // no area
}

TEST(Geometry, CotangentWeightsOfTheRegularLattice) {
  // Every angle is 60 degrees: an interior edge weighs (cot 60 + cot 60) / 2 = 1 / sqrt(3), a
  // boundary edge half that.
  const SurfaceMesh m = build(test::triangle_lattice(5));
  const std::vector<double> w = cotangent_weights(m);
  ASSERT_EQ(w.size(), m.edge_slots());
  for (Edge e : m.edges()) {
    const double expected = (m.is_boundary(e) ? 0.5 : 1.0) / std::sqrt(3.0);
    EXPECT_NEAR(w[e.idx()], expected, 1e-6) << "edge " << e.idx();
  }
  // The barycentric vertex areas share out the whole surface.
  const std::vector<double> a = vertex_areas(m);
  double sum = 0;
  for (Vertex v : m.vertices()) sum += a[v.idx()];
  EXPECT_NEAR(sum, surface_area(m), 1e-9);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Geometry, CotangentWeightsOfARightTriangle) {
  // Each side weighs half the cotangent of the angle opposite it: the hypotenuse 0 (a right angle),
  // the side along x half of 5 / 2 (the angle at (0, 5)), the side along y half of 2 / 5.
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {2, 0, 0}, {0, 5, 0}};
  in.indices = {0, 1, 2};
  const SurfaceMesh m = build(in);
  const std::vector<double> w = cotangent_weights(m);
  for (Edge e : m.edges()) {
    const Vec3 a = m.position(m.vertex(e, 0)), b = m.position(m.vertex(e, 1));
    const double expected = a.y == b.y ? 1.25 : a.x == b.x ? 0.2 : 0.0;
    EXPECT_NEAR(w[e.idx()], expected, 1e-12) << "edge " << e.idx();
  }
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Geometry, CotangentWeightsRefuseWhatTheyCannotWeigh) {
  const SurfaceMesh quads = build(test::cube());
  try {
    cotangent_weights(quads);
    FAIL() << "quads";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 has 4 corners"), std::string::npos) << e.what();
  }
  const SurfaceMesh tris = build(test::tetrahedron());
  const std::vector<Vec3d> three(3);
  try {
    cotangent_weights(tris, three);
    FAIL() << "three positions";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("3 positions for 4 vertex slots"), std::string::npos) << e.what();
  }
  EXPECT_THROW(vertex_areas(tris, three), InvalidInputError);
}

TEST(Geometry, SplitMix64GivesTheReferenceSequence) {
  // The first outputs of splitmix64 from seed 0, as published with the generator.
  SplitMix64 g(0);
  EXPECT_EQ(g.next(), 0xE220A8397B1DCDAFull);
  EXPECT_EQ(g.next(), 0x6E789E6AA1B965F4ull);
  EXPECT_EQ(g.next(), 0x06C45D188009454Full);
  // The stateless form draws value i of a stream on its own.
  EXPECT_EQ(splitmix64_mix(3 * SplitMix64::kGamma), 0x06C45D188009454Full);
  SplitMix64 u(42);
  for (int i = 0; i < 1000; ++i) {
    const double x = u.uniform();
    ASSERT_GE(x, 0);
    ASSERT_LT(x, 1);
  }
  EXPECT_EQ(unit_interval(~std::uint64_t(0)), 1 - 0x1.0p-53);
}

TEST(Geometry, VectorHelpers) {
  const Vec3d u = unit_or_zero(Vec3d{3, 0, 4});
  EXPECT_NEAR(u.x, 0.6, 1e-15);
  EXPECT_EQ(u.y, 0);
  EXPECT_NEAR(u.z, 0.8, 1e-15);
  EXPECT_EQ(unit_or_zero(Vec3d{0, 0, 0}), (Vec3d{0, 0, 0}));
  EXPECT_EQ(unit_or_zero(Vec3d{std::numeric_limits<double>::infinity(), 0, 0}), (Vec3d{0, 0, 0}));
  EXPECT_EQ(float_bits(1.0f), 0x3F800000u);
  EXPECT_NE(float_bits(-0.0f), float_bits(0.0f));
  EXPECT_LT(float_bits(1.5f), float_bits(2.5f));  // non-negative floats order as their bits
}

TEST(Geometry, WholeMeshMeasuresRefuseANonFinitePosition) {
  SurfaceMesh m = build(test::cube());
  test::expect_refuses_non_finite(m, Vertex(4), "bounding_box", [&] { bounding_box(m); });
  test::expect_refuses_non_finite(m, Vertex(4), "volume", [&] { volume(m); });
  test::expect_refuses_non_finite(m, Vertex(4), "surface_area", [&] { surface_area(m); });
  SurfaceMesh t = build(test::tetrahedron());
  test::expect_refuses_non_finite(t, Vertex(2), "vertex_areas", [&] { vertex_areas(t); });
  test::expect_refuses_non_finite(t, Vertex(2), "cotangent_weights", [&] { cotangent_weights(t); });
}

}  // namespace
}  // namespace hedge

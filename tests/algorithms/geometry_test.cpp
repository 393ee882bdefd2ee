#include "hedge/algorithms/geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
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

}  // namespace
}  // namespace hedge

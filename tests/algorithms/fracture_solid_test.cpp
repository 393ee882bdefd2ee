#include "hedge/algorithms/fracture_solid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fracture_solid_checks.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using solid_test::expect_solid_strike;

TEST(FractureSolid, CubeStruckAtAFaceCentreBreaksIntoClosedPieces) {
  // Planes of the region pass through the cube's vertices and along its faces.
  SurfaceMesh m = build(test::cube());
  const double before = volume(m);
  const SolidFractureResult r = fracture_solid(m, {0.5f, 0.5f, 1.0f}, {.radius = 0.4});
  EXPECT_GT(r.pieces.size(), 1u);
  expect_solid_strike(m, r, before);
}

TEST(FractureSolid, SphereBreaksIntoClosedPiecesAndStaysClosed) {
  SurfaceMesh m = read_mesh(test::data_path("icosahedron_binary.stl"));
  subdivide(m, Subdivision::loop, 3);
  const double before = volume(m);
  const Vec3 impact = m.position(Vertex(0));
  const SolidFractureResult r =
      fracture_solid(m, impact, {.material = fracture_material("glass"), .seed = 3});
  EXPECT_GT(r.pieces.size(), 5u);
  expect_solid_strike(m, r, before);
}

TEST(FractureSolid, QuadSphereBreaksWithPolygonsTriangulatedInTheRegion) {
  SurfaceMesh m = build(test::cube());
  subdivide(m, Subdivision::catmull_clark, 3);
  const double before = volume(m);
  const SolidFractureResult r = fracture_solid(m, m.position(Vertex(3)), {.radius = 0.3, .seed = 11});
  EXPECT_GT(r.pieces.size(), 1u);
  expect_solid_strike(m, r, before);
}

TEST(FractureSolid, SpotBreaksIntoClosedPiecesWithProperties) {
  SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  const double before = volume(m);
  ASSERT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord"));
  const Vec3 impact = m.position(Vertex(100));
  const SolidFractureResult r = fracture_solid(m, impact, {.seed = 7});
  EXPECT_GT(r.pieces.size(), 1u);
  expect_solid_strike(m, r, before);
}

}  // namespace
}  // namespace hedge

#include "algorithms/decimate_checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/error.h"

namespace hedge {
namespace {

using detail::decimation::bridge_distance2;
using detail::decimation::removed_distance2;

// A fan of six triangles around vertex 0 at height `apex` over the centre of a unit hexagon.
SurfaceMesh fan(float apex) {
  std::vector<Vec3> p{{0, 0, apex}};
  std::vector<std::uint32_t> t;
  for (int i = 0; i < 6; ++i) {
    const double a = i * std::numbers::pi / 3;
    p.push_back({float(std::cos(a)), float(std::sin(a)), 0});
    t.insert(t.end(), {0u, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % 6)});
  }
  return build_triangles(p, t);
}

TEST(DecimateChecks, AFlatFanLosesItsCentreForFree) {
  const SurfaceMesh m = fan(0);
  const Halfedge h = m.find_halfedge(Vertex(0), Vertex(1));
  EXPECT_EQ(removed_distance2(m, h, to_double(m.position(Vertex(1)))), 0.0);
}

TEST(DecimateChecks, ASpikeCostsItsHeight) {
  // The tip's quadric barely sees a tall spike: the planes of its sides pass near the base. The
  // removed tip is its height away from the faces left.
  const SurfaceMesh m = fan(5);
  const Halfedge h = m.find_halfedge(Vertex(0), Vertex(1));
  EXPECT_NEAR(removed_distance2(m, h, to_double(m.position(Vertex(1)))), 25.0, 1e-9);
  // A survivor that moves counts its old position too: moved to the rim's opposite corner, the
  // old corner is off the faces left.
  const Halfedge g = m.find_halfedge(Vertex(1), Vertex(0));
  EXPECT_GT(removed_distance2(m, g, to_double(m.position(Vertex(4)))), 0.0);
}

TEST(DecimateChecks, NewFacesOffTheOldSurfaceCostTheirCentroidsDistance) {
  const SurfaceMesh m = fan(0);
  const Halfedge h = m.find_halfedge(Vertex(0), Vertex(1));
  const Vec3d corner = to_double(m.position(Vertex(1)));
  // Merged into a rim corner that stays, the centre leaves faces on the old plane.
  EXPECT_EQ(bridge_distance2(m, h, corner), 0.0);
  // Lifted by 3, the survivor lifts each new face's centroid by 1 over the old faces, whose
  // vertices all still lie on that plane: the vertices alone would not tell.
  const Vec3d lifted = corner + Vec3d{0, 0, 3};
  EXPECT_NEAR(bridge_distance2(m, h, lifted), 1.0, 1e-6);
  // With a limit above it, the search may stop early, at some value within the limit.
  EXPECT_LE(bridge_distance2(m, h, lifted, 4.0), 4.0);
}

TEST(DecimateChecks, RefusesATriangleLessMeshInputByName) {
  IndexedMesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.indices = {0, 1, 2, 3};
  quad.face_sizes = {4};
  const SurfaceMesh m = build(quad);
  EXPECT_THROW(detail::decimation::check_input(m, {}), InvalidInputError);
}

}  // namespace
}  // namespace hedge

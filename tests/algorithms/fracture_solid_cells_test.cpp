// The region, the cells and the break points of solid fracture.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/fracture_solid_internal.h"
#include "hedge/algorithms/fracture.h"

namespace hedge::solid_detail {
namespace {

//! Volume of a polytope (its faces' fans about a point inside).
double polytope_volume(const Polytope& p, const Vec3d& inside) {
  double six_v = 0;
  for (const Polytope::Side& f : p.faces) {
    const Vec3d a = p.at(f.corners[0]) - inside;
    for (std::size_t k = 1; k + 1 < f.corners.size(); ++k)
      six_v += dot(a, cross(p.at(f.corners[k]) - inside, p.at(f.corners[k + 1]) - inside));
  }
  return six_v / 6;
}

TEST(FractureSolidCells, RegionIsAClosedPolytopeAroundItsSphere) {
  PlaneSet planes;
  const Vec3d c{1, 2, 3};
  const Polytope p = region_polytope(c, 2, planes, 0, 0);
  EXPECT_EQ(planes.planes.size(), 26u);
  EXPECT_EQ(p.faces.size(), 26u);
  for (const auto& [k, x] : p.points) EXPECT_GE(norm(x - c), 2 - 1e-12);
  // Between the inscribed ball and the cube of the axis planes.
  const double v = polytope_volume(p, c);
  EXPECT_GT(v, 4.0 / 3 * 3.14159265 * 8);
  EXPECT_LT(v, 64);
  // Every edge is shared by two faces in opposite directions.
  std::vector<std::pair<Key, Key>> edges;
  for (const auto& f : p.faces)
    for (std::size_t i = 0; i < f.corners.size(); ++i)
      edges.emplace_back(f.corners[i], f.corners[(i + 1) % f.corners.size()]);
  std::sort(edges.begin(), edges.end());
  for (const auto& [a, b] : edges)
    EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)));
}

TEST(FractureSolidCells, CellsPartitionTheRegion) {
  PlaneSet planes;
  const Vec3d c{0, 0, 0};
  const Polytope region = region_polytope(c, 1, planes, 0, 0);
  FractureMaterial m = fracture_material_at_radius(fracture_material("glass"), 0.9);
  const std::vector<Vec3d> points = break_points(m, c, 5, 0);
  EXPECT_EQ(points.size(), 40u);
  double total = 0;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    Polytope cell;
    ASSERT_TRUE(voronoi_cell(region, points, i, planes, cell));
    if (cell.empty()) continue;
    total += polytope_volume(cell, points[i]);
  }
  EXPECT_NEAR(total, polytope_volume(region, c), 1e-9);
}

TEST(FractureSolidCells, BreakPointsAreSeededShellsAboutTheImpact) {
  const FractureMaterial m = fracture_material_at_radius(fracture_material("stone"), 2);
  const Vec3d c{1, 1, 1};
  const std::vector<Vec3d> a = break_points(m, c, 9, 0), b = break_points(m, c, 9, 0),
                           d = break_points(m, c, 10, 0);
  ASSERT_EQ(a.size(), fracture_break_points({.material = m}));
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]);
  EXPECT_NE(a[0], d[0]);
  // Ring k's points lie at its radius, give or take half the jitter of its spacing.
  double radius = 0;
  std::size_t i = 0;
  for (const FractureRing& r : m.rings) {
    radius += r.spacing;
    for (unsigned k = 0; k < r.points; ++k, ++i)
      EXPECT_NEAR(norm(a[i] - c), radius, 0.5 * r.jitter * r.spacing + 1e-9);
  }
}

}  // namespace
}  // namespace hedge::solid_detail

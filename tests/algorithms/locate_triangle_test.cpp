// Point location without a tree: the triangle primitives against analytic answers and dense
// sampling, and the ray test's watertightness through the linear scan (and the tree, which must agree).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "locate_reference.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace locate_test;

// ---- Triangle primitives. ----

TEST(ClosestPointOnTriangle, AnalyticRegions) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  TrianglePoint r = closest_point_on_triangle({0.25f, 0.5f, 5}, a, b, c);  // above the interior
  EXPECT_DOUBLE_EQ(r.squared_distance, 25.0);
  EXPECT_DOUBLE_EQ(r.barycentric[0], 0.25);
  EXPECT_DOUBLE_EQ(r.barycentric[1], 0.25);
  EXPECT_DOUBLE_EQ(r.barycentric[2], 0.5);
  r = closest_point_on_triangle({-1, -1, 0}, a, b, c);  // beyond vertex a
  EXPECT_DOUBLE_EQ(r.squared_distance, 2.0);
  EXPECT_EQ(r.barycentric, (std::array<double, 3>{1, 0, 0}));
  r = closest_point_on_triangle({2, 2, 1}, a, b, c);  // beyond edge bc, at its midpoint
  EXPECT_DOUBLE_EQ(r.squared_distance, 1.5 * 1.5 * 2 + 1);
  EXPECT_DOUBLE_EQ(r.barycentric[1], 0.5);
  EXPECT_DOUBLE_EQ(r.barycentric[2], 0.5);
  r = closest_point_on_triangle({0.5f, -2, 0}, a, b, c);  // beyond edge ab
  EXPECT_DOUBLE_EQ(r.squared_distance, 4.0);
  EXPECT_DOUBLE_EQ(r.barycentric[1], 0.5);
  // Collinear corners: the distance to the segment they span.
  r = closest_point_on_triangle({1.5f, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0});
  EXPECT_DOUBLE_EQ(r.squared_distance, 1.0);
  r = closest_point_on_triangle({3, 0, 0}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1});  // a point
  EXPECT_DOUBLE_EQ(r.squared_distance, 6.0);
}

TEST(ClosestPointOnTriangle, NeverFartherThanAnySampleOfTheTriangle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const Vec3 p{2 * u(rng), 2 * u(rng), 2 * u(rng)};
    const TrianglePoint r = closest_point_on_triangle(p, a, b, c);
    const Vec3d q =
        to_double(a) * r.barycentric[0] + to_double(b) * r.barycentric[1] + to_double(c) * r.barycentric[2];
    EXPECT_NEAR(dot(to_double(p) - q, to_double(p) - q), r.squared_distance, 1e-12);
    double sampled = kInf;
    const int n = 60;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3d s = to_double(a) + (to_double(b) - to_double(a)) * (double(i) / n) +
                        (to_double(c) - to_double(a)) * (double(j) / n);
        sampled = std::min(sampled, dot(to_double(p) - s, to_double(p) - s));
      }
    EXPECT_LE(r.squared_distance, sampled + 1e-12);
    EXPECT_GE(r.squared_distance, sampled - 0.02 * std::sqrt(sampled) - 1e-3);  // grid spacing
  }
}

TEST(RayTriangle, HitsMissesAndParameters) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  auto h = intersect_ray_triangle({0.25f, 0.5f, 1}, {0, 0, -1}, a, b, c);
  ASSERT_TRUE(h);
  EXPECT_DOUBLE_EQ(h->t, 1.0);
  EXPECT_DOUBLE_EQ(h->barycentric[0], 0.25);
  EXPECT_DOUBLE_EQ(h->barycentric[1], 0.25);
  EXPECT_DOUBLE_EQ(h->barycentric[2], 0.5);
  h = intersect_ray_triangle({0.25f, 0.5f, 1}, {0, 0, -4}, a, b, c);  // t in direction lengths
  ASSERT_TRUE(h);
  EXPECT_DOUBLE_EQ(h->t, 0.25);
  EXPECT_TRUE(intersect_ray_triangle({0.25f, 0.5f, -1}, {0, 0, 1}, a, b, c));  // from behind: two-sided
  EXPECT_FALSE(intersect_ray_triangle({0.25f, 0.5f, 1}, {0, 0, 1}, a, b, c));  // pointing away
  EXPECT_FALSE(intersect_ray_triangle({0.25f, 0.5f, 1}, {0, 0, -1}, a, b, c, 0.99));  // beyond t_max
  EXPECT_TRUE(intersect_ray_triangle({0.25f, 0.5f, 1}, {0, 0, -1}, a, b, c, 1.0));
  EXPECT_FALSE(intersect_ray_triangle({0.75f, 0.75f, 1}, {0, 0, -1}, a, b, c));  // outside
  EXPECT_FALSE(intersect_ray_triangle({-1, 0.2f, 0}, {1, 0, 0}, a, b, c));       // in the plane
  EXPECT_FALSE(intersect_ray_triangle({0.2f, 0.2f, 1}, {0, 0, 0}, a, b, c));     // no direction
  EXPECT_FALSE(intersect_ray_triangle({kNaN, 0.2f, 1}, {0, 0, -1}, a, b, c));
  EXPECT_FALSE(intersect_ray_triangle({0.2f, 0.2f, 1}, {0, kNaN, -1}, a, b, c));
  // Oblique: from (2, 2, 2) toward (0.25, 0.25, 0).
  h = intersect_ray_triangle({2, 2, 2}, {-1.75f, -1.75f, -2}, a, b, c);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 1.0, 1e-12);
  EXPECT_NEAR(h->barycentric[1], 0.25, 1e-12);
}

// Rays aimed at vertices, edges and diagonals of a triangulated grid never slip through.
TEST(RayTriangle, WatertightOnSharedEdgesAndVertices) {
  const SurfaceMesh m = build(test::grid(8, true));
  const FaceBvh bvh(m);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.f, 1.f);
  int rays = 0;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      const Vec3 target{i * 0.5f, j * 0.5f, 0};  // vertices, edge midpoints and diagonal midpoints
      const bool interior = i > 0 && i < 16 && j > 0 && j < 16;
      for (int k = 0; k < 4; ++k) {
        const Vec3 dir = k == 0 ? Vec3{0, 0, -1} : Vec3{0.3f * u(rng), 0.3f * u(rng), -1};
        const Vec3 origin = target - dir * 3.f;
        const auto linear = first_hit_linear(m, origin, dir);
        const auto tree = bvh.first_hit(origin, dir);
        expect_same_hit(m, tree, linear);
        if (interior) {
          ++rays;
          ASSERT_TRUE(linear) << "slipped through at " << target.x << " " << target.y << " ray " << k;
          EXPECT_NEAR(linear->t, 3.0, 1e-5);
        }
      }
    }
  EXPECT_EQ(rays, 15 * 15 * 4);
}

}  // namespace
}  // namespace hedge

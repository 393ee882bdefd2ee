#include "hedge/algorithms/distance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "hedge/algorithms/split_all_faces.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

IndexedMesh moved(IndexedMesh m, Vec3 offset, float scale = 1) {
  for (Vec3& p : m.positions) p = p * scale + offset;
  return m;
}

TEST(Distance, PlaneAndACopyShiftedAlongItsNormalAreTheShiftApart) {
  const SurfaceMesh a = build(test::grid(4, true));
  const SurfaceMesh b = build(moved(test::grid(4, true), {0, 0, 0.25f}));
  const HausdorffDistance d = hausdorff_distance(a, b, {.samples = 2000});
  EXPECT_DOUBLE_EQ(d.distance, 0.25);
  EXPECT_NEAR(d.mean, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(d.a_to_b.max, 0.25);
  EXPECT_DOUBLE_EQ(d.b_to_a.max, 0.25);
  EXPECT_EQ(d.a_to_b.points, 25u + 2000u);
  EXPECT_EQ(d.b_to_a.points, 25u + 2000u);
}

TEST(Distance, PlaneShiftedSidewaysIsFarthestAtItsOuterEdge) {
  // [0, 4]^2 against [1, 5] x [0, 4]: the points of a with x < 1 are farthest, x = 0 at distance 1.
  const SurfaceMesh a = build(test::grid(4, true));
  const SurfaceMesh b = build(moved(test::grid(4, true), {1, 0, 0}));
  const OneSidedDistance d = one_sided_distance(a, b, {.samples = 1000});
  EXPECT_DOUBLE_EQ(d.max, 1.0);
  EXPECT_FLOAT_EQ(d.farthest.x, 0.0f);
  // A quarter of the area is uncovered, at distances uniform in [0, 1]: the mean is about 1/8.
  EXPECT_NEAR(d.mean, 0.125, 0.02);
  EXPECT_DOUBLE_EQ(hausdorff_distance(a, b, {.samples = 1000}).distance, 1.0);
}

TEST(Distance, CubeAndItsSubdivisionAreTheSameSurface) {
  const SurfaceMesh cube = build(test::cube());
  SurfaceMesh fine = build(test::cube());
  split_all_faces(fine);
  split_all_faces(fine);
  EXPECT_TRUE(fine.validate().empty());
  const HausdorffDistance d = hausdorff_distance(cube, fine, {.samples = 5000});
  EXPECT_LT(d.distance, 1e-6);
  EXPECT_LT(d.mean, 1e-7);
  EXPECT_EQ(d.b_to_a.points, fine.n_vertices() + 5000);
}

TEST(Distance, CubeInsideACubeOfTwiceItsSize) {
  // [0, 1]^3 against [-0.5, 1.5]^3, split: every point of the small cube is 0.5 from the big one;
  // the big one's corners are sqrt(3)/2 from the small one.
  const SurfaceMesh small = build(test::cube());
  SurfaceMesh big = build(moved(test::cube(), {-0.5f, -0.5f, -0.5f}, 2));
  split_all_faces(big);
  EXPECT_TRUE(big.validate().empty());
  const HausdorffDistance d = hausdorff_distance(small, big, {.samples = 3000});
  EXPECT_NEAR(d.a_to_b.max, 0.5, 1e-6);
  EXPECT_NEAR(d.a_to_b.mean, 0.5, 1e-6);
  EXPECT_NEAR(d.b_to_a.max, std::sqrt(3.0) / 2, 1e-6);
  EXPECT_NEAR(d.distance, std::sqrt(3.0) / 2, 1e-6);
  const Vec3 corner = d.b_to_a.farthest;
  EXPECT_FLOAT_EQ(std::abs(corner.x - 0.5f), 1.0f);
  EXPECT_FLOAT_EQ(std::abs(corner.y - 0.5f), 1.0f);
  EXPECT_FLOAT_EQ(std::abs(corner.z - 0.5f), 1.0f);
}

TEST(Distance, FaceSamplesFollowTheArea) {
  // A unit square at height 1 and a 3 x 1 rectangle at height 2, over a large plane at height 0:
  // a quarter of the face samples fall on the square (distance 1), the rest at distance 2.
  IndexedMesh two;
  two.positions = {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {2, 0, 2}, {5, 0, 2}, {5, 1, 2}, {2, 1, 2}};
  two.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  const SurfaceMesh a = build(two);
  const SurfaceMesh ground = build(moved(test::grid(2, true), {-2, -2, 0}, 5));
  const OneSidedDistance d = one_sided_distance(a, ground, {.samples = 1000});
  EXPECT_EQ(d.points, 1008u);
  // Stratified draws: the square gets 250 samples, give or take one.
  EXPECT_NEAR(d.mean, (4 * 1 + 4 * 2 + 250 * 1 + 750 * 2) / 1008.0, 1.5 / 1008);
  EXPECT_DOUBLE_EQ(d.max, 2.0);
}

TEST(Distance, SameAnswerOnAnyNumberOfThreadsAndReproducibleFromItsSeed) {
  const SurfaceMesh a = build(test::cube());
  SurfaceMesh b = build(moved(test::cube(), {0.1f, 0.2f, -0.05f}, 1.1f));
  split_all_faces(b);
  const HausdorffDistance one = hausdorff_distance(a, b, {.samples = 20000, .seed = 7, .threads = 1});
  const HausdorffDistance two = hausdorff_distance(a, b, {.samples = 20000, .seed = 7, .threads = 2});
  const HausdorffDistance three = hausdorff_distance(a, b, {.samples = 20000, .seed = 7, .threads = 3});
  EXPECT_EQ(one.distance, two.distance);
  EXPECT_EQ(one.mean, two.mean);
  EXPECT_EQ(one.a_to_b.farthest, two.a_to_b.farthest);
  EXPECT_EQ(one.mean, three.mean);
  const HausdorffDistance other = hausdorff_distance(a, b, {.samples = 20000, .seed = 8});
  EXPECT_NE(other.mean, one.mean);
  EXPECT_NEAR(other.mean, one.mean, 0.01);
}

TEST(Distance, VerticesOnlyWithoutSamplesAndIsolatedVerticesAreNotOnTheSurface) {
  IndexedMesh in = test::grid(2, true);
  in.positions.push_back({100, 100, 100});  // isolated
  const SurfaceMesh a = build(in);
  const SurfaceMesh b = build(moved(test::grid(2, true), {0, 0, 1}));
  const OneSidedDistance d = one_sided_distance(a, b, {.samples = 0});
  EXPECT_EQ(d.points, 9u);
  EXPECT_DOUBLE_EQ(d.max, 1.0);
}

TEST(Distance, EmptyMeshNaNPositionAndZeroThreadsAreRefused) {
  const SurfaceMesh cube = build(test::cube());
  const SurfaceMesh empty;
  try {
    (void)hausdorff_distance(cube, empty);
    FAIL() << "no error for an empty mesh";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh b has no faces"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)one_sided_distance(empty, cube), InvalidInputError);

  SurfaceMesh nan = build(test::cube());
  nan.set_position(Vertex(5), {0, std::numeric_limits<float>::quiet_NaN(), 0});
  try {
    (void)hausdorff_distance(nan, cube);
    FAIL() << "no error for a NaN position";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("(mesh a): vertex 5 has a non-finite position"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)hausdorff_distance(cube, cube, {.threads = 0}), InvalidInputError);
}

TEST(Distance, TooManySamplesAreRefusedInsteadOfWrappingAround) {
  const SurfaceMesh cube = build(test::cube());
  // V + samples used to wrap around to V - 1 points, measured as if that were the sample.
  for (const std::size_t samples : {std::numeric_limits<std::size_t>::max(), kMaxDistanceSamples + 1}) {
    try {
      (void)hausdorff_distance(cube, cube, {.samples = samples});
      FAIL() << "no error for " << samples << " samples";
    } catch (const InvalidInputError& e) {
      EXPECT_NE(std::string(e.what()).find("options.samples is " + std::to_string(samples)),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("100000000"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)one_sided_distance(cube, cube, {.samples = kMaxDistanceSamples + 1}), InvalidInputError);
}

TEST(Distance, RefusesANonFinitePositionInEitherMesh) {
  SurfaceMesh a = build(test::cube()), b = build(test::cube());
  test::expect_refuses_non_finite(a, Vertex(2), "hausdorff_distance (mesh a)",
                                  [&] { hausdorff_distance(a, b); });
  test::expect_refuses_non_finite(b, Vertex(5), "hausdorff_distance (mesh b)",
                                  [&] { hausdorff_distance(a, b); });
}

}  // namespace
}  // namespace hedge

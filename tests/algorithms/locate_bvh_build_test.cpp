// FaceBvh construction: the shape of the tree each split strategy builds.
#include <gtest/gtest.h>

#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "locate_reference.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace locate_test;

TEST(FaceBvh, ShapeOfTheTree) {
  const SurfaceMesh m = load("spot_triangulated.obj");
  for (BvhSplit split : {BvhSplit::sah, BvhSplit::median}) {
    const FaceBvh bvh(m, {.split = split, .max_leaf_size = 4});
    const FaceBvh::Stats s = bvh.stats();
    EXPECT_EQ(s.nodes, 2 * s.leaves - 1);
    EXPECT_GE(s.leaves, m.n_faces() / 4);
    EXPECT_LE(s.height, 40u);
    EXPECT_GE(s.height, 11u);  // ceil(log2(5856 / 4))
    EXPECT_EQ(s.dead_slots, 0u);
  }
}

TEST(FaceBvhBuild, RefusesANonFinitePosition) {
  SurfaceMesh m = build(test::grid(4, true));
  test::expect_refuses_non_finite(m, Vertex(6), "FaceBvh", [&] { FaceBvh bvh(m); });
}

}  // namespace
}  // namespace hedge

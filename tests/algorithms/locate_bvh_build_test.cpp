// FaceBvh construction: the shape of the tree each split strategy builds.
#include <gtest/gtest.h>

#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
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

// The root box is the mesh's box (no isolated vertex here), without a pass over the vertices; an
// empty tree has none, and faces removed later keep the box until the next build.
TEST(FaceBvhBuild, BoundsAreTheRootBox) {
  SurfaceMesh m = load("spot_triangulated.obj");
  EXPECT_TRUE(FaceBvh().bounds().empty);
  FaceBvh bvh(m);
  const BoundingBox expected = bounding_box(m), got = bvh.bounds();
  ASSERT_FALSE(got.empty);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(got.min[a], expected.min[a]) << "axis " << a;
    EXPECT_EQ(got.max[a], expected.max[a]) << "axis " << a;
  }
  std::vector<Face> removed;  // the faces at the far end in x
  for (Face f : m.faces())
    if (hedge::centroid(m, f).x > expected.max.x - 0.1 * expected.size().x) removed.push_back(f);
  detach_faces(m, removed);
  ASSERT_LT(bounding_box(m).max.x, expected.max.x);
  bvh.update();
  EXPECT_EQ(bvh.bounds().max.x, expected.max.x);
}

TEST(FaceBvhBuild, MeshClosedIsAskedOnceUntilTheMeshChanges) {
  SurfaceMesh m = load("spot_triangulated.obj");
  FaceBvh bvh(m);
  EXPECT_TRUE(bvh.mesh_closed());
  remove_face(m, Face(7));
  bvh.update();  // took in the removed face: asked again
  Halfedge open;
  EXPECT_FALSE(bvh.mesh_closed(&open));
  ASSERT_TRUE(open.is_valid());
  EXPECT_TRUE(m.is_boundary(open));
  // Kept without a pass: an algorithm's word stands until the next change.
  bvh.note_closed(true);
  EXPECT_TRUE(bvh.mesh_closed());
  bvh.update();  // nothing changed since
  EXPECT_TRUE(bvh.mesh_closed());
  bvh.rebuild();
  EXPECT_FALSE(bvh.mesh_closed());
  EXPECT_TRUE(m.validate().empty());
}

TEST(FaceBvhBuild, RefusesANonFinitePosition) {
  SurfaceMesh m = build(test::grid(4, true));
  test::expect_refuses_non_finite(m, Vertex(6), "FaceBvh", [&] { FaceBvh bvh(m); });
}

// A rebuild (update() calls it, in the middle of edits) does not throw: a face whose corner became
// non-finite without notice is left out, and every other face is found as before.
TEST(FaceBvhBuild, ARebuildLeavesOutAFaceWithANonFiniteCorner) {
  SurfaceMesh m = build(test::grid(4, true));
  FaceBvh bvh(m);
  const Vertex poisoned(6);  // (1, 1): its faces lie within x, y in [0, 2]
  test::poison(m, poisoned);
  ASSERT_NO_THROW(bvh.rebuild());
  // A ray down through the middle of each square: found unless the square has the poisoned corner.
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const Vec3 origin{i + 0.7f, j + 0.2f, 1};  // in the lower-right triangle (a, b, c) of the square
      const auto hit = bvh.first_hit(origin, {0, 0, -1});
      // The triangle's corners are (i, j), (i + 1, j) and (i + 1, j + 1); vertex 6 is (1, 1).
      const bool corner_in_triangle = (i == 1 && j == 1) || (i == 0 && j == 1) || (i == 0 && j == 0);
      if (corner_in_triangle) {
        EXPECT_FALSE(hit) << "square " << i << ", " << j;
      } else {
        ASSERT_TRUE(hit) << "square " << i << ", " << j;
        for (Vertex v : m.vertices(hit->face)) EXPECT_NE(v, poisoned);
      }
    }
  m.position(poisoned) = {1, 1, 0};
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

}  // namespace
}  // namespace hedge

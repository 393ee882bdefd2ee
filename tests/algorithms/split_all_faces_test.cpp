#include "hedge/algorithms/split_all_faces.h"

#include <gtest/gtest.h>

#include "edit_checks.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::counts;

TEST(SplitFace, SplitAllFacesTriplesTriangles) {
  SurfaceMesh m = build(test::tetrahedron());
  auto added = split_all_faces(m);
  EXPECT_EQ(added.size(), 4u);
  EXPECT_EQ(m.n_faces(), 12u);
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitAllFaces, QuadsBecomeFourTrianglesAboutTheirCentroids) {
  SurfaceMesh m = build(test::cube());
  std::vector<Vec3> centroids;
  for (Face f : m.faces()) centroids.push_back(face_centroid(m, f));
  const std::vector<Vertex> added = split_all_faces(m);
  ASSERT_EQ(added.size(), centroids.size());
  for (std::size_t i = 0; i < added.size(); ++i) {
    EXPECT_EQ(m.position(added[i]), centroids[i]);
    EXPECT_EQ(m.valence(added[i]), 4u);
  }
  EXPECT_EQ(m.n_faces(), 24u);
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitAllFaces, WithGarbageEveryIndexStays) {
  SurfaceMesh m = build(test::grid(3, true));
  ASSERT_TRUE(remove_face(m, Face(4)));
  const std::size_t faces = m.n_faces(), slots = m.vertex_slots();
  const SurfaceMesh before = m;
  const std::vector<Vertex> added = split_all_faces(m);
  EXPECT_EQ(added.size(), faces);
  EXPECT_TRUE(m.has_garbage());
  EXPECT_TRUE(m.is_deleted(Face(4)));
  for (Vertex v : added) EXPECT_GE(v.idx(), slots);
  for (Vertex v : before.vertices()) EXPECT_EQ(m.position(v), before.position(v));
  EXPECT_EQ(m.n_faces(), 3 * faces);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitAllFaces, RefusesANonFinitePosition) {
  SurfaceMesh m = build(test::cube());
  test::expect_refuses_non_finite(m, Vertex(1), "split_all_faces", [&] { split_all_faces(m); });
}

}  // namespace
}  // namespace hedge

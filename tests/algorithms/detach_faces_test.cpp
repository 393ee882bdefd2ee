#include "hedge/algorithms/detach_faces.h"

#include <gtest/gtest.h>

#include "edit_checks.h"

namespace hedge {
namespace {

using test::expect_corner_uv_matches_position;
using test::textured_grid;

TEST(DetachFaces, CopiesPropertiesAndSplitsPinchedVertices) {
  SurfaceMesh m = textured_grid(3, false);
  auto label = m.add_face_property<int>("f:label", 0);
  for (Face f : m.faces()) label[f] = static_cast<int>(f.idx()) + 100;
  // Faces 0 and 4 touch at one vertex (5): the piece has two fans there.
  std::vector<Face> set = {Face(0), Face(4)};
  std::vector<Vertex> origin;
  SurfaceMesh piece = detach_faces(m, set, &origin);
  EXPECT_EQ(piece.n_faces(), 2u);
  EXPECT_EQ(piece.n_vertices(), 8u);  // vertex 5 split in two
  EXPECT_TRUE(piece.validate().empty());
  auto plabel = piece.get_face_property<int>("f:label");
  ASSERT_TRUE(plabel);
  EXPECT_EQ(plabel[Face(0)], 100);
  EXPECT_EQ(plabel[Face(1)], 104);
  expect_corner_uv_matches_position(piece);
  for (Vertex v : piece.vertices()) EXPECT_EQ(piece.position(v), m.position(origin[v.idx()]));
  auto w = piece.get_vertex_property<float>("v:weight");
  for (Vertex v : piece.vertices()) EXPECT_EQ(w[v], m.position(origin[v.idx()]).x);
  // The source lost both faces; vertex 5 is pinched there too (faces 1, 3 remain on one side,
  // and the removal leaves two gaps), so it is split.
  EXPECT_EQ(m.n_faces(), 7u);
  EXPECT_TRUE(m.validate().empty());
  for (Vertex v : m.vertices()) EXPECT_TRUE(m.is_manifold(v));
  m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

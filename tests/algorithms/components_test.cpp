#include "hedge/algorithms/components.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "test_meshes.h"

namespace hedge {
namespace {

// Appends `piece` to `all`, its vertices renumbered after those already there.
void append(IndexedMesh& all, const IndexedMesh& piece, float shift) {
  const auto base = static_cast<std::uint32_t>(all.positions.size());
  for (Vec3 p : piece.positions) all.positions.push_back(p + Vec3{shift, 0, 0});
  for (std::uint32_t i : piece.indices) all.indices.push_back(base + i);
  if (!piece.face_sizes.empty() || !all.face_sizes.empty()) {
    // Mixed pieces: give every face its size.
    if (all.face_sizes.empty() && all.indices.size() > piece.indices.size())
      all.face_sizes.assign((all.indices.size() - piece.indices.size()) / 3, 3);
    if (piece.face_sizes.empty())
      all.face_sizes.insert(all.face_sizes.end(), piece.indices.size() / 3, 3);
    else
      all.face_sizes.insert(all.face_sizes.end(), piece.face_sizes.begin(), piece.face_sizes.end());
  }
}

// A tetrahedron, a cube and a 3 x 3 grid side by side, apart: three pieces of 4, 6 and 9 faces.
SurfaceMesh three_pieces() {
  IndexedMesh all;
  append(all, test::tetrahedron(), 0);
  append(all, test::cube(), 3);
  append(all, test::grid(3, false), 6);
  return build(all);
}

TEST(Components, ThreePiecesAreThreeComponentsOfTheirFaces) {
  const SurfaceMesh m = three_pieces();
  ASSERT_EQ(m.n_faces(), 4u + 6u + 9u);
  const Components faces = face_components(m);
  EXPECT_EQ(faces.count, 3u);
  ASSERT_EQ(faces.label.size(), m.face_slots());
  // Faces come in input order: 4 of the tetrahedron (component 0), 6 of the cube (1), 9 of the grid (2).
  for (Face f : m.faces()) {
    const Index expected = f.idx() < 4 ? 0 : f.idx() < 10 ? 1 : 2;
    EXPECT_EQ(faces.label[f.idx()], expected) << "face " << f.idx();
  }
  const Components vertices = vertex_components(m);
  EXPECT_EQ(vertices.count, 3u);
  for (Vertex v : m.vertices()) {
    const Index expected = v.idx() < 4 ? 0 : v.idx() < 12 ? 1 : 2;
    EXPECT_EQ(vertices.label[v.idx()], expected) << "vertex " << v.idx();
  }
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Components, IsolatedVerticesAndDeletedFacesBelongToNone) {
  SurfaceMesh m = three_pieces();
  const Vertex lone = m.add_vertex({-5, 0, 0});
  // Without the tetrahedron's faces the cube is component 0; whatever vertices stay behind are
  // isolated, in no component.
  const std::vector<Face> tet = {Face(0), Face(1), Face(2), Face(3)};
  remove_faces(m, tet);
  const Components faces = face_components(m);
  EXPECT_EQ(faces.count, 2u);
  for (Face f : tet) EXPECT_EQ(faces.label[f.idx()], kInvalidIndex);
  EXPECT_EQ(faces.label[4], 0u);
  EXPECT_EQ(faces.label[10], 1u);
  const Components vertices = vertex_components(m);
  EXPECT_EQ(vertices.count, 2u);
  EXPECT_EQ(vertices.label[lone.idx()], kInvalidIndex);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Components, CuttingAGridAlongAnEdgePathMakesTwoPieces) {
  // A 4 x 4 grid with its middle column of faces removed: the left and right strips share no edge.
  SurfaceMesh m = build(test::grid(3, false));
  remove_faces(m, std::vector<Face>{Face(1), Face(4), Face(7)});
  const Components faces = face_components(m);
  EXPECT_EQ(faces.count, 2u);
  std::set<Index> left, right;
  for (Face f : m.faces()) (f.idx() % 3 == 0 ? left : right).insert(faces.label[f.idx()]);
  EXPECT_EQ(left.size(), 1u);
  EXPECT_EQ(right.size(), 1u);
  EXPECT_NE(*left.begin(), *right.begin());
  EXPECT_EQ(vertex_components(m).count, 2u);
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(Components, TheEmptyMeshHasNone) {
  const SurfaceMesh m;
  EXPECT_EQ(face_components(m).count, 0u);
  EXPECT_EQ(vertex_components(m).count, 0u);
}

}  // namespace
}  // namespace hedge

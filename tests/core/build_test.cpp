// The driver of build() (src/core/build.cpp): entry points, report maps, corner attributes.
#include "hedge/core/build.h"

#include <gtest/gtest.h>

#include "core/build_test_util.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::euler;
using test::repair;
using test::tetrahedron;

TEST(Build, CleanMeshNeedsNoRepair) {
  BuildReport rep;
  SurfaceMesh m = build(tetrahedron(), repair(), &rep);
  EXPECT_EQ(rep.repairs(), 0u);
  EXPECT_EQ(rep.isolated_vertices, 0u);
  ASSERT_EQ(rep.vertex_map.size(), 4u);
  for (Index i = 0; i < 4; ++i) EXPECT_EQ(rep.vertex_map[i], i);
  ASSERT_EQ(rep.face_map.size(), 4u);
  for (Index i = 0; i < 4; ++i) EXPECT_EQ(rep.face_map[i], i);
  EXPECT_EQ(euler(m), 2);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, TrianglesFromSpansMatchIndexedBuild) {
  IndexedMesh in = test::grid(4, true);
  SurfaceMesh a = build(in);
  SurfaceMesh b = build_triangles(in.positions, in.indices);
  EXPECT_EQ(a.halfedge_vertex_array(), b.halfedge_vertex_array());
  EXPECT_EQ(a.halfedge_next_array(), b.halfedge_next_array());
  EXPECT_EQ(b.n_faces(), 32u);
  EXPECT_EQ(b.boundary_loops().size(), 1u);
  EXPECT_TRUE(b.validate().empty());
}

TEST(Build, CornerAttributesFollowCorners) {
  IndexedMesh in = test::cube();
  for (std::size_t c = 0; c < in.indices.size(); ++c) {
    in.texcoords.push_back({float(c), float(c) * 0.5f});
    in.texcoord_indices.push_back(static_cast<Index>(c));
  }
  SurfaceMesh m = build(in);
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(uv);
  // Corner k of face f is entered by the k-th half-edge from halfedge(f).
  for (Face f : m.faces()) {
    Index k = 0;
    for (Halfedge h : m.halfedges(f)) {
      Index c = f.idx() * 4 + k++;
      EXPECT_EQ(uv[h], in.texcoords[c]);
      EXPECT_EQ(m.to_vertex(h).idx(), in.indices[c]);
    }
  }
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

// The driver of build() (src/core/build.cpp): entry points, report maps, corner attributes.
#include "hedge/core/build.h"

#include <gtest/gtest.h>

#include <cstdint>

#include "core/build_test_util.h"
#include "hedge/core/properties.h"
#include "hedge/error.h"
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

// face_submeshes becomes "f:submesh", each kept face's own, through the face map when the repair
// drops a face; a submesh outside [0, kMaxSubmesh] or a count that is not one per face is refused.
TEST(Build, FaceSubmeshesBecomeTheSubmeshProperty) {
  IndexedMesh in = tetrahedron();
  in.face_submeshes = {0, 3, 1, 3};
  SurfaceMesh m = build(in);
  const auto submesh = m.get_face_property<std::int32_t>(kSubmeshProperty);
  ASSERT_TRUE(submesh);
  for (const Face f : m.faces()) EXPECT_EQ(submesh[f], in.face_submeshes[f.idx()]) << f.idx();
  EXPECT_TRUE(m.validate().empty());
  EXPECT_FALSE(build(tetrahedron()).get_face_property<std::int32_t>(kSubmeshProperty));

  IndexedMesh degenerate = tetrahedron();
  degenerate.indices.insert(degenerate.indices.begin(), {0, 0, 1});  // dropped by the repair
  degenerate.face_submeshes = {9, 0, 3, 1, 3};
  BuildReport rep;
  SurfaceMesh r = build(degenerate, repair(), &rep);
  ASSERT_EQ(rep.degenerate_faces, 1u);
  const auto kept = r.get_face_property<std::int32_t>(kSubmeshProperty);
  for (std::size_t f = 1; f < 5; ++f) EXPECT_EQ(kept[Face(rep.face_map[f])], degenerate.face_submeshes[f]);
  EXPECT_TRUE(r.validate().empty());

  in.face_submeshes = {0, 1, 2};
  EXPECT_THROW(build(in), InvalidInputError);
  in.face_submeshes = {0, 1, kMaxSubmesh + 1, 0};
  EXPECT_THROW(build(in), InvalidInputError);
}

}  // namespace
}  // namespace hedge

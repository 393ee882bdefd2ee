// The copy-and-restore of the binding core (src/binding/rollback.h).
#include "binding/rollback.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "test_meshes.h"

namespace hedge::binding {
namespace {

//! Everything that makes a mesh what it is, as plain values to compare.
struct Snapshot {
  std::vector<Vec3> positions;
  std::vector<Vertex> halfedge_vertex;
  std::vector<Halfedge> halfedge_next;
  std::vector<Face> halfedge_face;
  std::size_t vertices, edges, faces;
  bool operator==(const Snapshot& o) const {
    auto same = [](const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
      if (a.size() != b.size()) return false;
      for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z) return false;
      return true;
    };
    return same(positions, o.positions) && halfedge_vertex == o.halfedge_vertex &&
           halfedge_next == o.halfedge_next && halfedge_face == o.halfedge_face && vertices == o.vertices &&
           edges == o.edges && faces == o.faces;
  }
};

Snapshot snapshot(const SurfaceMesh& m) {
  return {m.positions().vector(),
          m.halfedge_vertex_array(),
          m.halfedge_next_array(),
          m.halfedge_face_array(),
          m.n_vertices(),
          m.n_edges(),
          m.n_faces()};
}

TEST(BindingRollback, ThrowingBodyLeavesTheMeshAsItWas) {
  SurfaceMesh m = build(test::grid(4, true));
  const Snapshot before = snapshot(m);
  EXPECT_THROW(with_rollback(m,
                             [&] {
                               // Halfway through a whole-mesh rewrite: elements gone, arrays
                               // compacted, positions moved, then a failure.
                               remove_face(m, Face(0));
                               remove_face(m, Face(5));
                               m.garbage_collection();
                               m.set_position(Vertex(0), Vec3{9, 9, 9});
                               throw std::runtime_error("failed halfway");
                             }),
               std::runtime_error);
  EXPECT_TRUE(snapshot(m) == before);
  EXPECT_TRUE(m.validate().empty());
}

TEST(BindingRollback, SuccessfulBodyKeepsItsResult) {
  SurfaceMesh m = build(test::grid(4, true));
  const std::size_t faces = m.n_faces();
  const std::size_t left = with_rollback(m, [&] {
    remove_face(m, Face(0));
    m.garbage_collection();
    return m.n_faces();
  });
  EXPECT_EQ(left, faces - 1);
  EXPECT_EQ(m.n_faces(), faces - 1);
  EXPECT_EQ(m.face_slots(), faces - 1);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge::binding

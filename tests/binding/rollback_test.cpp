// The copy-and-restore of the binding core (src/binding/rollback.h).
#include "binding/rollback.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "heap_hooks.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/reorder.h"
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

//! A triangle grid with garbage: two faces removed, not yet collected.
SurfaceMesh grid_with_garbage() {
  SurfaceMesh m = build(test::grid(8, true));
  remove_face(m, Face(0));
  remove_face(m, Face(40));
  return m;
}

//! Runs algorithm(mesh) with the allocation after k failing, for k = 0, 1, ... until it gets
//! through. Returns how many runs failed and how many of those left the mesh changed; with
//! `rollback` each runs under with_rollback().
template <typename Algorithm>
std::pair<int, int> fail_every_allocation(Algorithm algorithm, bool rollback) {
  const SurfaceMesh input = grid_with_garbage();
  const Snapshot before = snapshot(input);
  int failures = 0, changed = 0;
  for (long k = 0; k < 100000; ++k) {
    SurfaceMesh m = input;
    bool threw = false;
    test::fail_allocation_after(k);  // tests/heap_hooks.h
    try {
      if (rollback)
        with_rollback(m, [&] { algorithm(m); });
      else
        algorithm(m);
    } catch (const std::bad_alloc&) {
      threw = true;
    }
    test::disarm_allocation_failure();
    if (!threw) break;
    ++failures;
    if (!(snapshot(m) == before)) ++changed;
  }
  return {failures, changed};
}

TEST(BindingRollback, AllocationFailuresInTheAlgorithmsItGuardsLeaveTheMeshAsItWas) {
  const auto decimate_to_20 = [](SurfaceMesh& m) { decimate(m, {.target_faces = 20}); };
  const auto collect = [](SurfaceMesh& m) { m.garbage_collection(); };
  const auto spatial = [](SurfaceMesh& m) { reorder(m, Ordering::spatial); };
  // Without the rollback, decimate and the compactions leave a partial result behind at some
  // failure: that is why the bindings use it.
  EXPECT_GT(fail_every_allocation(decimate_to_20, false).second, 0);
  EXPECT_GT(fail_every_allocation(collect, false).second, 0);
  EXPECT_GT(fail_every_allocation(spatial, false).second, 0);
  for (const auto& [name, result] : {std::pair{"decimate", fail_every_allocation(decimate_to_20, true)},
                                     std::pair{"garbage_collection", fail_every_allocation(collect, true)},
                                     std::pair{"reorder", fail_every_allocation(spatial, true)}}) {
    EXPECT_GT(result.first, 3) << name;  // many failure points were tried
    EXPECT_EQ(result.second, 0) << name;
  }
}

}  // namespace
}  // namespace hedge::binding

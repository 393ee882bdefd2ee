#include "hedge/algorithms/fill_hole.h"

#include <gtest/gtest.h>

#include "edit_checks.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::Counts;
using test::counts;
using test::Snapshot;
using test::snapshot;
using test::textured_grid;

TEST(RemoveVertex, InteriorVertexLeavesAHoleThatFillHoleCloses) {
  SurfaceMesh m = build(test::grid(4, true));
  Counts before = counts(m);
  Vertex v(12);  // the centre
  std::size_t ring = m.valence(v);
  Halfedge outer = m.next(m.halfedge(v));
  ASSERT_TRUE(remove_vertex(m, v));
  EXPECT_TRUE(m.is_deleted(v));
  EXPECT_EQ(m.boundary_loops().size(), 2u);
  EXPECT_EQ(counts(m).f, before.f - static_cast<long long>(ring));
  EXPECT_TRUE(m.validate().empty());
  auto faces = fill_hole(m, outer);
  EXPECT_EQ(faces.size(), ring - 2);
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(counts(m).chi(), before.chi() - 1 + 1);
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_TRUE(m.validate().empty());
}

TEST(FillHole, OuterLoopOfAGridMakesASphere) {
  SurfaceMesh m = build(test::grid(3, false));
  auto loops = m.boundary_loops();
  ASSERT_EQ(loops.size(), 1u);
  auto faces = fill_hole(m, loops[0]);
  EXPECT_FALSE(faces.empty());
  EXPECT_TRUE(m.boundary_loops().empty());
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_TRUE(m.validate().empty());
  EXPECT_TRUE(fill_hole(m, m.halfedge(Face(0))).empty());  // not a boundary half-edge
}

TEST(CanFillHole, RefusesInteriorDeletedAndInvalidHalfedges) {
  SurfaceMesh m = textured_grid(3, false);
  ASSERT_TRUE(remove_face(m, Face(0)));  // a corner: two of its edges go with it
  Halfedge deleted;
  for (Index i = 0; i < m.halfedge_slots() && !deleted.is_valid(); ++i)
    if (m.is_deleted(Halfedge(i))) deleted = Halfedge(i);
  ASSERT_TRUE(deleted.is_valid());
  const Halfedge interior = m.halfedge(Face(4));
  ASSERT_FALSE(m.is_boundary(interior));
  const Snapshot s = snapshot(m);
  for (Halfedge h : {interior, deleted, Halfedge(), Halfedge(static_cast<Index>(m.halfedge_slots()))}) {
    EXPECT_FALSE(can_fill_hole(m, h)) << h.idx();
    EXPECT_TRUE(fill_hole(m, h).empty()) << h.idx();
  }
  EXPECT_TRUE(snapshot(m) == s);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CanFillHole, RefusesALoopOfTwoEdges) {
  // A tetrahedron with one edge cut open into two edges between the same vertices: the slit is a
  // boundary loop of two edges, a valid surface that no face fits.
  SurfaceMesh m = build(test::tetrahedron());
  const Halfedge h = SurfaceMesh::halfedge(Edge(0), 0), t = SurfaceMesh::twin(h);
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  const Face ft = m.face(t);
  const Halfedge t_prev = m.prev(t), t_next = m.next(t);
  const Halfedge n = m.new_edge(a, b), nt = SurfaceMesh::twin(n);  // nt replaces t in ft
  m.set_next(t_prev, nt);
  m.set_next(nt, t_next);
  m.set_face(nt, ft);
  m.set_halfedge(ft, nt);
  m.set_face(t, Face());
  m.set_face(n, Face());
  m.set_next(t, n);
  m.set_next(n, t);
  m.set_halfedge(a, n);
  m.set_halfedge(b, t);
  ASSERT_TRUE(m.validate().empty());
  ASSERT_EQ(m.boundary_loops().size(), 1u);
  const Snapshot s = snapshot(m);
  for (Halfedge g : {t, n}) {
    EXPECT_FALSE(can_fill_hole(m, g));
    EXPECT_TRUE(fill_hole(m, g).empty());
  }
  EXPECT_TRUE(snapshot(m) == s);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CanFillHole, AcceptsAHoleAndFillHoleFollowsItEverywhere) {
  // Two holes (around the removed inner quad and the outer border), deleted elements from a
  // removed corner, interior half-edges: fill_hole makes faces exactly where can_fill_hole says
  // yes, and leaves the mesh untouched where it says no.
  SurfaceMesh m = textured_grid(4, false);
  ASSERT_TRUE(remove_face(m, Face(5)));
  ASSERT_TRUE(remove_face(m, Face(15)));
  ASSERT_EQ(m.boundary_loops().size(), 2u);
  std::size_t accepted = 0, refused = 0;
  for (Index i = 0; i < m.halfedge_slots() + 2; ++i) {
    const Halfedge h(i);
    SurfaceMesh copy = m;
    const Snapshot s = snapshot(copy);
    const bool can = can_fill_hole(copy, h);
    EXPECT_EQ(can, m.is_live(h) && m.is_boundary(h)) << i;
    const std::vector<Face> faces = fill_hole(copy, h);
    EXPECT_EQ(faces.empty(), !can) << i;
    if (can) {
      ++accepted;
      EXPECT_TRUE(m.is_boundary(h));
      EXPECT_FALSE(copy.is_boundary(h));
      EXPECT_FALSE(can_fill_hole(copy, h));
      EXPECT_EQ(copy.boundary_loops().size(), 1u);
      EXPECT_TRUE(copy.validate().empty()) << i;
    } else {
      ++refused;
      EXPECT_TRUE(snapshot(copy) == s) << i;
    }
  }
  EXPECT_GT(accepted, 0u);
  EXPECT_GT(refused, 0u);
  EXPECT_TRUE(m.validate().empty());
}

// can_fill_hole as its comment states it: a live boundary half-edge on a loop of 3 edges or more.
bool fill_hole_contract(const SurfaceMesh& m, Halfedge h) {
  if (!m.is_live(h) || !m.is_boundary(h)) return false;
  std::size_t n = 0;
  for (Halfedge g = h; n == 0 || g != h; g = m.next(g)) ++n;
  return n >= 3;
}

// fill_hole_refusal against can_fill_hole, its contract and fill_hole, on half-edges of a mesh that random
// edits keep changing (its removals open holes).
TEST(Refusal, FillHoleAgreesWithItsEditOverRandomEdits) {
  SurfaceMesh m = build(test::grid(5, false));
  std::size_t refused = 0, allowed = 0;
  test::after_random_edits(m, 13, 250, [&](const SurfaceMesh& mesh) {
    for (std::size_t k = 0; k < 6; ++k) {
      Halfedge h(static_cast<Index>((k * 104729 + mesh.n_halfedges()) % mesh.halfedge_slots()));
      if (k % 2 == 0 && mesh.is_live(h) && !mesh.is_boundary(h)) h = SurfaceMesh::twin(h);
      const char* why = fill_hole_refusal(mesh, h);
      (why ? refused : allowed) += 1;
      test::expect_refusal_agrees(
          mesh, can_fill_hole(mesh, h), fill_hole_contract(mesh, h), why,
          [&](SurfaceMesh& c) { return !fill_hole(c, h).empty(); },
          "fill the hole at half-edge " + std::to_string(h.idx()));
    }
  });
  EXPECT_GT(refused, 100u);
  EXPECT_GT(allowed, 100u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Refusal, FillHoleSaysWhy) {
  SurfaceMesh m = build(test::grid(1, false));
  const Halfedge h = m.halfedge(Face(0));
  EXPECT_STREQ(fill_hole_refusal(m, h), "the half-edge is not on a boundary (it has a face)");
  EXPECT_EQ(fill_hole_refusal(m, SurfaceMesh::twin(h)), nullptr);
  EXPECT_TRUE(m.validate().empty());
}
}  // namespace
}  // namespace hedge

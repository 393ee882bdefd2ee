// split_edge, collapse and flip (src/core/edge_operations.cpp).
#include "hedge/core/edge_operations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "edit_checks.h"
#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace test;  // edit_checks.h and test_meshes.h

TEST(SplitEdge, InteriorEdgeSplitsBothTriangles) {
  SurfaceMesh m = textured_grid(2, true);
  Counts before = counts(m);
  Edge e = m.find_edge(Vertex(0), Vertex(4));  // a diagonal
  ASSERT_TRUE(e.is_valid());
  ASSERT_FALSE(m.is_boundary(e));
  Vertex v = split_edge(m, e, {0.5f, 0.5f, 0});
  ASSERT_TRUE(v.is_valid());
  Counts after = counts(m);
  EXPECT_EQ(after.v, before.v + 1);
  EXPECT_EQ(after.e, before.e + 3);
  EXPECT_EQ(after.f, before.f + 2);
  EXPECT_EQ(m.valence(v), 4u);
  EXPECT_NEAR(m.get_vertex_property<float>("v:weight")[v], 0.5f, 1e-6f);
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitEdge, BoundaryEdgeSplitsOneTriangle) {
  SurfaceMesh m = textured_grid(2, true);
  Counts before = counts(m);
  Edge e = m.find_edge(Vertex(0), Vertex(1));
  ASSERT_TRUE(m.is_boundary(e));
  Vertex v = split_edge(m, e, {0.25f, 0, 0});
  ASSERT_TRUE(v.is_valid());
  EXPECT_EQ(counts(m).v, before.v + 1);
  EXPECT_EQ(counts(m).e, before.e + 2);
  EXPECT_EQ(counts(m).f, before.f + 1);
  EXPECT_TRUE(m.is_boundary(v));
  EXPECT_TRUE(m.is_boundary(m.halfedge(v)));
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitEdge, PolygonGainsTheVertexAndOffSegmentPointsWork) {
  SurfaceMesh m = build(test::cube());
  Counts before = counts(m);
  Vertex v = split_edge(m, Edge(0), {5, 5, 5});  // far off the segment
  ASSERT_TRUE(v.is_valid());
  EXPECT_EQ(m.position(v), (Vec3{5, 5, 5}));
  EXPECT_EQ(counts(m).v, before.v + 1);
  EXPECT_EQ(counts(m).e, before.e + 1);
  EXPECT_EQ(counts(m).f, before.f);
  std::size_t pentagons = 0;
  for (Face f : m.faces()) pentagons += m.valence(f) == 5;
  EXPECT_EQ(pentagons, 2u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitEdge, UserInterpolationPolicy) {
  SurfaceMesh m = textured_grid(2, true);
  auto w = m.get_vertex_property<float>("v:weight");
  // Keep the largest weight instead of blending (e.g. a "distance to the impact" field).
  w.set_interpolator(
      [](const float* values, const float*, std::size_t n) { return *std::max_element(values, values + n); });
  auto tag = m.add_vertex_property<int>("v:tag", 0);
  tag[Vertex(0)] = 3;
  tag[Vertex(4)] = 9;
  Vertex v = split_edge(m, m.find_edge(Vertex(0), Vertex(4)), {0.2f, 0.2f, 0});
  EXPECT_EQ(w[v], 1.0f);  // max(x of vertex 0, x of vertex 4)
  EXPECT_EQ(tag[v], 3);   // integers take the nearest source (vertex 0 at 20%)
  w.set_interpolator({});
  Vertex u = split_edge(m, m.find_edge(Vertex(1), Vertex(2)), {1.5f, 0, 0});
  EXPECT_NEAR(w[u], 1.5f, 1e-6f);
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitEdge, RepeatedSplitsKeepNoState) {
  // Each call is independent: no state (such as a recursion lock) carries over between splits.
  SurfaceMesh m = build(test::tetrahedron());
  for (int i = 0; i < 50; ++i) {
    Edge e(static_cast<Index>(i % m.edge_slots()));
    Vec3 a = m.position(m.vertex(e, 0)), b = m.position(m.vertex(e, 1));
    ASSERT_TRUE(split_edge(m, e, (a + b) * 0.5f).is_valid());
    ASSERT_TRUE(m.validate().empty());
  }
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_FALSE(split_edge(m, Edge(9999), {}).is_valid());
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitEdge, PointInsideThePositionArray) {
  // The point may be a reference to a position of the mesh itself, whose array grows (and may
  // move) as the vertex is added.
  SurfaceMesh m = textured_grid(2, true);
  for (int i = 0; i < 200; ++i) {
    const Edge e(static_cast<Index>(i % m.edge_slots()));
    const Vec3 expected = m.position(m.vertex(e, 1));
    const Vertex v = split_edge(m, e, m.position(m.vertex(e, 1)));
    ASSERT_TRUE(v.is_valid());
    EXPECT_EQ(m.position(v), expected);
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Collapse, InteriorEdgeKeepsTheChosenVertex) {
  SurfaceMesh m = textured_grid(4, true);
  Counts before = counts(m);
  Halfedge h = m.find_halfedge(Vertex(6), Vertex(12));  // interior diagonal, both interior
  ASSERT_TRUE(h.is_valid());
  ASSERT_TRUE(can_collapse(m, h));
  Vertex kept = collapse(m, h);
  EXPECT_EQ(kept, Vertex(12));
  EXPECT_TRUE(m.is_deleted(Vertex(6)));
  EXPECT_EQ(counts(m).v, before.v - 1);
  EXPECT_EQ(counts(m).e, before.e - 3);
  EXPECT_EQ(counts(m).f, before.f - 2);
  EXPECT_TRUE(m.validate().empty());
  m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
}

TEST(Collapse, BoundaryEdgeAndVertexNearBoundary) {
  SurfaceMesh m = build(test::grid(4, true));
  Halfedge b = m.find_halfedge(Vertex(1), Vertex(2));
  ASSERT_TRUE(m.is_boundary(m.edge(b)));
  Counts before = counts(m);
  ASSERT_TRUE(collapse(m, b).is_valid());
  EXPECT_EQ(counts(m).f, before.f - 1);
  EXPECT_EQ(counts(m).chi(), before.chi());
  EXPECT_TRUE(m.validate().empty());
  // Interior vertex 6 into boundary vertex 5... (5 is on the left column? no: row 1, column 0 is 5)
  Halfedge h = m.find_halfedge(Vertex(6), Vertex(5));
  ASSERT_TRUE(h.is_valid());
  EXPECT_TRUE(can_collapse(m, h));
  EXPECT_TRUE(collapse(m, h).is_valid());
  EXPECT_TRUE(m.validate().empty());
}

TEST(Collapse, RefusalsLeaveTheMeshUntouched) {
  // Every edge of a tetrahedron: collapsing would leave a doubled triangle.
  SurfaceMesh tet = build(test::tetrahedron());
  Snapshot s = snapshot(tet);
  for (Halfedge h : tet.halfedges()) {
    EXPECT_FALSE(can_collapse(tet, h));
    EXPECT_FALSE(collapse(tet, h).is_valid());
  }
  EXPECT_TRUE(snapshot(tet) == s);

  // An interior edge joining two boundary vertices would pinch the surface.
  SurfaceMesh grid = textured_grid(2, true);
  Snapshot g = snapshot(grid);
  Halfedge pinch = grid.find_halfedge(Vertex(1), Vertex(4));
  Halfedge pinch2 = grid.find_halfedge(Vertex(3), Vertex(1));
  for (Halfedge h : {pinch, pinch2}) {
    if (!h.is_valid()) continue;
    if (!grid.is_boundary(grid.edge(h)) && grid.is_boundary(grid.from_vertex(h)) &&
        grid.is_boundary(grid.to_vertex(h))) {
      EXPECT_FALSE(collapse(grid, h).is_valid());
    }
  }
  // A lone triangle: any collapse would leave a dangling edge.
  IndexedMesh tri;
  tri.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  tri.indices = {0, 1, 2};
  SurfaceMesh t = build(tri);
  Snapshot ts = snapshot(t);
  for (Halfedge h : t.halfedges()) EXPECT_FALSE(collapse(t, h).is_valid());
  EXPECT_TRUE(snapshot(t) == ts);
  EXPECT_TRUE(snapshot(grid) == g);
  EXPECT_TRUE(grid.validate().empty());
}

TEST(Collapse, LinkConditionRefusesClosingATriangularHole) {
  // A tetrahedron without one face: the hole's edges join vertices whose third common neighbour
  // lies across the hole, not on a triangle of the edge.
  IndexedMesh in = test::tetrahedron();
  in.indices.resize(9);
  SurfaceMesh m = build(in);
  ASSERT_EQ(m.boundary_loops().size(), 1u);
  Snapshot s = snapshot(m);
  for (Halfedge h : m.halfedges())
    if (m.is_boundary(m.edge(h))) EXPECT_FALSE(collapse(m, h).is_valid());
  EXPECT_TRUE(snapshot(m) == s);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Collapse, EveryEdgeOfATriangulatedCube) {
  IndexedMesh cube = test::cube();
  IndexedMesh tri;
  tri.positions = cube.positions;
  for (std::size_t f = 0; f < 6; ++f) {
    const Index* q = &cube.indices[4 * f];
    tri.indices.insert(tri.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  SurfaceMesh m = build(tri);
  std::size_t refused = 0, done = 0;
  for (Halfedge h : m.halfedges()) {
    SurfaceMesh copy = m;
    Snapshot s = snapshot(copy);
    if (collapse(copy, h).is_valid()) {
      ++done;
      EXPECT_TRUE(copy.validate().empty());
      EXPECT_EQ(counts(copy).chi(), 2);
      EXPECT_EQ(copy.n_vertices(), 7u);
    } else {
      ++refused;
      EXPECT_TRUE(snapshot(copy) == s);
    }
  }
  EXPECT_EQ(done + refused, m.n_halfedges());
  EXPECT_GT(done, 0u);
}

TEST(Collapse, UntilRefusedEndsValid) {
  SurfaceMesh m = build(test::grid(6, true));
  bool any = true;
  while (any) {
    any = false;
    for (Halfedge h : m.halfedges())
      if (can_collapse(m, h)) {
        collapse(m, h);
        any = true;
        ASSERT_TRUE(m.validate().empty());
      }
  }
  EXPECT_EQ(counts(m).chi(), 1);
  EXPECT_LE(m.n_faces(), 2u);
  EXPECT_TRUE(m.validate().empty());
}

// ---- Corner attributes through split and collapse ----------------------------------------------

// A triangulated n x n grid of unit squares whose corners carry texcoords. Columns of squares left
// of `seam_column` map with uv = (x, y) / n; the others with uv = (x / n + 10, y / n), so the
// vertical line x = seam_column is a UV seam (none if seam_column >= n).
SurfaceMesh uv_grid(int n, int seam_column) {
  IndexedMesh in = test::grid(n, true);
  for (std::size_t t = 0; t < in.indices.size(); t += 3) {
    float cx = 0;
    for (int k = 0; k < 3; ++k) cx += in.positions[in.indices[t + k]].x / 3;
    const float shift = cx > float(seam_column) ? 10.f : 0.f;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = in.positions[in.indices[t + k]];
      in.texcoord_indices.push_back(static_cast<Index>(in.texcoords.size()));
      in.texcoords.push_back({p.x / float(n) + shift, p.y / float(n)});
    }
  }
  return build(in);
}

// The distinct texcoords among v's corners (the half-edges entering v in a face).
std::vector<Vec2> corner_uvs(const SurfaceMesh& m, Vertex v) {
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  std::vector<Vec2> out;
  for (Halfedge o : m.halfedges(v)) {
    const Halfedge c = m.twin(o);
    if (m.is_boundary(c)) continue;
    if (std::find(out.begin(), out.end(), uv[c]) == out.end()) out.push_back(uv[c]);
  }
  return out;
}

// Render vertices beyond one per vertex, as an engine export makes them: what the seams cost.
std::size_t seam_splits(const SurfaceMesh& m) {
  std::size_t n = 0;
  for (Vertex v : m.vertices())
    if (!m.is_isolated(v)) n += corner_uvs(m, v).size() - 1;
  return n;
}

// A live half-edge, uniformly at random.
Halfedge random_halfedge(const SurfaceMesh& m, std::mt19937& rng) {
  std::uniform_int_distribution<Index> pick(0, static_cast<Index>(m.halfedge_slots() - 1));
  for (;;) {
    const Halfedge h(pick(rng));
    if (m.is_live(h)) return h;
  }
}

TEST(CollapseCorners, SplitThenCollapseLeavesOneCornerValue) {
  // The reported case: split the edge from uv (0.5, 0.5) to (0.75, 0.5) at a quarter, then merge
  // the new vertex (uv (0.5625, 0.5)) into the first end. The survivor must keep one texcoord.
  SurfaceMesh m = uv_grid(4, 4);
  const Vertex a(12), b(13);  // positions (2, 2) and (3, 2)
  ASSERT_EQ(m.position(a), (Vec3{2, 2, 0}));
  const Vertex v = split_edge(m, m.find_edge(a, b), {2.25f, 2, 0});
  ASSERT_TRUE(v.is_valid());
  ASSERT_EQ(corner_uvs(m, v), (std::vector<Vec2>{{0.5625f, 0.5f}}));
  EXPECT_EQ(seam_splits(m), 0u);
  const Halfedge h = m.find_halfedge(v, a);
  ASSERT_TRUE(can_collapse(m, h));
  ASSERT_EQ(collapse(m, h), a);
  EXPECT_EQ(corner_uvs(m, a), (std::vector<Vec2>{{0.5f, 0.5f}}));
  EXPECT_EQ(seam_splits(m), 0u);
  // And the other way round: the new vertex survives with its own value.
  const Vertex w = split_edge(m, m.find_edge(a, b), {2.25f, 2, 0});
  ASSERT_EQ(collapse(m, m.find_halfedge(a, w)), w);
  EXPECT_EQ(corner_uvs(m, w), (std::vector<Vec2>{{0.5625f, 0.5f}}));
  EXPECT_EQ(seam_splits(m), 0u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CollapseCorners, RandomSplitsAndCollapsesMakeNoSeam) {
  for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    SurfaceMesh m = uv_grid(6, 6);
    std::size_t collapses = 0;
    for (int i = 0; i < 600; ++i) {
      const Halfedge h = random_halfedge(m, rng);
      const int kind = static_cast<int>(rng() % 3);
      if (kind == 0) {
        const Vec3 a = m.position(m.from_vertex(h)), b = m.position(m.to_vertex(h));
        const float s = std::uniform_real_distribution<float>(0.1f, 0.9f)(rng);
        ASSERT_TRUE(split_edge(m, m.edge(h), a + (b - a) * s).is_valid());
      } else if (kind == 1 && !m.is_boundary(h)) {
        ASSERT_TRUE(split_face(m, m.face(h), face_centroid(m, m.face(h))).is_valid());
      } else if (collapse(m, h).is_valid()) {
        ++collapses;
      }
      ASSERT_EQ(seam_splits(m), 0u) << "after operation " << i;
    }
    EXPECT_GT(collapses, 50u);
    EXPECT_TRUE(m.validate().empty());
  }
}

TEST(CollapseCorners, AlongASeamKeepsBothSidesAndOffItIsRefused) {
  // Seam at x = 2 of a 4 x 4 grid: vertices 2, 7, 12, 17, 22 lie on it.
  SurfaceMesh m = uv_grid(4, 2);
  const Vertex s0(12), s1(17), off(13);  // (2, 2), (2, 3) on the seam; (3, 2) right of it
  ASSERT_EQ(corner_uvs(m, s0).size(), 2u);
  ASSERT_EQ(seam_splits(m), 5u);  // every vertex on the seam, its boundary ends included
  // A seam vertex pulled off its seam: refused, and nothing changes.
  const Snapshot before = snapshot(m);
  EXPECT_FALSE(can_collapse(m, m.find_halfedge(s0, off)));
  EXPECT_FALSE(collapse(m, m.find_halfedge(s0, off)).is_valid());
  EXPECT_TRUE(snapshot(m) == before);
  // Along the seam: each side of s1 takes s0's value on that side.
  ASSERT_EQ(collapse(m, m.find_halfedge(s1, s0)), s0);
  EXPECT_EQ(corner_uvs(m, s0).size(), 2u);
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  for (Face f : m.faces()) {
    const bool right = face_centroid(m, f).x > 2;
    for (Halfedge c : m.halfedges(f)) {
      const Vec3 p = m.position(m.to_vertex(c));
      EXPECT_EQ(uv[c], (Vec2{p.x / 4 + (right ? 10.f : 0.f), p.y / 4}));
    }
  }
  EXPECT_EQ(seam_splits(m), 4u);
  // An off-seam vertex onto the seam: it joins the side it comes from.
  ASSERT_EQ(collapse(m, m.find_halfedge(off, s0)), s0);
  EXPECT_EQ(corner_uvs(m, s0).size(), 2u);
  EXPECT_EQ(seam_splits(m), 4u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CollapseCorners, SpotKeepsItsSeamsUnderRandomCollapses) {
  SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  ASSERT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord"));
  std::size_t splits = seam_splits(m);
  ASSERT_GT(splits, 0u);
  std::mt19937 rng(13);
  std::size_t done = 0, along_seams = 0;
  for (int i = 0; i < 1500; ++i) {
    const Halfedge h = random_halfedge(m, rng);
    const std::size_t merged = corner_uvs(m, m.from_vertex(h)).size() - 1;  // its own splits
    if (!collapse(m, h).is_valid()) continue;
    ++done;
    along_seams += merged > 0;
    // The merged vertex's splits go with it; no other vertex gains or loses one.
    ASSERT_EQ(seam_splits(m), splits - merged) << "after collapse " << done;
    splits -= merged;
  }
  EXPECT_GT(done, 500u);
  EXPECT_GT(along_seams, 0u);
  EXPECT_GT(splits, 0u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Flip, TurnsTheDiagonalAndBack) {
  SurfaceMesh m = textured_grid(1, true);  // two triangles 0-1-3, 0-3-2
  Edge e = m.find_edge(Vertex(0), Vertex(3));
  ASSERT_TRUE(can_flip(m, e));
  ASSERT_EQ(flip(m, e), e);
  EXPECT_TRUE(m.find_edge(Vertex(1), Vertex(2)).is_valid());
  EXPECT_FALSE(m.find_edge(Vertex(0), Vertex(3)).is_valid());
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());
  ASSERT_EQ(flip(m, e), e);
  EXPECT_TRUE(m.find_edge(Vertex(0), Vertex(3)).is_valid());
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Flip, Refusals) {
  SurfaceMesh tet = build(test::tetrahedron());
  Snapshot s = snapshot(tet);
  for (Edge e : tet.edges()) EXPECT_FALSE(flip(tet, e).is_valid());  // the flipped edge exists
  EXPECT_TRUE(snapshot(tet) == s);
  SurfaceMesh quads = build(test::grid(2, false));
  Snapshot q = snapshot(quads);
  for (Edge e : quads.edges()) EXPECT_FALSE(flip(quads, e).is_valid());  // not triangles / boundary
  EXPECT_TRUE(snapshot(quads) == q);
  EXPECT_TRUE(quads.validate().empty());
}

// can_flip as its comment states it, from the mesh's queries alone: e is interior, both its faces
// are triangles, its tips differ and are not joined by an edge, and neither end is an interior
// vertex of valence 3.
bool flip_contract(const SurfaceMesh& m, Edge e) {
  if (!m.is_live(e) || m.is_boundary(e)) return false;
  const Halfedge h = SurfaceMesh::halfedge(e, 0), t = SurfaceMesh::twin(h);
  if (m.valence(m.face(h)) != 3 || m.valence(m.face(t)) != 3) return false;
  const Vertex c = m.to_vertex(m.next(h)), d = m.to_vertex(m.next(t));
  if (c == d || m.find_edge(c, d).is_valid()) return false;
  for (const Vertex v : {m.from_vertex(h), m.to_vertex(h)})
    if (!m.is_boundary(v) && m.valence(v) <= 3) return false;
  return true;
}

// split_refusal, collapse_refusal and flip_refusal against their predicates, their contracts and the
// edits, on live and deleted elements of a mesh that random edits keep changing.
TEST(Refusal, SplitCollapseAndFlipAgreeWithTheirEditsOverRandomEdits) {
  SurfaceMesh m = build(test::grid(5, false));
  std::size_t refused = 0, allowed = 0;
  test::after_random_edits(m, 11, 250, [&](const SurfaceMesh& mesh) {
    for (std::size_t k = 0; k < 6; ++k) {
      const Edge e(static_cast<Index>((k * 7919 + mesh.n_edges()) % mesh.edge_slots()));
      const Halfedge h = SurfaceMesh::halfedge(e, k % 2);
      const std::string name = "edge " + std::to_string(e.idx());
      test::expect_refusal_agrees(
          mesh, can_split_edge(mesh, e), mesh.is_live(e), split_refusal(mesh, e),
          [&](SurfaceMesh& c) {
            return split_edge(c, e, Vec3{0.5f, 0.5f, 0}).is_valid();
          },
          "split " + name);
      test::expect_refusal_agrees(
          mesh, can_collapse(mesh, h), can_collapse(mesh, h), collapse_refusal(mesh, h),
          [&](SurfaceMesh& c) { return collapse(c, h).is_valid(); }, "collapse of " + name);
      const char* why = flip_refusal(mesh, e);
      (why ? refused : allowed) += 1;
      test::expect_refusal_agrees(
          mesh, can_flip(mesh, e), flip_contract(mesh, e), why,
          [&](SurfaceMesh& c) { return flip(c, e).is_valid(); }, "flip " + name);
    }
  });
  EXPECT_GT(refused, 100u);
  EXPECT_GT(allowed, 100u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Refusal, FlipSaysWhy) {
  SurfaceMesh m = build(test::grid(2, true));
  const Edge boundary = m.find_edge(Vertex(0), Vertex(1));
  EXPECT_STREQ(flip_refusal(m, boundary),
               "the edge is on the boundary (a flip needs a triangle on both sides)");
  SurfaceMesh quads = build(test::grid(2, false));
  EXPECT_STREQ(flip_refusal(quads, quads.find_edge(Vertex(1), Vertex(4))),
               "a face on the edge is not a triangle");
  const Halfedge inside =
      SurfaceMesh::halfedge(boundary, m.is_boundary(SurfaceMesh::halfedge(boundary, 0)) ? 1 : 0);
  ASSERT_TRUE(remove_face(m, m.face(inside)));
  ASSERT_FALSE(m.is_live(boundary));
  EXPECT_STREQ(flip_refusal(m, boundary), "the edge is not live");
  EXPECT_STREQ(split_refusal(m, boundary), "the edge is not live");
  EXPECT_TRUE(m.validate().empty());

  // A tetrahedron whose two faces away from edge e are split: the ends of e have 4 edges each, and
  // its tips are still joined by the tetrahedron's opposite edge.
  SurfaceMesh tet = build(test::tetrahedron());
  const Edge e(0);
  std::vector<Face> away;
  for (const Face f : tet.faces())
    if (tet.face(e, 0) != f && tet.face(e, 1) != f) away.push_back(f);
  ASSERT_EQ(away.size(), 2u);
  for (const Face f : away) ASSERT_TRUE(split_face(tet, f, face_centroid(tet, f)).is_valid());
  EXPECT_STREQ(flip_refusal(tet, e), "the tips of its triangles are already joined by an edge");
  EXPECT_FALSE(can_flip(tet, e));
  EXPECT_TRUE(tet.validate().empty());
}

}  // namespace
}  // namespace hedge

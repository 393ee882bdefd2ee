// split_face, cut_face, add_face and the removals (src/core/face_operations.cpp).
#include "hedge/core/face_operations.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "edit_checks.h"
#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace test;  // edit_checks.h and test_meshes.h

TEST(SplitFace, PointInsideThePositionArray) {
  // As for split_edge: the point may be a reference into the position array that grows.
  SurfaceMesh m = textured_grid(2, true);
  for (int i = 0; i < 200; ++i) {
    const Face f(static_cast<Index>(i % m.face_slots()));
    const Vertex corner = m.to_vertex(m.halfedge(f));
    const Vec3 expected = m.position(corner);
    const Vertex v = split_face(m, f, m.position(corner));
    ASSERT_TRUE(v.is_valid());
    EXPECT_EQ(m.position(v), expected);
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(SplitFace, TriangleAndPolygon) {
  SurfaceMesh m = textured_grid(1, true);
  Counts before = counts(m);
  Vertex v = split_face(m, Face(0), {0.6f, 0.3f, 0});
  ASSERT_TRUE(v.is_valid());
  EXPECT_EQ(counts(m).v, before.v + 1);
  EXPECT_EQ(counts(m).e, before.e + 3);
  EXPECT_EQ(counts(m).f, before.f + 2);
  EXPECT_EQ(m.valence(v), 3u);
  EXPECT_NEAR(m.get_vertex_property<float>("v:weight")[v], 0.6f, 1e-5f);  // barycentric blend of x
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());

  SurfaceMesh c = build(test::cube());
  auto label = c.add_face_property<int>("f:label", 0);
  label[Face(2)] = 7;
  v = split_face(c, Face(2), {0.5f, 0, 0.5f});
  EXPECT_EQ(c.valence(v), 4u);
  EXPECT_EQ(c.n_faces(), 9u);
  std::size_t labelled = 0;
  for (Face f : c.faces(v)) labelled += label[f] == 7;
  EXPECT_EQ(labelled, 4u);
  EXPECT_TRUE(c.validate().empty());
}

TEST(CutFace, AlongADiagonal) {
  SurfaceMesh m = textured_grid(1, false);  // one quad
  Halfedge h0 = m.halfedge(Face(0));
  Halfedge adjacent = m.next(h0);
  Snapshot s = snapshot(m);
  EXPECT_FALSE(cut_face(m, h0, adjacent).is_valid());
  EXPECT_FALSE(cut_face(m, h0, h0).is_valid());
  EXPECT_TRUE(snapshot(m) == s);
  Halfedge h1 = m.next(m.next(h0));
  Halfedge n = cut_face(m, h0, h1);
  ASSERT_TRUE(n.is_valid());
  EXPECT_EQ(m.from_vertex(n), m.to_vertex(h0));
  EXPECT_EQ(m.to_vertex(n), m.to_vertex(h1));
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_EQ(m.n_faces(), 2u);
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());
  // The diagonal now exists: cutting again is refused.
  EXPECT_FALSE(can_cut_face(m, m.prev(n), m.next(n)));
}

TEST(FaceCentroid, MeanOfTheCornersInDoubleAndRoundedToFloat) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {3, 0, 0}, {3, 4, 0}, {0, 4, 0}, {1, 5, 0}};
  in.indices = {0, 1, 2, 3, 3, 2, 4};
  in.face_sizes = {4, 3};
  const SurfaceMesh m = build(in);
  EXPECT_EQ(face_centroid<double>(m, Face(0)), (Vec3d{1.5, 2, 0}));
  // (0 + 3 + 1) / 3 and (4 + 4 + 5) / 3 are not floats: the mean is taken in double.
  EXPECT_EQ(face_centroid<double>(m, Face(1)), (Vec3d{4.0 / 3.0, 13.0 / 3.0, 0}));
  for (Face f : m.faces()) EXPECT_EQ(face_centroid(m, f), to_float(face_centroid<double>(m, f)));
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

TEST(AddRemoveFace, RemoveThenAddRestores) {
  SurfaceMesh m = build(test::tetrahedron());
  std::vector<Vertex> corners;
  for (Vertex v : m.vertices(Face(1))) corners.push_back(v);
  ASSERT_TRUE(remove_face(m, Face(1)));
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(m.n_faces(), 3u);
  EXPECT_TRUE(m.validate().empty());
  Face f = add_face(m, corners);
  ASSERT_TRUE(f.is_valid());
  EXPECT_TRUE(m.boundary_loops().empty());
  EXPECT_EQ(counts(m).chi(), 2);
  EXPECT_TRUE(m.validate().empty());
}

TEST(AddRemoveFace, BuildFaceByFaceMatchesBulkBuild) {
  // add_face keeps every vertex manifold, so a face must meet the mesh along an edge (a face
  // touching it at a vertex only is refused until a neighbour joins them): add faces in
  // breadth-first order over their adjacency, deferring those not attachable yet.
  IndexedMesh in = test::grid(4, true);
  SurfaceMesh bulk = build(in);
  std::vector<std::size_t> pending;
  std::vector<bool> queued(bulk.face_slots(), false);
  pending.push_back(0);
  queued[0] = true;
  for (std::size_t i = 0; i < pending.size(); ++i)
    for (Face g : bulk.faces(Face(static_cast<Index>(pending[i]))))
      if (!queued[g.idx()]) {
        queued[g.idx()] = true;
        pending.push_back(g.idx());
      }
  ASSERT_EQ(pending.size(), bulk.n_faces());
  for (auto& t : pending) t *= 3;
  SurfaceMesh m;
  for (const Vec3& p : in.positions) m.add_vertex(p);
  while (!pending.empty()) {
    std::vector<std::size_t> later;
    for (std::size_t t : pending) {
      Vertex tri[3] = {Vertex(in.indices[t]), Vertex(in.indices[t + 1]), Vertex(in.indices[t + 2])};
      if (add_face(m, tri).is_valid())
        ASSERT_TRUE(m.validate().empty()) << "after face " << t / 3;
      else
        later.push_back(t);
    }
    ASSERT_LT(later.size(), pending.size());
    pending.swap(later);
  }
  EXPECT_EQ(m.n_edges(), bulk.n_edges());
  EXPECT_EQ(m.n_faces(), bulk.n_faces());
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  for (std::size_t t = 0; t < in.indices.size(); t += 3) {
    Halfedge h = m.find_halfedge(Vertex(in.indices[t]), Vertex(in.indices[t + 1]));
    ASSERT_TRUE(h.is_valid());
    EXPECT_FALSE(m.is_boundary(h));
    EXPECT_EQ(m.to_vertex(m.next(h)), Vertex(in.indices[t + 2]));
  }
}

TEST(AddRemoveFace, RefusesNonManifoldResults) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, 1, 0}};
  in.indices = {0, 1, 2};
  SurfaceMesh m = build(in);
  Snapshot s = snapshot(m);
  Vertex bowtie[3] = {Vertex(0), Vertex(3), Vertex(4)};  // touches the triangle at vertex 0 only
  EXPECT_FALSE(can_add_face(m, bowtie));
  EXPECT_FALSE(add_face(m, bowtie).is_valid());
  Vertex same_side[3] = {Vertex(0), Vertex(1), Vertex(5)};  // edge 0->1 already has its face
  EXPECT_FALSE(add_face(m, same_side).is_valid());
  Vertex repeated[3] = {Vertex(0), Vertex(1), Vertex(1)};
  EXPECT_FALSE(add_face(m, repeated).is_valid());
  EXPECT_TRUE(snapshot(m) == s);
  // Across the free side of edge 1-0 is fine.
  Vertex ok[3] = {Vertex(1), Vertex(0), Vertex(4)};
  EXPECT_TRUE(add_face(m, ok).is_valid());
  EXPECT_TRUE(m.validate().empty());
  // Removing a face that touches the boundary only at a corner would pinch it: refused.
  SurfaceMesh g = build(test::grid(3, false));
  Face centre(4);
  EXPECT_TRUE(can_remove_face(g, centre));
  ASSERT_TRUE(remove_face(g, centre));
  Snapshot gs = snapshot(g);
  EXPECT_FALSE(remove_face(g, Face(0)));  // corner quad meets the new hole at a vertex only
  EXPECT_TRUE(snapshot(g) == gs);
  EXPECT_TRUE(g.validate().empty());
}

TEST(RemoveFaces, SplitsTheVertexItLeavesPinched) {
  SurfaceMesh m = textured_grid(3, false);
  // Quads 0 and 4 (the centre) share vertex 5 only: without them, quads 1 and 3 meet at 5 alone.
  const Vertex pinched(5);
  const Vec3 at = m.position(pinched);
  int notified = 0;
  m.changes().subscribe(ChangeEvent::all, [&](ChangeEvent) { ++notified; });
  std::vector<Face> set = {Face(4), Face(0), Face(4)};  // repeats are ignored
  remove_faces(m, set);
  EXPECT_EQ(notified, 1);
  EXPECT_TRUE(m.is_deleted(Face(0)));
  EXPECT_TRUE(m.is_deleted(Face(4)));
  EXPECT_TRUE(m.is_deleted(Vertex(0)));  // the grid's corner had no other face
  EXPECT_EQ(counts(m).f, 7);
  EXPECT_EQ(counts(m).e, 22);  // the corner's two edges go; the centre's edges keep a face
  EXPECT_EQ(counts(m).v, 16);  // one vertex gone, one copy of the pinched vertex
  EXPECT_EQ(counts(m).chi(), 1);
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  auto w = m.get_vertex_property<float>("v:weight");
  std::size_t at_pinch = 0;
  for (Vertex v : m.vertices()) {
    EXPECT_TRUE(m.is_manifold(v));
    if (m.position(v) == at) {
      ++at_pinch;
      EXPECT_EQ(w[v], at.x);
      EXPECT_FALSE(m.is_isolated(v));
    }
  }
  EXPECT_EQ(at_pinch, 2u);
  expect_corner_uv_matches_position(m);
  EXPECT_TRUE(m.validate().empty());
  m.garbage_collection();
  EXPECT_TRUE(m.validate().empty());
}

TEST(RemoveFaces, OneRemovableFaceAsRemoveFace) {
  for (IndexedMesh in : {test::tetrahedron(), test::grid(3, false), test::grid(3, true)}) {
    const SurfaceMesh source = build(in);
    for (Face f : source.faces()) {
      if (!can_remove_face(source, f)) continue;
      SurfaceMesh a = source, b = source;
      ASSERT_TRUE(remove_face(a, f));
      const Face one[1] = {f};
      remove_faces(b, one);
      EXPECT_TRUE(snapshot(b) == snapshot(a)) << "face " << f.idx();
      EXPECT_TRUE(b.validate().empty());
    }
  }
}

TEST(RemoveFaces, DeadOrNoFacesChangeNothing) {
  SurfaceMesh m = textured_grid(2, true);
  ASSERT_TRUE(remove_face(m, Face(0)));
  const Snapshot s = snapshot(m);
  int notified = 0;
  m.changes().subscribe(ChangeEvent::all, [&](ChangeEvent) { ++notified; });
  remove_faces(m, {});
  const Face dead[3] = {Face(0), Face(9999), Face()};
  remove_faces(m, dead);
  EXPECT_TRUE(snapshot(m) == s);
  EXPECT_EQ(notified, 0);
  EXPECT_TRUE(m.validate().empty());
}

TEST(RemoveFaces, EveryFaceLeavesAnEmptyMesh) {
  SurfaceMesh m = build(test::tetrahedron());
  std::vector<Face> all;
  for (Face f : m.faces()) all.push_back(f);
  remove_faces(m, all);
  EXPECT_EQ(m.n_faces(), 0u);
  EXPECT_EQ(m.n_edges(), 0u);
  EXPECT_EQ(m.n_vertices(), 0u);
  EXPECT_TRUE(m.validate().empty());
}

// can_cut_face as its comment states it, from the mesh's queries alone: h0 and h1 are two half-edges
// of the same live face, their targets are not adjacent in it, and no edge joins them yet.
bool cut_face_contract(const SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  if (!m.is_live(h0) || !m.is_live(h1) || h0 == h1 || !m.face(h0).is_valid() || m.face(h0) != m.face(h1))
    return false;
  const Vertex a = m.to_vertex(h0), b = m.to_vertex(h1);
  for (const Halfedge h : m.halfedges(m.face(h0)))
    if ((m.from_vertex(h) == a && m.to_vertex(h) == b) || (m.from_vertex(h) == b && m.to_vertex(h) == a))
      return false;
  return !m.find_edge(a, b).is_valid();
}

// split_face_refusal and cut_face_refusal against their predicates, their contracts and the edits,
// on live and deleted elements of a mesh that random edits keep changing.
TEST(Refusal, SplitFaceAndCutFaceAgreeWithTheirEditsOverRandomEdits) {
  SurfaceMesh m = build(test::grid(5, false));
  std::size_t refused = 0, allowed = 0;
  test::after_random_edits(m, 12, 250, [&](const SurfaceMesh& mesh) {
    for (std::size_t k = 0; k < 6; ++k) {
      const Face f(static_cast<Index>((k * 7919 + mesh.n_faces()) % mesh.face_slots()));
      test::expect_refusal_agrees(
          mesh, can_split_face(mesh, f), mesh.is_live(f), split_face_refusal(mesh, f),
          [&](SurfaceMesh& c) {
            return split_face(c, f, Vec3{0.5f, 0.5f, 0}).is_valid();
          },
          "split face " + std::to_string(f.idx()));
      // h0 in a face (or deleted, or on the boundary), h1 one to four steps further in its loop.
      const Halfedge h0(static_cast<Index>((k * 104729 + mesh.n_halfedges()) % mesh.halfedge_slots()));
      Halfedge h1 = h0;
      if (mesh.is_live(h0))
        for (std::size_t i = 0; i <= k % 4; ++i) h1 = mesh.next(h1);
      if (k == 5) h1 = Halfedge(static_cast<Index>((h1.idx() + 17) % mesh.halfedge_slots()));
      const char* why = cut_face_refusal(mesh, h0, h1);
      (why ? refused : allowed) += 1;
      test::expect_refusal_agrees(
          mesh, can_cut_face(mesh, h0, h1), cut_face_contract(mesh, h0, h1), why,
          [&](SurfaceMesh& c) { return cut_face(c, h0, h1).is_valid(); },
          "cut face at half-edges " + std::to_string(h0.idx()) + " and " + std::to_string(h1.idx()));
    }
  });
  EXPECT_GT(refused, 100u);
  EXPECT_GT(allowed, 30u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Refusal, CutFaceSaysWhy) {
  SurfaceMesh m = build(test::grid(1, false));  // one quad
  const Halfedge h = m.halfedge(Face(0));
  EXPECT_STREQ(cut_face_refusal(m, h, h), "the two half-edges are the same");
  EXPECT_STREQ(cut_face_refusal(m, h, m.next(h)),
               "their targets are neighbours in the face (the cut would double an edge)");
  EXPECT_STREQ(cut_face_refusal(m, SurfaceMesh::twin(h), m.next(h)),
               "the half-edges are on a boundary, not in a face");
  EXPECT_EQ(cut_face_refusal(m, h, m.next(m.next(h))), nullptr);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Refusal, AddAndRemoveSayWhy) {
  SurfaceMesh m = build(test::grid(3, false));  // 3 x 3 quads; face j * 3 + i
  const Vertex lone = m.add_vertex(Vec3{9, 9, 0});
  const Vertex two[] = {Vertex(0), Vertex(1)};
  EXPECT_STREQ(add_face_refusal(m, two), "a face needs at least 3 corners");
  const Vertex repeated[] = {Vertex(0), Vertex(1), Vertex(0)};
  EXPECT_STREQ(add_face_refusal(m, repeated), "a corner is repeated");
  const Vertex inside[] = {Vertex(0), Vertex(1), lone};  // 0 -> 1 runs inside face 0
  EXPECT_STREQ(add_face_refusal(m, inside), "an edge of the face already has a face on that side");
  const Vertex outside[] = {Vertex(1), Vertex(0), lone};
  EXPECT_EQ(add_face_refusal(m, outside), nullptr);
  EXPECT_TRUE(can_add_face(m, outside));

  ASSERT_EQ(remove_face_refusal(m, Face(4)), nullptr);
  ASSERT_TRUE(remove_face(m, Face(4)));  // the centre
  EXPECT_STREQ(remove_face_refusal(m, Face(4)), "the face is not live");
  // Face 0 meets the hole at vertex 5 only: removing it would pinch vertex 5.
  EXPECT_STREQ(remove_face_refusal(m, Face(0)),
               "a corner would be left with two gaps in its fan of faces (pinched)");
  EXPECT_FALSE(remove_face(m, Face(0)));
  EXPECT_STREQ(remove_vertex_refusal(m, Vertex(0)),
               "a corner of its faces would be left with two gaps in its fan of faces (pinched)");
  EXPECT_EQ(remove_vertex_refusal(m, Vertex(1)), nullptr);
  ASSERT_TRUE(remove_vertex(m, Vertex(1)));
  EXPECT_STREQ(remove_vertex_refusal(m, Vertex(1)), "the vertex is not live");
  ASSERT_TRUE(remove_vertex(m, lone));
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

#include "hedge/core/surface_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::article_example;
using test::tetrahedron;

template <typename Range>
auto collect(const Range& r) {
  std::vector<std::decay_t<decltype(*r.begin())>> out;
  for (auto x : r) out.push_back(x);
  return out;
}

// True if b is a rotation of a.
template <typename T>
bool same_cycle(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  for (std::size_t s = 0; s < a.size(); ++s) {
    bool ok = true;
    for (std::size_t i = 0; i < a.size() && ok; ++i) ok = a[i] == b[(i + s) % b.size()];
    if (ok) return true;
  }
  return false;
}

std::vector<Vertex> vs(std::initializer_list<int> ids) {
  std::vector<Vertex> out;
  for (int i : ids) out.push_back(Vertex(static_cast<Index>(i - 1)));  // the article counts from 1
  return out;
}

TEST(SurfaceMesh, ArticleRecordTable) {
  SurfaceMesh m = build(article_example());
  EXPECT_EQ(m.n_vertices(), 7u);
  EXPECT_EQ(m.n_faces(), 6u);
  EXPECT_EQ(m.n_edges(), 12u);
  EXPECT_EQ(m.n_halfedges(), 24u);
  std::size_t boundary = 0;
  for (Halfedge h : m.halfedges()) boundary += m.is_boundary(h);
  EXPECT_EQ(boundary, 6u);

  // The article's table, one row per half-edge: origin, twin, face (-1: none), next, prev.
  struct Row {
    int origin, twin, face, next, prev;
  };
  const Row rows[24] = {{1, 18, 0, 1, 2},   {3, 11, 0, 2, 0},   {4, 3, 0, 0, 1},     {1, 2, 1, 4, 5},
                        {4, 6, 1, 5, 3},    {2, 19, 1, 3, 4},   {2, 4, 2, 7, 8},     {4, 17, 2, 8, 6},
                        {5, 20, 2, 6, 7},   {3, 21, 3, 10, 11}, {6, 12, 3, 11, 9},   {4, 1, 3, 9, 10},
                        {4, 10, 4, 13, 14}, {6, 22, 4, 14, 12}, {7, 15, 4, 12, 13},  {4, 14, 5, 16, 17},
                        {7, 23, 5, 17, 15}, {5, 7, 5, 15, 16},  {3, 0, -1, 19, 21},  {1, 5, -1, 20, 18},
                        {2, 8, -1, 23, 19}, {6, 9, -1, 18, 22}, {7, 13, -1, 21, 23}, {5, 16, -1, 22, 20}};
  auto vtx = [](int article_vertex) { return Vertex(static_cast<Index>(article_vertex - 1)); };
  // Article half-edge e runs from origin(e) to origin(twin(e)); find ours by its endpoints.
  auto ours = [&](int e) { return m.find_halfedge(vtx(rows[e].origin), vtx(rows[rows[e].twin].origin)); };
  for (int e = 0; e < 24; ++e) {
    SCOPED_TRACE("article half-edge e" + std::to_string(e));
    Halfedge h = ours(e);
    ASSERT_TRUE(h.is_valid());
    EXPECT_EQ(m.twin(h), ours(rows[e].twin));
    EXPECT_EQ(m.next(h), ours(rows[e].next));
    EXPECT_EQ(m.prev(h), ours(rows[e].prev));
    if (rows[e].face < 0)
      EXPECT_TRUE(m.is_boundary(h));
    else
      EXPECT_EQ(m.face(h), Face(static_cast<Index>(rows[e].face)));
  }
  // Face cycles keep the input's corner order.
  EXPECT_EQ(collect(m.vertices(Face(0))), vs({1, 3, 4}));
  EXPECT_EQ(collect(m.vertices(Face(5))), vs({4, 7, 5}));
  // Vertex rings: CCW is he = twin(prev(he)), CW is he = next(twin(he)).
  EXPECT_TRUE(same_cycle(collect(m.vertices_ccw(Vertex(3))), vs({1, 3, 6, 7, 5, 2})));
  EXPECT_TRUE(same_cycle(collect(m.vertices(Vertex(3))), vs({1, 2, 5, 7, 6, 3})));
  // A boundary vertex starts at its gap: its half-edge is the boundary one.
  EXPECT_EQ(collect(m.vertices_ccw(Vertex(0))), vs({2, 3, 4}));
  EXPECT_EQ(collect(m.vertices(Vertex(0))), vs({2, 4, 3}));
  // The boundary loop v3 v1 v2 v5 v7 v6.
  auto loops = m.boundary_loops();
  ASSERT_EQ(loops.size(), 1u);
  std::vector<Vertex> loop;
  for (Halfedge h : m.loop(loops[0])) loop.push_back(m.from_vertex(h));
  EXPECT_TRUE(same_cycle(loop, vs({3, 1, 2, 5, 7, 6})));
  EXPECT_TRUE(m.validate().empty());
}

TEST(SurfaceMesh, CirculatorsOnClosedMesh) {
  SurfaceMesh m = build(tetrahedron());
  for (Vertex v : m.vertices()) {
    EXPECT_EQ(m.valence(v), 3u);
    EXPECT_EQ(m.faces(v).count(), 3u);
    EXPECT_EQ(m.edges(v).count(), 3u);
    EXPECT_FALSE(m.is_boundary(v));
    EXPECT_TRUE(m.is_manifold(v));
    auto cw = collect(m.vertices(v));
    auto ccw = collect(m.vertices_ccw(v));
    std::reverse(ccw.begin(), ccw.end());
    EXPECT_TRUE(same_cycle(cw, ccw));
    for (Halfedge h : m.halfedges(v)) EXPECT_EQ(m.from_vertex(h), v);
  }
  for (Face f : m.faces()) {
    EXPECT_EQ(m.valence(f), 3u);
    EXPECT_EQ(m.faces(f).count(), 3u);
    EXPECT_FALSE(m.is_boundary(f));
    std::set<Face> adj;
    for (Face g : m.faces(f)) adj.insert(g);
    EXPECT_EQ(adj.size(), 3u);
    EXPECT_FALSE(adj.count(f));
  }
  for (Edge e : m.edges()) {
    EXPECT_EQ(m.faces(e).size(), 2u);
    EXPECT_EQ(m.adjacent_edges(e).size(), 4u);
    auto [a, b] = m.vertices(e);
    EXPECT_EQ(m.find_edge(a, b), e);
    EXPECT_EQ(m.find_edge(b, a), e);
  }
  EXPECT_TRUE(m.is_triangle_mesh());
  EXPECT_FALSE(m.is_quad_mesh());
  EXPECT_TRUE(m.boundary_loops().empty());
  EXPECT_FALSE(m.find_halfedge(Vertex(0), Vertex(0)).is_valid());
}

TEST(SurfaceMesh, BoundaryQueriesOnGrid) {
  SurfaceMesh m = build(test::grid(3, false));
  EXPECT_TRUE(m.is_quad_mesh());
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  // Corner vertex: one face, two edges; the face circulator skips the gap.
  Vertex corner(0);
  EXPECT_TRUE(m.is_boundary(corner));
  EXPECT_EQ(m.valence(corner), 2u);
  EXPECT_EQ(m.faces(corner).count(), 1u);
  EXPECT_EQ(m.faces_ccw(corner).count(), 1u);
  Vertex inner(5);  // (1,1)
  EXPECT_FALSE(m.is_boundary(inner));
  EXPECT_EQ(m.valence(inner), 4u);
  std::size_t boundary_faces = 0;
  for (Face f : m.faces()) boundary_faces += m.is_boundary(f);
  EXPECT_EQ(boundary_faces, 8u);
  for (Halfedge h : m.halfedges()) {
    EXPECT_EQ(m.next(m.prev(h)), h);
    EXPECT_EQ(m.prev(m.next(h)), h);
  }
  Edge be = m.find_edge(Vertex(0), Vertex(1));
  EXPECT_TRUE(m.is_boundary(be));
  EXPECT_EQ(m.faces(be).size(), 1u);
}

TEST(SurfaceMesh, PropertiesAreNamedAndTyped) {
  SurfaceMesh m = build(tetrahedron());
  auto w = m.add_vertex_property<double>("v:weight", 2.5);
  EXPECT_DOUBLE_EQ(w[Vertex(3)], 2.5);
  w[Vertex(1)] = 7.0;
  EXPECT_THROW(m.add_vertex_property<double>("v:weight"), InvalidInputError);
  EXPECT_FALSE(m.get_vertex_property<float>("v:weight"));  // wrong type
  EXPECT_DOUBLE_EQ(m.get_vertex_property<double>("v:weight")[Vertex(1)], 7.0);
  auto same = m.vertex_property<double>("v:weight");
  EXPECT_EQ(same.array(), w.array());
  EXPECT_FALSE(m.remove_vertex_property("v:position"));
  EXPECT_TRUE(m.remove_vertex_property("v:weight"));
  EXPECT_FALSE(m.get_vertex_property<double>("v:weight"));

  auto fl = m.add_face_property<int>("f:label", -1);
  auto el = m.add_edge_property<int>("e:label", 0);
  auto hl = m.add_halfedge_property<int>("h:label", 0);
  EXPECT_EQ(fl.vector().size(), m.face_slots());
  EXPECT_EQ(el.vector().size(), m.edge_slots());
  EXPECT_EQ(hl.vector().size(), m.halfedge_slots());
  // Properties grow with the mesh.
  Vertex v = m.add_vertex({5, 5, 5});
  EXPECT_EQ(m.position(v), (Vec3{5, 5, 5}));
  EXPECT_TRUE(m.is_isolated(v));

  // Copies are deep.
  SurfaceMesh copy = m;
  copy.position(Vertex(0)) = {9, 9, 9};
  copy.get_face_property<int>("f:label")[Face(0)] = 4;
  EXPECT_EQ(m.position(Vertex(0)), (Vec3{0, 0, 0}));
  EXPECT_EQ(fl[Face(0)], -1);
  EXPECT_EQ(copy.positions().array(), copy.get_vertex_property<Vec3>("v:position").array());
  EXPECT_TRUE(copy.validate().empty());
  EXPECT_TRUE(m.validate().empty());
}

TEST(SurfaceMesh, GarbageCollectionCompactsAndReturnsMaps) {
  // Two tetrahedra; delete the first one entirely, and an isolated vertex.
  IndexedMesh in = tetrahedron();
  IndexedMesh two = in;
  for (auto p : in.positions) two.positions.push_back(p + Vec3{3, 0, 0});
  for (auto i : in.indices) two.indices.push_back(i + 4);
  two.positions.push_back({7, 7, 7});  // isolated vertex 8
  SurfaceMesh m = build(two);
  auto tag = m.add_vertex_property<int>("v:tag");
  for (Vertex v : m.vertices()) tag[v] = static_cast<int>(v.idx()) * 10;
  auto ftag = m.add_face_property<int>("f:tag");
  for (Face f : m.faces()) ftag[f] = static_cast<int>(f.idx());

  for (Index f = 0; f < 4; ++f) m.mark_deleted(Face(f));
  for (Index e = 0; e < m.edge_slots(); ++e)
    if (m.vertex(Edge(e), 0).idx() < 4) m.mark_deleted(Edge(e));
  for (Index v = 0; v < 4; ++v) m.mark_deleted(Vertex(v));
  m.mark_deleted(Vertex(8));
  EXPECT_TRUE(m.has_garbage());
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(m.n_faces(), 4u);
  std::size_t live = 0;
  for (Vertex v : m.vertices()) live += v.idx() >= 4;
  EXPECT_EQ(live, 4u);
  EXPECT_TRUE(m.validate().empty());

  GarbageMaps maps = m.garbage_collection();
  EXPECT_FALSE(m.has_garbage());
  EXPECT_EQ(m.vertex_slots(), 4u);
  EXPECT_EQ(m.edge_slots(), 6u);
  EXPECT_EQ(m.face_slots(), 4u);
  EXPECT_EQ(maps.vertices[0], kInvalidIndex);
  EXPECT_EQ(maps.vertices[4], 0u);
  EXPECT_EQ(maps.vertices[7], 3u);
  EXPECT_EQ(maps.vertices[8], kInvalidIndex);
  EXPECT_EQ(maps.faces[5], 1u);
  for (Vertex v : m.vertices()) EXPECT_EQ(tag[v], static_cast<int>(v.idx() + 4) * 10);
  for (Face f : m.faces()) EXPECT_EQ(ftag[f], static_cast<int>(f.idx() + 4));
  EXPECT_EQ(m.position(Vertex(1)), (Vec3{4, 0, 0}));
  EXPECT_TRUE(m.validate().empty());
}

TEST(SurfaceMesh, MemoryPerVertexOfClosedTriangleMesh) {
  SurfaceMesh m = build(tetrahedron());
  // 4 vertices, 6 edges, 4 faces: 12 half-edges x 12 B + 4 x (12 + 4) B + 4 x 4 B, plus flag bits.
  const std::size_t arrays = 12 * 12 + 4 * 16 + 4 * 4;
  EXPECT_GE(m.memory_bytes(), arrays);
  EXPECT_LE(m.memory_bytes(), arrays + 3 * 8);
}

TEST(SurfaceMesh, PropertiesTellTheBytesOfOneElement) {
  SurfaceMesh m = build(tetrahedron());
  EXPECT_EQ(m.vertex_properties().element_bytes(), sizeof(Vec3));  // the positions
  EXPECT_EQ(m.face_properties().element_bytes(), 0u);
  m.add_vertex_property<double>("v:weight", 0);
  m.add_face_property<std::uint8_t>("f:tag", 0);
  EXPECT_EQ(m.vertex_properties().element_bytes(), sizeof(Vec3) + sizeof(double));
  EXPECT_EQ(m.face_properties().element_bytes(), 1u);
}

TEST(SurfaceMesh, ReleaseConnectivityHandsTheOldLinksOverAndResizes) {
  SurfaceMesh m = build(tetrahedron());
  auto id = m.add_face_property<int>("f:id", -1);
  for (Face f : m.faces()) id[f] = int(f.idx());
  const std::vector<Vertex> to = m.halfedge_vertex_array();
  const std::vector<Halfedge> next = m.halfedge_next_array();
  const SurfaceMesh::Connectivity old = m.release_connectivity(5, 8, 6);
  EXPECT_EQ(old.h_vertex, to);
  EXPECT_EQ(old.h_next, next);
  EXPECT_EQ(old.v_halfedge.size(), 4u);
  EXPECT_EQ(old.f_halfedge.size(), 4u);
  EXPECT_EQ(m.vertex_slots(), 5u);
  EXPECT_EQ(m.edge_slots(), 8u);
  EXPECT_EQ(m.face_slots(), 6u);
  for (Halfedge h : m.halfedges()) EXPECT_FALSE(m.to_vertex(h).is_valid());
  EXPECT_EQ(m.get_face_property<int>("f:id")[Face(3)], 3);  // properties keep their values
  EXPECT_EQ(m.get_face_property<int>("f:id")[Face(5)], -1);
  EXPECT_FALSE(m.validate().empty());  // no links: the caller writes them all

  // Writing the links back, as an algorithm writes its new ones, gives a valid mesh again.
  SurfaceMesh t = build(tetrahedron());
  const SurfaceMesh::Connectivity links = t.release_connectivity(4, 6, 4);
  for (std::size_t i = 0; i < links.h_vertex.size(); ++i) {
    const Halfedge h(static_cast<Index>(i));
    t.set_vertex(h, links.h_vertex[i]);
    t.set_next(h, links.h_next[i]);
    t.set_face(h, links.h_face[i]);
  }
  for (std::size_t v = 0; v < links.v_halfedge.size(); ++v)
    t.set_halfedge(Vertex(static_cast<Index>(v)), links.v_halfedge[v]);
  for (std::size_t f = 0; f < links.f_halfedge.size(); ++f)
    t.set_halfedge(Face(static_cast<Index>(f)), links.f_halfedge[f]);
  EXPECT_TRUE(t.validate().empty());
}

TEST(SurfaceMesh, SwapElementsExchangesContentsAndKeepsThePropertyArrays) {
  SurfaceMesh a = build(tetrahedron());
  auto id = a.add_face_property<int>("f:id", -1);
  for (Face f : a.faces()) id[f] = int(f.idx());
  SurfaceMesh b = build(test::grid(2, true));
  b.face_properties().add_missing_from(a.face_properties());
  b.get_face_property<int>("f:id")[Face(5)] = 55;
  const Vec3 b_point = b.position(Vertex(8));
  const std::size_t faces_b = b.n_faces();
  a.swap_elements(b);
  EXPECT_EQ(a.n_faces(), faces_b);
  EXPECT_EQ(b.n_faces(), 4u);
  EXPECT_TRUE(a.validate().empty());
  EXPECT_TRUE(b.validate().empty());
  EXPECT_EQ(a.position(Vertex(8)), b_point);  // through the mesh's own positions handle
  EXPECT_EQ(id.vector().size(), faces_b);     // the handle taken before sees the new values
  EXPECT_EQ(id[Face(5)], 55);
  EXPECT_EQ(b.get_face_property<int>("f:id")[Face(3)], 3);
  EXPECT_EQ(b.face_properties().size(), 4u);
}

}  // namespace
}  // namespace hedge

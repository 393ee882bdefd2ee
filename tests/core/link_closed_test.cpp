// Linking closed triangle sets (src/core/link_closed.cpp): the numbering build_triangles() gives,
// and each defect named in build()'s order with the mesh left as it was.
#include "core/link_closed.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using link_detail::ClosedLinkDefect;
using link_detail::describe;
using link_detail::link_closed_triangles;
using Kind = ClosedLinkDefect::Kind;

const std::vector<std::uint32_t> kTetrahedron = test::tetrahedron().indices;
const std::vector<std::uint32_t> kOctahedron{0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                             2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

//! An n x m grid closed around both ways (a torus), each quad cut into two triangles.
std::vector<std::uint32_t> torus(std::uint32_t n, std::uint32_t m) {
  std::vector<std::uint32_t> t;
  auto v = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * m + j % m; };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < m; ++j)
      t.insert(t.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j), v(i + 1, j + 1), v(i, j + 1)});
  return t;
}

std::uint32_t vertex_count(const std::vector<std::uint32_t>& tris) {
  std::uint32_t n = 0;
  for (std::uint32_t v : tris) n = std::max(n, v + 1);
  return n;
}

//! Each corner's twin, by brute force.
std::vector<std::uint32_t> twins_of(const std::vector<std::uint32_t>& tris) {
  auto next = [](std::size_t c) { return c % 3 == 2 ? c - 2 : c + 1; };
  std::vector<std::uint32_t> twin(tris.size(), 0);
  for (std::size_t c = 0; c < tris.size(); ++c)
    for (std::size_t d = 0; d < tris.size(); ++d)
      if (tris[d] == tris[next(c)] && tris[next(d)] == tris[c]) twin[c] = static_cast<std::uint32_t>(d);
  return twin;
}

//! Every link of a equals b's.
void expect_same_links(const SurfaceMesh& a, const SurfaceMesh& b) {
  ASSERT_EQ(a.halfedge_slots(), b.halfedge_slots());
  ASSERT_EQ(a.vertex_slots(), b.vertex_slots());
  ASSERT_EQ(a.face_slots(), b.face_slots());
  for (Index h = 0; h < a.halfedge_slots(); ++h) {
    EXPECT_EQ(a.to_vertex(Halfedge(h)), b.to_vertex(Halfedge(h))) << h;
    EXPECT_EQ(a.next(Halfedge(h)), b.next(Halfedge(h))) << h;
    EXPECT_EQ(a.face(Halfedge(h)), b.face(Halfedge(h))) << h;
  }
  for (Index v = 0; v < a.vertex_slots(); ++v) EXPECT_EQ(a.halfedge(Vertex(v)), b.halfedge(Vertex(v))) << v;
  for (Index f = 0; f < a.face_slots(); ++f) EXPECT_EQ(a.halfedge(Face(f)), b.halfedge(Face(f))) << f;
}

//! Links tris both ways (searching the twins and given them) and checks that both give what
//! build_triangles() gives, with validate() reporting nothing.
void expect_linked_as_build_would(const std::vector<std::uint32_t>& tris, std::size_t n_vertices) {
  SurfaceMesh searched, given;
  const ClosedLinkDefect d = link_closed_triangles(tris, n_vertices, searched);
  ASSERT_FALSE(d) << describe(d);
  const std::vector<std::uint32_t> twin = twins_of(tris);
  const ClosedLinkDefect g = link_closed_triangles(tris, twin, n_vertices, given);
  ASSERT_FALSE(g) << describe(g);
  EXPECT_TRUE(searched.validate().empty());
  EXPECT_TRUE(given.validate().empty());
  std::vector<Vec3> positions(n_vertices, Vec3{0, 0, 0});
  for (std::size_t v = 0; v < n_vertices; ++v) positions[v] = {float(v), float(v * v % 7), float(v % 3)};
  BuildOptions bo;
  bo.corner_attributes = false;
  const SurfaceMesh expected = build_triangles(positions, tris, bo);
  expect_same_links(searched, expected);
  expect_same_links(given, expected);
}

//! The defect of linking tris into a mesh that holds a tetrahedron, which must be left as it was.
ClosedLinkDefect defect_of(const std::vector<std::uint32_t>& tris, std::size_t n_vertices) {
  SurfaceMesh before;
  EXPECT_FALSE(link_closed_triangles(kTetrahedron, 4, before));
  SurfaceMesh mesh = before;
  const ClosedLinkDefect d = link_closed_triangles(tris, n_vertices, mesh);
  expect_same_links(mesh, before);
  EXPECT_TRUE(mesh.validate().empty());
  return d;
}

TEST(LinkClosed, ATetrahedronAndAnOctahedronAreLinkedAsBuildLinksThem) {
  expect_linked_as_build_would(kTetrahedron, 4);
  expect_linked_as_build_would(kOctahedron, 6);
  SurfaceMesh mesh;
  ASSERT_FALSE(link_closed_triangles(kOctahedron, 6, mesh));
  EXPECT_EQ(mesh.n_vertices(), 6u);
  EXPECT_EQ(mesh.n_edges(), 12u);
  EXPECT_EQ(mesh.n_faces(), 8u);
  EXPECT_EQ(mesh.position(Vertex(5)), (Vec3{0, 0, 0}));
}

TEST(LinkClosed, ATorusInAnyFaceOrderIsLinkedAsBuildLinksIt) {
  std::vector<std::uint32_t> tris = torus(7, 5);
  expect_linked_as_build_would(tris, 35);
  // Faces in another order and each rotated: another numbering, still build()'s.
  std::vector<std::uint32_t> shuffled;
  for (std::size_t k = 0; k < tris.size() / 3; ++k) {
    const std::size_t t = (k * 17) % (tris.size() / 3), r = k % 3;
    for (std::size_t i = 0; i < 3; ++i) shuffled.push_back(tris[3 * t + (i + r) % 3]);
  }
  expect_linked_as_build_would(shuffled, 35);
}

TEST(LinkClosed, AVertexNoTriangleUsesStaysIsolated) {
  std::vector<std::uint32_t> tris = kTetrahedron;
  for (std::uint32_t& v : tris) v += v >= 2;  // vertex 2 unused
  expect_linked_as_build_would(tris, 5);
  SurfaceMesh mesh;
  ASSERT_FALSE(link_closed_triangles(tris, 5, mesh));
  EXPECT_TRUE(mesh.is_isolated(Vertex(2)));
}

TEST(LinkClosed, AnOpenSetNamesTheFirstCornerWithoutAReverse) {
  std::vector<std::uint32_t> tris = kTetrahedron;
  tris.resize(9);  // face 1 2 3 gone: 2 -> 1 (face 0's second corner) has no 1 -> 2
  const ClosedLinkDefect d = defect_of(tris, 4);
  EXPECT_EQ(d.kind, Kind::open_edge);
  EXPECT_EQ(d.a, 2u);
  EXPECT_EQ(d.b, 1u);
  EXPECT_EQ(describe(d),
            "the set is open: no triangle runs along the edge from vertex 2 to vertex 1 the other way");
}

TEST(LinkClosed, AnEdgeOfThreeTrianglesIsUsedTwiceOneWay) {
  // The octahedron with a fin on its edge 2 -> 4 (face 0's): that edge is now used twice.
  std::vector<std::uint32_t> tris = kOctahedron;
  tris.insert(tris.end(), {2, 4, 6});
  const ClosedLinkDefect d = defect_of(tris, 7);
  EXPECT_EQ(d.kind, Kind::edge_used_twice);
  EXPECT_EQ(d.a, 2u);
  EXPECT_EQ(d.b, 4u);
  EXPECT_EQ(describe(d), "two triangles run along the edge from vertex 2 to vertex 4 the same way");
  // Of the other way, it is the reverse that is used twice.
  tris.resize(tris.size() - 3);
  tris.insert(tris.end(), {4, 2, 6});
  EXPECT_EQ(defect_of(tris, 7).kind, Kind::edge_used_twice);
}

TEST(LinkClosed, ARepeatedTriangleUsesItsEdgesTwice) {
  std::vector<std::uint32_t> tris = kTetrahedron;
  tris.insert(tris.end(), {1, 2, 3});
  const ClosedLinkDefect d = defect_of(tris, 4);
  EXPECT_EQ(d.kind, Kind::edge_used_twice);
  EXPECT_EQ(d.a, 1u);  // the smallest vertex with a doubled edge, then the smallest end
  EXPECT_EQ(d.b, 2u);
}

TEST(LinkClosed, TwoTetrahedraSharingAVertexAreTwoFans) {
  std::vector<std::uint32_t> tris = kTetrahedron;
  for (std::uint32_t v : kTetrahedron) tris.push_back(v == 0 ? 0 : v + 3);
  const ClosedLinkDefect d = defect_of(tris, 7);
  EXPECT_EQ(d.kind, Kind::several_fans);
  EXPECT_EQ(d.a, 0u);
  EXPECT_EQ(describe(d), "the triangles around vertex 0 form more than one fan");
}

TEST(LinkClosed, IndicesOutOfRangeAndRepeatedVerticesAreNamedByTriangle) {
  std::vector<std::uint32_t> tris = kTetrahedron;
  tris[7] = 4;
  ClosedLinkDefect d = defect_of(tris, 4);
  EXPECT_EQ(d.kind, Kind::vertex_out_of_range);
  EXPECT_EQ(d.triangle, 2u);
  EXPECT_EQ(d.a, 4u);
  EXPECT_EQ(describe(d), "triangle 2 uses vertex 4, beyond the vertices");
  tris = kTetrahedron;
  tris[10] = tris[9];
  d = defect_of(tris, 4);
  EXPECT_EQ(d.kind, Kind::repeated_vertex);
  EXPECT_EQ(d.triangle, 3u);
  EXPECT_EQ(describe(d), "triangle 3 repeats a vertex");
  EXPECT_THROW(defect_of({0, 1}, 4), std::logic_error);
}

TEST(LinkClosed, WrongTwinsAreRefused) {
  std::vector<std::uint32_t> twin = twins_of(kOctahedron);
  SurfaceMesh mesh;
  std::swap(twin[3], twin[4]);
  ClosedLinkDefect d = link_closed_triangles(kOctahedron, twin, 6, mesh);
  EXPECT_EQ(d.kind, Kind::wrong_twin);
  EXPECT_EQ(d.corner, 3u);
  EXPECT_EQ(mesh.halfedge_slots(), 0u);
  twin.pop_back();
  EXPECT_EQ(link_closed_triangles(kOctahedron, twin, 6, mesh).kind, Kind::wrong_twin);
  EXPECT_TRUE(mesh.validate().empty());
}

}  // namespace
}  // namespace hedge

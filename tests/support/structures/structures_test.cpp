// The three reference structures must answer every Table 1 query exactly as hedge's SurfaceMesh
// does (as sets; edges compared by their vertex pairs), and their memory must be what their arrays
// say. Also checks the edge matching and the midpoint subdivision the benchmark relies on
// (bench/structures measures these structures; its report code is tested in bench/structures).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "hedge/error.h"
#include "hedge/io/io.h"
#include "support/structures/edge_table.h"
#include "support/structures/half_edge_view.h"
#include "support/structures/indexed_triangles.h"
#include "support/structures/subdivide.h"
#include "support/structures/triangle_neighbors.h"
#include "support/structures/winged_edge.h"

namespace hedge::structures {

// Readable failure messages (found by argument-dependent lookup).
void PrintTo(const VertexPair& p, std::ostream* os) { *os << "{" << p.a << "," << p.b << "}"; }

namespace {

// ---- Meshes ----

TriangleArrays octahedron() {
  TriangleArrays m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return m;
}

//! An open n x n grid, two triangles per cell (one boundary loop; corner vertices of valence 2 and 3).
TriangleArrays grid(int n) {
  TriangleArrays m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({float(i), float(j), 0.f});
  auto id = [&](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.triangles.insert(m.triangles.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j),
                                             id(i + 1, j + 1), id(i, j + 1)});
  return m;
}

//! A closed double cone: two apices of valence n, a ring of valence 4.
TriangleArrays double_cone(int n) {
  TriangleArrays m;
  for (int i = 0; i < n; ++i) m.positions.push_back({float(i), 0.f, 0.f});
  m.positions.push_back({0, 0, 1});   // n: top
  m.positions.push_back({0, 0, -1});  // n + 1: bottom
  for (int i = 0; i < n; ++i) {
    const Index a = static_cast<Index>(i), b = static_cast<Index>((i + 1) % n);
    m.triangles.insert(m.triangles.end(), {a, b, Index(n), b, a, Index(n + 1)});
  }
  return m;
}

//! The mesh with triangle t removed (opens a hole), vertices kept.
TriangleArrays without_triangle(TriangleArrays m, std::size_t t) {
  m.triangles.erase(m.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t),
                    m.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
  return m;
}

//! A repository mesh, or an empty one (the test then skips) when the file is absent.
TriangleArrays data_mesh(const std::string& name) {
  TriangleArrays m;
  const std::string path = std::string(HEDGE_DATA_DIR) + "/" + name;
  if (!std::filesystem::exists(path)) return m;
  IndexedMesh in = read_indexed_file(path);
  m.positions = std::move(in.positions);
  m.triangles = std::move(in.indices);
  return m;
}

// ---- Answers, in input numbering, as sorted lists ----

struct Answers {
  std::vector<std::vector<Index>> vertex_faces, face_vertices, face_faces;
  std::vector<std::vector<VertexPair>> vertex_edges, face_edges;
  std::map<VertexPair, std::vector<Index>> edge_vertices, edge_faces;
  std::map<VertexPair, std::vector<VertexPair>> edge_edges;
};

template <typename T>
std::vector<T> sorted(std::vector<T> v) {
  std::sort(v.begin(), v.end());
  return v;
}

//! Element numbering of a structure against the input: identity for the three reference
//! structures, the build maps for hedge.
struct Numbering {
  std::vector<Index> vertex_to_input, face_to_input, vertex_from_input, face_from_input;
  Index vin(Index v) const { return vertex_to_input.empty() ? v : vertex_to_input[v]; }
  Index fin(Index f) const { return face_to_input.empty() ? f : face_to_input[f]; }
  Index vout(Index v) const { return vertex_from_input.empty() ? v : vertex_from_input[v]; }
  Index fout(Index f) const { return face_from_input.empty() ? f : face_from_input[f]; }
};

template <typename S>
Answers collect(const S& s, std::size_t n_v, std::size_t n_f, const Numbering& num = {}) {
  Answers a;
  auto pair_in = [&](typename S::EdgeRef e) {
    const VertexPair p = s.endpoints(e);
    return VertexPair::ordered(num.vin(p.a), num.vin(p.b));
  };
  a.vertex_faces.resize(n_v);
  a.vertex_edges.resize(n_v);
  for (Index v = 0; v < n_v; ++v) {
    std::vector<Index> faces;
    s.vertex_faces(num.vout(v), [&](Index f) { faces.push_back(num.fin(f)); });
    a.vertex_faces[v] = sorted(faces);
    std::vector<VertexPair> edges;
    s.vertex_edges(num.vout(v), [&](typename S::EdgeRef e) { edges.push_back(pair_in(e)); });
    a.vertex_edges[v] = sorted(edges);
  }
  a.face_vertices.resize(n_f);
  a.face_faces.resize(n_f);
  a.face_edges.resize(n_f);
  for (Index f = 0; f < n_f; ++f) {
    std::vector<Index> corners;
    s.face_vertices(num.fout(f), [&](Index v) { corners.push_back(num.vin(v)); });
    // Corner order matters up to rotation: keep it, starting at the smallest.
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    a.face_vertices[f] = corners;
    std::vector<Index> faces;
    s.face_faces(num.fout(f), [&](Index g) { faces.push_back(num.fin(g)); });
    a.face_faces[f] = sorted(faces);
    std::vector<VertexPair> edges;
    s.face_edges(num.fout(f), [&](typename S::EdgeRef e) { edges.push_back(pair_in(e)); });
    a.face_edges[f] = sorted(edges);
  }
  for (const typename S::EdgeRef& e : s.edge_list()) {
    const VertexPair key = pair_in(e);
    EXPECT_EQ(a.edge_vertices.count(key), 0u) << "edge listed twice";
    std::vector<Index> vertices;
    s.edge_vertices(e, [&](Index v) { vertices.push_back(num.vin(v)); });
    a.edge_vertices[key] = sorted(vertices);
    std::vector<Index> faces;
    s.edge_faces(e, [&](Index f) { faces.push_back(num.fin(f)); });
    a.edge_faces[key] = sorted(faces);
    std::vector<VertexPair> edges;
    s.edge_adjacent_edges(e, [&](typename S::EdgeRef x) { edges.push_back(pair_in(x)); });
    a.edge_edges[key] = sorted(edges);
  }
  return a;
}

Numbering hedge_numbering(const BuildReport& report, std::size_t n_mesh_faces) {
  Numbering num;
  num.vertex_from_input = report.vertex_map;
  num.vertex_to_input = report.vertex_origin;
  num.face_from_input = report.face_map;
  if (report.face_map.empty()) return num;
  num.face_to_input.assign(n_mesh_faces, kInvalidIndex);
  for (std::size_t f = 0; f < report.face_map.size(); ++f)
    if (report.face_map[f] != kInvalidIndex) num.face_to_input[report.face_map[f]] = static_cast<Index>(f);
  return num;
}

void expect_same(const Answers& want, const Answers& got, const char* who) {
  SCOPED_TRACE(who);
  for (std::size_t v = 0; v < want.vertex_faces.size(); ++v) {
    EXPECT_EQ(got.vertex_faces[v], want.vertex_faces[v]) << "vertex -> faces of vertex " << v;
    EXPECT_EQ(got.vertex_edges[v], want.vertex_edges[v]) << "vertex -> edges of vertex " << v;
  }
  for (std::size_t f = 0; f < want.face_vertices.size(); ++f) {
    EXPECT_EQ(got.face_vertices[f], want.face_vertices[f]) << "face -> vertices of face " << f;
    EXPECT_EQ(got.face_faces[f], want.face_faces[f]) << "face -> faces of face " << f;
    EXPECT_EQ(got.face_edges[f], want.face_edges[f]) << "face -> edges of face " << f;
  }
  EXPECT_EQ(got.edge_vertices, want.edge_vertices) << "edge -> vertices";
  EXPECT_EQ(got.edge_faces, want.edge_faces) << "edge -> faces";
  EXPECT_EQ(got.edge_edges, want.edge_edges) << "edge -> adjacent edges";
}

//! Builds all four structures on `mesh` and compares every answer with hedge's.
void check_all_agree(const TriangleArrays& mesh) {
  const std::size_t n_v = mesh.n_vertices(), n_f = mesh.n_faces();
  BuildReport report;
  const HalfEdgeView hem = HalfEdgeView::build(mesh.positions, mesh.triangles, &report);
  ASSERT_TRUE(hem.mesh().validate().empty());
  const Answers want = collect(hem, n_v, n_f, hedge_numbering(report, hem.n_faces()));

  // Sanity of the reference itself: every corner is one vertex -> face incidence.
  std::size_t incidences = 0;
  for (const auto& faces : want.vertex_faces) incidences += faces.size();
  EXPECT_EQ(incidences, mesh.triangles.size());
  EXPECT_EQ(want.edge_faces.size(), hem.mesh().n_edges());

  expect_same(want, collect(IndexedTriangles::build(mesh.positions, mesh.triangles), n_v, n_f),
              "indexed mesh");
  expect_same(want, collect(TriangleNeighbors::build(mesh.positions, mesh.triangles), n_v, n_f), "TNS");
  expect_same(want, collect(WingedEdge::build(mesh.positions, mesh.triangles), n_v, n_f), "WEM");
}

// ---- Agreement with hedge ----

TEST(StructuresAgree, Octahedron) { check_all_agree(octahedron()); }
TEST(StructuresAgree, SubdividedOctahedron) {
  check_all_agree(subdivide_midpoint(subdivide_midpoint(octahedron())));
}
TEST(StructuresAgree, OpenGrid) { check_all_agree(grid(5)); }
TEST(StructuresAgree, HighValenceDoubleCone) { check_all_agree(double_cone(40)); }
TEST(StructuresAgree, OctahedronWithHole) { check_all_agree(without_triangle(octahedron(), 3)); }
TEST(StructuresAgree, SubdividedWithQuadHole) {
  // Children 3 (middle) and 0 (a corner) of the first octahedron face share an edge: one quad hole.
  check_all_agree(without_triangle(without_triangle(subdivide_midpoint(octahedron()), 3), 0));
}

class StructuresAgreeOnData : public testing::TestWithParam<const char*> {};
TEST_P(StructuresAgreeOnData, File) {
  const TriangleArrays mesh = data_mesh(GetParam());
  if (mesh.triangles.empty()) GTEST_SKIP() << GetParam() << " is absent";
  check_all_agree(mesh);
}
INSTANTIATE_TEST_SUITE_P(Data, StructuresAgreeOnData,
                         testing::Values("tet.obj", "bob_small.ply", "anchor.off", "spot_triangulated.obj"));

// ---- Memory accounting ----

TEST(StructuresMemory, ArraysAreCountedExactly) {
  const TriangleArrays mesh = subdivide_midpoint(octahedron());
  const std::size_t n_v = mesh.n_vertices(), n_t = mesh.n_faces(), n_e = n_v + n_t - 2;  // closed, genus 0
  EXPECT_EQ(IndexedTriangles::build(mesh.positions, mesh.triangles).memory_bytes(), 12 * n_v + 12 * n_t);
  EXPECT_EQ(TriangleNeighbors::build(mesh.positions, mesh.triangles).memory_bytes(), 16 * n_v + 24 * n_t);
  const WingedEdge wem = WingedEdge::build(mesh.positions, mesh.triangles);
  EXPECT_EQ(wem.n_edges(), n_e);
  EXPECT_EQ(wem.memory_bytes(), 16 * n_v + 4 * n_t + 32 * n_e);
  HalfEdgeView hem = HalfEdgeView::build(mesh.positions, mesh.triangles);
  hem.shrink_to_fit();
  // 12 bytes per half-edge, 4 per vertex and face, float positions; flags and property bookkeeping
  // may add a little.
  EXPECT_GE(hem.memory_bytes(), 24 * n_e + 16 * n_v + 4 * n_t);
}

// ---- Edge matching ----

TEST(MatchEdges, ClosedMeshHasNoBoundary) {
  const TriangleArrays m = octahedron();
  const EdgeTable t = match_edges(m.triangles, m.n_vertices());
  EXPECT_EQ(t.n_edges(), 12u);
  for (Index c = 0; c < m.triangles.size(); ++c) {
    ASSERT_NE(t.opposite[c], kInvalidIndex);
    EXPECT_EQ(t.opposite[t.opposite[c]], c);
    EXPECT_EQ(t.edge_of[t.opposite[c]], t.edge_of[c]);
    EXPECT_EQ(m.triangles[t.opposite[c]], m.triangles[corner_next(c)]);
  }
}

TEST(MatchEdges, CountsBoundary) {
  const TriangleArrays m = grid(3);
  const EdgeTable t = match_edges(m.triangles, m.n_vertices());
  EXPECT_EQ(t.n_edges(), 33u);  // 3 * 4 * 2 axis-aligned + 9 diagonals
  EXPECT_EQ(std::count(t.opposite.begin(), t.opposite.end(), kInvalidIndex), 12);
}

TEST(MatchEdges, RejectsWhatNoStructureHereCanHold) {
  const std::vector<Index> three_on_an_edge = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_THROW(match_edges(three_on_an_edge, 5), TopologyError);
  const std::vector<Index> flipped = {0, 1, 2, 0, 1, 3};
  EXPECT_THROW(match_edges(flipped, 4), TopologyError);
  const std::vector<Index> repeated = {0, 1, 1};
  EXPECT_THROW(match_edges(repeated, 2), TopologyError);
  const std::vector<Index> out_of_range = {0, 1, 7};
  EXPECT_THROW(match_edges(out_of_range, 3), TopologyError);
}

// ---- Subdivision ----

TEST(SubdivideMidpoint, QuadruplesTrianglesAndKeepsTopology) {
  TriangleArrays m = octahedron();
  for (int level = 0; level < 3; ++level) {
    const std::size_t n_v = m.n_vertices(), n_t = m.n_faces();
    const std::size_t n_e = match_edges(m.triangles, n_v).n_edges();
    const TriangleArrays s = subdivide_midpoint(m);
    EXPECT_EQ(s.n_vertices(), n_v + n_e);
    EXPECT_EQ(s.n_faces(), 4 * n_t);
    for (std::size_t v = 0; v < n_v; ++v) EXPECT_EQ(s.positions[v], m.positions[v]);
    const SurfaceMesh hem = build_triangles(s.positions, s.triangles);  // strict: oriented manifold
    EXPECT_TRUE(hem.validate().empty());
    // Euler characteristic of the sphere.
    EXPECT_EQ(static_cast<long>(hem.n_vertices()) - static_cast<long>(hem.n_edges()) +
                  static_cast<long>(hem.n_faces()),
              2);
    m = s;
  }
}

TEST(SubdivideMidpoint, SplitsEveryBoundaryEdgeInTwo) {
  const TriangleArrays s = subdivide_midpoint(grid(2));
  const EdgeTable t = match_edges(s.triangles, s.n_vertices());
  EXPECT_EQ(std::count(t.opposite.begin(), t.opposite.end(), kInvalidIndex), 16);  // 8 boundary edges before
}

}  // namespace
}  // namespace hedge::structures

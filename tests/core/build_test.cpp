#include "hedge/core/build.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::tetrahedron;

BuildOptions repair() {
  BuildOptions o;
  o.policy = TopologyPolicy::repair;
  return o;
}

long long euler(const SurfaceMesh& m) {
  return static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
         static_cast<long long>(m.n_faces());
}

// Two tetrahedra glued at vertex 0: the classic pinched (hourglass) vertex.
IndexedMesh hourglass() {
  IndexedMesh m = tetrahedron();
  m.positions.push_back({-1, 0, 0});
  m.positions.push_back({0, -1, 0});
  m.positions.push_back({0, 0, -1});
  // Mirror of the first tetrahedron through vertex 0, same orientation rule.
  m.indices.insert(m.indices.end(), {0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5});
  return m;
}

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

TEST(Build, PolygonsAndIsolatedVertices) {
  IndexedMesh in = test::cube();
  in.positions.push_back({5, 5, 5});
  BuildReport rep;
  SurfaceMesh m = build(in, {}, &rep);
  EXPECT_EQ(m.n_faces(), 6u);
  EXPECT_EQ(m.n_edges(), 12u);
  EXPECT_EQ(rep.isolated_vertices, 1u);
  EXPECT_TRUE(m.is_isolated(Vertex(8)));
  EXPECT_TRUE(m.is_quad_mesh());
  EXPECT_EQ(euler(m), 3);  // 2 for the cube + 1 for the lone vertex
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, BadIndicesAndCoordinatesAreInputErrors) {
  IndexedMesh in = tetrahedron();
  in.indices[4] = 9;
  try {
    build(in);
    FAIL() << "expected InvalidInputError";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("corner 4 refers to vertex 9"), std::string::npos) << e.what();
  }
  in = tetrahedron();
  in.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(build(in, repair()), InvalidInputError);
  in = tetrahedron();
  in.indices.pop_back();
  EXPECT_THROW(build(in), InvalidInputError);
  in = test::cube();
  in.face_sizes[0] = 5;
  EXPECT_THROW(build(in), InvalidInputError);
}

TEST(Build, StrictRejectsNonManifoldEdgeNamingVertices) {
  IndexedMesh in = tetrahedron();
  in.positions.push_back({1, 1, 1});
  in.indices.insert(in.indices.end(), {0, 1, 4});  // a third face on edge 0-1
  try {
    build(in);
    FAIL() << "expected TopologyError";
  } catch (const TopologyError& e) {
    EXPECT_NE(std::string(e.what()).find("edge"), std::string::npos) << e.what();
    ASSERT_FALSE(e.vertices().empty());
    EXPECT_TRUE((e.vertices()[0] == 0 && e.vertices()[1] == 1) || (e.vertices()[0] == 1 && e.vertices()[1] == 0));
  }
}

TEST(Build, StrictRejectsPinchedVertexAndDegenerateFace) {
  try {
    build(hourglass());
    FAIL() << "expected TopologyError";
  } catch (const TopologyError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 0"), std::string::npos) << e.what();
    EXPECT_EQ(e.vertices(), std::vector<Index>{0});
  }
  IndexedMesh in = tetrahedron();
  in.indices[1] = in.indices[0];
  EXPECT_THROW(build(in), TopologyError);
}

TEST(Build, RepairSplitsPinchedVertex) {
  BuildReport rep;
  SurfaceMesh m = build(hourglass(), repair(), &rep);
  EXPECT_EQ(rep.non_manifold_vertices, 1u);
  EXPECT_EQ(rep.duplicated_vertices, 1u);
  EXPECT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.n_faces(), 8u);
  EXPECT_EQ(euler(m), 4);  // two spheres
  ASSERT_EQ(rep.vertex_origin.size(), 8u);
  EXPECT_EQ(rep.vertex_origin[7], 0u);
  EXPECT_EQ(m.position(Vertex(7)), m.position(Vertex(0)));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairSplitsBowTie) {
  // Two triangles touching at one vertex: two boundary gaps at vertex 0.
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  in.indices = {0, 1, 2, 0, 3, 4};
  EXPECT_THROW(build(in), TopologyError);
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(rep.non_manifold_vertices, 1u);
  EXPECT_EQ(m.n_vertices(), 6u);
  EXPECT_EQ(m.boundary_loops().size(), 2u);
  for (Vertex v : m.vertices()) EXPECT_TRUE(m.is_manifold(v));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairReorientsFlippedFaces) {
  IndexedMesh in = tetrahedron();
  std::swap(in.indices[1], in.indices[2]);  // face 0 reversed
  EXPECT_THROW(build(in), TopologyError);
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(rep.reoriented_faces, 1u);  // the majority orientation wins
  EXPECT_EQ(rep.non_manifold_edges, 0u);
  EXPECT_EQ(m.n_edges(), 6u);
  EXPECT_TRUE(m.boundary_loops().empty());
  // Face 0 now runs 0 1 2 (reversed), as the other three faces demand.
  std::vector<Vertex> corners;
  for (Vertex v : m.vertices(Face(0))) corners.push_back(v);
  EXPECT_EQ(corners, (std::vector<Vertex>{Vertex(0), Vertex(2), Vertex(1)}));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairCutsNonManifoldEdgeWithoutDroppingFaces) {
  // Three triangles on edge 0-1 (a book with three pages).
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}};
  in.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(m.n_faces(), 3u);
  EXPECT_EQ(rep.non_manifold_edges, 1u);
  EXPECT_GT(rep.duplicated_vertices, 0u);
  for (Vertex v : m.vertices()) EXPECT_TRUE(m.is_manifold(v));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairCutsMoebiusStrip) {
  // A strip of n quads closed with a half twist: not orientable, so one edge must be cut.
  const int n = 8;
  IndexedMesh in;
  for (int i = 0; i < n; ++i) {
    double t = 2 * M_PI * i / n;
    in.positions.push_back({float(std::cos(t)), float(std::sin(t)), -0.2f});
    in.positions.push_back({float(std::cos(t)), float(std::sin(t)), 0.2f});
  }
  for (int i = 0; i < n; ++i) {
    Index a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % n), d = 2 * ((i + 1) % n) + 1;
    if (i == n - 1) std::swap(c, d);  // the twist
    in.indices.insert(in.indices.end(), {a, c, d, b});
    in.face_sizes.push_back(4);
  }
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(m.n_faces(), static_cast<std::size_t>(n));
  EXPECT_EQ(rep.non_manifold_edges, 1u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, RepairDropsOnlyDegenerateFaces) {
  IndexedMesh in = test::grid(2, false);
  in.indices.insert(in.indices.end(), {0, 1, 0});           // repeated vertex: dropped
  in.face_sizes.push_back(3);
  in.indices.insert(in.indices.end(), {0, 1});              // two corners: dropped
  in.face_sizes.push_back(2);
  in.indices.insert(in.indices.end(), {9, 10, 10, 11, 9});  // consecutive repeats: kept as a triangle
  in.face_sizes.push_back(5);
  in.positions.push_back({3, 0, 0});
  in.positions.push_back({4, 0, 0});
  in.positions.push_back({4, 1, 0});
  BuildReport rep;
  SurfaceMesh m = build(in, repair(), &rep);
  EXPECT_EQ(rep.degenerate_faces, 2u);
  EXPECT_EQ(rep.repeated_corners, 2u);
  EXPECT_EQ(m.n_faces(), 5u);
  EXPECT_EQ(rep.face_map[4], kInvalidIndex);
  EXPECT_EQ(rep.face_map[5], kInvalidIndex);
  EXPECT_EQ(rep.face_map[6], 4u);
  EXPECT_EQ(m.valence(Face(4)), 3u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, ExactWeldingOfTriangleSoup) {
  IndexedMesh soup;
  IndexedMesh tet = tetrahedron();
  for (Index i : tet.indices) {
    soup.indices.push_back(static_cast<Index>(soup.positions.size()));
    soup.positions.push_back(tet.positions[i]);
  }
  soup.positions[0].x = -0.0f;  // -0 and +0 weld
  BuildOptions o;
  o.weld = Weld::exact;
  BuildReport rep;
  SurfaceMesh m = build(soup, o, &rep);
  EXPECT_EQ(m.n_vertices(), 4u);
  EXPECT_EQ(rep.welded_vertices, 8u);
  EXPECT_EQ(rep.vertex_map.size(), 12u);
  EXPECT_EQ(m.boundary_loops().size(), 0u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Build, EpsilonWeldingMergesFloatNoiseOnly) {
  IndexedMesh in = test::grid(2, true);
  // Duplicate vertex 4 (the centre) with noise and rewire the upper-right triangles to it.
  in.positions.push_back(in.positions[4] + Vec3{1e-7f, -1e-7f, 0});
  for (std::size_t c = 12; c < in.indices.size(); ++c)
    if (in.indices[c] == 4) in.indices[c] = 9;
  BuildOptions o = repair();
  o.weld = Weld::exact;
  // Exact welding cannot see it: the slit pinches vertices 3 and 5, which repair splits.
  EXPECT_EQ(build(in, o).n_vertices(), 12u);
  o.weld = Weld::epsilon;
  o.weld_epsilon = 1e-6;
  BuildReport rep;
  SurfaceMesh m = build(in, o, &rep);
  EXPECT_EQ(m.n_vertices(), 9u);
  EXPECT_EQ(rep.vertex_map[9], 4u);
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_TRUE(m.validate().empty());
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

TEST(Build, HighValenceVertex) {
  // A fan of 200 triangles around one vertex takes the sorted-bucket path.
  const int n = 200;
  IndexedMesh in;
  in.positions.push_back({0, 0, 0});
  for (int i = 0; i < n; ++i) in.positions.push_back({float(std::cos(i * 0.0314)), float(std::sin(i * 0.0314)), 0});
  for (int i = 0; i < n; ++i) in.indices.insert(in.indices.end(), {0, Index(1 + i), Index(1 + (i + 1) % n)});
  SurfaceMesh m = build(in);
  EXPECT_EQ(m.valence(Vertex(0)), static_cast<std::size_t>(n));
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

// build(), linking (src/core/build_link.cpp): mesh arrays, fan checks and vertex splitting,
// boundary loops.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "core/build_test_util.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::euler;
using test::repair;
using test::tetrahedron;

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

TEST(Build, LinksFacesFromFirstCornerAndBoundaryLoops) {
  // A 3 x 3 grid without its middle quad: an outer boundary loop of 12 edges and a hole of 4. The
  // triangle and polygon inputs take different linking loops.
  for (bool tri : {true, false}) {
    IndexedMesh in = test::grid(3, tri);
    const std::ptrdiff_t per_quad = tri ? 6 : 4;
    in.indices.erase(in.indices.begin() + 4 * per_quad, in.indices.begin() + 5 * per_quad);
    if (!tri) in.face_sizes.pop_back();
    const std::size_t n = tri ? 3 : 4;
    SurfaceMesh m = build(in);
    ASSERT_EQ(m.n_faces(), in.face_count());
    // Each face starts at its first input corner and runs through the others in input order.
    for (Face f : m.faces()) {
      std::vector<Index> corners;
      for (Halfedge h : m.halfedges(f)) {
        EXPECT_EQ(m.face(h), f);
        corners.push_back(m.to_vertex(h).idx());
      }
      const auto first = in.indices.begin() + static_cast<std::ptrdiff_t>(n * f.idx());
      EXPECT_EQ(corners, std::vector<Index>(first, first + static_cast<std::ptrdiff_t>(n)));
    }
    // Boundary loops: each boundary half-edge is followed by the one leaving its target, which is
    // also that vertex's half-edge.
    std::vector<std::size_t> lengths;
    std::vector<Index> hole;
    for (Halfedge start : m.boundary_loops()) {
      std::vector<Index> loop;
      Halfedge h = start;
      do {
        EXPECT_TRUE(m.is_boundary(h));
        EXPECT_EQ(m.halfedge(m.to_vertex(h)), m.next(h));
        loop.push_back(m.to_vertex(h).idx());
        h = m.next(h);
      } while (h != start && loop.size() <= m.n_halfedges());
      lengths.push_back(loop.size());
      if (loop.size() == 4) hole = loop;
    }
    std::sort(lengths.begin(), lengths.end());
    EXPECT_EQ(lengths, (std::vector<std::size_t>{4, 12}));
    // The hole is traversed as the missing quad 5 6 10 9 was.
    ASSERT_EQ(hole.size(), 4u);
    std::rotate(hole.begin(), std::find(hole.begin(), hole.end(), Index(5)), hole.end());
    EXPECT_EQ(hole, (std::vector<Index>{5, 6, 10, 9}));
    EXPECT_TRUE(m.validate().empty());
  }
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

// Two polygons of `n` corners each on a circle, touching at vertex 0 (a bow tie of polygons), or
// one polygon when `two` is false.
IndexedMesh big_polygons(std::size_t n, bool two) {
  IndexedMesh in;
  in.positions.push_back({0, 0, 0});
  for (int side : {1, -1}) {
    if (side < 0 && !two) break;
    const Index first = static_cast<Index>(in.positions.size());
    in.indices.push_back(0);
    for (std::size_t k = 1; k < n; ++k) {
      const double a = 3.14159 * static_cast<double>(k) / static_cast<double>(n);
      in.positions.push_back(
          {static_cast<float>(side * (1 - std::cos(a))), static_cast<float>(std::sin(a)), 0});
      in.indices.push_back(first + static_cast<Index>(k - 1));
    }
    in.face_sizes.push_back(static_cast<Index>(n));
  }
  return in;
}

// Every corner of a large polygon is on the boundary, and the walk about each one needs the
// half-edge before it: found by walking the face, that was n^2 steps (minutes for this polygon).
TEST(Build, LargePolygonsAreLinkedAndSplitWithoutWalkingTheirFaces) {
  constexpr std::size_t kCorners = 200000;
  SurfaceMesh m = build(big_polygons(kCorners, false));
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(m.n_edges(), kCorners);
  ASSERT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_TRUE(m.validate().empty());

  // Two of them pinched at vertex 0: the second fan gets a copy of the vertex.
  BuildReport rep;
  SurfaceMesh pinched = build(big_polygons(kCorners, true), repair(), &rep);
  EXPECT_EQ(rep.non_manifold_vertices, 1u);
  EXPECT_EQ(rep.duplicated_vertices, 1u);
  EXPECT_EQ(pinched.n_vertices(), 2 * kCorners);
  EXPECT_EQ(pinched.boundary_loops().size(), 2u);
  for (Vertex v : pinched.vertices()) EXPECT_TRUE(pinched.is_manifold(v));
  EXPECT_TRUE(pinched.validate().empty());
}

}  // namespace
}  // namespace hedge

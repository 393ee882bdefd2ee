// build(), linking (src/core/build_link.cpp): mesh arrays, fan checks and vertex splitting,
// boundary loops.
#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace hedge

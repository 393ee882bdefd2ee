// build(), general path (src/core/build_repair.cpp): strict errors on edges, re-orientation,
// cutting non-manifold edges.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/build_test_util.h"
#include "hedge/core/build.h"
#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::repair;
using test::tetrahedron;

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
    EXPECT_TRUE((e.vertices()[0] == 0 && e.vertices()[1] == 1) ||
                (e.vertices()[0] == 1 && e.vertices()[1] == 0));
  }
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

}  // namespace
}  // namespace hedge

// build(), fast pairing of clean input (src/core/build_pairing.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::tetrahedron;

TEST(Build, FastPairingNumbersEdgesAsTheGeneralPath) {
  // With more vertices than corners build() does not use the fast pairing (its table would cost
  // more than it saves) and pairs by sorting instead. On clean input both must give the same mesh,
  // half-edge numbers included.
  for (const IndexedMesh& clean : {tetrahedron(), test::grid(4, true), test::cube(), test::grid(3, false)}) {
    IndexedMesh sparse = clean;
    for (std::size_t i = 0; i < clean.indices.size(); ++i) sparse.positions.push_back({9, 9, 9});
    SurfaceMesh fast = build(clean);
    SurfaceMesh general = build(sparse);
    EXPECT_EQ(general.n_vertices(), fast.n_vertices() + clean.indices.size());
    EXPECT_EQ(fast.halfedge_vertex_array(), general.halfedge_vertex_array());
    EXPECT_EQ(fast.halfedge_next_array(), general.halfedge_next_array());
    for (Vertex v : fast.vertices()) EXPECT_EQ(fast.halfedge(v), general.halfedge(v));
    for (Face f : fast.faces()) EXPECT_EQ(fast.halfedge(f), general.halfedge(f));
    EXPECT_TRUE(fast.validate().empty());
    EXPECT_TRUE(general.validate().empty());
  }
}

TEST(Build, HighValenceVertex) {
  // A fan of 200 triangles around one vertex: on the fast path, most of its edges go to the overflow
  // map past the per-vertex slots.
  const int n = 200;
  IndexedMesh in;
  in.positions.push_back({0, 0, 0});
  for (int i = 0; i < n; ++i)
    in.positions.push_back({float(std::cos(i * 0.0314)), float(std::sin(i * 0.0314)), 0});
  for (int i = 0; i < n; ++i) in.indices.insert(in.indices.end(), {0, Index(1 + i), Index(1 + (i + 1) % n)});
  SurfaceMesh m = build(in);
  EXPECT_EQ(m.valence(Vertex(0)), static_cast<std::size_t>(n));
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

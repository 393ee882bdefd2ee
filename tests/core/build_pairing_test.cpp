// build(), fast pairing of clean input (src/core/build_pairing.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::tetrahedron;

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

// Corner texture coordinates through one collapse: seam edges, and the corners at the survivor
// interpolated in the chart of their own face (decimate_test.cpp tests them through decimate()).
#include "algorithms/decimate_corners.h"

#include <gtest/gtest.h>

#include "hedge/core/build.h"
#include "hedge/core/edge_operations.h"
#include "test_meshes.h"

namespace hedge::detail::decimation {
namespace {

constexpr int kN = 4;

// A flat kN x kN grid with two texture charts: faces left of x = kN / 2 map to (x, y) / kN, faces
// right of it to the same plus 10 in u, so the column x = kN / 2 is a seam.
SurfaceMesh seamed_grid() {
  IndexedMesh in = test::grid(kN, true);
  for (std::size_t c = 0; c < in.indices.size(); ++c) {
    const std::size_t f = c / 3;
    float cx = 0;
    for (std::size_t k = 0; k < 3; ++k) cx += in.positions[in.indices[3 * f + k]].x / 3;
    const Vec3 p = in.positions[in.indices[c]];
    in.texcoords.push_back({p.x / kN + (cx > kN / 2.f ? 10.f : 0.f), p.y / kN});
    in.texcoord_indices.push_back(Index(c));
  }
  return build(in);
}

Vertex vertex_at(const SurfaceMesh& m, float x, float y) {
  for (Vertex v : m.vertices())
    if (m.position(v) == Vec3{x, y, 0}) return v;
  return Vertex();
}

float centroid_x(const SurfaceMesh& m, Face f) {
  float x = 0;
  for (Vertex v : m.vertices(f)) x += m.position(v).x / 3;
  return x;
}

TEST(DecimateCorners, SeamsAreTheInteriorEdgesWhereTheChartsMeet) {
  const SurfaceMesh m = seamed_grid();
  const auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(uv);
  std::size_t seams = 0;
  for (Edge e : m.edges()) {
    const Vertex a = m.from_vertex(SurfaceMesh::halfedge(e, 0)), b = m.to_vertex(SurfaceMesh::halfedge(e, 0));
    const bool on_column = m.position(a).x == kN / 2.f && m.position(b).x == kN / 2.f;
    const bool interior = !m.is_boundary(e);
    EXPECT_EQ(is_seam(m, uv, e), on_column && interior) << "edge " << e.idx();
    seams += is_seam(m, uv, e);
  }
  EXPECT_EQ(seams, std::size_t(kN));
}

// Collapses a into b, moving b to p, with the corners carried by a CornerRing; checks that every
// corner at b holds its chart's texture coordinates at p.
void collapse_and_check(SurfaceMesh& m, Vertex a, Vertex b, const Vec3& p) {
  auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  const Halfedge h = m.find_halfedge(a, b);
  ASSERT_TRUE(h.is_valid());
  CornerRing ring;
  ring.gather(m, uv, h);
  ASSERT_TRUE(collapse(m, h).is_valid());
  m.position(b) = p;
  ring.interpolate(m, uv, b, to_double(p));
  std::size_t corners = 0;
  for (Halfedge o : m.halfedges(b)) {
    const Halfedge in = SurfaceMesh::twin(o);
    if (!m.face(in).is_valid()) continue;
    const float u0 = centroid_x(m, m.face(in)) > kN / 2.f ? 10.f : 0.f;
    EXPECT_NEAR(uv[in].x, p.x / kN + u0, 1e-6) << "corner in face " << m.face(in).idx();
    EXPECT_NEAR(uv[in].y, p.y / kN, 1e-6) << "corner in face " << m.face(in).idx();
    ++corners;
  }
  EXPECT_GE(corners, 4u);
  EXPECT_TRUE(m.validate().empty());
}

TEST(DecimateCorners, ACollapseInsideAChartKeepsItsLinearMap) {
  SurfaceMesh m = seamed_grid();
  collapse_and_check(m, vertex_at(m, 1, 1), vertex_at(m, 1, 2), {1.f, 1.5f, 0.f});
}

// Along the seam both charts meet at the survivor: each corner takes the value of its own side.
TEST(DecimateCorners, ACollapseAlongTheSeamKeepsBothCharts) {
  SurfaceMesh m = seamed_grid();
  collapse_and_check(m, vertex_at(m, 2, 1), vertex_at(m, 2, 2), {2.f, 1.5f, 0.f});
}

}  // namespace
}  // namespace hedge::detail::decimation

// Triangulation of regions with holes and the tracing of planar regions in solid fracture.
#include <gtest/gtest.h>

#include <cmath>

#include "algorithms/fracture_solid_internal.h"
#include "hedge/core/build.h"

namespace hedge::solid_detail {
namespace {

using P2 = std::array<double, 2>;

double area_of(const std::vector<P2>& xy, const std::vector<std::array<std::uint32_t, 3>>& tris,
               const std::vector<std::uint32_t>& ids) {
  double a = 0;
  for (const auto& t : tris) {
    P2 p[3];
    for (int k = 0; k < 3; ++k) p[k] = xy[std::find(ids.begin(), ids.end(), t[k]) - ids.begin()];
    const double s = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    EXPECT_GE(s, 0);  // counter-clockwise
    a += s / 2;
  }
  return a;
}

TEST(FractureSolidClip, SquareWithASquareHole) {
  const std::vector<P2> outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<std::uint32_t> outer_id{0, 1, 2, 3};
  const std::vector<std::vector<P2>> holes{{{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  const std::vector<std::vector<std::uint32_t>> hole_ids{{4, 5, 6, 7}};
  std::vector<std::array<std::uint32_t, 3>> tris;
  ASSERT_TRUE(triangulate_with_holes(outer, outer_id, holes, hole_ids, tris));
  EXPECT_EQ(tris.size(), 8u);  // n + 2 h - 2 for n corners in all and h holes
  std::vector<P2> xy = outer;
  xy.insert(xy.end(), holes[0].begin(), holes[0].end());
  EXPECT_NEAR(area_of(xy, tris, {0, 1, 2, 3, 4, 5, 6, 7}), 12, 1e-12);
}

TEST(FractureSolidClip, ConcavePolygonWithTwoHoles) {
  // An L shape with two square holes in its arms.
  const std::vector<P2> outer{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}};
  const std::vector<std::uint32_t> outer_id{0, 1, 2, 3, 4, 5};
  const std::vector<std::vector<P2>> holes{{{4, 0.5}, {4, 1.5}, {5, 1.5}, {5, 0.5}},
                                           {{0.5, 4}, {0.5, 5}, {1.5, 5}, {1.5, 4}}};
  const std::vector<std::vector<std::uint32_t>> hole_ids{{6, 7, 8, 9}, {10, 11, 12, 13}};
  std::vector<std::array<std::uint32_t, 3>> tris;
  ASSERT_TRUE(triangulate_with_holes(outer, outer_id, holes, hole_ids, tris));
  EXPECT_EQ(tris.size(), 14u + 4 - 2);
  std::vector<P2> xy = outer;
  for (const auto& h : holes) xy.insert(xy.end(), h.begin(), h.end());
  std::vector<std::uint32_t> ids(14);
  for (std::uint32_t i = 0; i < 14; ++i) ids[i] = i;
  EXPECT_NEAR(area_of(xy, tris, ids), 20 - 2, 1e-12);
}

TEST(FractureSolidClip, HoleBridgedAroundItsOwnPointInLine) {
  // The outer point nearest the hole's rightmost point (3, 1) is (0, 1), in line with the hole's
  // leftmost point (1, 1): a bridge there runs across the hole through that point, crossing no
  // edge, and the ears clipped then overlap. (A cut through the anchor's round hole: its leftmost
  // and rightmost points in one row with a point of the outline.)
  const std::vector<P2> outer{{0, 1}, {2, -20}, {20, 1}, {2, 20}};
  const std::vector<std::uint32_t> outer_id{0, 1, 2, 3};
  const std::vector<std::vector<P2>> holes{{{1, 1}, {2, 1.5}, {3, 1}, {2, 0.5}}};
  const std::vector<std::vector<std::uint32_t>> hole_ids{{4, 5, 6, 7}};
  std::vector<std::array<std::uint32_t, 3>> tris;
  ASSERT_TRUE(triangulate_with_holes(outer, outer_id, holes, hole_ids, tris));
  EXPECT_EQ(tris.size(), 8u);
  std::vector<P2> xy = outer;
  xy.insert(xy.end(), holes[0].begin(), holes[0].end());
  // The outline's area (two triangles on its diagonal y = 1, of base 20 and heights 21 and 19)
  // less the hole's.
  EXPECT_NEAR(area_of(xy, tris, {0, 1, 2, 3, 4, 5, 6, 7}), 400 - 1, 1e-9);
}

TEST(FractureSolidClip, RegionCutByAChainKeepsItsLeftSide) {
  // The unit square in z = 0, cut by a chain from its bottom side to its top side at x = 0.25: the
  // region is on the chain's left, x < 0.25.
  RegionInput r;
  r.normal = {0, 0, 1};
  for (std::uint32_t i = 0; i < 4; ++i) r.corners.push_back({Key::vertex, i, 0, 0});
  r.corner_pos = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Key bottom{Key::edge, 0, 1, 7}, top{Key::edge, 2, 3, 7};
  r.chain.push_back({bottom, top, {0.25, 0, 0}, {0.25, 1, 0}});
  r.side = [&](const Key& k) { return k == bottom ? 0 : k == top ? 2 : -2; };
  r.inside = [] { return true; };
  std::vector<std::array<Key, 3>> tris;
  std::vector<std::pair<Key, Vec3d>> points;
  ASSERT_TRUE(fill_region(r, tris, points));
  auto at = [&](const Key& k) {
    for (const auto& [kk, p] : points)
      if (kk == k) return p;
    ADD_FAILURE() << "no point";
    return Vec3d{};
  };
  double area = 0;
  for (const auto& t : tris) area += cross(at(t[1]) - at(t[0]), at(t[2]) - at(t[0])).z / 2;
  EXPECT_NEAR(area, 0.25, 1e-12);
  // Without the chain, the whole square when inside, nothing when not.
  r.chain.clear();
  tris.clear();
  ASSERT_TRUE(fill_region(r, tris, points));
  EXPECT_EQ(tris.size(), 2u);
  r.inside = [] { return false; };
  tris.clear();
  ASSERT_TRUE(fill_region(r, tris, points));
  EXPECT_TRUE(tris.empty());
  // A chain that ends inside the outline is an inconsistency, not a crash.
  r.chain.push_back({bottom, Key{Key::triangle, 0, 1, 2}, {0.25, 0, 0}, {0.25, 0.5, 0}});
  r.side = [&](const Key& k) { return k == bottom ? 0 : -1; };
  EXPECT_FALSE(fill_region(r, tris, points));
}

TEST(FractureSolidClip, ClippingFromTheFirstHalfSpaceATriangleLeavesGivesTheSamePolygon) {
  // A triangle in z = 0 and four half-spaces: the first two hold it whole, the third cuts a corner
  // off, the fourth cuts the polygon left.
  IndexedMesh im;
  im.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  im.indices = {0, 1, 2};
  im.face_sizes = {3};
  const SurfaceMesh m = build(im);
  SoupTriangle t;
  t.face = Face(0);
  int k = 0;
  for (Halfedge h : m.halfedges(t.face)) {
    t.corner[k] = h;
    t.v[k++] = m.to_vertex(h).idx();
  }
  const std::vector<SoupTriangle> soup{t};
  PlaneSet planes;
  planes.planes = {{{1, 0, 0}, -2}, {{0, 0, 1}, -1}, {{1, 0, 0}, -0.5}, {{0, 1, 0}, -0.25}};
  const Geometry g{&m, &planes, &soup, nullptr};
  std::vector<HalfSpace> hs;
  for (std::uint32_t p = 0; p < 4; ++p) hs.push_back({p, false});
  ClipPolygon all, from_third;
  clip_triangle(g, 0, hs, all);
  clip_triangle(g, 0, hs, from_third, 2);
  EXPECT_EQ(all.keys.size(), 4u);  // x < 0.5 and y < 0.25: a quadrilateral
  EXPECT_EQ(from_third.keys, all.keys);
  EXPECT_EQ(from_third.support, all.support);
  ASSERT_EQ(from_third.pos.size(), all.pos.size());
  for (std::size_t i = 0; i < all.pos.size(); ++i) EXPECT_EQ(from_third.pos[i], all.pos[i]);
  for (const Vec3d& p : all.pos) EXPECT_TRUE(p.x <= 0.5 && p.y <= 0.25);
}

}  // namespace
}  // namespace hedge::solid_detail

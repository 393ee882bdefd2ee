#include "hedge/core/triangulate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"

namespace hedge {
namespace {

double signed_area_xy(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

double polygon_area_xy(const std::vector<Vec3d>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d& u = p[i];
    const Vec3d& v = p[(i + 1) % p.size()];
    a += u.x * v.y - v.x * u.y;
  }
  return 0.5 * a;
}

// n - 2 triangles, every corner used, each triangle keeps the polygon's orientation, and the
// areas add up to the polygon's: the triangles tile the polygon without folding over.
void expect_tiles(const std::vector<Vec3d>& p) {
  std::vector<std::array<Index, 3>> tris;
  triangulate_polygon(p, tris);
  ASSERT_EQ(tris.size(), p.size() - 2);
  std::set<Index> used;
  double sum = 0;
  for (const auto& t : tris) {
    for (Index i : t) {
      ASSERT_LT(i, p.size());
      used.insert(i);
    }
    const double a = signed_area_xy(p[t[0]], p[t[1]], p[t[2]]);
    EXPECT_GT(a, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2] << " is flipped or flat";
    sum += a;
  }
  EXPECT_EQ(used.size(), p.size());
  const double area = polygon_area_xy(p);
  EXPECT_GT(area, 0);
  EXPECT_NEAR(sum, area, 1e-9 * std::max(1.0, area));
}

TEST(Triangulate, ConvexQuad) { expect_tiles({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}); }

TEST(Triangulate, ConcaveQuadUsesTheInnerDiagonal) {
  // A dart: the fan from corner 0 would put a triangle outside the polygon.
  const std::vector<Vec3d> dart = {{0, 0, 0}, {2, 1, 0}, {4, 0, 0}, {2, 3, 0}};
  expect_tiles({dart[1], dart[2], dart[3], dart[0]});
  expect_tiles(dart);
}

TEST(Triangulate, LShapeAndComb) {
  expect_tiles({{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}});
  // A comb: teeth up to y = 4, notches down to y = 1 (four reflex corners).
  const std::vector<Vec3d> comb = {{0, 0, 0},   {9, 0, 0}, {9, 4, 0},   {7.5, 1, 0}, {6, 4, 0},
                                   {4.5, 1, 0}, {3, 4, 0}, {1.5, 1, 0}, {0, 4, 0}};
  expect_tiles(comb);
}

TEST(Triangulate, TiltedPlanesKeepOrientation) {
  // The same concave polygon in a plane that is neither axis-aligned nor facing +z: the triangles
  // follow the polygon's own orientation (checked after rotating back into the xy plane).
  const std::vector<Vec3d> flat = {{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
  const double c = std::cos(1.1), s = std::sin(1.1);
  std::vector<Vec3d> tilted;
  for (const Vec3d& p : flat) tilted.push_back({p.x, c * p.y, s * p.y});
  std::vector<std::array<Index, 3>> tris;
  triangulate_polygon(tilted, tris);
  ASSERT_EQ(tris.size(), 4u);
  double sum = 0;
  for (const auto& t : tris) {
    const double a = signed_area_xy(flat[t[0]], flat[t[1]], flat[t[2]]);
    EXPECT_GT(a, 0);
    sum += a;
  }
  EXPECT_NEAR(sum, polygon_area_xy(flat), 1e-9);
}

TEST(Triangulate, SelfIntersectingInputStillGivesNMinusTwoTriangles) {
  // A bow tie has no valid triangulation; the fallback still covers every corner.
  std::vector<std::array<Index, 3>> tris;
  triangulate_polygon(std::vector<Vec3d>{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}, tris);
  EXPECT_EQ(tris.size(), 2u);
}

// The definition the triangles follow, written the slow way: after every clip, the first corner
// from corner 0 on that is convex and has no other corner left in (or on) its triangle is clipped.
std::vector<std::array<Index, 3>> first_ear_reference(const std::vector<Vec3d>& p) {
  std::vector<Index> ring;
  for (std::size_t i = 0; i < p.size(); ++i) ring.push_back(static_cast<Index>(i));
  auto cross = [&](Index a, Index b, Index c) {
    return (p[b].x - p[a].x) * (p[c].y - p[a].y) - (p[b].y - p[a].y) * (p[c].x - p[a].x);
  };
  std::vector<std::array<Index, 3>> tris;
  for (bool clipped = true; ring.size() > 3 && clipped;) {
    clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const Index a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
      bool ear = cross(a, b, c) > 0;
      for (Index r : ring)
        ear = ear &&
              (r == a || r == b || r == c || cross(a, b, r) < 0 || cross(b, c, r) < 0 || cross(c, a, r) < 0);
      if (!ear) continue;
      tris.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) tris.push_back({ring[0], ring[i], ring[i + 1]});
  return tris;
}

TEST(Triangulate, ClipsTheFirstEarFromCornerZeroEveryTime) {
  // Random star-shaped polygons (simple, many reflex corners) of 3 to 80 corners: exactly the
  // triangles of the definition, in its order, as export and render buffers have always made them.
  SplitMix64 random(11);
  for (std::size_t k = 0; k < 300; ++k) {
    const std::size_t n = 3 + k % 78;
    std::vector<Vec3d> p;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 2 * 3.141592653589793 * static_cast<double>(i) / static_cast<double>(n);
      const double r = 0.2 + random.uniform();
      p.push_back({r * std::cos(t), r * std::sin(t), 0});
    }
    std::vector<std::array<Index, 3>> tris;
    triangulate_polygon(p, tris);
    ASSERT_EQ(tris, first_ear_reference(p)) << "polygon " << k << ", " << n << " corners";
  }
}

// Huge polygons, as a file from anywhere may hold: each clip tests only the two corners next to
// it again (O(n^2) in all); a scan from corner 0 after every clip took 25 s for a zigzag strip of
// 10,000 corners.
TEST(Triangulate, HugeJitteredRegularPolygonTiles) {
  // 20,000 corners on a circle, each moved in or out by up to 1e-4: far more than the circle's
  // bulge between corners (5e-8), so about half of the corners are reflex.
  constexpr std::size_t kCorners = 20000;
  SplitMix64 random(7);
  std::vector<Vec3d> p;
  std::size_t reflex = 0;
  for (std::size_t i = 0; i < kCorners; ++i) {
    const double t = 2 * 3.141592653589793 * static_cast<double>(i) / kCorners;
    const double r = 1 + 1e-4 * (random.uniform() - 0.5);
    p.push_back({r * std::cos(t), r * std::sin(t), 0});
  }
  for (std::size_t i = 0; i < kCorners; ++i)
    reflex += signed_area_xy(p[(i + kCorners - 1) % kCorners], p[i], p[(i + 1) % kCorners]) < 0;
  EXPECT_GT(reflex, kCorners / 3);
  expect_tiles(p);
}

TEST(Triangulate, HugeCombAndStarTile) {
  // A comb of 9,998 teeth (up to y = 4, notches down to y = 1, every notch reflex) on a base from
  // (0, 0) to (9998, 0), closed by a bump on its left side: 20,000 corners.
  constexpr std::size_t kTeeth = 9998;
  std::vector<Vec3d> comb = {{0, 0, 0}, {double(kTeeth), 0, 0}};
  for (std::size_t j = kTeeth; j >= 1; --j) {
    comb.push_back({double(j), 4, 0});
    comb.push_back({double(j) - 0.5, 1, 0});
  }
  comb.push_back({0, 4, 0});
  comb.push_back({-1, 2, 0});
  ASSERT_EQ(comb.size(), 20000u);
  expect_tiles(comb);
  // A star of 10,000 points, its 10,000 inner corners reflex.
  std::vector<Vec3d> star;
  for (std::size_t i = 0; i < 20000; ++i) {
    const double t = 2 * 3.141592653589793 * static_cast<double>(i) / 20000, r = i % 2 ? 0.5 : 1;
    star.push_back({r * std::cos(t), r * std::sin(t), 0});
  }
  expect_tiles(star);
}

TEST(Triangulate, HugeSelfCrossingPolygonStillGivesNMinusTwoTriangles) {
  // A star polygon {2001/1000}: each edge jumps almost halfway round, so every edge crosses many
  // others; there are no true ears to find, and the fallback still covers every corner once.
  constexpr std::size_t kCorners = 2001;
  std::vector<Vec3d> p;
  for (std::size_t i = 0; i < kCorners; ++i) {
    const double t = 2 * 3.141592653589793 * static_cast<double>(i * 1000 % kCorners) / kCorners;
    p.push_back({std::cos(t), std::sin(t), 0});
  }
  std::vector<std::array<Index, 3>> tris;
  triangulate_polygon(p, tris);
  ASSERT_EQ(tris.size(), kCorners - 2);
  std::set<Index> used;
  for (const auto& t : tris)
    for (Index i : t) {
      ASSERT_LT(i, kCorners);
      used.insert(i);
    }
  EXPECT_EQ(used.size(), kCorners);
  // The same input gives the same triangles.
  std::vector<std::array<Index, 3>> again;
  triangulate_polygon(p, again);
  EXPECT_EQ(again, tris);
}

TEST(Triangulate, FanApexIsTheFirstCornerUnlessThatFanFolds) {
  // Triangles and convex polygons keep corner 0.
  EXPECT_EQ(fan_apex(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), 0u);
  EXPECT_EQ(fan_apex(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), 0u);
  // A slightly non-planar quad whose first-corner fan does not fold keeps it too.
  EXPECT_EQ(fan_apex(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0.1}, {1, 1, 0}, {0, 1, 0.1}}), 0u);
  // A dart, its notch at corner 3: the diagonal from corner 0 runs outside it (its second triangle
  // points down), so the fan starts at corner 1, along the other diagonal.
  const std::vector<Vec3d> dart{{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {0.5, 1, 0}};
  EXPECT_EQ(fan_apex(dart), 1u);
  // The dart with its notch lifted (non-planar, as on a coarse control mesh) folds the same way.
  EXPECT_EQ(fan_apex(std::vector<Vec3d>{{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {0.5, 1, 0.4}}), 1u);
  // An L hexagon: only the fan from the notch's corner (2) tiles it.
  EXPECT_EQ(fan_apex(std::vector<Vec3d>{{2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}}),
            2u);
}

TEST(Triangulate, FanApexOfALargePolygonIsOneOfSixtyFourCorners) {
  // The L hexagon with 1,000 corners on each side: only corners in its inner square see all of it,
  // the notch (corner 2,000) first; trying all 6,000 would cost 36 million tilts.
  const std::vector<Vec3d> hexagon{{2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}};
  constexpr std::size_t kSide = 1000;
  std::vector<Vec3d> p;
  for (std::size_t e = 0; e < 6; ++e)
    for (std::size_t i = 0; i < kSide; ++i) {
      const double t = static_cast<double>(i) / kSide;
      p.push_back(hexagon[e] * (1 - t) + hexagon[(e + 1) % 6] * t);
    }
  const std::size_t n = p.size(), k = fan_apex(p);
  bool candidate = false;
  for (std::size_t j = 0; j < 64; ++j) candidate |= k == j * n / 64;
  EXPECT_TRUE(candidate) << k;
  // The corner chosen is in the inner square, on the left or the bottom side: its fan does not fold.
  EXPECT_EQ(k, 48 * n / 64);  // (0, 1), the first candidate there
  const Vec3d up{0, 0, 1};
  for (std::size_t i = 1; i + 1 < n; ++i)
    EXPECT_GE(dot(cross(p[(k + i) % n] - p[k], p[(k + i + 1) % n] - p[k]), up), -1e-12) << i;
}

TEST(Triangulate, FanStartNamesTheApexOfAFace) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {2, 1, 0}, {0, 2, 0}, {0.5f, 1, 0}, {5, 0, 0},
                  {6, 0, 0}, {6, 1, 0}, {5, 1, 0}, {5, -1, 0}};
  in.indices = {0, 1, 2, 3, 4, 5, 6, 7, 5, 4, 8};
  in.face_sizes = {4, 4, 3};
  const SurfaceMesh m = build(in);
  EXPECT_EQ(fan_start(m, Face(0)), m.next(m.halfedge(Face(0))));  // the dart: from corner 1
  EXPECT_EQ(fan_start(m, Face(1)), m.halfedge(Face(1)));          // a square: its first corner
  EXPECT_EQ(fan_start(m, Face(2)), m.halfedge(Face(2)));          // a triangle
}

}  // namespace
}  // namespace hedge

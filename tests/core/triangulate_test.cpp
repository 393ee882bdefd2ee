#include "hedge/core/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

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
  EXPECT_NEAR(sum, polygon_area_xy(p), 1e-9);
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

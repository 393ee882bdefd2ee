#include "hedge/algorithms/convex_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/build.h"
#include "hedge/error.h"

namespace hedge {
namespace {

struct Plane {
  Vec3d n;  // unit, outward
  double d;
};

// The hull's face planes, computed here in double from the mesh's float positions.
std::vector<Plane> planes(const SurfaceMesh& m) {
  std::vector<Plane> out;
  for (Face f : m.faces()) {
    std::vector<Vec3d> p;
    for (Vertex v : m.vertices(f)) p.push_back(to_double(m.position(v)));
    const Vec3d n = normalize(cross(p[1] - p[0], p[2] - p[0]));
    out.push_back({n, dot(n, (p[0] + p[1] + p[2]) * (1.0 / 3))});
  }
  return out;
}

// How far a point lies beyond the hull's face planes (negative inside).
double outside_distance(const std::vector<Plane>& ps, const Vec3& q) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const Plane& p : ps) worst = std::max(worst, dot(p.n, to_double(q)) - p.d);
  return worst;
}

// Every property a solid hull must have; `slack` is added to the hull's own tolerance for the
// planes recomputed here from float positions.
void expect_hull_of(const ConvexHull& h, const std::vector<Vec3>& points, double slack = 0) {
  const SurfaceMesh& m = h.mesh;
  ASSERT_FALSE(m.is_empty());
  EXPECT_TRUE(m.validate().empty());
  EXPECT_TRUE(m.is_triangle_mesh());
  for (Halfedge e : m.halfedges()) ASSERT_FALSE(m.is_boundary(e)) << "the hull is not closed";
  EXPECT_EQ(long(m.n_vertices()) - long(m.n_edges()) + long(m.n_faces()), 2);
  EXPECT_GT(volume(m), 0) << "faces wind inward";
  ASSERT_EQ(h.input_index.size(), m.n_vertices());
  const std::vector<Plane> ps = planes(m);
  const double tol = h.tolerance + slack;
  for (Vertex v : m.vertices())
    EXPECT_LE(outside_distance(ps, m.position(v)), tol) << "not convex at " << v.idx();
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_LE(outside_distance(ps, points[i]), tol + h.max_outside_distance)
        << "point " << i << " is outside";
}

std::vector<Vec3> cube_corners(float lo = 0, float hi = 1) {
  std::vector<Vec3> c;
  for (int i = 0; i < 8; ++i) c.push_back({i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
  return c;
}

std::vector<Vec3> ball(std::size_t n, unsigned seed, float radius = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-radius, radius);
  std::vector<Vec3> pts;
  while (pts.size() < n) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    if (dot(p, p) <= radius * radius) pts.push_back(p);
  }
  return pts;
}

std::vector<Vec3> sphere(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<Vec3> pts;
  while (pts.size() < n) {
    const Vec3d p{g(rng), g(rng), g(rng)};
    if (norm(p) > 1e-3) pts.push_back(to_float(normalize(p)));
  }
  return pts;
}

TEST(ConvexHull, CubeCornersWithInteriorPointsGiveTheCube) {
  std::vector<Vec3> pts = ball(200, 1, 0.4f);
  for (Vec3& p : pts) p += Vec3{0.5f, 0.5f, 0.5f};
  for (const Vec3& c : cube_corners()) pts.push_back(c);
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::solid);
  EXPECT_EQ(h.mesh.n_vertices(), 8u);
  EXPECT_EQ(h.mesh.n_faces(), 12u);
  EXPECT_NEAR(volume(h.mesh), 1, 1e-12);
  for (std::uint32_t i : h.input_index) EXPECT_GE(i, 200u);
  expect_hull_of(h, pts);
}

// The hull's mesh is linked directly from the quickhull's faces; it must be numbered as build()
// numbers the same triangles (so that results did not change when build() was left out).
TEST(ConvexHull, TheMeshIsNumberedAsBuildNumbersItsTriangles) {
  for (const std::vector<Vec3>& pts : {ball(300, 5), sphere(400, 6), cube_corners()}) {
    const ConvexHull h = convex_hull(pts);
    const SurfaceMesh& m = h.mesh;
    ASSERT_TRUE(m.validate().empty());
    std::vector<Vec3> positions;
    for (Vertex v : m.vertices()) positions.push_back(m.position(v));
    std::vector<std::uint32_t> tris;
    for (Face f : m.faces()) {  // a face's half-edge enters its first corner
      const Halfedge first = m.next(m.halfedge(f));
      for (Halfedge e : {first, m.next(first), m.next(m.next(first))}) tris.push_back(m.from_vertex(e).idx());
    }
    const SurfaceMesh b = build_triangles(positions, tris, {.corner_attributes = false});
    ASSERT_EQ(b.vertex_slots(), m.vertex_slots());
    ASSERT_EQ(b.halfedge_slots(), m.halfedge_slots());
    ASSERT_EQ(b.face_slots(), m.face_slots());
    for (Vertex v : m.vertices()) EXPECT_EQ(b.halfedge(v), m.halfedge(v)) << "vertex " << v.idx();
    for (Face f : m.faces()) EXPECT_EQ(b.halfedge(f), m.halfedge(f)) << "face " << f.idx();
    for (Halfedge e : m.halfedges()) {
      EXPECT_EQ(b.to_vertex(e), m.to_vertex(e)) << "half-edge " << e.idx();
      EXPECT_EQ(b.next(e), m.next(e)) << "half-edge " << e.idx();
      EXPECT_EQ(b.face(e), m.face(e)) << "half-edge " << e.idx();
    }
  }
}

TEST(ConvexHull, PointsOnTheCubesFacesAndEdgesAreNotVertices) {
  // A 5 x 5 x 5 lattice: 98 points on the surface, only the 8 corners are vertices.
  std::vector<Vec3> pts;
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j)
      for (int k = 0; k <= 4; ++k) pts.push_back({i * 0.25f, j * 0.25f, k * 0.25f});
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.mesh.n_vertices(), 8u);
  EXPECT_EQ(h.mesh.n_faces(), 12u);
  expect_hull_of(h, pts);
}

TEST(ConvexHull, EveryPointOfASphereSampleIsOnTheHull) {
  const std::vector<Vec3> pts = sphere(500, 7);
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.mesh.n_vertices(), pts.size());
  EXPECT_EQ(h.mesh.n_faces(), 2 * pts.size() - 4);
  expect_hull_of(h, pts, 1e-6);
}

TEST(ConvexHull, RandomCloudsWithFixedSeeds) {
  for (unsigned seed : {1u, 2u, 3u, 42u, 1234u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Vec3> pts = ball(2000, seed);
    const ConvexHull h = convex_hull(pts);
    EXPECT_EQ(h.dimension, HullDimension::solid);
    expect_hull_of(h, pts, 1e-6);
    EXPECT_EQ(h.max_outside_distance, 0) << "a point was left out";
    // The same input gives the same hull.
    const ConvexHull again = convex_hull(pts);
    EXPECT_EQ(again.input_index, h.input_index);
  }
}

TEST(ConvexHull, ShardSizedAndQuantizedCloudsWithFixedSeeds) {
  // Few points, and points snapped to a coarse grid (many coplanar and collinear subsets).
  for (unsigned seed = 0; seed < 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> size(4, 200), grid(0, 4);
    std::vector<Vec3> pts = ball(std::size_t(size(rng)), seed + 1000);
    if (seed % 2)
      for (Vec3& p : pts) p = {float(grid(rng)), float(grid(rng)), float(grid(rng))};
    const ConvexHull h = convex_hull(pts);
    if (h.dimension == HullDimension::solid || h.dimension == HullDimension::flat)
      expect_hull_of(h, pts, 1e-6);
    EXPECT_EQ(h.max_outside_distance, 0) << "a point was left out";
  }
}

TEST(ConvexHull, ACoarseToleranceDropsNearPointsButStaysConvex) {
  // Points within 1e-2 of the diagonal of the hull are not added; the hull is still convex to
  // rounding, not to that tolerance, and contains every point within it.
  const std::vector<Vec3> pts = sphere(5000, 13);
  const ConvexHull fine = convex_hull(pts);
  const ConvexHull coarse = convex_hull(pts, {.relative_tolerance = 1e-2});
  EXPECT_NEAR(coarse.tolerance, 1e-2 * 2 * std::sqrt(3.0), 1e-3);  // the sample's box is nearly [-1, 1]^3
  EXPECT_LT(coarse.mesh.n_vertices(), fine.mesh.n_vertices() / 4);
  expect_hull_of(coarse, pts, 1e-6);
  const std::vector<Plane> ps = planes(coarse.mesh);
  for (Vertex v : coarse.mesh.vertices()) EXPECT_LE(outside_distance(ps, coarse.mesh.position(v)), 1e-6);
}

TEST(ConvexHull, ACubeSampleWithManyCoplanarPoints) {
  // Points on the faces of a box, drawn from a grid so that many are exactly coplanar.
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> cell(0, 16), face(0, 5);
  std::vector<Vec3> pts;
  for (int n = 0; n < 3000; ++n) {
    const float a = cell(rng) / 16.f, b = cell(rng) / 16.f;
    const int f = face(rng);
    const float c = f % 2 ? 1.f : 0.f;
    pts.push_back(f < 2 ? Vec3{c, a, b} : f < 4 ? Vec3{a, c, b} : Vec3{a, b, c});
  }
  const ConvexHull h = convex_hull(pts);
  expect_hull_of(h, pts);
  EXPECT_NEAR(volume(h.mesh), 1, 1e-9);
}

TEST(ConvexHull, FarFromTheOriginKeepsItsDigits) {
  std::vector<Vec3> pts = ball(500, 9, 4.f);
  for (Vec3& p : pts) p += Vec3{1e6f, -1e6f, 2e6f};
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::solid);
  expect_hull_of(h, pts, 1e-6);
  // Cube corners far away: still exactly the cube.
  const ConvexHull c = convex_hull(cube_corners(1e6f, 1e6f + 2));
  EXPECT_EQ(c.mesh.n_vertices(), 8u);
  EXPECT_NEAR(volume(c.mesh), 8, 1e-9);
}

TEST(ConvexHull, DuplicatesAreFine) {
  std::vector<Vec3> pts;
  for (int copy = 0; copy < 5; ++copy)
    for (const Vec3& c : cube_corners()) pts.push_back(c);
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.mesh.n_vertices(), 8u);
  for (std::uint32_t i : h.input_index) EXPECT_LT(i, 8u) << "the first copy of a duplicate is used";
  expect_hull_of(h, pts);
}

TEST(ConvexHull, NoPointsOnePointAndCoincidentPoints) {
  EXPECT_EQ(convex_hull({}).dimension, HullDimension::empty);
  EXPECT_TRUE(convex_hull({}).mesh.is_empty());
  const std::vector<Vec3> one{{1, 2, 3}};
  EXPECT_EQ(convex_hull(one).dimension, HullDimension::point);
  const std::vector<Vec3> same(10, Vec3{1, 2, 3});
  const ConvexHull h = convex_hull(same);
  EXPECT_EQ(h.dimension, HullDimension::point);
  EXPECT_TRUE(h.mesh.is_empty());
  EXPECT_TRUE(h.input_index.empty());
}

TEST(ConvexHull, CollinearPointsAreASegment) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 20; ++i) pts.push_back({float(i), 2.f * float(i), -float(i)});
  EXPECT_EQ(convex_hull(pts).dimension, HullDimension::segment);
  EXPECT_TRUE(convex_hull(pts).mesh.is_empty());
  const std::vector<Vec3> two{{0, 0, 0}, {1, 1, 1}};
  EXPECT_EQ(convex_hull(two).dimension, HullDimension::segment);
}

TEST(ConvexHull, CoplanarPointsGiveAThinPrism) {
  // A disc sample in a tilted plane.
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1);
  const Vec3d e1 = normalize(Vec3d{1, 1, 0}), e2 = normalize(Vec3d{-1, 1, 1});
  std::vector<Vec3> pts;
  for (int i = 0; i < 300; ++i) pts.push_back(to_float(e1 * double(u(rng)) + e2 * double(u(rng))));
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::flat);
  expect_hull_of(h, pts, 1e-6);
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& p : pts)
    for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double diagonal = norm(to_double(hi - lo));
  EXPECT_GT(h.thickness, 0);
  EXPECT_NEAR(h.thickness, 1e-3 * diagonal, 1e-9);
  // The prism's volume is its area times its thickness; its two sides are copies of one polygon.
  EXPECT_GT(volume(h.mesh), 0);
  EXPECT_EQ(h.mesh.n_vertices() % 2, 0u);
  for (std::uint32_t i : h.input_index) EXPECT_LT(i, pts.size());
  // Three points are flat too.
  const std::vector<Vec3> tri{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const ConvexHull t = convex_hull(tri, {.flat_thickness = 0.01});
  EXPECT_EQ(t.dimension, HullDimension::flat);
  EXPECT_EQ(t.mesh.n_vertices(), 6u);
  EXPECT_EQ(t.mesh.n_faces(), 8u);
  EXPECT_NEAR(volume(t.mesh), 0.5 * t.thickness, 1e-7);
  expect_hull_of(t, tri, 1e-7);
}

TEST(ConvexHull, AFlatSetWithRunsOfCollinearPointsKeepsThemInside) {
  // A shard of a plane cut from a triangulated CAD model: edge midpoints make runs of (nearly)
  // collinear points along its outline, whose prism sides would be slivers.
  const std::vector<Vec3> pts{
      {3.20485997, 16.2800999, 0}, {3.40387011, 16.7730999, 0}, {2.62102008, 15.9261999, 0},
      {3.51379991, 16.4207001, 0}, {3.83365989, 16.5291004, 0}, {2.92791009, 16.9009991, 0},
      {3.00586009, 15.8112001, 0}, {3.37041998, 15.6170998, 0}, {3.66072989, 15.7016001, 0},
      {3.29994988, 15.948, 0},     {3.59925008, 16.0596008, 0}, {3.90320992, 16.1371994, 0},
      {2.90821004, 16.1124992, 0}, {2.78157997, 16.4013996, 0}, {3.08107996, 16.6009998, 0},
      {3.74403, 16.9099007, 0},    {3.63676, 17.2675991, 0},    {3.26939988, 17.1040001, 0},
      {4.02573013, 17.3866997, 0}, {3.77624512, 15.9075003, 0}, {3.19042492, 15.7285004, 0},
      {3.10536003, 16.0456505, 0}, {2.99321985, 16.3407497, 0}, {3.30436516, 16.5265999, 0},
      {3.40205503, 16.1698494, 0}, {3.16589022, 16.8370495, 0}, {3.61876488, 16.6511002, 0},
      {2.70130014, 16.1637993, 0}, {3.70850492, 16.2789497, 0}, {2.85474491, 16.6511993, 0},
      {3.48483515, 15.8383503, 0}, {3.52031517, 17.0203495, 0}, {3.86943007, 17.1374493, 0},
  };
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::flat);
  expect_hull_of(h, pts, 1e-6);
  // And a square with many points along each side, exactly collinear: only the corners remain.
  std::vector<Vec3> square;
  for (int i = 0; i < 40; ++i) {
    const float t = float(i) / 40;
    square.insert(square.end(), {{t, 0, 0}, {1, t, 0}, {1 - t, 1, 0}, {0, 1 - t, 0}});
  }
  const ConvexHull sq = convex_hull(square);
  EXPECT_EQ(sq.dimension, HullDimension::flat);
  EXPECT_EQ(sq.mesh.n_vertices(), 8u);
  expect_hull_of(sq, square, 1e-7);
}

TEST(ConvexHull, APointNearAFaceThatIsReplacedLaterIsNotLost) {
  // A nearly flat shard of a curved surface: point 7 lies within the tolerance of a face of the
  // first tetrahedron, and a nearly coplanar face built later next to it has it 1.8e-5 outside
  // (ten times the tolerance). It is a corner of the hull and must be one.
  const std::vector<Vec3> pts{
      {1.85828996f, 12.8351002f, -2.26317f},    {2.1122601f, 12.8323002f, -2.26268005f},
      {2.10625005f, 12.6082001f, -2.22318006f}, {2.10558009f, 13.2533998f, -2.33693004f},
      {1.84082997f, 13.2761002f, -2.34094f},    {1.85353005f, 13.0513f, -2.30130005f},
      {1.59774995f, 13.0655003f, -2.30379009f}, {2.1177001f, 13.0323f, -2.29795003f}};
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::solid);
  expect_hull_of(h, pts, 1e-7);
  EXPECT_EQ(h.max_outside_distance, 0);
  EXPECT_NE(std::find(h.input_index.begin(), h.input_index.end(), 7u), h.input_index.end());
}

TEST(ConvexHull, AFlatSetFarFromTheOriginIsThickerThanFloatSteps) {
  std::vector<Vec3> pts;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) pts.push_back({1e6f + float(i), 1e6f + float(j), 1e6f});
  const ConvexHull h = convex_hull(pts);
  EXPECT_EQ(h.dimension, HullDimension::flat);
  EXPECT_GE(h.thickness, 16 * 0.0625);  // a float step at 1e6 is 1/16
  EXPECT_EQ(h.mesh.n_vertices(), 8u);
  expect_hull_of(h, pts);
}

TEST(ConvexHull, TheVertexLimitKeepsTheMostExtremePoints) {
  const std::vector<Vec3> pts = sphere(2000, 3);
  const ConvexHull full = convex_hull(pts);
  const ConvexHull h = convex_hull(pts, {.max_vertices = 255});
  EXPECT_EQ(h.mesh.n_vertices(), 255u);
  EXPECT_GT(h.max_outside_distance, 0);
  EXPECT_LT(h.max_outside_distance, 0.1);  // 255 points cover a unit sphere closely
  EXPECT_LT(volume(h.mesh), volume(full.mesh));
  EXPECT_GT(volume(h.mesh), 0.9 * volume(full.mesh));
  expect_hull_of(h, pts, 1e-6);
  // A hull under the limit is not touched by it.
  const ConvexHull c = convex_hull(cube_corners(), {.max_vertices = 8});
  EXPECT_EQ(c.mesh.n_vertices(), 8u);
  EXPECT_EQ(c.max_outside_distance, 0);
  // The smallest limit is a tetrahedron.
  EXPECT_EQ(convex_hull(pts, {.max_vertices = 4}).mesh.n_vertices(), 4u);
}

TEST(ConvexHull, NonFinitePointsAndIllegalOptionsAreRefused) {
  std::vector<Vec3> pts = cube_corners();
  pts[5].y = std::numeric_limits<float>::quiet_NaN();
  try {
    convex_hull(pts);
    FAIL() << "a NaN was accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("point 5"), std::string::npos) << e.what();
  }
  pts[5].y = std::numeric_limits<float>::infinity();
  EXPECT_THROW(convex_hull(pts), InvalidInputError);
  const std::vector<Vec3> ok = cube_corners();
  EXPECT_THROW(convex_hull(ok, {.max_vertices = 3}), InvalidInputError);
  EXPECT_THROW(convex_hull(ok, {.relative_tolerance = -1}), InvalidInputError);
  EXPECT_THROW(convex_hull(ok, {.relative_tolerance = std::nan("")}), InvalidInputError);
  EXPECT_THROW(convex_hull(ok, {.flat_thickness = 0}), InvalidInputError);
}

}  // namespace
}  // namespace hedge

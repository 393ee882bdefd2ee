// FaceBvh queries against an independent brute force over every fan triangle of every live face
// (exact equality, ties included). Refit and update: locate_bvh_update_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "edits/random_edits.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "locate_reference.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace locate_test;

// ---- FaceBvh: closest point. ----

TEST(FaceBvh, ClosestPointOnUnitCubeIsTheClampedPoint) {
  const SurfaceMesh m = build(test::cube());
  const FaceBvh bvh(m);
  const FanTriangles fans(m);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.f, 2.f);
  int outside = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const auto r = bvh.closest_point(p);
    ASSERT_TRUE(r);
    expect_consistent(m, *r);
    const Vec3 clamped{std::clamp(p.x, 0.f, 1.f), std::clamp(p.y, 0.f, 1.f), std::clamp(p.z, 0.f, 1.f)};
    if (!(clamped == p)) {
      ++outside;
      const double want = dot(to_double(p - clamped), to_double(p - clamped));
      EXPECT_NEAR(r->squared_distance, want, 1e-12 + 1e-12 * want);
      EXPECT_NEAR(r->point.x, clamped.x, 1e-6);
      EXPECT_NEAR(r->point.y, clamped.y, 1e-6);
      EXPECT_NEAR(r->point.z, clamped.z, 1e-6);
    } else {
      const double d = std::min({p.x, p.y, p.z, 1 - p.x, 1 - p.y, 1 - p.z});
      EXPECT_NEAR(r->squared_distance, d * d, 1e-12);
    }
    expect_same_closest(m, p, r, brute_closest(fans, p));
  }
  EXPECT_GT(outside, 2000);
}

TEST(FaceBvh, ClosestPointOnTetrahedronMatchesBruteForce) {
  const SurfaceMesh m = build(test::tetrahedron());
  const FaceBvh bvh(m, {.max_leaf_size = 1});
  const FanTriangles fans(m);
  EXPECT_EQ(bvh.stats().leaves, 4u);
  for (const Vec3& p : query_points(m, 3000, 5))
    expect_same_closest(m, p, bvh.closest_point(p), brute_closest(fans, p));
  // A vertex is equally near to its three faces: the smallest face index wins.
  const auto r = bvh.closest_point({-1, -1, -1});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->face, Face(0));
  EXPECT_DOUBLE_EQ(r->squared_distance, 3.0);
}

struct MeshCase {
  const char* file;
  BvhSplit split;
};

class FaceBvhOnMesh : public ::testing::TestWithParam<MeshCase> {};

TEST_P(FaceBvhOnMesh, ClosestPointMatchesBruteForce) {
  const SurfaceMesh m = load(GetParam().file);
  const FaceBvh bvh(m, {.split = GetParam().split});
  const FanTriangles fans(m);
  EXPECT_EQ(bvh.stats().live_faces, m.n_faces());
  int i = 0;
  for (const Vec3& p : query_points(m, 2000, 21)) {
    const auto want = brute_closest(fans, p);
    expect_same_closest(m, p, bvh.closest_point(p), want);
    if (i++ % 4 == 0) expect_same_closest(m, p, closest_point_linear(m, p), want);
  }
}

TEST_P(FaceBvhOnMesh, FacesInBoxMatchBruteForce) {
  SurfaceMesh m = load(GetParam().file);
  FaceBvh bvh(m, {.split = GetParam().split});
  auto brute = [&](const Vec3& lo, const Vec3& hi) {
    std::vector<Face> want;
    for (Face f : m.faces()) {
      bool overlap = true;
      for (int a = 0; a < 3; ++a) {
        float flo = std::numeric_limits<float>::infinity(), fhi = -flo;
        for (Vertex v : m.vertices(f)) {
          flo = std::min(flo, m.position(v)[a]);
          fhi = std::max(fhi, m.position(v)[a]);
        }
        overlap = overlap && flo <= hi[a] && fhi >= lo[a];
      }
      if (overlap) want.push_back(f);
    }
    return want;
  };
  Vec3 root_lo, root_hi;
  ASSERT_TRUE(bvh.bounds(root_lo, root_hi));
  const Vec3 size = root_hi - root_lo;
  int nonempty = 0;
  for (const Vec3& p : query_points(m, 200, 5)) {
    const Vec3 half = size * 0.07f;
    std::vector<Face> got;
    bvh.faces_in_box(p - half, p + half, got);
    EXPECT_EQ(got, brute(p - half, p + half));
    nonempty += !got.empty();
  }
  EXPECT_GT(nonempty, 10);
  // After an edit through update(): removed faces are no longer found, new ones are.
  std::vector<Face> some;
  bvh.faces_in_box(root_lo, root_hi, some);
  EXPECT_EQ(some.size(), m.n_faces());
  split_face(m, some.front(), face_centroid(m, some.front()));
  bvh.update();
  some.clear();
  bvh.faces_in_box(root_lo, root_hi, some);
  EXPECT_EQ(some, brute(root_lo, root_hi));
  EXPECT_TRUE(m.validate().empty());
}

TEST_P(FaceBvhOnMesh, FirstHitMatchesBruteForce) {
  const SurfaceMesh m = load(GetParam().file);
  const FaceBvh bvh(m, {.split = GetParam().split});
  const FanTriangles fans(m);
  int hits = 0, misses = 0;
  int i = 0;
  for (const Ray& ray : query_rays(m, 2000, 31)) {
    const double t_max = (i++ % 5 == 0) ? 1.0 : kInf;
    const auto want = brute_first_hit(fans, ray.origin, ray.direction, t_max);
    expect_same_hit(m, bvh.first_hit(ray.origin, ray.direction, t_max), want);
    if (i % 4 == 0) expect_same_hit(m, first_hit_linear(m, ray.origin, ray.direction, t_max), want);
    (want ? hits : misses)++;
  }
  EXPECT_GT(hits, 400);
  EXPECT_GT(misses, 100);
}

TEST_P(FaceBvhOnMesh, FaceContainingMatchesBruteForce) {
  const SurfaceMesh m = load(GetParam().file);
  const FaceBvh bvh(m, {.split = GetParam().split});
  const FanTriangles fans(m);
  int found = 0;
  for (const Vec3& p3 : query_points(m, 600, 41)) {
    const Vec2 p{p3.x, p3.y};
    const auto want = brute_containing(fans, p);
    const auto got = bvh.face_containing(p);
    ASSERT_EQ(got.has_value(), want.has_value());
    if (!want) continue;
    ++found;
    EXPECT_EQ(got->face, want->face);
    EXPECT_EQ(got->corners, want->corners);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got->barycentric[k], want->barycentric[k], 1e-12);
    expect_consistent(m, *got);
    const auto linear = face_containing_linear(m, p);
    ASSERT_TRUE(linear);
    EXPECT_EQ(linear->face, got->face);
    EXPECT_EQ(linear->barycentric, got->barycentric);
  }
  EXPECT_GT(found, 100);
}

INSTANTIATE_TEST_SUITE_P(RealMeshes, FaceBvhOnMesh,
                         ::testing::Values(MeshCase{"anchor.off", BvhSplit::sah},
                                           MeshCase{"anchor.off", BvhSplit::median},
                                           MeshCase{"spot_triangulated.obj", BvhSplit::sah},
                                           MeshCase{"spot_control_mesh.obj", BvhSplit::sah},
                                           MeshCase{"fandisk_quads.off", BvhSplit::median},
                                           MeshCase{"three_peaks.off", BvhSplit::sah}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           return name + (info.param.split == BvhSplit::sah ? "_sah" : "_median");
                         });

// ---- FaceBvh: 2D plates and height fields. ----

TEST(FaceBvh, FaceContainingOnFlatPlate) {
  for (bool triangles : {true, false}) {
    const SurfaceMesh m = build(test::grid(10, triangles));
    const FaceBvh bvh(m);
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> u(0.02f, 0.98f);
    for (Face f : m.faces()) {
      const std::vector<Vertex> c = corners_of(m, f);
      for (int k = 0; k < 10; ++k) {
        // A point strictly inside the face: a convex combination with positive weights.
        float w[4] = {u(rng), u(rng), u(rng), u(rng)};
        float sum = 0;
        for (std::size_t i = 0; i < c.size(); ++i) sum += w[i];
        Vec3 p3{0, 0, 0};
        for (std::size_t i = 0; i < c.size(); ++i) p3 += m.position(c[i]) * (w[i] / sum);
        const Vec2 p{p3.x, p3.y};
        const auto r = bvh.face_containing(p);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->face, f);
        expect_consistent(m, *r);
        EXPECT_NEAR(r->point.x, p.x, 1e-5);
        EXPECT_NEAR(r->point.y, p.y, 1e-5);
        EXPECT_EQ(r->point.z, 0.f);
      }
    }
    // Outside the plate, including just outside its corners and edges.
    for (Vec2 p : {Vec2{-0.01f, 5}, Vec2{10.01f, 5}, Vec2{5, -0.001f}, Vec2{5, 10.5f}, Vec2{-1, -1},
                   Vec2{11, 11}, Vec2{1e30f, 0}})
      EXPECT_FALSE(bvh.face_containing(p)) << p.x << " " << p.y;
    // On the plate's boundary and on a shared edge: found, the smaller face index wins.
    EXPECT_TRUE(bvh.face_containing({0, 0}));
    EXPECT_TRUE(bvh.face_containing({10, 10}));
    const auto shared = bvh.face_containing({3, 4.5f});  // the edge x = 3 between two quads/triangles
    ASSERT_TRUE(shared);
    const auto want = brute_containing(FanTriangles(m), {3, 4.5f});
    EXPECT_EQ(shared->face, want->face);
  }
}

// three_peaks.off is a height field over the XZ plane (y up).
TEST(FaceBvh, FaceContainingSamplesATerrainLikeARayFromAbove) {
  const SurfaceMesh m = load("three_peaks.off");
  const FaceBvh bvh(m);
  const FanTriangles fans(m);
  const Bounds b = bounds(m);
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  int found = 0;
  for (int i = 0; i < 1500; ++i) {
    const Vec2 p{b.lo.x + u(rng) * (b.hi.x - b.lo.x), b.lo.z + u(rng) * (b.hi.z - b.lo.z)};
    const auto r = bvh.face_containing(p, ProjectionPlane::xz);
    const auto want = brute_containing(fans, p, ProjectionPlane::xz);
    ASSERT_EQ(r.has_value(), want.has_value());
    const auto hit = bvh.first_hit({p.x, b.hi.y + 1, p.y}, {0, -1, 0});
    ASSERT_EQ(r.has_value(), hit.has_value()) << p.x << " " << p.y;
    if (!r) continue;
    ++found;
    EXPECT_EQ(r->face, want->face);
    expect_consistent(m, *r);
    EXPECT_NEAR(r->point.x, p.x, 1e-5);
    EXPECT_NEAR(r->point.z, p.y, 1e-5);
    EXPECT_NEAR(r->point.y, hit->point.y, 1e-4);  // the height under p
    // In the XY plane the same terrain folds over itself: other answers, still the brute force's.
    const Vec2 q{r->point.x, r->point.y};
    const auto xy = bvh.face_containing(q);
    const auto xy_want = brute_containing(fans, q);
    ASSERT_EQ(xy.has_value(), xy_want.has_value());
    if (xy) EXPECT_EQ(xy->face, xy_want->face);
  }
  EXPECT_GT(found, 1000);
}

TEST(FaceBvh, FaceContainingInEachCoordinatePlane) {
  const IndexedMesh grid = test::grid(5, false);
  for (ProjectionPlane plane : {ProjectionPlane::xy, ProjectionPlane::xz, ProjectionPlane::yz}) {
    IndexedMesh in = grid;
    const auto [i, j] = kept(plane);
    for (Vec3& p : in.positions) {
      Vec3 q{7, 7, 7};  // the dropped coordinate: a plate away from the origin
      q[i] = p.x;
      q[j] = p.y;
      p = q;
    }
    const SurfaceMesh m = build(in);
    const FaceBvh bvh(m);
    const auto r = bvh.face_containing({2.5f, 3.5f}, plane);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->face, Face(3 * 5 + 2));  // row 3, column 2
    EXPECT_FLOAT_EQ(r->point[i], 2.5f);
    EXPECT_FLOAT_EQ(r->point[j], 3.5f);
    EXPECT_FALSE(bvh.face_containing({5.5f, 3.5f}, plane));
    // Seen along another axis the plate is edge-on and contains nothing.
    for (ProjectionPlane other : {ProjectionPlane::xy, ProjectionPlane::xz, ProjectionPlane::yz})
      if (other != plane) {
        EXPECT_FALSE(bvh.face_containing({7, 2.5f}, other));
        EXPECT_FALSE(face_containing_linear(m, {7, 2.5f}, other));
      }
  }
}

TEST(FaceBvh, FaceContainingIn3DWithinTolerance) {
  // A plate tilted by 30 degrees about the x axis and moved away from the origin.
  IndexedMesh in = test::grid(6, true);
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  for (Vec3& p : in.positions) p = Vec3{p.x + 3, c * p.y - s * p.z - 2, s * p.y + c * p.z + 1};
  const SurfaceMesh m = build(in);
  const FaceBvh bvh(m);
  const Vec3 normal{0, -s, c};
  std::mt19937 rng(19);
  std::uniform_real_distribution<float> u(0.05f, 5.95f);
  for (int i = 0; i < 500; ++i) {
    const float gx = u(rng), gy = u(rng);
    const Vec3 plate{gx + 3, c * gy - 2, s * gy + 1};
    const auto exact = bvh.face_containing(plate, 1e-4);
    ASSERT_TRUE(exact);
    const Vec3 off = plate + normal * 0.01f;
    const auto near = bvh.face_containing(off, 0.02);
    ASSERT_TRUE(near);
    EXPECT_EQ(near->face, exact->face);
    EXPECT_NEAR(std::sqrt(near->squared_distance), 0.01, 1e-4);
    EXPECT_FALSE(bvh.face_containing(off, 0.005));
  }
  EXPECT_FALSE(bvh.face_containing(Vec3{2, c * 3 - 2, s * 3 + 1}, 0.5));  // 1 beyond an edge, in the plane
  EXPECT_TRUE(bvh.face_containing(Vec3{2, c * 3 - 2, s * 3 + 1}, 1.01));
}

// ---- Degenerate input. ----

TEST(FaceBvh, NonFiniteQueriesAndEmptyMeshesFindNothing) {
  const SurfaceMesh m = build(test::tetrahedron());
  const FaceBvh bvh(m);
  const float inf = std::numeric_limits<float>::infinity();
  for (Vec3 p : {Vec3{kNaN, 0, 0}, Vec3{0, kNaN, 0}, Vec3{0, 0, inf}, Vec3{-inf, 0, 0}}) {
    EXPECT_FALSE(bvh.closest_point(p));
    EXPECT_FALSE(closest_point_linear(m, p));
    EXPECT_FALSE(bvh.face_containing(p, 1.0));
    EXPECT_FALSE(bvh.first_hit(p, {0, 0, 1}));
    EXPECT_FALSE(bvh.first_hit({0.1f, 0.1f, -1}, p));
    EXPECT_FALSE(first_hit_linear(m, p, {0, 0, 1}));
    EXPECT_FALSE(bvh.face_containing(Vec2{p.x, p.y + p.z}));
  }
  EXPECT_FALSE(bvh.first_hit({0.1f, 0.1f, -1}, {0, 0, 0}));  // no direction
  EXPECT_FALSE(bvh.first_hit({0.1f, 0.1f, -1}, {0, 0, 1}, std::nan("")));
  EXPECT_FALSE(bvh.first_hit({0.1f, 0.1f, -1}, {0, 0, 1}, -1.0));
  EXPECT_TRUE(bvh.first_hit({0.1f, 0.1f, -1}, {0, 0, 1}));
  EXPECT_FALSE(bvh.closest_point({0, 0, 0}, std::nan("")));
  EXPECT_FALSE(bvh.closest_point({5, 5, 5}, 1.0));  // nothing within the radius
  EXPECT_TRUE(bvh.closest_point({5, 5, 5}, 10.0));

  const FaceBvh none;
  EXPECT_TRUE(none.empty());
  EXPECT_FALSE(none.closest_point({0, 0, 0}));
  EXPECT_FALSE(none.first_hit({0, 0, 0}, {1, 0, 0}));
  EXPECT_FALSE(none.face_containing(Vec2{0, 0}));
  EXPECT_THROW(FaceBvh().update(std::vector<Face>{Face(0)}), InvalidInputError);

  const SurfaceMesh empty;
  FaceBvh on_empty(empty);
  EXPECT_TRUE(on_empty.empty());
  EXPECT_FALSE(on_empty.closest_point({0, 0, 0}));
  EXPECT_FALSE(closest_point_linear(empty, {0, 0, 0}));
  EXPECT_FALSE(on_empty.first_hit({0, 0, 0}, {1, 0, 0}));
  EXPECT_FALSE(on_empty.face_containing(Vec2{0, 0}));
  on_empty.refit();
  on_empty.update({}, {});
  EXPECT_FALSE(on_empty.closest_point({0, 0, 0}));

  EXPECT_THROW(FaceBvh(m, {.max_leaf_size = 0}), InvalidInputError);
  EXPECT_THROW(FaceBvh(m, {.rebuild_fraction = 0}), InvalidInputError);
}

}  // namespace
}  // namespace hedge

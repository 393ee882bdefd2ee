// Shared by the point location tests (tests/algorithms/locate_*_test.cpp): an independent
// reference (a brute force over every fan triangle of every live face, in the documented tie
// order), consistency checks, query generators, and a split made with the low-level API.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "hedge/algorithms/locate.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/triangulate.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge::locate_test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// ---- An independent reference: corners from the mesh's own circulator, fan triangles from the
// first corner (or from the corner fan_start() names where that fan folds), the public triangle
// primitives, and the documented tie order (smaller value, then smaller face index, then earlier
// fan triangle). ----

//! The face's corners from its fan's apex on.
inline std::vector<Vertex> corners_of(const SurfaceMesh& m, Face f) {
  std::vector<Vertex> c;
  for (Vertex v : m.vertices(f)) c.push_back(v);
  const Vertex apex = m.to_vertex(fan_start(m, f));
  std::rotate(c.begin(), std::find(c.begin(), c.end(), apex), c.end());
  return c;
}

// Every fan triangle of every live face, in face order. Rebuild after editing the mesh.
struct FanTriangles {
  explicit FanTriangles(const SurfaceMesh& mesh) : m(mesh) {
    for (Face f : m.faces()) {
      const std::vector<Vertex> c = corners_of(m, f);
      for (std::size_t i = 1; i + 1 < c.size(); ++i) tris.push_back({f, {c[0], c[i], c[i + 1]}});
    }
  }
  template <typename Fn>
  void for_each(Fn fn) const {
    for (const auto& [f, t] : tris) fn(f, t);
  }
  const SurfaceMesh& m;
  std::vector<std::pair<Face, std::array<Vertex, 3>>> tris;
};

inline std::optional<LocateResult> brute_closest(const FanTriangles& fans, const Vec3& p) {
  const SurfaceMesh& m = fans.m;
  std::optional<LocateResult> best;
  fans.for_each([&](Face f, const std::array<Vertex, 3>& t) {
    const TrianglePoint r =
        closest_point_on_triangle(p, m.position(t[0]), m.position(t[1]), m.position(t[2]));
    if (!best || r.squared_distance < best->squared_distance) {
      best = LocateResult{};
      best->face = f;
      best->corners = t;
      best->barycentric = r.barycentric;
      best->squared_distance = r.squared_distance;
    }
  });
  return best;
}

inline std::optional<RayHit> brute_first_hit(const FanTriangles& fans, const Vec3& o, const Vec3& d,
                                             double t_max) {
  const SurfaceMesh& m = fans.m;
  std::optional<RayHit> best;
  fans.for_each([&](Face f, const std::array<Vertex, 3>& t) {
    const auto h = intersect_ray_triangle(o, d, m.position(t[0]), m.position(t[1]), m.position(t[2]), t_max);
    if (h && (!best || h->t < best->t)) {
      best = RayHit{};
      best->face = f;
      best->corners = t;
      best->barycentric = h->barycentric;
      best->t = h->t;
    }
  });
  return best;
}

// The two coordinates a projection keeps.
inline std::array<int, 2> kept(ProjectionPlane plane) {
  switch (plane) {
    case ProjectionPlane::xy:
      return {0, 1};
    case ProjectionPlane::xz:
      return {0, 2};
    case ProjectionPlane::yz:
      return {1, 2};
  }
  return {0, 1};
}

// Point in the projection of a triangle, boundary included, in long double.
inline std::optional<std::array<double, 3>> brute_in_triangle_2d(const Vec2& p, const Vec3& a, const Vec3& b,
                                                                 const Vec3& c, ProjectionPlane plane) {
  const auto [i, j] = kept(plane);
  auto orient = [](long double ax, long double ay, long double bx, long double by, long double cx,
                   long double cy) { return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax); };
  const long double area = orient(a[i], a[j], b[i], b[j], c[i], c[j]);
  if (area == 0) return std::nullopt;
  const long double w[3] = {orient(p.x, p.y, b[i], b[j], c[i], c[j]),
                            orient(a[i], a[j], p.x, p.y, c[i], c[j]),
                            orient(a[i], a[j], b[i], b[j], p.x, p.y)};
  for (long double x : w)
    if ((area > 0 && x < 0) || (area < 0 && x > 0)) return std::nullopt;
  return std::array<double, 3>{double(w[0] / area), double(w[1] / area), double(w[2] / area)};
}

inline std::optional<SurfacePoint> brute_containing(const FanTriangles& fans, const Vec2& p,
                                                    ProjectionPlane plane = ProjectionPlane::xy) {
  const SurfaceMesh& m = fans.m;
  std::optional<SurfacePoint> best;
  fans.for_each([&](Face f, const std::array<Vertex, 3>& t) {
    if (best) return;  // faces come in index order: the first one found wins
    if (auto w = brute_in_triangle_2d(p, m.position(t[0]), m.position(t[1]), m.position(t[2]), plane)) {
      best = SurfacePoint{};
      best->face = f;
      best->corners = t;
      best->barycentric = *w;
    }
  });
  return best;
}

// ---- Checks. ----

inline Vec3 interpolate(const SurfaceMesh& m, const SurfacePoint& s) {
  Vec3d p{0, 0, 0};
  for (int i = 0; i < 3; ++i) p += to_double(m.position(s.corners[i])) * s.barycentric[i];
  return to_float(p);
}

// The answer is self-consistent: corners are a fan triangle of the face, the weights are convex and
// reproduce the point.
inline void expect_consistent(const SurfaceMesh& m, const SurfacePoint& s) {
  ASSERT_TRUE(s.face.is_valid());
  ASSERT_FALSE(m.is_deleted(s.face));
  const std::vector<Vertex> c = corners_of(m, s.face);
  EXPECT_EQ(s.corners[0], c[0]) << "fan triangles start at the fan's apex";
  for (Vertex v : s.corners) EXPECT_NE(std::find(c.begin(), c.end(), v), c.end());
  double sum = 0;
  for (double w : s.barycentric) {
    EXPECT_GE(w, -1e-12);
    EXPECT_LE(w, 1 + 1e-12);
    sum += w;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  const Vec3 q = interpolate(m, s);
  EXPECT_EQ(s.point, q);
}

inline void expect_same_closest(const SurfaceMesh& m, const Vec3& p, const std::optional<LocateResult>& got,
                                const std::optional<LocateResult>& want) {
  ASSERT_EQ(got.has_value(), want.has_value()) << p.x << " " << p.y << " " << p.z;
  if (!want) return;
  EXPECT_EQ(got->squared_distance, want->squared_distance) << p.x << " " << p.y << " " << p.z;
  EXPECT_EQ(got->face, want->face) << p.x << " " << p.y << " " << p.z;
  EXPECT_EQ(got->corners, want->corners);
  EXPECT_EQ(got->barycentric, want->barycentric);
  expect_consistent(m, *got);
}

inline void expect_same_hit(const SurfaceMesh& m, const std::optional<RayHit>& got,
                            const std::optional<RayHit>& want) {
  ASSERT_EQ(got.has_value(), want.has_value());
  if (!want) return;
  EXPECT_EQ(got->t, want->t);
  EXPECT_EQ(got->face, want->face);
  EXPECT_EQ(got->corners, want->corners);
  EXPECT_EQ(got->barycentric, want->barycentric);
  expect_consistent(m, *got);
}

struct Bounds {
  Vec3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  float diagonal() const { return norm(hi - lo); }
};

inline Bounds bounds(const SurfaceMesh& m) {
  Bounds b;
  for (Vertex v : m.vertices())
    for (int a = 0; a < 3; ++a) {
      b.lo[a] = std::min(b.lo[a], m.position(v)[a]);
      b.hi[a] = std::max(b.hi[a], m.position(v)[a]);
    }
  return b;
}

// Query points: uniform in the box grown by 20%, near the surface, and exactly on it (in float).
inline std::vector<Vec3> query_points(const SurfaceMesh& m, int n, unsigned seed) {
  std::mt19937 rng(seed);
  const Bounds b = bounds(m);
  const float d = b.diagonal();
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::normal_distribution<float> noise(0.f, 0.01f * d);
  std::vector<Face> faces(m.faces().begin(), m.faces().end());
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    if (i % 3 == 0) {
      Vec3 p;
      for (int a = 0; a < 3; ++a) p[a] = b.lo[a] - 0.2f * d + unit(rng) * (b.hi[a] - b.lo[a] + 0.4f * d);
      pts.push_back(p);
    } else {
      const Face f = faces[rng() % faces.size()];
      const std::vector<Vertex> c = corners_of(m, f);
      float u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      Vec3 p = m.position(c[0]) + (m.position(c[1]) - m.position(c[0])) * u +
               (m.position(c[2]) - m.position(c[0])) * v;
      if (i % 3 == 1) p += Vec3{noise(rng), noise(rng), noise(rng)};
      pts.push_back(p);
    }
  }
  return pts;
}

struct Ray {
  Vec3 origin, direction;
};

// Rays from outside the box toward random points of it (many hit, some miss), and from inside.
inline std::vector<Ray> query_rays(const SurfaceMesh& m, int n, unsigned seed) {
  std::mt19937 rng(seed);
  const Bounds b = bounds(m);
  const float d = b.diagonal();
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::normal_distribution<float> gauss(0.f, 1.f);
  std::vector<Vec3> targets = query_points(m, n, seed + 1);
  std::vector<Ray> rays;
  for (int i = 0; i < n; ++i) {
    Vec3 dir{gauss(rng), gauss(rng), gauss(rng)};
    dir = normalize(dir);
    if (i % 4 == 3) {
      rays.push_back({targets[i], dir});  // from on or near the surface, any direction
    } else {
      const Vec3 o = targets[i] - dir * (d * (0.6f + unit(rng)));
      rays.push_back({o, dir * (0.5f + 2 * unit(rng))});  // not unit length on purpose
    }
  }
  return rays;
}

inline SurfaceMesh load(const std::string& name) { return read_mesh(test::data_path(name)); }

// Splits triangle f at p into three triangles with the low-level API; f is reused for one of them.
inline std::array<Face, 3> split_triangle(SurfaceMesh& m, Face f, const Vec3& p) {
  const Halfedge h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
  const Vertex c0 = m.to_vertex(h0), c1 = m.to_vertex(h1), c2 = m.to_vertex(h2);
  const Vertex v = m.add_vertex(p);
  const Halfedge e0 = m.new_edge(v, c0), e1 = m.new_edge(v, c1), e2 = m.new_edge(v, c2);
  const Face f1 = m.new_face(), f2 = m.new_face();
  auto link = [&](Face face, Halfedge a, Halfedge b, Halfedge c) {
    m.set_next(a, b);
    m.set_next(b, c);
    m.set_next(c, a);
    for (Halfedge h : {a, b, c}) m.set_face(h, face);
    m.set_halfedge(face, a);
  };
  link(f, h1, SurfaceMesh::twin(e1), e0);   // c0 -> c1 -> v
  link(f1, h2, SurfaceMesh::twin(e2), e1);  // c1 -> c2 -> v
  link(f2, h0, SurfaceMesh::twin(e0), e2);  // c2 -> c0 -> v
  m.set_halfedge(v, e0);
  return {f, f1, f2};
}

inline Vec3 centroid(const SurfaceMesh& m, Face f) {
  Vec3 c{0, 0, 0};
  const std::vector<Vertex> v = corners_of(m, f);
  for (Vertex x : v) c += m.position(x);
  return c / float(v.size());
}

inline void expect_matches_brute_force(const SurfaceMesh& m, const FaceBvh& bvh, unsigned seed,
                                       int n = 1200) {
  const FanTriangles fans(m);
  for (const Vec3& p : query_points(m, n, seed))
    expect_same_closest(m, p, bvh.closest_point(p), brute_closest(fans, p));
  for (const Ray& ray : query_rays(m, n / 2, seed + 1))
    expect_same_hit(m, bvh.first_hit(ray.origin, ray.direction),
                    brute_first_hit(fans, ray.origin, ray.direction, kInf));
}

}  // namespace hedge::locate_test

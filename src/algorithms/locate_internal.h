// Internal to point location (src/algorithms/locate_*.cpp): the triangle code and the per-face
// searches shared by the linear scans and FaceBvh's queries, and FaceBvh's box.
//
// These are the inner loops of the queries, so they are defined here rather than behind a call
// into another file, and with internal linkage (an unnamed namespace): each file gets its own copy
// and the compiler inlines them as freely as when they were private to one file (with external
// linkage it must also keep a shared copy, and then it inlines less). The queries compile to the
// same machine code as before the split. [[maybe_unused]]: not every file uses every function.
//
// Exactness: the tree prunes a node only when its box is farther than the best answer so far by
// more than a small relative (and, for distances, absolute) slack. The slack covers the rounding of
// the box tests, so every face that could equal or beat the best answer is tested with the same
// double-precision triangle code as the linear scans, and the answers are identical.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "hedge/algorithms/locate.h"
#include "hedge/core/triangulate.h"

namespace hedge {
namespace locate_detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kInfF = std::numeric_limits<float>::infinity();
// Relative slack of the box tests (float boxes and slabs round to a few ulps, about 1e-7).
constexpr double kRelSlack = 1e-5;

}  // namespace
}  // namespace locate_detail

struct FaceBvh::Box {
  float lo[3] = {locate_detail::kInfF, locate_detail::kInfF, locate_detail::kInfF};
  float hi[3] = {-locate_detail::kInfF, -locate_detail::kInfF, -locate_detail::kInfF};

  void grow(const Vec3& p) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  void grow(const Box& b) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], b.lo[a]);
      hi[a] = std::max(hi[a], b.hi[a]);
    }
  }
  bool empty() const { return !(lo[0] <= hi[0]); }
  //! Half the surface area; 0 for an empty box.
  double half_area() const {
    if (empty()) return 0;
    double dx = double(hi[0]) - lo[0], dy = double(hi[1]) - lo[1], dz = double(hi[2]) - lo[2];
    return dx * dy + dy * dz + dz * dx;
  }
  Box merged(const Box& b) const {
    Box r = *this;
    r.grow(b);
    return r;
  }
};

namespace locate_detail {
namespace {

[[maybe_unused]] double sq(double x) { return x * x; }

//! Calls fn(c0, c[i], c[i+1]) for the fan triangles of f (from fan_start()) until fn returns true. Returns
//! whether it stopped. The walk is bounded by the number of half-edges, so a broken loop cannot hang it.
template <typename Fn>
bool for_each_fan(const SurfaceMesh& m, Face f, Fn&& fn) {
  Halfedge h0 = m.halfedge(f);
  if (!h0.is_valid() || !m.is_valid(h0)) return false;
  h0 = fan_start(m, f);  // from the first corner unless that fan folds (core/triangulate.h)
  const Vertex c0 = m.to_vertex(h0);
  Halfedge h = m.next(h0);
  if (!m.is_valid(h)) return false;
  Vertex b = m.to_vertex(h);
  std::size_t guard = m.halfedge_slots();
  for (h = m.next(h); m.is_valid(h) && h != h0 && guard-- > 0; h = m.next(h)) {
    const Vertex c = m.to_vertex(h);
    if (fn(c0, b, c)) return true;
    b = c;
  }
  return false;
}

struct SegmentPoint {
  double squared_distance;
  double u;  // the point is x + u (y - x)
};

[[maybe_unused]] SegmentPoint closest_on_segment(const Vec3d& p, const Vec3d& x, const Vec3d& y) {
  const Vec3d xy = y - x;
  const double len2 = dot(xy, xy);
  const double u = len2 > 0 ? std::clamp(dot(p - x, xy) / len2, 0.0, 1.0) : 0.0;
  const Vec3d pq = p - (x + xy * u);
  return {dot(pq, pq), u};
}

[[maybe_unused]] TrianglePoint closest_on_triangle(const Vec3d& p, const Vec3d& a, const Vec3d& b,
                                                   const Vec3d& c) {
  const Vec3d ab = b - a, ac = c - a, ap = p - a;
  const Vec3d n = cross(ab, ac);
  const double nn = dot(n, n);
  // Barycentric coordinates of p's projection onto the plane (p's normal component drops out).
  // For float corners the differences and products are nearly exact, so this holds for slivers too.
  bool edge_ab = true, edge_bc = true, edge_ca = true;
  if (nn > 0) {
    const double s = dot(cross(ap, ac), n) / nn;  // weight of b
    const double t = dot(cross(ab, ap), n) / nn;  // weight of c
    const double r = 1 - s - t;                   // weight of a
    if (s >= 0 && t >= 0 && r >= 0) return {sq(dot(ap, n)) / nn, {r, s, t}};
    // Outside, the nearest point lies on an edge the projection is beyond: one with a negative
    // opposite weight (two near a corner).
    edge_bc = r < 0;
    edge_ca = s < 0;
    edge_ab = t < 0;
    if (!(edge_ab || edge_bc || edge_ca)) edge_ab = edge_bc = edge_ca = true;  // NaN corners
  }
  TrianglePoint best{kInf, {}};
  if (edge_ab) {
    const SegmentPoint e = closest_on_segment(p, a, b);
    best = {e.squared_distance, {1 - e.u, e.u, 0}};
  }
  if (edge_bc) {
    const SegmentPoint e = closest_on_segment(p, b, c);
    if (e.squared_distance < best.squared_distance) best = {e.squared_distance, {0, 1 - e.u, e.u}};
  }
  if (edge_ca) {
    const SegmentPoint e = closest_on_segment(p, c, a);
    if (e.squared_distance < best.squared_distance) best = {e.squared_distance, {e.u, 0, 1 - e.u}};
  }
  return best;
}

// The searches' call, kept out of line as the compiler chose when point location was one file: the
// tree walk inlines the search around it, whose box test rejects most triangles before this test.
[[maybe_unused, gnu::noinline]] TrianglePoint closest_on_triangle_call(const Vec3d& p, const Vec3d& a,
                                                                       const Vec3d& b, const Vec3d& c) {
  return closest_on_triangle(p, a, b, c);
}

//! A ray prepared for the watertight test: the coordinate frame in which it runs along +z, and
//! float reciprocals for the slab tests against boxes.
struct PreparedRay {
  double o[3];
  int kx, ky, kz;
  double sx, sy, sz;
  float of[3];
  float inv[3];
  bool parallel[3];

  PreparedRay(const Vec3& origin, const Vec3& d) {
    kz = 0;
    for (int a = 1; a < 3; ++a)
      if (std::fabs(d[a]) > std::fabs(d[kz])) kz = a;
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);  // keeps the edge functions' winding
    sx = double(d[kx]) / d[kz];
    sy = double(d[ky]) / d[kz];
    sz = 1.0 / d[kz];
    for (int a = 0; a < 3; ++a) {
      o[a] = origin[a];
      of[a] = origin[a];
      inv[a] = 1.0f / d[a];
      // A zero (or subnormal) component: the slab of that axis either holds the whole ray or none
      // of it, decided by the origin alone (a reciprocal would give 0 * inf on the slab's face).
      parallel[a] = std::isinf(inv[a]);
    }
  }

  std::optional<TriangleHit> intersect(const Vec3& pa, const Vec3& pb, const Vec3& pc, double t_max) const {
    const double A[3] = {pa.x - o[0], pa.y - o[1], pa.z - o[2]};
    const double B[3] = {pb.x - o[0], pb.y - o[1], pb.z - o[2]};
    const double C[3] = {pc.x - o[0], pc.y - o[1], pc.z - o[2]};
    const double ax = A[kx] - sx * A[kz], ay = A[ky] - sy * A[kz];
    const double bx = B[kx] - sx * B[kz], by = B[ky] - sy * B[kz];
    const double cx = C[kx] - sx * C[kz], cy = C[ky] - sy * C[kz];
    // Edge functions; a shared edge gives exactly opposite values in its two triangles.
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return std::nullopt;
    const double det = u + v + w;
    if (det == 0) return std::nullopt;
    const double tn = u * (sz * A[kz]) + v * (sz * B[kz]) + w * (sz * C[kz]);
    const double t = tn / det;
    if (!(t >= 0) || t > t_max) return std::nullopt;
    return TriangleHit{t, {u / det, v / det, w / det}};
  }

  //! Entry parameter of the ray into a box, if it enters before `limit`.
  bool enters(const float* lo, const float* hi, double limit, float& t_near) const {
    if (!(lo[0] <= hi[0])) return false;  // empty box (only tombstones below)
    float near = 0, far = kInfF;
    for (int a = 0; a < 3; ++a) {
      if (parallel[a]) {
        if (of[a] < lo[a] || of[a] > hi[a]) return false;
        continue;
      }
      float t0 = (lo[a] - of[a]) * inv[a];
      float t1 = (hi[a] - of[a]) * inv[a];
      if (t0 > t1) std::swap(t0, t1);
      near = std::max(near, t0);
      far = std::min(far, t1);
    }
    // Each slab bound is off by a few ulps, so a ray grazing the box (a triangle's edge on the box's
    // face) may compute near a little past far.
    if (near - far > float(kRelSlack) * (std::fabs(near) + std::fabs(far))) return false;
    if (double(near) > limit) return false;
    t_near = near;
    return true;
  }
};

//! Twice the signed area of the 2D triangle (a, b, c). Differences of floats are exact in double
//! and so are their products, so the sign is exact for float input of similar magnitude.
[[maybe_unused]] double orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

[[maybe_unused]] Vec3 interpolate(const SurfaceMesh& m, const std::array<Vertex, 3>& c,
                                  const std::array<double, 3>& w) {
  Vec3d p{0, 0, 0};
  for (int i = 0; i < 3; ++i) p += to_double(m.position(c[i])) * w[i];
  return to_float(p);
}

// ---- Searches: one face's triangles at a time, shared by the tree and the linear scans. Each keeps
// the best answer under the documented order: better value, then smaller face index, then the
// earlier fan triangle. ----

//! The best triangle a search has found so far, and the answer it makes.
struct Found {
  Found(const SurfaceMesh& mesh, double bound) : m(mesh), best(bound) {}
  const SurfaceMesh& m;
  double best;  // the value to beat (or to equal, before anything is found)
  bool found = false;
  Face face;
  std::array<Vertex, 3> corners;
  std::array<double, 3> barycentric{};

  //! Keeps triangle (a, b, c) of face f if its value is better: smaller, or equal on a smaller face.
  void offer(Face f, Vertex a, Vertex b, Vertex c, double value, const std::array<double, 3>& w) {
    if (found ? (value < best || (value == best && f < face)) : value <= best) {
      best = value;
      found = true;
      face = f;
      corners = {a, b, c};
      barycentric = w;
    }
  }
  template <typename Result>
  std::optional<Result> report() const {
    if (!found) return std::nullopt;
    Result r;
    r.face = face;
    r.corners = corners;
    r.barycentric = barycentric;
    r.point = interpolate(m, corners, barycentric);
    return r;
  }
  //! The same, with `best` (a squared distance or a ray parameter) stored in r.*distance.
  template <typename Result>
  std::optional<Result> report(double Result::*distance) const {
    std::optional<Result> r = report<Result>();
    if (r) (*r).*distance = best;
    return r;
  }
};

struct ClosestSearch : Found {
  //! \param slack_sq if not negative, triangles whose box is farther than the best face by more than
  //!   this (and the relative slack) are passed over before the exact test, as in the tree.
  ClosestSearch(const SurfaceMesh& mesh, const Vec3d& point, double bound, double slack_sq = -1)
      : Found(mesh, bound), p(point), slack(slack_sq) {}
  Vec3d p;
  double slack;

  double limit() const { return best + best * kRelSlack + slack; }

  bool operator()(Face f, Vertex a, Vertex b, Vertex c) {
    const Vec3& pa = m.position(a);
    const Vec3& pb = m.position(b);
    const Vec3& pc = m.position(c);
    if (slack >= 0) {
      double d = 0;
      for (int i = 0; i < 3; ++i) {
        const double lo = std::min({pa[i], pb[i], pc[i]}), hi = std::max({pa[i], pb[i], pc[i]});
        d += p[i] < lo ? sq(lo - p[i]) : (p[i] > hi ? sq(p[i] - hi) : 0.0);
      }
      if (d > limit()) return false;
    }
    const TrianglePoint r = closest_on_triangle_call(p, to_double(pa), to_double(pb), to_double(pc));
    offer(f, a, b, c, r.squared_distance, r.barycentric);
    return false;
  }
  std::optional<LocateResult> result() const { return report(&LocateResult::squared_distance); }
};

struct RaySearch : Found {
  RaySearch(const SurfaceMesh& mesh, const PreparedRay& r, double t_max) : Found(mesh, t_max), ray(r) {}
  const PreparedRay& ray;

  bool operator()(Face f, Vertex a, Vertex b, Vertex c) {
    const std::optional<TriangleHit> h = ray.intersect(m.position(a), m.position(b), m.position(c), best);
    if (h) offer(f, a, b, c, h->t, h->barycentric);
    return false;
  }
  std::optional<RayHit> result() const { return report(&RayHit::t); }
};

struct ContainSearch : Found {
  ContainSearch(const SurfaceMesh& mesh, const Vec2& p, ProjectionPlane plane)
      : Found(mesh, 0),
        px(p.x),
        py(p.y),
        i(plane == ProjectionPlane::yz ? 1 : 0),
        j(plane == ProjectionPlane::xy ? 1 : 2) {}
  double px, py;
  int i, j;  // the coordinates kept by the projection

  //! Faces of larger index than the one found cannot win.
  bool skip(Face f) const { return found && f >= face; }
  bool box_contains(const float* lo, const float* hi) const {
    return lo[i] <= px && px <= hi[i] && lo[j] <= py && py <= hi[j];
  }
  bool operator()(Face f, Vertex a, Vertex b, Vertex c) {
    const Vec3& pa = m.position(a);
    const Vec3& pb = m.position(b);
    const Vec3& pc = m.position(c);
    const double area = orient2d(pa[i], pa[j], pb[i], pb[j], pc[i], pc[j]);
    if (area == 0 || std::isnan(area)) return false;
    const double wa = orient2d(px, py, pb[i], pb[j], pc[i], pc[j]);
    const double wb = orient2d(pa[i], pa[j], px, py, pc[i], pc[j]);
    const double wc = orient2d(pa[i], pa[j], pb[i], pb[j], px, py);
    const bool inside = area > 0 ? (wa >= 0 && wb >= 0 && wc >= 0) : (wa <= 0 && wb <= 0 && wc <= 0);
    if (!inside) return false;
    // Containment has no value to minimise: every face ties at 0 and the smallest index wins.
    offer(f, a, b, c, 0, {wa / area, wb / area, wc / area});
    return true;  // the first fan triangle of this face that contains p
  }
  std::optional<SurfacePoint> result() const { return report<SurfacePoint>(); }
};

[[maybe_unused]] bool valid_direction(const Vec3& d) {
  return is_finite(d) && (d.x != 0 || d.y != 0 || d.z != 0);
}

}  // namespace
}  // namespace locate_detail

template <typename Fn>
bool FaceBvh::for_each_triangle(const Entry& e, Fn&& fn) const {
  if (e.corner[0] != kInvalidIndex)
    return fn(Face(e.face), Vertex(e.corner[0]), Vertex(e.corner[1]), Vertex(e.corner[2]));
  const Face f(e.face);
  return locate_detail::for_each_fan(*mesh_, f, [&](Vertex a, Vertex b, Vertex c) { return fn(f, a, b, c); });
}

}  // namespace hedge

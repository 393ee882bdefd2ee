// Ear clipping in the polygon's Newell plane.
#include "hedge/core/triangulate.h"

#include <algorithm>
#include <cmath>

namespace hedge {

void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = p.size();
  Vec3d nrm{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d& a = p[i];
    const Vec3d& b = p[(i + 1) % n];
    add_newell_term(nrm, a, b);
  }
  // Project onto the plane: drop the dominant normal axis, keeping orientation.
  int ax = 0;
  if (std::abs(nrm.y) > std::abs(nrm[ax])) ax = 1;
  if (std::abs(nrm.z) > std::abs(nrm[ax])) ax = 2;
  const int u = (ax + 1) % 3, v = (ax + 2) % 3;
  const double sign = nrm[ax] < 0 ? -1.0 : 1.0;
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {p[i][u], sign * p[i][v]};
  auto cross2 = [&](Index a, Index b, Index c) {
    return (q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[a][0]);
  };
  std::vector<Index> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = static_cast<Index>(i);
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const Index a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
      if (cross2(a, b, c) <= 0) continue;  // reflex or flat corner
      bool inside = false;
      for (Index r : ring) {
        if (r == a || r == b || r == c) continue;
        if (cross2(a, b, r) >= 0 && cross2(b, c, r) >= 0 && cross2(c, a, r) >= 0) {
          inside = true;
          break;
        }
      }
      if (inside) continue;
      tris.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) tris.push_back({ring[0], ring[i], ring[i + 1]});
}

namespace {

//! The cosine of the angle between the normal of triangle (a, b, c) and the unit vector n; 0 for
//! a degenerate triangle.
double tilt(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& n) {
  const Vec3d t = cross(b - a, c - a);
  const double l = std::sqrt(dot(t, t));
  return l > 0 ? dot(t, n) / l : 0.0;
}

//! The smallest tilt() of the fan's triangles from corner k.
double worst_tilt(std::span<const Vec3d> p, std::size_t k, const Vec3d& n) {
  const std::size_t m = p.size();
  double worst = 2;
  for (std::size_t i = 1; i + 1 < m; ++i)
    worst = std::min(worst, tilt(p[k], p[(k + i) % m], p[(k + i + 1) % m], n));
  return worst;
}

// The most corners fan_apex() tries: each try costs the polygon's size, so trying every corner of a
// large polygon would cost n^2 (minutes for a face of 100,000 corners, a file of half a megabyte).
constexpr std::size_t kApexCandidates = 64;

}  // namespace

std::size_t fan_apex(std::span<const Vec3d> p) {
  const std::size_t n = p.size();
  if (n <= 3) return 0;
  Vec3d nrm{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) add_newell_term(nrm, p[i], p[(i + 1) % n]);
  const double len = std::sqrt(dot(nrm, nrm));
  if (!(len > 0)) return 0;
  nrm = nrm * (1 / len);
  bool folds = false;
  for (std::size_t i = 1; i + 1 < n && !folds; ++i) folds = dot(cross(p[i] - p[0], p[i + 1] - p[0]), nrm) < 0;
  if (!folds) return 0;
  std::size_t best = 0;
  double best_tilt = worst_tilt(p, 0, nrm);
  const std::size_t tries = std::min(n, kApexCandidates);
  for (std::size_t j = 1; j < tries; ++j) {
    const std::size_t k = j * n / tries;
    if (const double t = worst_tilt(p, k, nrm); t > best_tilt) {
      best_tilt = t;
      best = k;
    }
  }
  return best;
}

Halfedge fan_start(const SurfaceMesh& mesh, Face f) {
  const Halfedge h0 = mesh.halfedge(f);
  if (mesh.next(mesh.next(mesh.next(h0))) == h0) return h0;
  // Without allocating for the usual small polygons (the picking tree asks once per face visit).
  constexpr std::size_t kSmall = 16;
  std::array<Vec3d, kSmall> small;
  std::vector<Vec3d> large;
  std::size_t n = 0;
  for (Halfedge h : mesh.halfedges(f)) {
    const Vec3d x = to_double(mesh.position(mesh.to_vertex(h)));
    if (n < kSmall) small[n] = x;
    if (n == kSmall) large.assign(small.begin(), small.end());
    if (n >= kSmall) large.push_back(x);
    ++n;
  }
  const std::size_t k = n <= kSmall ? fan_apex(std::span<const Vec3d>(small.data(), n)) : fan_apex(large);
  Halfedge h = h0;
  for (std::size_t i = 0; i < k; ++i) h = mesh.next(h);
  return h;
}

}  // namespace hedge

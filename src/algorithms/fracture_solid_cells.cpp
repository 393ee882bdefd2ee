// Solid fracture: the break points, the region's planes and the cells (convex polytopes).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fracture_solid_internal.h"
#include "hedge/algorithms/geometry.h"

namespace hedge::solid_detail {

Key corner_key(std::uint32_t p, std::uint32_t q, std::uint32_t r) {
  std::array<std::uint32_t, 3> s{p, q, r};
  std::sort(s.begin(), s.end());
  return {Key::corner, s[0], s[1], s[2]};
}

void Polytope::box(double margin, float lo[3], float hi[3]) const {
  double l[3] = {1e300, 1e300, 1e300}, h[3] = {-1e300, -1e300, -1e300};
  for (const auto& [k, p] : points)
    for (int a = 0; a < 3; ++a) {
      l[a] = std::min(l[a], p[a]);
      h[a] = std::max(h[a], p[a]);
    }
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::nextafter(static_cast<float>(l[a] - margin), -1e30f);
    hi[a] = std::nextafter(static_cast<float>(h[a] + margin), 1e30f);
  }
}

std::uint32_t PlaneSet::bisector(std::uint32_t i, std::uint32_t j, const std::vector<Vec3d>& points) {
  if (i > j) std::swap(i, j);
  const auto [it, inserted] =
      bisector_of.emplace(std::make_pair(i, j), static_cast<std::uint32_t>(planes.size()));
  if (inserted) {
    const Vec3d n = points[j] - points[i];
    const Vec3d mid = (points[i] + points[j]) * 0.5;
    planes.push_back({n, -dot(n, mid)});
    pair_of.emplace_back(i, j);
  }
  return it->second;
}

void plane_frame(const Vec3d& n, Vec3d& u, Vec3d& v) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const Vec3d axis = ax <= ay && ax <= az ? Vec3d{1, 0, 0} : ay <= az ? Vec3d{0, 1, 0} : Vec3d{0, 0, 1};
  u = normalize(cross(n, axis));
  v = cross(n, u);
}

namespace {

//! The plane two adjacent corners of face `plane` share besides it; kNoPlane if none.
std::uint32_t shared_plane(const Key& a, const Key& b, std::uint32_t plane) {
  const std::array<std::uint32_t, 3> x{a.a, a.b, a.c}, y{b.a, b.b, b.c};
  for (std::uint32_t p : x)
    if (p != plane && std::find(y.begin(), y.end(), p) != y.end()) return p;
  return kNoPlane;
}

bool inside(const PlaneSet& planes, HalfSpace h, const Vec3d& x) {
  return planes.planes[h.plane].below(x) != h.flip;
}

}  // namespace

const Vec3d& Polytope::at(const Key& k) const {
  const auto it =
      std::lower_bound(points.begin(), points.end(), k,
                       [](const std::pair<Key, Vec3d>& x, const Key& key) { return x.first < key; });
  if (it == points.end() || it->first != k)
    throw std::out_of_range("solid fracture: a polytope lacks a corner");
  return it->second;
}

// Each face is clipped as a convex polygon (Sutherland-Hodgman); a new corner lies on the face's
// edge from a to b and the clipping plane, named by the three planes and placed by interpolation
// along the edge from its smaller key, so both faces of the edge place it alike. The new face's
// corners come from the cut edges: the face leaves the half-space at X and comes back at Y, so the
// new face (seen from outside) runs from Y to X. The polytope changes only once the clip has
// succeeded; its storage is reused (a strike clips some ten thousand times).
bool clip_polytope(Polytope& p, HalfSpace h, const PlaneSet& planes) {
  const Plane& pl = planes.planes[h.plane];
  // Scratch kept between calls: each point's side (by its slot in p.points) and whether a face
  // keeps it; the faces' new corners end to end (face f's from first[f] on); the new face's links
  // entry -> exit; the new points with the first position made for each.
  thread_local std::vector<char> in, kept;
  thread_local std::vector<std::size_t> slot;
  thread_local std::vector<Key> corners;
  thread_local std::vector<std::size_t> first;
  thread_local std::vector<std::pair<Key, Key>> next;
  thread_local std::vector<std::pair<Key, Vec3d>> made;
  bool any_out = false, any_in = false;
  in.resize(p.points.size());
  for (std::size_t i = 0; i < p.points.size(); ++i)
    ((in[i] = char(inside(planes, h, p.points[i].second))) ? any_in : any_out) = true;
  if (!any_out) return true;
  if (!any_in) {
    p.faces.clear();
    p.points.clear();
    return true;
  }
  kept.assign(p.points.size(), 0);
  corners.clear();
  first.clear();
  next.clear();
  made.clear();
  const auto slot_of = [&](const Key& k) {
    const auto it =
        std::lower_bound(p.points.begin(), p.points.end(), k,
                         [](const std::pair<Key, Vec3d>& x, const Key& key) { return x.first < key; });
    if (it == p.points.end() || it->first != k)
      throw std::out_of_range("solid fracture: a polytope lacks a corner");
    return static_cast<std::size_t>(it - p.points.begin());
  };
  for (const Polytope::Side& f : p.faces) {
    first.push_back(corners.size());
    const std::size_t n = f.corners.size();
    slot.resize(n);
    for (std::size_t i = 0; i < n; ++i) slot[i] = slot_of(f.corners[i]);
    Key exit_key{}, entry_key{};
    bool has_exit = false, has_entry = false;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t sa = slot[i], sb = slot[(i + 1) % n];
      const Key& a = f.corners[i];
      const Key& b = f.corners[(i + 1) % n];
      const Vec3d& pa = p.points[sa].second;
      const Vec3d& pb = p.points[sb].second;
      const bool ia = in[sa], ib = in[sb];
      if (ia) {
        corners.push_back(a);
        kept[sa] = 1;
      }
      if (ia != ib) {
        const std::uint32_t e = shared_plane(a, b, f.h.plane);
        if (e == kNoPlane) return false;
        const Key x = corner_key(f.h.plane, e, h.plane);
        const bool a_first = a < b;
        const Vec3d& p0 = a_first ? pa : pb;
        const Vec3d& p1 = a_first ? pb : pa;
        const double s0 = pl.value(p0), s1 = pl.value(p1);
        const double t = s0 == s1 ? 0.5 : std::clamp(s0 / (s0 - s1), 0.0, 1.0);
        made.emplace_back(x, p0 + (p1 - p0) * t);
        corners.push_back(x);
        if (ia) {
          exit_key = x;
          has_exit = true;
        } else {
          entry_key = x;
          has_entry = true;
        }
      }
    }
    if (has_exit != has_entry) return false;
    if (has_exit) {
      // One link per entry key: a later one replaces an earlier.
      bool found = false;
      for (auto& [from, to] : next)
        if (from == entry_key) {
          to = exit_key;
          found = true;
        }
      if (!found) next.emplace_back(entry_key, exit_key);
    }
  }
  first.push_back(corners.size());
  thread_local std::vector<Key> cap;
  cap.clear();
  if (!next.empty()) {
    std::sort(next.begin(), next.end());
    Key k = next.front().first;
    for (std::size_t guard = 0; guard <= next.size(); ++guard) {
      cap.push_back(k);
      const auto it = std::lower_bound(next.begin(), next.end(), std::make_pair(k, Key{}));
      if (it == next.end() || it->first != k) return false;
      k = it->second;
      if (k == cap.front()) break;
    }
    if (cap.size() != next.size()) return false;
  }
  // Commit: the faces that keep three corners or more, in order, then the new face.
  std::size_t live = 0;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    if (first[f + 1] - first[f] < 3) continue;
    Polytope::Side& to = p.faces[live++];
    if (&to != &p.faces[f]) to.h = p.faces[f].h;
    to.corners.assign(corners.begin() + static_cast<std::ptrdiff_t>(first[f]),
                      corners.begin() + static_cast<std::ptrdiff_t>(first[f + 1]));
  }
  p.faces.resize(live);
  if (cap.size() >= 3) p.faces.push_back({h, cap});
  // The points: the kept ones (in key order already) with their old positions, merged with the new
  // ones, each with the first position made for it; a kept key wins over a new one.
  std::stable_sort(made.begin(), made.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  made.erase(
      std::unique(made.begin(), made.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
      made.end());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.points.size(); ++i)
    if (kept[i]) p.points[k++] = p.points[i];
  p.points.resize(k);
  const std::size_t old = p.points.size();
  p.points.insert(p.points.end(), made.begin(), made.end());
  std::inplace_merge(p.points.begin(), p.points.begin() + static_cast<std::ptrdiff_t>(old), p.points.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
  p.points.erase(std::unique(p.points.begin(), p.points.end(),
                             [](const auto& x, const auto& y) { return x.first == y.first; }),
                 p.points.end());
  return true;
}

Polytope region_polytope(const Vec3d& centre, double radius, PlaneSet& planes, std::uint64_t seed,
                         double nudge) {
  SplitMix64 rng(seed ^ 0x5a17d0u);
  // 26 directions: the axes first (they make the starting cube), then the face and body diagonals.
  std::vector<Vec3d> dirs;
  for (int a = 0; a < 3; ++a)
    for (int s : {1, -1}) {
      Vec3d d{};
      d[a] = s;
      dirs.push_back(d);
    }
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (std::abs(x) + std::abs(y) + std::abs(z) >= 2)
          dirs.push_back(normalize(Vec3d{double(x), double(y), double(z)}));
  for (const Vec3d& d : dirs) {
    const double offset = radius + (nudge > 0 ? nudge * (rng.uniform() - 0.5) : 0.0);
    planes.planes.push_back({d, -dot(d, centre) - offset});
    planes.pair_of.emplace_back(-1, -1);
  }
  // The cube of the first six planes.
  Polytope p;
  for (int sx = 0; sx < 2; ++sx)
    for (int sy = 0; sy < 2; ++sy)
      for (int sz = 0; sz < 2; ++sz) {
        const Vec3d x = centre + Vec3d{sx ? -radius : radius, sy ? -radius : radius, sz ? -radius : radius};
        p.points.emplace_back(corner_key(std::uint32_t(sx), std::uint32_t(2 + sy), std::uint32_t(4 + sz)), x);
      }
  std::sort(p.points.begin(), p.points.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::uint32_t f = 0; f < 6; ++f) {
    const Vec3d n = planes.planes[f].n;
    Vec3d u, v;
    plane_frame(n, u, v);
    Polytope::Side side{{f, false}, {}};
    std::vector<std::pair<double, Key>> around;
    for (const auto& [k, x] : p.points)
      if (k.a == f || k.b == f || k.c == f) {
        const Vec3d d = x - centre;
        around.emplace_back(std::atan2(dot(d, v), dot(d, u)), k);
      }
    std::sort(around.begin(), around.end());
    for (const auto& [angle, k] : around) side.corners.push_back(k);
    p.faces.push_back(std::move(side));
  }
  for (std::uint32_t f = 6; f < planes.planes.size(); ++f) clip_polytope(p, {f, false}, planes);
  return p;
}

bool voronoi_cell(const Polytope& region, const std::vector<Vec3d>& points, std::uint32_t i, PlaneSet& planes,
                  Polytope& cell) {
  cell = region;
  std::vector<std::pair<double, std::uint32_t>> order;
  order.reserve(points.size());
  for (std::uint32_t j = 0; j < points.size(); ++j)
    if (j != i) order.emplace_back(dot(points[j] - points[i], points[j] - points[i]), j);
  std::sort(order.begin(), order.end());
  double reach = 0;  // squared distance from points[i] to the farthest corner
  for (const auto& [k, x] : cell.points) reach = std::max(reach, dot(x - points[i], x - points[i]));
  for (const auto& [d2, j] : order) {
    if (cell.empty()) break;
    if (d2 > 4 * reach) break;  // the bisector lies beyond every corner
    const std::uint32_t plane = planes.bisector(i, j, points);
    if (!clip_polytope(cell, {plane, i > j}, planes)) return false;
    reach = 0;
    for (const auto& [k, x] : cell.points) reach = std::max(reach, dot(x - points[i], x - points[i]));
  }
  return true;
}

std::vector<Vec3d> break_points(const FractureMaterial& material, const Vec3d& centre, std::uint64_t seed,
                                double nudge) {
  SplitMix64 rng(seed);
  std::vector<Vec3d> out;
  double ring_radius = 0;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (const FractureRing& ring : material.rings) {
    ring_radius += ring.spacing;
    // A seeded rotation of the ring's lattice: a random axis (uniform on the sphere) and angle.
    const double z0 = 2 * rng.uniform() - 1, phi0 = 2 * std::numbers::pi * rng.uniform();
    const double r0 = std::sqrt(std::max(0.0, 1 - z0 * z0));
    const Vec3d axis{r0 * std::cos(phi0), r0 * std::sin(phi0), z0};
    const double angle = 2 * std::numbers::pi * rng.uniform();
    const double c = std::cos(angle), s = std::sin(angle);
    const unsigned n = ring.points;
    for (unsigned k = 0; k < n; ++k) {
      const double jz = ring.jitter * (rng.uniform() - 0.5), jp = ring.jitter * (rng.uniform() - 0.5);
      const double jr = ring.jitter * (rng.uniform() - 0.5);
      const double z = std::clamp(1 - 2 * (k + 0.5 + jz) / n, -1.0, 1.0);
      const double rho = std::sqrt(std::max(0.0, 1 - z * z));
      const double phi = golden * k + jp * golden;
      const Vec3d d{rho * std::cos(phi), rho * std::sin(phi), z};
      // Rodrigues' rotation of d about the axis.
      const Vec3d rotated = d * c + cross(axis, d) * s + axis * (dot(axis, d) * (1 - c));
      const double r = std::max(0.0, ring_radius + ring.jitter * ring.spacing * jr);
      Vec3d x = centre + rotated * r;
      if (nudge > 0) x += Vec3d{rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5} * nudge;
      out.push_back(x);
    }
  }
  // Exact duplicates would share a cell: keep the first.
  std::vector<Vec3d> unique;
  std::vector<std::pair<std::array<double, 3>, std::size_t>> sorted;
  for (std::size_t i = 0; i < out.size(); ++i) sorted.push_back({{out[i].x, out[i].y, out[i].z}, i});
  std::sort(sorted.begin(), sorted.end());
  std::vector<bool> keep(out.size(), true);
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first) keep[sorted[i].second] = false;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (keep[i]) unique.push_back(out[i]);
  return unique;
}

}  // namespace hedge::solid_detail

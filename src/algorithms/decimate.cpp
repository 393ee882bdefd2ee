// Quadric-error decimation, as named steps: check the input; gather each vertex's quadric; then
// passes of rank (every live edge gets its best collapse and cost), sort (a radix sort on the
// costs' bits) and collapse (cheapest first, each vertex at most once per pass); finally collect
// the garbage. A pass does half of the collapses still needed (at least 1/32 of all). A vertex that
// survived a collapse is locked until the next pass, because the costs of its edges are stale; the
// costs of all other edges are still exact, since a collapse changes no other vertex's quadric, so
// the next pass re-ranks only the survivors' edges. Within kGreedyFrom times the target, the sorted
// keys become a lazy binary heap and the rest goes in true greedy order (collapse_greedy). A
// candidate is collapsed at the point its ranking found (kept per edge), not placed again.
// No allocation happens per collapse.
#include "hedge/algorithms/decimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "decimate_checks.h"
#include "decimate_corners.h"
#include "decimate_internal.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/core/edge_operations.h"
#include "hedge/error.h"

namespace hedge {

namespace {

using Mesh = SurfaceMesh;
using detail::decimation::bridge_distance2;
using detail::decimation::check_input;
using detail::decimation::kBridgeWeight;
using detail::decimation::kRemovedWeight;
using detail::decimation::prefetch;
using detail::decimation::Quadric;
using detail::decimation::removed_distance2;

// A collapse in a flat region (its error at most kFlat times its edge's squared length, a
// root-mean-square distance of 1/1000 of the edge) may not make a face whose quality,
// 4 sqrt(3) area / (sum of its squared edge lengths) (1 for an equilateral triangle, 0 for a
// degenerate one), is below kMinQuality, unless a face around the edge is already that bad and the
// worst new face is no worse than it. 0.1 is a needle with an angle of about 3.3 degrees. Where
// every collapse is free, the error cannot tell them apart and the shape decides; elsewhere the
// error alone does. When this check alone stops the decimation short of its target, it is lifted
// for the rest of the run.
constexpr double kMinQuality = 0.1, kFlat = 1e-6;

// Passes run while the mesh has more than kGreedyFrom times the target's vertices (or faces); then
// true greedy order (Decimator::collapse_greedy).
constexpr std::size_t kGreedyFrom = 3;

// The state of one decimation: per-vertex quadrics, pass stamps and flags, the candidates of the
// pass, and the scratch lists of one collapse, all allocated once.
class Decimator {
 public:
  Decimator(Mesh& m, const DecimateOptions& o)
      : m_(m),
        o_(o),
        pos_(m.positions().vector().data()),
        uv_(m.get_halfedge_property<Vec2>("h:texcoord")),
        crease_(m.get_edge_property<std::uint8_t>("e:crease")) {
    const double cos_max = std::cos(o.max_normal_change_degrees * std::numbers::pi / 180);
    min_cos_ = o.max_normal_change_degrees >= 180 ? -2.0 : cos_max;
    max_cost_ = std::isinf(o.max_error) ? std::numeric_limits<double>::infinity() : o.max_error * o.max_error;
    seams_ = uv_ && o.keep_seams;
  }

  DecimateResult run();

 private:
  // How many collapses are still needed to meet the targets (a large number when there is none).
  std::size_t needed() const {
    std::size_t n = 0;
    const bool any = o_.target_vertices > 0 || o_.target_faces > 0;
    if (!any) return std::numeric_limits<std::size_t>::max() / 4;
    if (o_.target_vertices > 0 && m_.n_vertices() > o_.target_vertices)
      n = m_.n_vertices() - o_.target_vertices;
    if (o_.target_faces > 0 && m_.n_faces() > o_.target_faces)
      n = std::max(n, (m_.n_faces() - o_.target_faces + 1) / 2);
    return n;
  }
  // Reports the share of the initially needed collapses done (with a target only).
  void report() const {
    if (o_.target_vertices == 0 && o_.target_faces == 0) return;
    report_progress(o_.progress, double(initial_ - std::min(initial_, needed())) / double(initial_));
  }
  // Passes and the greedy tail report after this many collapses (about 64 times in a run).
  std::size_t report_every() const { return std::max<std::size_t>(1, initial_ / 64); }
  bool done() const {
    const bool any = o_.target_vertices > 0 || o_.target_faces > 0;
    return any && (o_.target_vertices == 0 || m_.n_vertices() <= o_.target_vertices) &&
           (o_.target_faces == 0 || m_.n_faces() <= o_.target_faces);
  }

  Vec3d pos(Vertex v) const { return to_double(pos_[v.idx()]); }
  void gather_quadrics();
  void classify();
  bool seam(Edge e) const;
  bool removable(Vertex v, bool seam_edge) const;
  bool fixed(Vertex v) const;
  // The best collapse of e: the half-edge to collapse, the surviving point, its cost. False if e
  // may not collapse either way. `placed`: p is the point placement(h) gives.
  bool best_collapse(Edge e, Halfedge& h, Vec3d& p, double& cost, bool& placed) const;
  bool placement(Halfedge h, Vec3d& p, double& cost) const;
  // placement(h) for a candidate: the point its edge's last ranking kept, if any, with its cost.
  void placed(Halfedge h, Vec3d& p, double& cost) const;
  double cost_at(Halfedge h, const Quadric& q, const Vec3d& p) const;
  double bridged(Halfedge h, const Vec3d& p, double cost) const;
  enum class Check { ok, normal, shape };
  Check check_faces(Halfedge h, const Vec3d& p, bool shape) const;
  // The key of e's best collapse: (cost's float bits << 32) | half-edge, kOverError or kNoKey.
  // Keeps the surviving point in point_ for placed().
  std::uint64_t rank(Edge e);
  Check check(Halfedge h, const Vec3d& p, double cost, bool shapely) const;
  bool apply(Halfedge h, const Vec3d& p, double cost, DecimateResult& result, double& max_cost);
  // Collapses done and refused by the face checks in one pass or in the greedy tail.
  struct Tally {
    std::size_t done = 0, refused_shape = 0, refused_normal = 0;
  };
  Tally collapse_pass(std::uint32_t pass, std::size_t budget, bool shapely, DecimateResult& result,
                      double& max_cost, bool& over_error);
  Tally collapse_greedy(bool shapely, DecimateResult& result, double& max_cost, bool& over_error);
  // Within kGreedyFrom times every target: the rest is done in true greedy order.
  bool near_target() const {
    const bool any = o_.target_vertices > 0 || o_.target_faces > 0;
    return any && (o_.target_vertices == 0 || m_.n_vertices() <= kGreedyFrom * o_.target_vertices) &&
           (o_.target_faces == 0 || m_.n_faces() <= kGreedyFrom * o_.target_faces);
  }

  Mesh& m_;
  const DecimateOptions& o_;
  Vec3* pos_;
  HalfedgeProperty<Vec2> uv_;
  EdgeProperty<std::uint8_t> crease_;
  bool seams_ = false;
  bool tail_ = false;  // near the target: the removed positions' distance counts
  double min_cos_ = 0, max_cost_ = 0, tiny_area2_ = 0;
  std::size_t initial_ = 0;  // collapses needed at the start

  std::vector<Quadric> q_;
  // Each face's unit normal in the input: small steps must not add up to a face turned over.
  std::vector<Vec3> input_normal_;
  std::vector<std::uint32_t> stamp_;      // pass in which the vertex survived a collapse
  std::vector<std::uint8_t> seam_count_;  // seam edges at the vertex, saturated at 3
  // Candidates: (cost bits << 32) | half-edge, per edge (kept between passes) and of this pass.
  static constexpr std::uint64_t kNoKey = ~std::uint64_t(0);
  // An edge whose best collapse exceeds max_error (sorts last; never pushed as a candidate).
  static constexpr std::uint64_t kOverError = kNoKey - 1;
  std::vector<std::uint64_t> edge_key_, keys_, scratch_;
  // Per edge, the surviving point of its key's collapse as rank() found it (NaN: place again). Both
  // ends are unchanged while the key is current, so placing again would give the same point. Kept
  // in float: placement() returns it rounded to float (rounded_to_float), so nothing is lost.
  std::vector<Vec3> point_;
  std::vector<std::uint8_t> refused_;  // greedy tail: the edge's key was refused by a check
  // Greedy tail: the cost with bridged() of the edge's current key, when bridged() raised it (NaN:
  // not known). Cleared wherever the faces around either end may have changed.
  std::vector<double> full_;
  detail::decimation::CornerRing ring_;  // one collapse's corners (decimate_corners.h)
};

void Decimator::gather_quadrics() {
  q_.assign(m_.vertex_slots(), Quadric{});
  input_normal_.assign(m_.face_slots(), Vec3{0, 0, 0});
  const double feature_cos =
      o_.feature_angle_degrees >= 180 ? -2.0 : std::cos(o_.feature_angle_degrees * std::numbers::pi / 180);
  const double wa2 = o_.attribute_weight * o_.attribute_weight;
  const BoundingBox box = bounding_box(m_);
  const Vec3d extent = to_double(box.max) - to_double(box.min);
  const double diag2 = dot(extent, extent);
  // A face whose doubled area is below 1e-12 of the squared bounding-box diagonal counts as
  // degenerate: a collapse may not make one.
  tiny_area2_ = 1e-24 * diag2 * diag2;

  for (Face f : m_.faces()) {
    const Halfedge h0 = m_.halfedge(f), h1 = m_.next(h0), h2 = m_.next(h1);
    const Vertex v[3] = {m_.to_vertex(h2), m_.to_vertex(h0), m_.to_vertex(h1)};
    const Vec3d x0 = pos(v[0]), x1 = pos(v[1]), x2 = pos(v[2]);
    const Vec3d n = cross(x1 - x0, x2 - x0);
    const double len = norm(n);
    if (!(len > 0)) continue;
    const Vec3d u = n / len;
    input_normal_[f.idx()] = to_float(u);
    Quadric face;
    const double area = len / 2;
    face.add_plane(u, -dot(u, x0), area);
    face.w = area;
    for (const Vertex c : v) q_[c.idx()].add(face);
    if (wa2 > 0 && uv_) {
      // The texture map of the face is linear: uv(x) = G x + d. A corner that keeps its value
      // while its vertex moves to p is off by G p + d - uv; that costs wa2 x area x its square.
      const Vec2 s[3] = {uv_[h2], uv_[h0], uv_[h1]};
      const Vec3d e1 = x1 - x0, e2 = x2 - x0;
      const Vec3d g1 = cross(e2, n) / (len * len), g2 = cross(n, e1) / (len * len);
      for (int k = 0; k < 2; ++k) {
        const double s0 = s[0][k], s1 = s[1][k], s2 = s[2][k];
        const Vec3d g = g1 * (s1 - s0) + g2 * (s2 - s0);
        const double d = s0 - dot(g, x0);
        for (int i = 0; i < 3; ++i) q_[v[i].idx()].add_plane(g, d - double(s[i][k]), wa2 * area);
      }
    }
  }
  // Planes through boundary and feature edges, perpendicular to their faces, keep those edges
  // where they are; scaled by the squared length, like a face's area.
  const bool features = o_.feature_weight > 0 && (feature_cos > -2.0 || crease_);
  if (!(o_.boundary_weight > 0) && !features) return;
  for (Edge e : m_.edges()) {
    const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
    const Face f0 = m_.face(h), f1 = m_.face(t);
    const bool boundary = !f0.is_valid() || !f1.is_valid();
    if (boundary ? !(o_.boundary_weight > 0) : !features) continue;
    auto normal_of = [&](Face f) { return to_double(input_normal_[f.idx()]); };
    if (!boundary && !(crease_ && crease_[e] != 0) && !(dot(normal_of(f0), normal_of(f1)) < feature_cos))
      continue;
    const Vertex a = m_.from_vertex(h), b = m_.to_vertex(h);
    const Vec3d xa = pos(a), dir = pos(b) - xa;
    const double len2 = dot(dir, dir);
    auto constrain = [&](Face f, double weight) {
      const Vec3d n = cross(dir, normal_of(f));
      const double l = norm(n);
      if (!(l > 0)) return;
      const Vec3d u = n / l;
      Quadric plane;
      plane.add_plane(u, -dot(u, xa), weight * len2);
      plane.w = weight * len2;
      q_[a.idx()].add(plane);
      q_[b.idx()].add(plane);
    };
    if (boundary) {
      constrain(f0.is_valid() ? f0 : f1, o_.boundary_weight);
    } else {
      constrain(f0, o_.feature_weight);
      constrain(f1, o_.feature_weight);
    }
  }
}

bool Decimator::seam(Edge e) const { return detail::decimation::is_seam(m_, uv_, e); }

void Decimator::classify() {
  if (!seams_) return;
  seam_count_.assign(m_.vertex_slots(), 0);
  for (Edge e : m_.edges()) {
    if (!seam(e)) continue;
    for (const Vertex v : m_.vertices(e))
      seam_count_[v.idx()] = std::uint8_t(std::min(3, seam_count_[v.idx()] + 1));
  }
}

// May v be merged away over an edge (a seam edge or not)? A boundary vertex is kept with
// keep_boundary; a seam vertex only along its seam, where it has exactly two seam edges.
bool Decimator::removable(Vertex v, bool seam_edge) const {
  if (o_.keep_boundary && m_.is_boundary(v)) return false;
  if (!seams_) return true;
  const int s = seam_count_[v.idx()];
  return s == 0 || (s == 2 && seam_edge);
}

// Must v stay where it is if it survives?
bool Decimator::fixed(Vertex v) const {
  return (o_.keep_boundary && m_.is_boundary(v)) || (seams_ && seam_count_[v.idx()] > 0);
}

// The surviving point of collapsing h and its cost: to_vertex(h)'s position if it must stay,
// else the quadric's minimiser if it is well defined, within an edge length of the midpoint and
// clearly better than the best of the two ends and the midpoint, else that best (the midpoint
// only if clearly better than the ends). "Clearly": an end that is already exact (a mesh refined
// without moving, a flat region) keeps its position bit for bit instead of moving to a point that
// differs from it only by rounding.
bool Decimator::placement(Halfedge h, Vec3d& p, double& cost) const {
  const Vertex a = m_.from_vertex(h), b = m_.to_vertex(h);
  const Quadric q = sum(q_[a.idx()], q_[b.idx()]);
  const Vec3d xa = pos(a), xb = pos(b);
  p = xb;
  if (!fixed(b)) {
    const Vec3d mid = (xa + xb) * 0.5, ab = xb - xa;
    // Each further candidate must beat the best so far clearly, so that rounding never moves a
    // point off an exact end: the ends first, then the midpoint, then the minimiser.
    const double clearly = 1e-10 * dot(ab, ab);
    double best = error_at(q, xb);
    if (const double ea = error_at(q, xa); ea < best - clearly) p = xa, best = ea;
    if (const double em = error_at(q, mid); em < best - clearly) p = mid, best = em;
    Vec3d opt;
    if (q.minimiser(mid, dot(ab, ab), opt) && error_at(q, opt) < best - clearly) p = opt;
  }
  // The cost and the checks see the point as it will be stored.
  p = rounded_to_float(p);
  cost = cost_at(h, q, p);
  return true;
}

bool Decimator::best_collapse(Edge e, Halfedge& h, Vec3d& p, double& cost, bool& placed) const {
  const Halfedge h0 = Mesh::halfedge(e, 0), h1 = Mesh::twin(h0);
  const bool s = seams_ && seam(e);
  const bool go0 = removable(m_.from_vertex(h0), s), go1 = removable(m_.from_vertex(h1), s);
  if (!go0 && !go1) return false;
  if (go0 && go1) {
    // Both ways: if one end must stay, collapse into it; else the point is the same either way,
    // and the end it lands on (if it is one) survives, keeping its own properties.
    const bool f0 = fixed(m_.to_vertex(h0)), f1 = fixed(m_.to_vertex(h1));
    if (f0 != f1) {
      h = f0 ? h0 : h1;
      placed = true;
      return placement(h, p, cost);
    }
    Vec3d p0, p1;
    double c0, c1;
    placement(h0, p0, c0);
    if (!f0) {
      h = p0 == pos(m_.to_vertex(h1)) ? h1 : h0;
      p = p0, cost = c0;
      // Placing h1 need not give p0 back (the ends are tried in the other order).
      placed = h == h0;
      return true;
    }
    placement(h1, p1, c1);
    placed = true;
    if (c1 < c0)
      h = h1, p = p1, cost = c1;
    else
      h = h0, p = p0, cost = c0;
    return true;
  }
  h = go0 ? h0 : h1;
  placed = true;
  return placement(h, p, cost);
}

// No face around either end of h (other than the faces on h, which vanish) may turn by more than
// the allowed angle or lose its area when the survivor moves to p; with `shape`, none may become a
// sliver (quality below kMinQuality) unless one of them already was one at least as bad.
Decimator::Check Decimator::check_faces(Halfedge h, const Vec3d& p, bool shape) const {
  const Face fl = m_.face(h), fr = m_.face(Mesh::twin(h));
  // Squared qualities (see kMinQuality): 12 |n|^2 / (sum of squared edges)^2.
  double worst_old = kMinQuality * kMinQuality, worst_new = worst_old;
  auto quality2 = [](const Vec3d& n, const Vec3d& u, const Vec3d& v, const Vec3d& w) {
    const double s = dot(u, u) + dot(v, v) + dot(w, w);
    return s > 0 ? 12 * dot(n, n) / (s * s) : 0.0;
  };
  for (const Halfedge start : {h, Mesh::twin(h)}) {
    const Vec3d x = pos(m_.from_vertex(start));
    Halfedge o = start;
    do {
      const Face f = m_.face(o);
      if (f.is_valid() && f != fl && f != fr) {
        const Halfedge on = m_.next(o);
        const Vec3d b = pos(m_.to_vertex(o)), c = pos(m_.to_vertex(on));
        const Vec3d n0 = cross(b - x, c - x), n1 = cross(b - p, c - p);
        const double l1 = dot(n1, n1);
        if (!(l1 > tiny_area2_)) return Check::normal;
        const double d = dot(n0, n1), l0 = dot(n0, n0);
        if (l0 > 0 && d < min_cos_ * std::sqrt(l0 * l1)) return Check::normal;
        if (dot(n1, to_double(input_normal_[f.idx()])) < 0) return Check::normal;
        if (shape) {
          worst_old = std::min(worst_old, quality2(n0, b - x, c - x, c - b));
          worst_new = std::min(worst_new, quality2(n1, b - p, c - p, c - b));
        }
      }
      o = m_.rotate_cw(o);
    } while (o != start);
  }
  return worst_new < worst_old ? Check::shape : Check::ok;
}

std::uint64_t Decimator::rank(Edge e) {
  Halfedge h;
  Vec3d p;
  double cost;
  bool kept;
  if (!best_collapse(e, h, p, cost, kept)) return kNoKey;
  if (!(cost <= max_cost_)) return kOverError;
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  point_[e.idx()] = kept ? to_float(p) : Vec3{nan, nan, nan};
  return std::uint64_t(float_bits(static_cast<float>(cost))) << 32 | h.idx();
}

// placement() takes the cost at the point it returns, so the kept point and the cost of the same
// quadric at it are what placing again would give, bit for bit.
void Decimator::placed(Halfedge h, Vec3d& p, double& cost) const {
  const Vec3 kept = point_[Mesh::edge(h).idx()];
  if (std::isnan(kept.x)) {
    placement(h, p, cost);
    return;
  }
  p = to_double(kept);
  cost = cost_at(h, sum(q_[m_.from_vertex(h).idx()], q_[m_.to_vertex(h).idx()]), p);
}

// The cost of collapsing h to p with the ends' summed quadric q: its error at p, and near the target
// at least the weighted squared distance of the removed positions to the new faces. The distance
// counts only where it exceeds the quadric's error: the search may stop below that.
double Decimator::cost_at(Halfedge h, const Quadric& q, const Vec3d& p) const {
  const double e = error_at(q, p);
  if (!tail_) return e;
  return std::max(e, kRemovedWeight * removed_distance2(m_, h, p, e / kRemovedWeight));
}

// The cost of collapsing h to p near the target once the candidate is taken: at least the weighted
// squared distance of the new faces from the old ones (only where it exceeds `cost`).
double Decimator::bridged(Halfedge h, const Vec3d& p, double cost) const {
  return std::max(cost, kBridgeWeight * bridge_distance2(m_, h, p, cost / kBridgeWeight));
}

Decimator::Check Decimator::check(Halfedge h, const Vec3d& p, double cost, bool shapely) const {
  const Vec3d ab = pos(m_.to_vertex(h)) - pos(m_.from_vertex(h));
  return check_faces(h, p, shapely && cost <= kFlat * dot(ab, ab));
}

// Collapses h, moving the survivor to p; false (and nothing changed) if can_collapse() refuses.
bool Decimator::apply(Halfedge h, const Vec3d& p, double cost, DecimateResult& result, double& max_cost) {
  const Vertex a = m_.from_vertex(h), b = m_.to_vertex(h);
  if (uv_) ring_.gather(m_, uv_, h);
  if (!collapse(m_, h).is_valid()) {
    ++result.refused.topology;
    return false;
  }
  pos_[b.idx()] = to_float(p);
  q_[b.idx()].add(q_[a.idx()]);
  if (uv_) ring_.interpolate(m_, uv_, b, p);
  max_cost = std::max(max_cost, cost);
  ++result.collapses;
  return true;
}

// One pass over the sorted candidates: cheapest first, at most `budget` collapses, each vertex
// once (a survivor is stamped with the pass: its edges' costs are stale until the next rank).
Decimator::Tally Decimator::collapse_pass(std::uint32_t pass, std::size_t budget, bool shapely,
                                          DecimateResult& result, double& max_cost, bool& over_error) {
  Tally t;
  const std::size_t n_keys = keys_.size();
  // Nor beyond 16x the cost of the budget-th cheapest candidate (4 more in a float's exponent bits),
  // unless nothing was done yet: when locked vertices skip cheap candidates, the pass ends rather
  // than reach for dearer ones the next pass may not need (a refined flat region collapses back
  // exactly this way). A shape refusal moves the limit on by one: it waits for no locked vertex,
  // and in a flat region (every cost 0) the limit would end the pass at its first refusals.
  std::size_t limit_index = std::min(budget, n_keys) - 1;
  std::uint64_t cost_limit = n_keys == 0 ? 0 : (keys_[limit_index] >> 32) + (4u << 23);
  const Vertex* to = m_.halfedge_vertex_array().data();
  for (std::size_t k = 0; k < n_keys; ++k) {
    // The keys come in cost order, so every candidate's data is cold: fetch the half-edges of the
    // 16th next candidate, and the vertex data of the 8th next (whose half-edges arrived by now).
    if (k + 16 < n_keys) {
      const std::uint32_t h16 = std::uint32_t(keys_[k + 16]);
      prefetch(to + h16);
      prefetch(m_.halfedge_next_array().data() + h16);
    }
    if (k + 8 < n_keys) {
      const std::uint32_t h8 = std::uint32_t(keys_[k + 8]);
      prefetch(point_.data() + (h8 >> 1));
      for (const Vertex v : {to[h8], to[h8 ^ 1u]}) {
        prefetch(pos_ + v.idx());
        prefetch(q_.data() + v.idx());
        prefetch(reinterpret_cast<const char*>(q_.data() + v.idx()) + 64);  // a quadric spans two lines
        prefetch(stamp_.data() + v.idx());
      }
    }
    if ((keys_[k] >> 32) > cost_limit && t.done > 0) break;
    const Halfedge h(static_cast<Index>(keys_[k] & 0xffffffffu));
    if (m_.is_deleted(h)) continue;
    const Vertex a = m_.from_vertex(h), b = m_.to_vertex(h);
    if (stamp_[a.idx()] == pass || stamp_[b.idx()] == pass) continue;
    Vec3d p;
    double cost;
    placed(h, p, cost);
    if (!(cost <= max_cost_)) {
      over_error = true;
      continue;
    }
    if (const Check c = check(h, p, cost, shapely); c != Check::ok) {
      ++(c == Check::normal ? result.refused.normal : result.refused.shape);
      t.refused_shape += c == Check::shape;
      if (c == Check::shape && limit_index + 1 < n_keys)
        cost_limit = (keys_[++limit_index] >> 32) + (4u << 23);
      t.refused_normal += c == Check::normal;
      continue;
    }
    if (!apply(h, p, cost, result, max_cost)) continue;
    stamp_[b.idx()] = pass;
    if (++t.done % report_every() == 0) report();
    if (done() || t.done >= budget) break;
  }
  return t;
}

// The greedy tail: the sorted candidates are a binary min-heap; each step takes the cheapest, and
// after a collapse re-ranks the edges around the survivor (only their costs changed) and offers
// again the refused edges around its neighbours (whose faces changed). An entry whose key is no
// longer its edge's is stale and skipped (a lazy heap), so nothing is allocated per collapse
// beyond the heap's growth.
Decimator::Tally Decimator::collapse_greedy(bool shapely, DecimateResult& result, double& max_cost,
                                            bool& over_error) {
  Tally t;
  refused_.assign(m_.edge_slots(), 0);
  full_.assign(m_.edge_slots(), std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint64_t>& heap = keys_;  // sorted ascending, so already a min-heap
  const std::greater<std::uint64_t> later;
  auto offer = [&](std::uint64_t key) {
    heap.push_back(key);
    std::push_heap(heap.begin(), heap.end(), later);
  };
  while (!heap.empty() && !done()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const std::uint64_t key = heap.back();
    heap.pop_back();
    const Halfedge h(static_cast<Index>(key & 0xffffffffu));
    const Index e = Mesh::edge(h).idx();
    if (m_.is_deleted(h) || edge_key_[e] != key || refused_[e]) continue;
    Vec3d p;
    double cost;
    placed(h, p, cost);
    // The key ranked without the new faces' distance from the old ones (bridged()), a lower bound:
    // if that distance raises the cost, the candidate goes back into the heap at its full cost.
    // Taken again at that cost with nothing around it changed, it costs what bridged() gave.
    if (!std::isnan(full_[e])) {
      cost = full_[e];
    } else if (const double full = bridged(h, p, cost); static_cast<float>(full) > static_cast<float>(cost)) {
      const std::uint64_t k = full <= max_cost_
                                  ? std::uint64_t(float_bits(static_cast<float>(full))) << 32 | h.idx()
                                  : kOverError;
      if (k != key) {
        edge_key_[e] = k;
        full_[e] = full;
        if (k == kOverError)
          over_error = true;
        else
          offer(k);
        continue;
      }
      cost = full;
    }
    if (const Check c = check(h, p, cost, shapely); c != Check::ok) {
      ++(c == Check::normal ? result.refused.normal : result.refused.shape);
      t.refused_shape += c == Check::shape;
      t.refused_normal += c == Check::normal;
      refused_[e] = 1;
      continue;
    }
    const Vertex b = m_.to_vertex(h);
    if (!apply(h, p, cost, result, max_cost)) {
      refused_[e] = 1;
      continue;
    }
    if (++t.done % report_every() == 0) report();
    const Halfedge start = m_.halfedge(b);
    Halfedge o = start;
    do {
      const Index s = Mesh::edge(o).idx();
      const std::uint64_t k = rank(Mesh::edge(o));
      edge_key_[s] = k, refused_[s] = 0;
      full_[s] = std::numeric_limits<double>::quiet_NaN();
      if (k == kOverError) over_error = true;
      if (k < kOverError) offer(k);
      const Halfedge first = m_.halfedge(m_.to_vertex(o));
      Halfedge r = first;
      do {
        const Index x = Mesh::edge(r).idx();
        full_[x] = std::numeric_limits<double>::quiet_NaN();  // a face around its end has changed
        if (refused_[x]) {
          refused_[x] = 0;
          if (edge_key_[x] < kOverError) offer(edge_key_[x]);
        }
        r = m_.rotate_cw(r);
      } while (r != first);
      o = m_.rotate_cw(o);
    } while (o != start);
  }
  return t;
}

DecimateResult Decimator::run() {
  DecimateResult result;
  report_progress(o_.progress, 0);
  const std::size_t initial = initial_ = needed();
  if (initial == 0 || m_.n_faces() == 0) {
    result.vertices = m_.n_vertices(), result.faces = m_.n_faces();
    result.stop = initial == 0 ? DecimateStop::target_reached : DecimateStop::no_legal_collapse;
    report_progress(o_.progress, 1);
    return result;
  }
  gather_quadrics();
  stamp_.assign(m_.vertex_slots(), 0);
  edge_key_.assign(m_.edge_slots(), kNoKey);
  point_.resize(m_.edge_slots());
  double max_cost = 0;
  bool over_error = false;  // a candidate of this pass exceeded max_error
  bool shapely = true;      // the shape check is on (see check_faces)
  bool rerank_all = true;   // every edge's key is stale (the first pass, or after the greedy tail)
  const bool endless = o_.target_vertices == 0 && o_.target_faces == 0;
  for (std::uint32_t pass = 1;; ++pass) {
    classify();
    if (!tail_ && near_target()) tail_ = rerank_all = true;
    // Rank: every live edge's best collapse within the error limit.
    // Only edges at a vertex that survived a collapse in the last pass need a new ranking: no
    // other vertex's quadric, position or class has changed.
    keys_.clear();
    over_error = false;
    const std::size_t slots = m_.edge_slots();
    for (std::size_t i = 0; i < slots; ++i) {
      const Edge e(static_cast<Index>(i));
      if (m_.is_deleted(e)) continue;
      std::uint64_t& key = edge_key_[i];
      const Halfedge h0 = Mesh::halfedge(e, 0);
      if (rerank_all || stamp_[m_.to_vertex(h0).idx()] == pass - 1 ||
          stamp_[m_.from_vertex(h0).idx()] == pass - 1)
        key = rank(e);
      if (key == kOverError) {
        over_error = true;
        continue;
      }
      if (key != kNoKey) keys_.push_back(key);
    }
    detail::decimation::radix_sort(keys_, scratch_);
    rerank_all = false;
    Tally t;
    if (near_target()) {
      t = collapse_greedy(shapely, result, max_cost, over_error);
      rerank_all = true;
    } else {
      // Half of what is still needed, but not less than 1/32 of the whole, so that the tail of
      // ever smaller passes (each a full re-sort) stops after a few.
      const std::size_t budget =
          endless ? keys_.size() : std::max<std::size_t>({1, (needed() + 1) / 2, initial / 32});
      t = collapse_pass(pass, budget, shapely, result, max_cost, over_error);
    }
    report();
    if (done()) break;
    if (t.done == 0 && t.refused_shape > 0 && shapely) {
      // The shape check alone may stop the decimation short of its target: lift it, and go on.
      shapely = false;
      continue;
    }
    if (t.done == 0 && t.refused_normal > 0 && min_cos_ > 0 && o_.relax_normal_change) {
      // Likewise the turn limit, when it is below 90 degrees: faces may turn up to 90 degrees (never
      // over) for the rest of the run, so that coarse targets are reached.
      min_cos_ = 0;
      continue;
    }
    if (t.done == 0) {
      result.stop = over_error ? DecimateStop::error_bound : DecimateStop::no_legal_collapse;
      break;
    }
  }
  if (result.collapses > 0) m_.garbage_collection();
  result.vertices = m_.n_vertices(), result.faces = m_.n_faces();
  result.max_error = std::sqrt(max_cost);
  report_progress(o_.progress, 1);
  return result;
}

}  // namespace

DecimateResult decimate(SurfaceMesh& mesh, const DecimateOptions& options) {
  check_input(mesh, options);
  Decimator d(mesh, options);
  return d.run();
}

}  // namespace hedge

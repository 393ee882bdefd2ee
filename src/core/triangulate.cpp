// Ear clipping in the polygon's Newell plane.
#include "hedge/core/triangulate.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>

namespace hedge {

namespace {

// Ear clipping over a circular doubly linked list of the corners left. Every corner keeps whether
// it is an ear; clipping corner b changes only the shape at its two neighbours, so only they are
// tested again, and in a simple polygon no other corner changes (a corner blocked by some corner
// inside its triangle is also blocked by a reflex one, which clipping elsewhere leaves in place).
// The ear tests look only at the corners that are not strictly convex, bucketed in a grid and
// visited row by row across the triangle. The ear clipped is always the one of the smallest
// index, so the triangles are those of a scan for the first ear from corner 0 after every clip.
// Each ear test costs O(n) at most and there are O(n) of them, hence O(n^2) in the worst case.
class EarClipper {
 public:
  explicit EarClipper(std::vector<std::array<double, 2>> q) : q_(std::move(q)) {}

  void run(std::vector<std::array<Index, 3>>& tris);

 private:
  double cross2(Index a, Index b, Index c) const {
    return (q_[b][0] - q_[a][0]) * (q_[c][1] - q_[a][1]) - (q_[b][1] - q_[a][1]) * (q_[c][0] - q_[a][0]);
  }
  bool inside(Index a, Index b, Index c, Index r) const {
    return cross2(a, b, r) >= 0 && cross2(b, c, r) >= 0 && cross2(c, a, r) >= 0;
  }
  bool blocked(Index a, Index b, Index c) const;
  // Recomputes whether corner b is convex and an ear, queueing it when it is.
  void classify(Index b);

  std::vector<std::array<double, 2>> q_;
  std::vector<Index> prev_, next_;
  std::vector<char> convex_, ear_, removed_, listed_;
  // Buckets the corners that were not strictly convex at the start in a grid of cells over the
  // polygon's bounding box (rows of cells, cell c's corners in grid_[start_[c]] .. grid_[start_[c+1]]).
  void build_grid(const std::vector<Index>& reflex);
  std::size_t cell_of(double x, int k) const;
  double lo_[2] = {0, 0}, size_[2] = {1, 1};
  std::size_t cells_[2] = {1, 1};
  std::vector<std::size_t> start_;
  std::vector<Index> grid_;
  std::vector<Index> late_;  // corners that stopped being convex later (only in a self-crossing input)
  std::priority_queue<Index, std::vector<Index>, std::greater<>> ears_;  // may hold stale entries
};

std::size_t EarClipper::cell_of(double x, int k) const {
  const double c = (x - lo_[k]) / size_[k];
  if (!(c >= 1)) return 0;  // also NaN
  return c >= static_cast<double>(cells_[k]) ? cells_[k] - 1 : static_cast<std::size_t>(c);
}

void EarClipper::build_grid(const std::vector<Index>& reflex) {
  const std::size_t r = reflex.size();
  double hi[2] = {0, 0};
  bool finite = r > 0;
  for (int k = 0; k < 2 && finite; ++k) {
    lo_[k] = hi[k] = q_[reflex[0]][k];
    for (Index i : reflex) {
      lo_[k] = std::min(lo_[k], q_[i][k]);
      hi[k] = std::max(hi[k], q_[i][k]);
    }
    finite = std::isfinite(hi[k] - lo_[k]);
  }
  // About one corner a cell, the cells about as wide as high; one cell for non-finite input.
  if (finite) {
    const double w = hi[0] - lo_[0], h = hi[1] - lo_[1], rd = static_cast<double>(r);
    const double gx = w <= 0 ? 1 : h <= 0 ? rd : std::clamp(std::round(std::sqrt(rd * w / h)), 1.0, rd);
    cells_[0] = static_cast<std::size_t>(gx);
    cells_[1] = h <= 0 ? 1 : std::max<std::size_t>(1, r / cells_[0]);
    for (int k = 0; k < 2; ++k)
      size_[k] = cells_[k] > 1 ? (hi[k] - lo_[k]) / static_cast<double>(cells_[k]) : 1;
    if (!(size_[0] > 0) || !(size_[1] > 0)) cells_[0] = cells_[1] = 1;
  }
  if (cells_[0] == 1 && cells_[1] == 1) lo_[0] = lo_[1] = 0, size_[0] = size_[1] = 1;
  start_.assign(cells_[0] * cells_[1] + 1, 0);
  auto cell = [&](Index i) { return cell_of(q_[i][1], 1) * cells_[0] + cell_of(q_[i][0], 0); };
  for (Index i : reflex) ++start_[cell(i) + 1];
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  grid_.resize(r);
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  for (Index i : reflex) grid_[fill[cell(i)]++] = i;
}

bool EarClipper::blocked(Index a, Index b, Index c) const {
  auto blocks = [&](Index r) {
    return !convex_[r] && !removed_[r] && r != a && r != b && r != c && inside(a, b, c, r);
  };
  for (Index r : late_)
    if (blocks(r)) return true;
  const Index t[3] = {a, b, c};
  const double ylo = std::min({q_[a][1], q_[b][1], q_[c][1]}), yhi = std::max({q_[a][1], q_[b][1], q_[c][1]});
  const std::size_t row_end = cell_of(yhi, 1) + 1;
  for (std::size_t row = cell_of(ylo, 1); row < row_end; ++row) {
    std::size_t col = 0, col_end = cells_[0];
    if (cells_[0] > 1) {
      // The triangle's extent in x over the row, widened by half a row up and down and a cell
      // left and right so that rounding cannot lose a corner: the ends of its edges clipped to
      // the row.
      const double y0 = std::max(ylo, lo_[1] + (static_cast<double>(row) - 0.5) * size_[1]);
      const double y1 = std::min(yhi, lo_[1] + (static_cast<double>(row) + 1.5) * size_[1]);
      double xlo = INFINITY, xhi = -INFINITY;
      for (int e = 0; e < 3; ++e) {
        const auto& p = q_[t[e]];
        const auto& q = q_[t[(e + 1) % 3]];
        double s0 = 0, s1 = 1;
        if (p[1] != q[1]) {
          s0 = (y0 - p[1]) / (q[1] - p[1]);
          s1 = (y1 - p[1]) / (q[1] - p[1]);
          if (s0 > s1) std::swap(s0, s1);
          s0 = std::max(s0, 0.0);
          s1 = std::min(s1, 1.0);
        } else if (p[1] < y0 || p[1] > y1) {
          continue;
        }
        if (!(s0 <= s1)) continue;
        for (double s : {s0, s1}) {
          const double x = p[0] + s * (q[0] - p[0]);
          xlo = std::min(xlo, x);
          xhi = std::max(xhi, x);
        }
      }
      if (!(xlo <= xhi)) xlo = -INFINITY, xhi = INFINITY;  // NaN: every column
      col = cell_of(xlo, 0);
      col = col > 0 ? col - 1 : 0;
      col_end = std::min(cells_[0], cell_of(xhi, 0) + 2);
    }
    for (std::size_t i = start_[row * cells_[0] + col]; i < start_[row * cells_[0] + col_end]; ++i)
      if (blocks(grid_[i])) return true;
  }
  return false;
}

void EarClipper::classify(Index b) {
  const bool was_convex = convex_[b];
  convex_[b] = cross2(prev_[b], b, next_[b]) > 0;  // a flat corner counts as reflex
  if (was_convex && !convex_[b] && !listed_[b]) {
    late_.push_back(b);
    listed_[b] = 1;
  }
  ear_[b] = convex_[b] && !blocked(prev_[b], b, next_[b]);
  if (ear_[b]) ears_.push(b);
}

void EarClipper::run(std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = q_.size();
  prev_.resize(n);
  next_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev_[i] = static_cast<Index>((i + n - 1) % n);
    next_[i] = static_cast<Index>((i + 1) % n);
  }
  convex_.assign(n, 0);
  ear_.assign(n, 0);
  removed_.assign(n, 0);
  listed_.assign(n, 0);
  std::vector<Index> reflex;
  for (std::size_t i = 0; i < n; ++i) {
    const Index b = static_cast<Index>(i);
    convex_[b] = cross2(prev_[b], b, next_[b]) > 0;
    if (!convex_[b]) {
      reflex.push_back(b);
      listed_[b] = 1;
    }
  }
  build_grid(reflex);
  for (std::size_t i = 0; i < n; ++i)
    if (convex_[i]) classify(static_cast<Index>(i));
  // Corners whose ear test was stale (only in a self-crossing input, where an ear may appear away
  // from a clip) are found by testing every corner again when no ear is queued; those passes are
  // capped at a few times the corners, keeping the whole O(n^2), before the rest is fanned.
  std::size_t retest_budget = std::max<std::size_t>(4 * n, 4096);
  std::size_t left = n, first = 0;
  while (left > 3) {
    while (!ears_.empty() && (removed_[ears_.top()] || !ear_[ears_.top()])) ears_.pop();
    if (ears_.empty()) {
      if (retest_budget < left) break;
      retest_budget -= left;
      Index b = static_cast<Index>(first);
      for (std::size_t k = 0; k < left; ++k, b = next_[b]) classify(b);
      if (ears_.empty()) break;
      continue;
    }
    const Index b = ears_.top(), a = prev_[b], c = next_[b];
    ears_.pop();
    // A corner that stopped being convex may lie in the triangle of an ear queued before.
    if (!late_.empty() && blocked(a, b, c)) {
      ear_[b] = 0;
      continue;
    }
    tris.push_back({a, b, c});
    removed_[b] = 1;
    next_[a] = c;
    prev_[c] = a;
    --left;
    while (removed_[first]) ++first;
    classify(a);
    classify(c);
  }
  if (left < 3) return;
  // What is left is fanned from its smallest corner, as for self-crossing input where no ear is found.
  const Index f = static_cast<Index>(first);
  for (Index b = next_[f]; next_[b] != f; b = next_[b]) tris.push_back({f, b, next_[b]});
}

}  // namespace

void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = p.size();
  if (n < 3) return;
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
  EarClipper(std::move(q)).run(tris);
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

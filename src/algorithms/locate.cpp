// Point location: triangle primitives, FaceBvh (build, refit, update, queries) and the linear scans.
//
// Exactness: the tree prunes a node only when its box is farther than the best answer so far by
// more than a small relative (and, for distances, absolute) slack. The slack covers the rounding of
// the box tests, so every face that could equal or beat the best answer is tested with the same
// double-precision triangle code as the linear scans, and the answers are identical.
#include "hedge/algorithms/locate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "hedge/core/small_vector.h"
#include "hedge/error.h"

namespace hedge {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kInfF = std::numeric_limits<float>::infinity();
// Relative slack of the box tests (float boxes and slabs round to a few ulps, about 1e-7).
constexpr double kRelSlack = 1e-5;
// Subtrees inserted by update() stay mergeable up to this many entries: the last one inserted
// (rebuilt in place) and the others (copied, leaving as many tombstones).
constexpr Index kMergeLimit = 128;
constexpr Index kCopyMergeLimit = 32;
constexpr int kBins = 16;
// Nodes with fewer faces are split at the median instead of by SAH (see Builder::split).
constexpr unsigned kMinSahItems = 32;

}  // namespace

struct FaceBvh::Box {
  float lo[3] = {kInfF, kInfF, kInfF};
  float hi[3] = {-kInfF, -kInfF, -kInfF};

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

namespace {

double sq(double x) { return x * x; }

//! Calls fn(c0, c[i], c[i+1]) for the fan triangles of f until fn returns true. Returns whether it
//! stopped. The walk is bounded by the number of half-edges, so a broken loop cannot hang it.
template <typename Fn>
bool for_each_fan(const SurfaceMesh& m, Face f, Fn&& fn) {
  const Halfedge h0 = m.halfedge(f);
  if (!h0.is_valid() || !m.is_valid(h0)) return false;
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

SegmentPoint closest_on_segment(const Vec3d& p, const Vec3d& x, const Vec3d& y) {
  const Vec3d xy = y - x;
  const double len2 = dot(xy, xy);
  const double u = len2 > 0 ? std::clamp(dot(p - x, xy) / len2, 0.0, 1.0) : 0.0;
  const Vec3d pq = p - (x + xy * u);
  return {dot(pq, pq), u};
}

TrianglePoint closest_on_triangle(const Vec3d& p, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
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
double orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

Vec3 interpolate(const SurfaceMesh& m, const std::array<Vertex, 3>& c, const std::array<double, 3>& w) {
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
    const TrianglePoint r = closest_on_triangle(p, to_double(pa), to_double(pb), to_double(pc));
    offer(f, a, b, c, r.squared_distance, r.barycentric);
    return false;
  }
  std::optional<LocateResult> result() const {
    auto r = report<LocateResult>();
    if (r) r->squared_distance = best;
    return r;
  }
};

struct RaySearch : Found {
  RaySearch(const SurfaceMesh& mesh, const PreparedRay& r, double t_max) : Found(mesh, t_max), ray(r) {}
  const PreparedRay& ray;

  bool operator()(Face f, Vertex a, Vertex b, Vertex c) {
    const std::optional<TriangleHit> h = ray.intersect(m.position(a), m.position(b), m.position(c), best);
    if (h) offer(f, a, b, c, h->t, h->barycentric);
    return false;
  }
  std::optional<RayHit> result() const {
    auto r = report<RayHit>();
    if (r) r->t = best;
    return r;
  }
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

double box_distance_sq(const float* lo, const float* hi, const Vec3d& p) {
  double d = 0;
  for (int a = 0; a < 3; ++a) {
    const double l = double(lo[a]) - p[a];
    const double h = p[a] - double(hi[a]);
    if (l > 0)
      d += l * l;
    else if (h > 0)
      d += h * h;
  }
  if (!(lo[0] <= hi[0])) return kInf;  // empty box
  return d;
}

bool valid_direction(const Vec3& d) { return is_finite(d) && (d.x != 0 || d.y != 0 || d.z != 0); }

}  // namespace

// ---- Triangle primitives. ----

TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return closest_on_triangle(to_double(p), to_double(a), to_double(b), to_double(c));
}

std::optional<TriangleHit> intersect_ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a,
                                                  const Vec3& b, const Vec3& c, double t_max) {
  if (!is_finite(origin) || !valid_direction(direction) || std::isnan(t_max)) return std::nullopt;
  return PreparedRay(origin, direction).intersect(a, b, c, t_max);
}

// ---- FaceBvh: building. ----

//! Builds one subtree over a contiguous range of entries (binned SAH or median split), writing its
//! root into a given node slot and appending the other nodes. The entries' boxes are partitioned
//! in place, so every pass over a node's range reads memory in order.
struct FaceBvh::Builder {
  struct Item {
    Box box;
    Index entry;  // offset in the range
    //! Twice the box centre: the halving is left out, it changes no comparison.
    float centre2(int a) const { return box.lo[a] + box.hi[a]; }
  };
  //! The box of some items. Splits bin the centres over the box's extent rather than the centres'
  //! own, which spares a second box per node and loses little.
  struct Bounds {
    Box box;
    void grow(const Item& it) { box.grow(it.box); }
    void grow(const Bounds& o) { box.grow(o.box); }
    int widest_axis() const {
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (box.hi[a] - box.lo[a] > box.hi[axis] - box.lo[axis]) axis = a;
      return axis;
    }
  };
  struct Task {
    Index node, begin, end;
    Bounds bounds;
  };
  //! A node's split: the right child starts at mid (== begin for a leaf).
  struct Split {
    Index mid;
    Bounds left, right;
  };

  FaceBvh& t;
  Index first;
  std::vector<Item> items;

  Builder(FaceBvh& tree, Index first_entry, Index count) : t(tree), first(first_entry), items(count) {
    for (Index i = 0; i < count; ++i) items[i] = {t.entry_box(t.entries_[first + i]), i};
  }

  Bounds bounds(Index begin, Index end) const {
    Bounds b;
    for (Index k = begin; k < end; ++k) b.grow(items[k]);
    return b;
  }

  static int bin_of(float c, float cmin, float scale) {
    return std::clamp(static_cast<int>((c - cmin) * scale), 0, kBins - 1);
  }

  //! Halves at the median centre along the widest axis.
  Split median_split(Index begin, Index end, const Bounds& b) {
    const int axis = b.widest_axis();
    const Index mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const Item& x, const Item& y) { return x.centre2(axis) < y.centre2(axis); });
    return {mid, bounds(begin, mid), bounds(mid, end)};
  }

  //! Bins the centres along the widest axis in one pass (which also gives the children's bounds),
  //! prices every cut between bins as left count x left area + right count x right area, and
  //! partitions at the cheapest.
  Split sah_split(Index begin, Index end, const Bounds& b) {
    const int a = b.widest_axis();
    const float lo = 2 * b.box.lo[a];  // in centre2 units
    const float extent = 2 * b.box.hi[a] - lo;
    if (!(extent > 0)) return median_split(begin, end, b);  // coincident centres: any halving
    const float scale = float(kBins) / extent;
    std::array<Index, kBins> count{};
    std::array<Bounds, kBins> bin;
    for (Index k = begin; k < end; ++k) {
      const int i = bin_of(items[k].centre2(a), lo, scale);
      ++count[i];
      bin[i].grow(items[k]);
    }
    std::array<Bounds, kBins> right;  // right[i]: bins i.. (i >= 1)
    std::array<Index, kBins> right_count{};
    for (int i = kBins - 1; i > 0; --i) {
      right[i] = bin[i];
      if (i + 1 < kBins) right[i].grow(right[i + 1]);
      right_count[i] = count[i] + (i + 1 < kBins ? right_count[i + 1] : 0);
    }
    Bounds left, best_left;
    Index n = 0;
    int best = -1;
    double best_cost = kInf;
    for (int i = 0; i < kBins - 1; ++i) {
      left.grow(bin[i]);
      n += count[i];
      if (n == 0 || right_count[i + 1] == 0) continue;
      const double cost = n * left.box.half_area() + right_count[i + 1] * right[i + 1].box.half_area();
      if (cost < best_cost) {
        best_cost = cost;
        best = i;
        best_left = left;
      }
    }
    if (best < 0) return median_split(begin, end, b);
    const auto it = std::partition(items.begin() + begin, items.begin() + end,
                                   [&](const Item& x) { return bin_of(x.centre2(a), lo, scale) <= best; });
    return {static_cast<Index>(it - items.begin()), best_left, right[best + 1]};
  }

  Split split(Index begin, Index end, const Bounds& b) {
    const Index n = end - begin;
    if (n <= 1 || n <= t.options_.max_leaf_size) return {begin, {}, {}};
    // Binning costs a fixed sweep per node, more than it saves on small nodes: halve those.
    if (t.options_.split == BvhSplit::median || n < kMinSahItems) return median_split(begin, end, b);
    return sah_split(begin, end, b);
  }

  void run(Index root) {
    const std::size_t first_new_node = t.nodes_.size();
    std::vector<Task> tasks{{root, 0, Index(items.size()), bounds(0, Index(items.size()))}};
    while (!tasks.empty()) {
      const Task task = tasks.back();
      tasks.pop_back();
      const Split s = split(task.begin, task.end, task.bounds);
      Node& node = t.nodes_[task.node];
      std::copy(task.bounds.box.lo, task.bounds.box.lo + 3, node.lo);
      std::copy(task.bounds.box.hi, task.bounds.box.hi + 3, node.hi);
      if (s.mid == task.begin) {
        node.index = first + task.begin;
        node.count = task.end - task.begin;
        continue;
      }
      const Index children = static_cast<Index>(t.nodes_.size());
      node.index = children;
      node.count = 0;
      t.nodes_.resize(t.nodes_.size() + 2);  // invalidates `node`
      tasks.push_back({children + 1, s.mid, task.end, s.right});
      tasks.push_back({children, task.begin, s.mid, s.left});
    }

    // Entries into leaf order.
    std::vector<Entry> sorted(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) sorted[k] = t.entries_[first + items[k].entry];
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      t.entries_[first + k] = sorted[k];
      if (sorted[k].face != kInvalidIndex) t.slot_of_face_[sorted[k].face] = first + Index(k);
    }
    // Heights: every new node's children come after it, so a reverse sweep sees children first.
    t.height_.resize(t.nodes_.size(), 0);
    t.young_.resize(t.nodes_.size(), 0);
    for (std::size_t k = t.nodes_.size(); k-- > first_new_node;) t.set_height(Index(k));
    t.set_height(root);
  }
};

FaceBvh::FaceBvh(const SurfaceMesh& mesh, const BvhOptions& options) { build(mesh, options); }

FaceBvh::Entry FaceBvh::make_entry(Face f) const {
  const SurfaceMesh& m = *mesh_;
  Entry e{f.idx(), {kInvalidIndex, kInvalidIndex, kInvalidIndex}};
  const Halfedge h0 = m.halfedge(f);
  if (!h0.is_valid()) return e;
  const Halfedge h1 = m.next(h0);
  const Halfedge h2 = m.next(h1);
  if (m.next(h2) == h0) {
    e.corner[0] = m.to_vertex(h0).idx();
    e.corner[1] = m.to_vertex(h1).idx();
    e.corner[2] = m.to_vertex(h2).idx();
  }
  return e;
}

template <typename Fn>
bool FaceBvh::for_each_triangle(const Entry& e, Fn&& fn) const {
  if (e.corner[0] != kInvalidIndex)
    return fn(Face(e.face), Vertex(e.corner[0]), Vertex(e.corner[1]), Vertex(e.corner[2]));
  const Face f(e.face);
  return for_each_fan(*mesh_, f, [&](Vertex a, Vertex b, Vertex c) { return fn(f, a, b, c); });
}

FaceBvh::Box FaceBvh::entry_box(const Entry& e) const {
  Box box;
  if (e.face == kInvalidIndex) return box;
  for_each_triangle(e, [&](Face, Vertex a, Vertex b, Vertex c) {
    box.grow(mesh_->position(a));
    box.grow(mesh_->position(b));
    box.grow(mesh_->position(c));
    return false;
  });
  return box;
}

void FaceBvh::set_height(Index n) {
  const Node& node = nodes_[n];
  height_[n] = node.is_leaf() ? 0 : 1 + std::max(height_[node.index], height_[node.index + 1]);
}

void FaceBvh::build_subtree(Index first_entry, Index count, Index root) {
  Builder(*this, first_entry, count).run(root);
}

void FaceBvh::build(const SurfaceMesh& mesh, const BvhOptions& options) {
  if (options.max_leaf_size < 1 || options.max_leaf_size > 255)
    throw InvalidInputError("FaceBvh: max_leaf_size must be in 1..255, got " +
                            std::to_string(options.max_leaf_size));
  if (!(options.rebuild_fraction > 0 && options.rebuild_fraction <= 1))
    throw InvalidInputError("FaceBvh: rebuild_fraction must be in (0, 1]");
  mesh_ = &mesh;
  options_ = options;
  nodes_.clear();
  entries_.clear();
  height_.clear();
  young_.clear();
  slot_of_face_.assign(mesh.face_slots(), kInvalidIndex);
  entries_.reserve(mesh.n_faces());
  for (Face f : mesh.faces()) entries_.push_back(make_entry(f));
  live_ = entries_.size();
  dead_ = 0;
  orphan_nodes_ = 0;
  tail_root_ = kInvalidIndex;
  ++builds_;
  remember_sizes();
  if (live_ > 0) {
    nodes_.reserve(live_ + 1);  // enough for leaves of two faces on average; trimmed below
    nodes_.resize(1);
    build_subtree(0, static_cast<Index>(entries_.size()), 0);
    nodes_.shrink_to_fit();
    height_.shrink_to_fit();
    young_.shrink_to_fit();
  }
  height_at_build_ = nodes_.empty() ? 0 : height_[0];
  update_slack();
}

void FaceBvh::rebuild() {
  if (mesh_) build(*mesh_, options_);
}

void FaceBvh::remember_sizes() {
  sizes_ = {mesh_->vertex_slots(), mesh_->halfedge_slots(), mesh_->face_slots()};
}

void FaceBvh::update_slack() {
  // Absolute slack for distances near zero, where the double triangle code's error is absolute
  // (about 1e-16 of the squared extent); this is far larger and still negligible.
  slack_sq_ = 0;
  if (nodes_.empty()) return;
  const Node& r = nodes_[0];
  if (!(r.lo[0] <= r.hi[0])) return;
  double diag2 = 0;
  for (int a = 0; a < 3; ++a) diag2 += sq(double(r.hi[a]) - r.lo[a]);
  slack_sq_ = diag2 * 1e-12;
}

void FaceBvh::check_fresh() const {
  if (mesh_->vertex_slots() < sizes_[0] || mesh_->halfedge_slots() < sizes_[1] ||
      mesh_->face_slots() < sizes_[2])
    throw InvalidInputError(
        "FaceBvh: the mesh has fewer elements than when the tree was built (garbage_collection?); "
        "build the tree again");
}

// ---- Refit and update. ----

void FaceBvh::refit_leaf(Index n) {
  Box box;
  const Node& node = nodes_[n];
  for (Index k = node.index; k < node.index + node.count; ++k) box.grow(entry_box(entries_[k]));
  std::copy(box.lo, box.lo + 3, nodes_[n].lo);
  std::copy(box.hi, box.hi + 3, nodes_[n].hi);
}

void FaceBvh::refit_internal(Index n) {
  Node& node = nodes_[n];
  const Node& a = nodes_[node.index];
  const Node& b = nodes_[node.index + 1];
  for (int i = 0; i < 3; ++i) {
    node.lo[i] = std::min(a.lo[i], b.lo[i]);
    node.hi[i] = std::max(a.hi[i], b.hi[i]);
  }
  set_height(n);
}

void FaceBvh::refit() {
  if (nodes_.empty()) return;
  check_fresh();
  // Post-order without recursion: update() may have placed children before their parents.
  SmallVector<std::pair<Index, bool>, 96> stack;  // no allocation for the usual depths
  stack.push_back({0, false});
  while (!stack.empty()) {
    const auto [n, children_done] = stack.pop_back();
    if (nodes_[n].is_leaf()) {
      refit_leaf(n);
    } else if (children_done) {
      refit_internal(n);
    } else {
      stack.push_back({n, true});
      stack.push_back({nodes_[n].index, false});
      stack.push_back({nodes_[n].index + 1, false});
    }
  }
  update_slack();
}

void FaceBvh::insert_entries(Index first, Index count) {
  if (nodes_.empty()) {
    nodes_.resize(1);
    height_.assign(1, 0);
    young_.assign(1, 0);
    tail_root_ = 0;
    tail_first_entry_ = first;
    tail_first_node_ = 1;
    build_subtree(first, count, 0);
    young_[0] = count;
    height_at_build_ = height_[0];
    return;
  }
  Box s;
  for (Index k = first; k < first + count; ++k) s.grow(entry_box(entries_[k]));

  // Descend to the node whose pairing with the new subtree costs the least added area: pairing at n
  // creates a node of area(n + s); going down instead grows n by the same amount, plus the area of
  // the pair made lower down.
  auto box_of = [&](Index n) {
    Box b;
    std::copy(nodes_[n].lo, nodes_[n].lo + 3, b.lo);
    std::copy(nodes_[n].hi, nodes_[n].hi + 3, b.hi);
    return b;
  };
  std::vector<Index> path;
  Index n = 0;
  bool merge = false;
  for (;;) {
    // A young subtree is merged with the new entries if that is cheap: in place when it is the
    // tail (no garbage), by copying when it is small; a larger one is descended like any other.
    if (young_[n] != 0 && young_[n] + count <= (n == tail_root_ ? kMergeLimit : kCopyMergeLimit)) {
      merge = true;
      break;
    }
    if (nodes_[n].is_leaf()) break;
    const Box b = box_of(n);
    const double here = b.merged(s).half_area();
    const double inherited = here - b.half_area();
    const Index c = nodes_[n].index;
    const double down0 = inherited + box_of(c).merged(s).half_area();
    const double down1 = inherited + box_of(c + 1).merged(s).half_area();
    if (here <= std::min(down0, down1)) break;
    path.push_back(n);
    n = down0 <= down1 ? c : c + 1;
  }

  if (merge && n == tail_root_) {
    // The young subtree made last: its entries end where the new ones start and its nodes end the
    // node array, so it is rebuilt in place, and its tombstones are dropped.
    Index w = tail_first_entry_;
    for (Index k = tail_first_entry_; k < entries_.size(); ++k) {
      if (entries_[k].face != kInvalidIndex)
        entries_[w++] = entries_[k];
      else
        --dead_;
    }
    entries_.resize(w);
    nodes_.resize(tail_first_node_);
    height_.resize(tail_first_node_);
    young_.resize(tail_first_node_);
    build_subtree(tail_first_entry_, w - tail_first_entry_, n);
    young_[n] = w - tail_first_entry_;
    ++merged_;
  } else if (merge) {
    // An older young subtree: its live entries move next to the new ones (leaving tombstones) and
    // the lot is rebuilt at its root; its old nodes are orphaned until the next build.
    SmallVector<Index, 96> stack;  // no allocation for the usual depths
    stack.push_back(n);
    while (!stack.empty()) {
      const Index x = stack.pop_back();
      const Node node = nodes_[x];
      if (x != n) ++orphan_nodes_;
      if (!node.is_leaf()) {
        stack.push_back(node.index);
        stack.push_back(node.index + 1);
        continue;
      }
      for (Index k = node.index; k < node.index + node.count; ++k) {
        if (entries_[k].face == kInvalidIndex) continue;
        entries_.push_back(entries_[k]);
        entries_[k].face = kInvalidIndex;
        ++dead_;
      }
    }
    const Index total = static_cast<Index>(entries_.size()) - first;
    tail_root_ = n;
    tail_first_entry_ = first;
    tail_first_node_ = static_cast<Index>(nodes_.size());
    build_subtree(first, total, n);
    young_[n] = total;
    ++merged_;
  } else {
    // Hang the new subtree next to n: n's content moves to a new slot, n becomes their parent.
    const Index j = static_cast<Index>(nodes_.size());
    nodes_.resize(j + 2);
    height_.resize(j + 2, 0);
    young_.resize(j + 2, 0);
    nodes_[j] = nodes_[n];
    height_[j] = height_[n];
    young_[j] = young_[n];
    tail_root_ = j + 1;
    tail_first_entry_ = first;
    tail_first_node_ = j + 2;
    build_subtree(first, count, j + 1);
    young_[j + 1] = count;
    nodes_[n].index = j;
    nodes_[n].count = 0;
    young_[n] = 0;
    refit_internal(n);
    ++inserted_;
  }
  for (std::size_t i = path.size(); i-- > 0;) refit_internal(path[i]);
}

void FaceBvh::update(std::span<const Face> changed_or_added, std::span<const Face> removed) {
  if (!mesh_) throw InvalidInputError("FaceBvh::update: the tree was never built over a mesh");
  check_fresh();
  const SurfaceMesh& m = *mesh_;
  for (std::span<const Face> list : {changed_or_added, removed})
    for (Face f : list)
      if (!m.is_valid(f))
        throw InvalidInputError("FaceBvh::update: face " + std::to_string(f.idx()) +
                                " is not a face slot of the mesh (" + std::to_string(m.face_slots()) +
                                " slots)");
  slot_of_face_.resize(m.face_slots(), kInvalidIndex);
  auto tombstone = [&](Face f) {
    Index& slot = slot_of_face_[f.idx()];
    if (slot == kInvalidIndex) return;
    entries_[slot].face = kInvalidIndex;
    slot = kInvalidIndex;
    --live_;
    ++dead_;
  };
  for (Face f : removed) tombstone(f);
  for (Face f : changed_or_added) tombstone(f);
  const Index first = static_cast<Index>(entries_.size());
  for (Face f : changed_or_added) {
    if (m.is_deleted(f) || slot_of_face_[f.idx()] != kInvalidIndex) continue;
    slot_of_face_[f.idx()] = static_cast<Index>(entries_.size());
    entries_.push_back(make_entry(f));
    ++live_;
  }
  remember_sizes();
  const Index count = static_cast<Index>(entries_.size()) - first;
  if (double(dead_) > options_.rebuild_fraction * double(entries_.size())) {
    rebuild();
    return;
  }
  if (count > 0) insert_entries(first, count);
  if (dead_ > 0 && double(dead_) > options_.rebuild_fraction * double(entries_.size())) {
    rebuild();
    return;
  }
  if (!nodes_.empty() && height_[0] > 2 * height_at_build_ + 16) {
    rebuild();
    return;
  }
  update_slack();
}

// ---- Queries. ----

std::optional<LocateResult> FaceBvh::closest_point(const Vec3& p) const { return closest_point(p, kInf); }

std::optional<LocateResult> FaceBvh::closest_point(const Vec3& p, double max_distance) const {
  if (empty() || !is_finite(p) || !(max_distance >= 0)) return std::nullopt;
  check_fresh();
  ClosestSearch search(*mesh_, to_double(p), sq(max_distance), slack_sq_);
  auto limit = [&] { return search.limit(); };
  SmallVector<std::pair<Index, double>, 96> stack;  // no allocation for the usual depths
  stack.push_back({0, box_distance_sq(nodes_[0].lo, nodes_[0].hi, search.p)});
  while (!stack.empty()) {
    const auto [n, d] = stack.pop_back();
    if (d > limit()) continue;
    const Node& node = nodes_[n];
    if (node.is_leaf()) {
      for (Index k = node.index; k < node.index + node.count; ++k)
        if (entries_[k].face != kInvalidIndex) for_each_triangle(entries_[k], search);
      continue;
    }
    const Index c = node.index;
    double d0 = box_distance_sq(nodes_[c].lo, nodes_[c].hi, search.p);
    double d1 = box_distance_sq(nodes_[c + 1].lo, nodes_[c + 1].hi, search.p);
    Index near = c, far = c + 1;
    if (d1 < d0) {
      std::swap(near, far);
      std::swap(d0, d1);
    }
    const double lim = limit();
    if (d1 <= lim) stack.push_back({far, d1});
    if (d0 <= lim) stack.push_back({near, d0});
  }
  return search.result();
}

std::optional<LocateResult> FaceBvh::face_containing(const Vec3& p, double tolerance) const {
  return closest_point(p, tolerance);
}

std::optional<SurfacePoint> FaceBvh::face_containing(const Vec2& p, ProjectionPlane plane) const {
  if (empty() || !is_finite(p)) return std::nullopt;
  check_fresh();
  ContainSearch search(*mesh_, p, plane);
  SmallVector<Index, 96> stack;  // no allocation for the usual depths
  stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.pop_back()];
    if (!search.box_contains(node.lo, node.hi)) continue;
    if (!node.is_leaf()) {
      stack.push_back(node.index + 1);
      stack.push_back(node.index);
      continue;
    }
    for (Index k = node.index; k < node.index + node.count; ++k) {
      const Entry& e = entries_[k];
      if (e.face == kInvalidIndex || search.skip(Face(e.face))) continue;
      for_each_triangle(e, search);
    }
  }
  return search.result();
}

std::optional<RayHit> FaceBvh::first_hit(const Vec3& origin, const Vec3& direction, double t_max) const {
  if (empty() || !is_finite(origin) || !valid_direction(direction) || !(t_max >= 0)) return std::nullopt;
  check_fresh();
  const PreparedRay ray(origin, direction);
  RaySearch search(*mesh_, ray, t_max);
  auto limit = [&] { return search.best + std::fabs(search.best) * kRelSlack; };
  SmallVector<std::pair<Index, float>, 96> stack;  // no allocation for the usual depths
  float t0 = 0, t1 = 0;
  if (!ray.enters(nodes_[0].lo, nodes_[0].hi, limit(), t0)) return std::nullopt;
  stack.push_back({0, t0});
  while (!stack.empty()) {
    const auto [n, t_near] = stack.pop_back();
    if (double(t_near) > limit()) continue;
    const Node& node = nodes_[n];
    if (node.is_leaf()) {
      for (Index k = node.index; k < node.index + node.count; ++k)
        if (entries_[k].face != kInvalidIndex) for_each_triangle(entries_[k], search);
      continue;
    }
    const Index c = node.index;
    const double lim = limit();
    const bool h0 = ray.enters(nodes_[c].lo, nodes_[c].hi, lim, t0);
    const bool h1 = ray.enters(nodes_[c + 1].lo, nodes_[c + 1].hi, lim, t1);
    if (h0 && h1) {
      if (t0 <= t1) {
        stack.push_back({c + 1, t1});
        stack.push_back({c, t0});
      } else {
        stack.push_back({c, t0});
        stack.push_back({c + 1, t1});
      }
    } else if (h0) {
      stack.push_back({c, t0});
    } else if (h1) {
      stack.push_back({c + 1, t1});
    }
  }
  return search.result();
}

std::size_t FaceBvh::memory_bytes() const {
  return nodes_.capacity() * sizeof(Node) + entries_.capacity() * sizeof(Entry) +
         height_.capacity() * sizeof(std::uint32_t) + young_.capacity() * sizeof(Index) +
         slot_of_face_.capacity() * sizeof(Index);
}

FaceBvh::Stats FaceBvh::stats() const {
  Stats s;
  s.nodes = nodes_.size();
  s.live_faces = live_;
  s.dead_slots = dead_;
  s.height = nodes_.empty() ? 0 : height_[0];
  s.height_at_build = height_at_build_;
  s.builds = builds_;
  s.orphan_nodes = orphan_nodes_;
  s.inserted_subtrees = inserted_;
  s.merged_subtrees = merged_;
  if (!nodes_.empty()) {
    SmallVector<Index, 96> stack;  // no allocation for the usual depths
    stack.push_back(0);
    while (!stack.empty()) {
      const Node& node = nodes_[stack.pop_back()];
      if (node.is_leaf()) {
        ++s.leaves;
      } else {
        stack.push_back(node.index);
        stack.push_back(node.index + 1);
      }
    }
  }
  return s;
}

// ---- Linear scans. ----

std::optional<LocateResult> closest_point_linear(const SurfaceMesh& mesh, const Vec3& p) {
  if (!is_finite(p)) return std::nullopt;
  ClosestSearch search(mesh, to_double(p), kInf);
  for (Face f : mesh.faces())
    for_each_fan(mesh, f, [&](Vertex a, Vertex b, Vertex c) { return search(f, a, b, c); });
  return search.result();
}

std::optional<RayHit> first_hit_linear(const SurfaceMesh& mesh, const Vec3& origin, const Vec3& direction,
                                       double t_max) {
  if (!is_finite(origin) || !valid_direction(direction) || !(t_max >= 0)) return std::nullopt;
  const PreparedRay ray(origin, direction);
  RaySearch search(mesh, ray, t_max);
  for (Face f : mesh.faces())
    for_each_fan(mesh, f, [&](Vertex a, Vertex b, Vertex c) { return search(f, a, b, c); });
  return search.result();
}

std::optional<SurfacePoint> face_containing_linear(const SurfaceMesh& mesh, const Vec2& p,
                                                   ProjectionPlane plane) {
  if (!is_finite(p)) return std::nullopt;
  ContainSearch search(mesh, p, plane);
  for (Face f : mesh.faces()) {
    if (search.skip(f)) break;  // faces come in index order
    for_each_fan(mesh, f, [&](Vertex a, Vertex b, Vertex c) { return search(f, a, b, c); });
  }
  return search.result();
}

}  // namespace hedge

#include "hedge/algorithms/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

#include "core_private/link_closed.h"
#include "hedge/error.h"

namespace hedge {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

void check_options(const ConvexHullOptions& o) {
  if (!std::isfinite(o.relative_tolerance) || o.relative_tolerance < 0 || o.relative_tolerance > 0.01)
    throw InvalidInputError("convex_hull: relative_tolerance must be in [0, 0.01], got " +
                            std::to_string(o.relative_tolerance));
  if (!std::isfinite(o.flat_thickness) || o.flat_thickness <= 0 || o.flat_thickness > 1)
    throw InvalidInputError("convex_hull: flat_thickness must be in (0, 1], got " +
                            std::to_string(o.flat_thickness));
  if (o.max_vertices != 0 && o.max_vertices < 4)
    throw InvalidInputError("convex_hull: max_vertices must be 0 (no limit) or at least 4, got " +
                            std::to_string(o.max_vertices));
}

void check_points(std::span<const Vec3> points) {
  if (points.size() >= kNone)
    throw InvalidInputError("convex_hull: too many points (" + std::to_string(points.size()) + ")");
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!is_finite(points[i]))
      throw InvalidInputError("convex_hull: point " + std::to_string(i) + " is not finite (" +
                              std::to_string(points[i].x) + ", " + std::to_string(points[i].y) + ", " +
                              std::to_string(points[i].z) + ")");
}

// The points in double, relative to their bounding-box centre, and the box's diagonal length.
struct Centred {
  std::vector<Vec3d> p;
  double extent = 0;
  float max_abs = 0;  // the largest absolute input coordinate
};

Centred centre(std::span<const Vec3> points) {
  Centred c;
  if (points.empty()) return c;
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3& q : points)
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], q[k]);
      hi[k] = std::max(hi[k], q[k]);
      c.max_abs = std::max(c.max_abs, std::abs(q[k]));
    }
  const Vec3d mid = (to_double(lo) + to_double(hi)) * 0.5;
  c.extent = norm(to_double(hi) - to_double(lo));
  c.p.reserve(points.size());
  for (const Vec3& q : points) c.p.push_back(to_double(q) - mid);
  return c;
}

// The unit normal of triangle abc from its two shorter edges (the better-conditioned cross
// product); zero for a triangle without area.
inline Vec3d triangle_normal(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  const Vec3d ab = b - a, bc = c - b, ca = a - c;
  const double lab = dot(ab, ab), lbc = dot(bc, bc), lca = dot(ca, ca);
  Vec3d n;
  if (lab >= lbc && lab >= lca)
    n = cross(bc, ca);  // ab longest: the edges meeting at c
  else if (lbc >= lca)
    n = cross(ca, ab);  // the edges meeting at a
  else
    n = cross(ab, bc);  // the edges meeting at b
  return normalize(n);
}

// The four points of the starting tetrahedron, or fewer when the set spans less than a volume.
struct Simplex {
  HullDimension dimension = HullDimension::empty;
  std::array<std::uint32_t, 4> v{kNone, kNone, kNone, kNone};
};

Simplex find_simplex(const std::vector<Vec3d>& p, double eps) {
  Simplex s;
  if (p.empty()) return s;
  s.dimension = HullDimension::point;
  const auto n = static_cast<std::uint32_t>(p.size());
  // The extreme points along the axes; the farthest pair of them spans the first edge.
  std::array<std::uint32_t, 6> ext{};
  for (std::uint32_t i = 1; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      if (p[i][k] < p[ext[2 * k]][k]) ext[2 * k] = i;
      if (p[i][k] > p[ext[2 * k + 1]][k]) ext[2 * k + 1] = i;
    }
  double best = -1;
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = i + 1; j < 6; ++j) {
      const Vec3d d = p[ext[j]] - p[ext[i]];
      if (dot(d, d) > best) {
        best = dot(d, d);
        s.v[0] = ext[i];
        s.v[1] = ext[j];
      }
    }
  if (std::sqrt(best) <= eps) return s;
  s.dimension = HullDimension::segment;
  const Vec3d a = p[s.v[0]], dir = normalize(p[s.v[1]] - a);
  best = -1;
  for (std::uint32_t i = 0; i < n; ++i) {
    const Vec3d off = cross(p[i] - a, dir);
    if (const double d = dot(off, off); d > best) best = d, s.v[2] = i;  // squared
  }
  if (std::sqrt(best) <= eps) return s;
  s.dimension = HullDimension::flat;
  const Vec3d nrm = triangle_normal(a, p[s.v[1]], p[s.v[2]]);
  best = -1;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double d = std::abs(dot(nrm, p[i] - a));
    if (d > best) best = d, s.v[3] = i;
  }
  if (best <= eps) return s;
  s.dimension = HullDimension::solid;
  return s;
}

// Quickhull on a set that spans a volume. Faces are triangles with their three neighbours; a
// face's outside set holds the unassigned points beyond its plane, and a max-heap over the faces'
// farthest points picks the next point to add. The sets are lists threaded through one array of
// the points (a point is in one set at a time), so that no step allocates: faces are plain values.
class Quickhull {
 public:
  // A point is outside a face when it lies more than eps beyond its plane, so points on the hull
  // within eps are not added; but a face counts as seen by the point being added as soon as it
  // lies beyond rounding noise, so the hull stays convex to that noise rather than to eps.
  Quickhull(const std::vector<Vec3d>& p, double eps, double extent)
      : p_(p), eps_(eps), visible_eps_(std::min(eps, 1e-12 * extent)), next_(p.size(), kNone) {}

  // Builds the hull from the simplex; stops early once it has max_vertices vertices (0: never).
  void run(const Simplex& s, std::size_t max_vertices) {
    start(s);
    while (!heap_.empty()) {
      const std::uint32_t f = heap_.top().second;
      heap_.pop();
      if (!faces_[f].alive) continue;
      if (max_vertices != 0 && n_vertices_ >= max_vertices) {
        heap_.push({faces_[f].farthest_distance, f});  // keep it for max_outside_distance()
        break;
      }
      add_point(f);
    }
    while (!heap_.empty() && !faces_[heap_.top().second].alive) heap_.pop();
  }

  // The largest distance of a point still outside beyond its face's plane (0 after a full run).
  double max_outside_distance() const { return std::max(dropped_, heap_.empty() ? 0.0 : heap_.top().first); }

  // The hull as a mesh of the points it uses, numbered in input order (so that the output depends
  // on the input only), and `input_index` (hull vertex -> point).
  SurfaceMesh mesh(std::span<const Vec3> points, std::vector<std::uint32_t>& input_index) const;

 private:
  // A set of points in the order they were added, linked through next_.
  struct List {
    std::uint32_t head = kNone, tail = kNone;
    bool empty() const { return head == kNone; }
  };
  void append(List& l, std::uint32_t i) {
    next_[i] = kNone;
    (l.head == kNone ? l.head : next_[l.tail]) = i;
    l.tail = i;
  }
  struct Face_ {
    std::array<std::uint32_t, 3> v{};   // counter-clockwise seen from outside
    std::array<std::uint32_t, 3> nb{};  // nb[i]: the face across edge v[i] -> v[i + 1]
    List outside;
    // Points within eps of the plane, neither outside nor clearly inside. They are sorted again
    // when the face is replaced or a face is built next to it: a nearly coplanar new face, tilted
    // against this one, may have them outside.
    List near;
    std::uint32_t farthest = kNone;
    double farthest_distance = 0;
    std::uint32_t seen = 0;  // the stamp of the last point that saw the face
    bool alive = true;
  };
  struct HorizonEdge {
    std::uint32_t from, to, outer;  // outer: the face beyond it that stays
    std::size_t outer_slot;         // the edge's slot in the outer face
  };

  // A face's plane: the points x with dot(normal, x) == offset. Kept apart from the faces, so that
  // the loops over the faces a point may go to read them in one run.
  struct Plane {
    Vec3d normal;
    double offset = 0;
  };

  double distance(std::uint32_t f, std::uint32_t i) const {
    return dot(planes_[f].normal, p_[i]) - planes_[f].offset;
  }

  std::uint32_t new_face(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    faces_.emplace_back().v = {a, b, c};
    Plane& pl = planes_.emplace_back();
    pl.normal = triangle_normal(p_[a], p_[b], p_[c]);
    pl.offset = dot(pl.normal, (p_[a] + p_[b] + p_[c]) * (1.0 / 3.0));
    return static_cast<std::uint32_t>(faces_.size() - 1);
  }

  // The faces made together (the four of the simplex, a fan) are numbered in one run.
  struct Run {
    std::uint32_t first = 0, count = 0;
  };

  // The face of `run` that point i lies farthest beyond (the first of equals), and how far.
  std::pair<std::uint32_t, double> farthest_face(std::uint32_t i, Run run) const {
    const Vec3d q = p_[i];
    const Plane* pl = planes_.data() + run.first;
    std::uint32_t best = kNone;
    double best_d = -std::numeric_limits<double>::infinity();
    for (std::uint32_t k = 0; k < run.count; ++k)
      if (const double d = dot(pl[k].normal, q) - pl[k].offset; d > best_d) best_d = d, best = run.first + k;
    return {best, best_d};
  }

  // Gives point i to the face of `run` it lies farthest beyond: as an outside point if that is
  // beyond eps, as a near point if within eps; a point inside by more is dropped.
  void assign(std::uint32_t i, Run run) {
    const auto [best, best_d] = farthest_face(i, run);
    if (best == kNone || best_d < -eps_) return;  // inside
    Face_& f = faces_[best];
    if (best_d <= eps_) {  // on the hull within the tolerance, for now
      append(f.near, i);
      return;
    }
    append(f.outside, i);
    if (best_d > f.farthest_distance) f.farthest_distance = best_d, f.farthest = i;
  }

  void push_if_outside(Run run) {
    for (std::uint32_t f = run.first; f < run.first + run.count; ++f)
      if (!faces_[f].outside.empty()) heap_.push({faces_[f].farthest_distance, f});
  }

  void start(const Simplex& s) {
    auto [a, b, c, d] = s.v;
    if (dot(triangle_normal(p_[a], p_[b], p_[c]), p_[d] - p_[a]) > 0) std::swap(b, c);
    // Now d is below abc: abc, and the three faces through d, wind outward.
    // Room for the faces of a typical hull, bounded so that a large cloud (whose hull is usually
    // far smaller) does not reserve memory in proportion to its points; beyond it, it grows.
    const std::size_t room = std::min<std::size_t>(8 * p_.size() + 16, std::size_t(1) << 14);
    faces_.reserve(room);
    planes_.reserve(room);
    const std::array<std::uint32_t, 4> f{new_face(a, b, c), new_face(a, d, b), new_face(b, d, c),
                                         new_face(c, d, a)};
    for (std::uint32_t x : f)
      for (std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t from = faces_[x].v[i], to = faces_[x].v[(i + 1) % 3];
        for (std::uint32_t y : f)
          for (std::size_t j = 0; j < 3; ++j)
            if (faces_[y].v[j] == to && faces_[y].v[(j + 1) % 3] == from) faces_[x].nb[i] = y;
      }
    point_mark_.assign(p_.size(), 0);
    start_face_.assign(p_.size(), kNone);
    end_face_.assign(p_.size(), kNone);
    for (std::uint32_t i = 0; i < p_.size(); ++i)
      if (i != a && i != b && i != c && i != d) assign(i, {f[0], 4});
    push_if_outside({f[0], 4});
    n_vertices_ = 4;
  }

  void add_point(std::uint32_t f0) {
    const std::uint32_t apex = faces_[f0].farthest;
    ++stamp_;
    // The faces the apex sees, found by a walk from f0, and the horizon around them.
    visible_.clear();
    horizon_.clear();
    faces_[f0].seen = stamp_;
    visible_.push_back(f0);
    for (std::size_t k = 0; k < visible_.size(); ++k) {
      const Face_& f = faces_[visible_[k]];
      for (std::size_t i = 0; i < 3; ++i) {
        const std::uint32_t g = f.nb[i];
        if (faces_[g].seen == stamp_) continue;
        if (distance(g, apex) > visible_eps_) {
          faces_[g].seen = stamp_;
          visible_.push_back(g);
        } else {
          const std::array<std::uint32_t, 3>& back = faces_[g].nb;  // one of them is this face
          const std::size_t slot = back[0] == visible_[k] ? 0 : back[1] == visible_[k] ? 1 : 2;
          horizon_.push_back({f.v[i], f.v[(i + 1) % 3], g, slot});
        }
      }
    }
    // The horizon of a point beyond a convex hull is one loop. Should rounding ever make the seen
    // faces pinch or hold a hole (not one loop), the point is left out rather than the
    // surface broken, and how far out it was is reported.
    for (std::size_t k = 0; k < horizon_.size(); ++k) {
      const std::uint32_t from = horizon_[k].from;
      if (point_mark_[from] == stamp_) return drop(f0);
      point_mark_[from] = stamp_;
      start_face_[from] = static_cast<std::uint32_t>(k);  // for now: the horizon edge starting here
    }
    std::size_t loop = 0;
    std::uint32_t at = horizon_[0].to;
    for (; loop < horizon_.size() && point_mark_[at] == stamp_ && at != horizon_[0].from; ++loop)
      at = horizon_[start_face_[at]].to;
    if (at != horizon_[0].from || loop + 1 != horizon_.size()) return drop(f0);  // not one loop
    // Vertices of the visible region that are not on the horizon (marked just now) leave the hull.
    std::size_t removed = 0;
    for (std::uint32_t f : visible_)
      for (std::uint32_t v : faces_[f].v)
        if (point_mark_[v] != stamp_) point_mark_[v] = stamp_, ++removed;
    n_vertices_ = n_vertices_ + 1 - removed;

    // A fan of new faces from the apex to the horizon, linked to the outer faces and each other.
    const Run fan{static_cast<std::uint32_t>(faces_.size()), static_cast<std::uint32_t>(horizon_.size())};
    for (const HorizonEdge& e : horizon_) {
      const std::uint32_t nf = new_face(e.from, e.to, apex);
      faces_[nf].nb[0] = e.outer;
      faces_[e.outer].nb[e.outer_slot] = nf;
      start_face_[e.from] = nf;
      end_face_[e.to] = nf;
    }
    for (std::uint32_t nf = fan.first; nf < fan.first + fan.count; ++nf) {
      Face_& f = faces_[nf];
      f.nb[1] = start_face_[f.v[1]];  // across to -> apex: the face whose horizon edge starts at `to`
      f.nb[2] = end_face_[f.v[0]];    // across apex -> from: the face whose horizon edge ends at `from`
    }

    // The visible faces' outside points go to the new faces or, now inside, are dropped.
    for (std::uint32_t f : visible_) {
      faces_[f].alive = false;
      const List outside = std::exchange(faces_[f].outside, {}), near = std::exchange(faces_[f].near, {});
      for (std::uint32_t i = outside.head, after; i != kNone; i = after) {
        after = next_[i];
        if (i != apex) assign(i, fan);
      }
      for (std::uint32_t i = near.head, after; i != kNone; i = after) {
        after = next_[i];
        assign(i, fan);
      }
    }
    // The near points of the faces beyond the horizon, against their face and the new ones.
    for (const HorizonEdge& e : horizon_) {
      if (faces_[e.outer].near.empty()) continue;
      const List near = std::exchange(faces_[e.outer].near, {});
      for (std::uint32_t i = near.head, after; i != kNone; i = after) {
        after = next_[i];
        const auto [best, best_d] = farthest_face(i, fan);
        assign(i, best_d > eps_ ? Run{best, 1} : Run{e.outer, 1});
      }
    }
    push_if_outside(fan);
  }

  void drop(std::uint32_t f0) {
    Face_& f = faces_[f0];
    dropped_ = std::max(dropped_, f.farthest_distance);
    const List outside = std::exchange(f.outside, {});
    for (std::uint32_t i = outside.head, after; i != kNone; i = after) {
      after = next_[i];
      if (i != f.farthest) append(f.outside, i);
    }
    f.farthest = kNone;
    f.farthest_distance = 0;
    for (std::uint32_t i = f.outside.head; i != kNone; i = next_[i])
      if (const double d = distance(f0, i); d > f.farthest_distance) f.farthest_distance = d, f.farthest = i;
    push_if_outside({f0, 1});
  }

  const std::vector<Vec3d>& p_;
  double eps_, visible_eps_;
  double dropped_ = 0;               // the farthest a point left out by drop() was beyond its face
  std::vector<std::uint32_t> next_;  // the point after each in its face's outside or near list
  std::vector<Face_> faces_;
  std::vector<Plane> planes_;  // each face's
  // The faces with outside points, by their farthest point's distance, then by index (the larger
  // first). Distances are finite, so this is the order of the pairs themselves, compared directly.
  struct ByDistance {
    bool operator()(const std::pair<double, std::uint32_t>& a,
                    const std::pair<double, std::uint32_t>& b) const {
      return a.first < b.first || (a.first == b.first && a.second < b.second);
    }
  };
  std::priority_queue<std::pair<double, std::uint32_t>, std::vector<std::pair<double, std::uint32_t>>,
                      ByDistance>
      heap_;
  std::size_t n_vertices_ = 0;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> point_mark_, start_face_, end_face_;
  std::vector<std::uint32_t> visible_;
  std::vector<HorizonEdge> horizon_;
};

// The live faces are linked into a mesh by the closed-set linker, given each corner's twin from
// the faces' known neighbours, so that nothing searches for them: the numbering is the one build()
// gives the same triangles (faces in creation order). The hull is closed and manifold by
// construction (every horizon is one loop); the linker checks the twins and fans all the same.
SurfaceMesh Quickhull::mesh(std::span<const Vec3> points, std::vector<std::uint32_t>& input_index) const {
  std::vector<std::uint32_t> rank(faces_.size(), kNone), index(points.size(), kNone);
  std::uint32_t n_faces = 0;
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    if (faces_[f].alive) {
      rank[f] = n_faces++;
      for (std::uint32_t v : faces_[f].v) index[v] = 0;
    }
  input_index.clear();
  for (std::uint32_t i = 0; i < points.size(); ++i)
    if (index[i] != kNone) {
      index[i] = static_cast<std::uint32_t>(input_index.size());
      input_index.push_back(i);
    }
  // Face rank k's corner i is corner 3 k + i; its twin is found from the side of the face made
  // first, and set for both.
  std::vector<std::uint32_t> corners(3 * std::size_t(n_faces)), twins(3 * std::size_t(n_faces), kNone);
  for (std::uint32_t f = 0; f < faces_.size(); ++f) {
    const std::uint32_t k = rank[f];
    if (k == kNone) continue;
    const Face_& face = faces_[f];
    for (std::size_t i = 0; i < 3; ++i) {
      corners[3 * k + i] = index[face.v[i]];
      const std::uint32_t g = face.nb[i];
      if (rank[g] > k) continue;       // the later face sets it
      const Face_& other = faces_[g];  // it runs the other way along the edge
      std::size_t j = 0;
      while (j < 3 && (other.v[j] != face.v[(i + 1) % 3] || other.v[(j + 1) % 3] != face.v[i])) ++j;
      if (j == 3) throw std::logic_error("convex_hull: neighbouring faces do not share their edge");
      twins[3 * k + i] = static_cast<std::uint32_t>(3 * rank[g] + j);
      twins[3 * rank[g] + j] = static_cast<std::uint32_t>(3 * k + i);
    }
  }
  SurfaceMesh m;
  if (const link_detail::ClosedLinkDefect d =
          link_detail::link_closed_triangles(corners, twins, input_index.size(), m))
    throw std::logic_error("convex_hull: the hull's faces are not closed and manifold: " +
                           link_detail::describe(d));
  for (std::uint32_t v = 0; v < input_index.size(); ++v) m.position(Vertex(v)) = points[input_index[v]];
  return m;
}

// The hull of a set known to span a volume, as a mesh of the points it uses.
ConvexHull solid_hull(std::span<const Vec3> points, const Centred& c, const Simplex& s, double eps,
                      std::size_t max_vertices) {
  Quickhull qh(c.p, eps, c.extent);
  qh.run(s, max_vertices);
  ConvexHull hull;
  hull.mesh = qh.mesh(points, hull.input_index);
  hull.dimension = HullDimension::solid;
  hull.tolerance = eps;
  hull.max_outside_distance = qh.max_outside_distance();
  return hull;
}

// The corners of a flat set's convex polygon, by input index (ascending): Andrew's monotone chain
// in 2D coordinates of the plane, points within eps of the line of their neighbours left out. The
// prism is then built over these alone, so that no run of nearly collinear points along an edge
// reaches the quickhull of the thin prism (its side faces are slivers there, and such runs could
// leave a point outside). Fewer than 3 corners when the polygon collapses at eps.
std::vector<std::uint32_t> flat_corners(const Centred& c, const Simplex& s, double eps) {
  const Vec3d nn = triangle_normal(c.p[s.v[0]], c.p[s.v[1]], c.p[s.v[2]]);
  const Vec3d u = normalize(c.p[s.v[1]] - c.p[s.v[0]]);
  const Vec3d w = cross(nn, u);
  struct P2 {
    double x, y;
    std::uint32_t i;
  };
  std::vector<P2> q;
  q.reserve(c.p.size());
  for (std::uint32_t i = 0; i < c.p.size(); ++i) q.push_back({dot(c.p[i], u), dot(c.p[i], w), i});
  std::sort(q.begin(), q.end(), [](const P2& a, const P2& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.i < b.i);
  });
  // a -> b -> c turns left (counter-clockwise) when b lies more than eps to the right of the line
  // a -> c; otherwise b is not a corner.
  auto turns_left = [&](const P2& a, const P2& b, const P2& cc) {
    const double dx = cc.x - a.x, dy = cc.y - a.y;
    const double len = std::sqrt(dx * dx + dy * dy);
    return dy * (b.x - a.x) - dx * (b.y - a.y) > eps * len;
  };
  std::vector<P2> chain;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = chain.size();
    for (std::size_t k = 0; k < q.size(); ++k) {
      const P2& pt = pass == 0 ? q[k] : q[q.size() - 1 - k];
      while (chain.size() >= base + 2 && !turns_left(chain[chain.size() - 2], chain.back(), pt))
        chain.pop_back();
      chain.push_back(pt);
    }
    chain.pop_back();  // the last point of each half starts the other
  }
  std::vector<std::uint32_t> corners;
  for (const P2& pt : chain) corners.push_back(pt.i);
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  return corners;
}

float float_step(float x) { return std::nextafter(x, std::numeric_limits<float>::infinity()) - x; }

// Float input is already rounded by half a float step of its coordinates: points of a tilted
// plane are coplanar only to that, so the tolerance is never finer.
double tolerance(const ConvexHullOptions& o, const Centred& c) {
  return std::max(o.relative_tolerance * c.extent, 2.0 * float_step(c.max_abs));
}

}  // namespace

ConvexHull convex_hull(std::span<const Vec3> points, const ConvexHullOptions& options) {
  check_options(options);
  check_points(points);
  const Centred c = centre(points);
  const double eps = tolerance(options, c);
  const Simplex s = find_simplex(c.p, eps);
  if (s.dimension == HullDimension::solid) return solid_hull(points, c, s, eps, options.max_vertices);
  if (s.dimension != HullDimension::flat) {
    ConvexHull hull;
    hull.dimension = s.dimension;
    hull.tolerance = eps;
    return hull;
  }
  // A flat set: the hull of the prism of the points moved half the thickness off their plane to
  // either side. The thickness is kept well above the tolerance and float rounding, so the prism
  // spans a volume.
  const double step = float_step(c.max_abs);
  const double thickness = std::max({options.flat_thickness * c.extent, 16.0 * step, 4.0 * eps});
  const Vec3d n = triangle_normal(c.p[s.v[0]], c.p[s.v[1]], c.p[s.v[2]]) * (0.5 * thickness);
  std::vector<std::uint32_t> corners = flat_corners(c, s, eps);
  if (corners.size() < 3) {  // not expected for a set found flat; then every point
    corners.resize(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) corners[i] = i;
  }
  std::vector<Vec3> prism;
  prism.reserve(2 * corners.size());
  for (std::uint32_t i : corners) {
    prism.push_back(to_float(to_double(points[i]) + n));
    prism.push_back(to_float(to_double(points[i]) - n));
  }
  const Centred pc = centre(prism);
  const double prism_eps = tolerance(options, pc);
  const Simplex ps = find_simplex(pc.p, prism_eps);
  if (ps.dimension != HullDimension::solid)
    throw std::logic_error("convex_hull: the prism of a flat set does not span a volume");
  ConvexHull hull = solid_hull(prism, pc, ps, prism_eps, options.max_vertices);
  for (std::uint32_t& i : hull.input_index) i = corners[i / 2];
  hull.dimension = HullDimension::flat;
  hull.thickness = thickness;
  // The input points lie within eps of the mid-plane and of the polygon of the corners; the prism's
  // corners moved by float rounding.
  hull.tolerance = std::max(prism_eps, eps + step);
  return hull;
}

}  // namespace hedge

// Quadric-error decimation, as named steps: check the input; gather each vertex's quadric; then
// passes of rank (every live edge gets its best collapse and cost), sort (a radix sort on the
// costs' bits) and collapse (cheapest first, each vertex at most once per pass); finally collect
// the garbage. A pass does half of the collapses still needed (at least 1/32 of all), so about
// six to eight passes run. A vertex that survived a collapse is locked until the next pass,
// because the costs of its edges are stale; the costs of all other edges are still exact, since a
// collapse changes no other vertex's quadric, so the next pass re-ranks only the survivors' edges.
// No allocation happens per collapse.
#include "hedge/algorithms/decimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/edge_operations.h"
#include "hedge/error.h"

namespace hedge {

namespace {

using Mesh = SurfaceMesh;

// Sum of weighted squared distances to planes n.x + d = 0: x'Ax + 2b'x + c, with A symmetric
// (a00 a01 a02 a11 a12 a22) and w the total weight of the geometric planes.
// Directions of a quadric whose eigenvalue is below this fraction of the largest are left
// undetermined by the placement (see Quadric::minimiser).
constexpr double kRankTolerance = 1e-3;

// A collapse in a flat region (its error at most kFlat times its edge's squared length, a
// root-mean-square distance of 1/1000 of the edge) may not make a face whose quality,
// 4 sqrt(3) area / (sum of its squared edge lengths) (1 for an equilateral triangle, 0 for a
// degenerate one), is below kMinQuality, unless a face around the edge is already that bad and the
// worst new face is no worse than it. 0.1 is a needle with an angle of about 3.3 degrees. Where
// every collapse is free, the error cannot tell them apart and the shape decides; elsewhere the
// error alone does. When this check alone stops the decimation short of its target, it is lifted
// for the rest of the run.
constexpr double kMinQuality = 0.1, kFlat = 1e-6;

struct Quadric {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0, b0 = 0, b1 = 0, b2 = 0, c = 0, w = 0;

  void add(const Quadric& q) {
    a00 += q.a00, a01 += q.a01, a02 += q.a02, a11 += q.a11, a12 += q.a12, a22 += q.a22;
    b0 += q.b0, b1 += q.b1, b2 += q.b2, c += q.c, w += q.w;
  }
  // Adds weight x (n.x + d)^2; n need not be unit length (its length scales the term).
  void add_plane(const Vec3d& n, double d, double weight) {
    a00 += weight * n.x * n.x, a01 += weight * n.x * n.y, a02 += weight * n.x * n.z;
    a11 += weight * n.y * n.y, a12 += weight * n.y * n.z, a22 += weight * n.z * n.z;
    b0 += weight * d * n.x, b1 += weight * d * n.y, b2 += weight * d * n.z;
    c += weight * d * d;
  }
  double eval(const Vec3d& p) const {
    const double x = p.x, y = p.y, z = p.z;
    return x * (a00 * x + 2 * (a01 * y + a02 * z + b0)) + y * (a11 * y + 2 * (a12 * z + b1)) +
           z * (a22 * z + 2 * b2) + c;
  }
  // (A + c u u^T)^-1 v, for a unit u (c = 0: A^-1 v); false if singular.
  bool solve(const Vec3d& u, double c, const Vec3d& v, Vec3d& x) const {
    const double m00 = a00 + c * u.x * u.x, m01 = a01 + c * u.x * u.y, m02 = a02 + c * u.x * u.z;
    const double m11 = a11 + c * u.y * u.y, m12 = a12 + c * u.y * u.z, m22 = a22 + c * u.z * u.z;
    const double c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
    const double det = m00 * c00 + m01 * c01 + m02 * c02;
    if (!(std::abs(det) > 0)) return false;
    const double c11 = m00 * m22 - m02 * m02, c12 = m01 * m02 - m00 * m12, c22 = m00 * m11 - m01 * m01;
    const double inv = 1 / det;
    x = {inv * (c00 * v.x + c01 * v.y + c02 * v.z), inv * (c01 * v.x + c11 * v.y + c12 * v.z),
         inv * (c02 * v.x + c12 * v.y + c22 * v.z)};
    return true;
  }

  // The eigenvalues of A, largest first (the closed form for symmetric 3x3 matrices).
  std::array<double, 3> eigenvalues() const {
    const double q = (a00 + a11 + a22) / 3;
    const double off = a01 * a01 + a02 * a02 + a12 * a12;
    const double p2 = (a00 - q) * (a00 - q) + (a11 - q) * (a11 - q) + (a22 - q) * (a22 - q) + 2 * off;
    const double p = std::sqrt(p2 / 6);
    if (!(p > 0)) return {q, q, q};
    // B = (A - q I) / p; its eigenvalues are 2 cos(phi + 2 pi k / 3), with cos(3 phi) = det(B) / 2.
    const double b00 = (a00 - q) / p, b11 = (a11 - q) / p, b22 = (a22 - q) / p, b01 = a01 / p, b02 = a02 / p,
                 b12 = a12 / p;
    const double det =
        b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
    const double phi = std::acos(std::clamp(det / 2, -1.0, 1.0)) / 3;
    const double l0 = q + 2 * p * std::cos(phi), l2 = q + 2 * p * std::cos(phi + 2 * std::numbers::pi / 3);
    return {l0, 3 * q - l0 - l2, l2};
  }

  // A unit vector spanning the image of (A - x I)(A - y I): the eigenvector of the third eigenvalue
  // when x and y are the other two. False if that product vanishes.
  bool eigenvector(double x, double y, Vec3d& u) const {
    const Vec3d r0{a00 - x, a01, a02}, r1{a01, a11 - x, a12}, r2{a02, a12, a22 - x};
    const Vec3d s0{a00 - y, a01, a02}, s1{a01, a11 - y, a12}, s2{a02, a12, a22 - y};
    // Columns of the (symmetric) product.
    const Vec3d col[3] = {{dot(r0, s0), dot(r1, s0), dot(r2, s0)},
                          {dot(r0, s1), dot(r1, s1), dot(r2, s1)},
                          {dot(r0, s2), dot(r1, s2), dot(r2, s2)}};
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (dot(col[i], col[i]) > dot(col[k], col[k])) k = i;
    const double l = norm(col[k]);
    if (!(l > 0)) return false;
    u = col[k] / l;
    return true;
  }

  // The point that minimises the quadric near `mid`, in the directions the quadric determines:
  // A's eigenvectors whose eigenvalue is at least kRankTolerance times the largest (a truncated
  // pseudo-inverse, as in Lindstrom and Turk's placement). Along the others (the plane of a flat
  // patch, the axis of a cylinder, the tangent plane where curvature is low) the point stays at
  // `mid`. The test is a ratio of eigenvalues, so it does not depend on the mesh's scale. If the
  // point lies farther than sqrt(max_dist2) from mid, the weakest direction kept is dropped and the
  // point found again. False if no direction is left or a value is not finite.
  bool minimiser(const Vec3d& mid, double max_dist2, Vec3d& p) const {
    const double tr = a00 + a11 + a22;
    if (!(tr > 0)) return false;
    const Vec3d g{a00 * mid.x + a01 * mid.y + a02 * mid.z + b0, a01 * mid.x + a11 * mid.y + a12 * mid.z + b1,
                  a02 * mid.x + a12 * mid.y + a22 * mid.z + b2};
    auto accept = [&](const Vec3d& d) {
      if (!(dot(d, d) <= max_dist2)) return false;
      p = mid - d;
      return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    // Fast path: det >= kRankTolerance tr^3 / 4 implies the smallest eigenvalue is at least
    // kRankTolerance times the largest (lambda_min >= 4 det / tr^2 and lambda_max <= tr).
    const double det =
        a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02) + a02 * (a01 * a12 - a11 * a02);
    Vec3d d;
    const bool full = det >= 0.25 * kRankTolerance * tr * tr * tr;
    if (full && solve({0, 0, 0}, 0, g, d) && accept(d)) return true;
    const std::array<double, 3> l = eigenvalues();
    int rank = 1;
    while (rank < 3 && l[rank] >= kRankTolerance * l[0]) ++rank;
    if (rank == 3 && !full && solve({0, 0, 0}, 0, g, d) && accept(d)) return true;
    Vec3d u;
    // Rank 2: solve in the plane normal to the weakest eigenvector u (A + l0 u u^T has the same
    // eigenvectors, with u's eigenvalue lifted, and g is projected off u).
    if (rank >= 2 && eigenvector(l[0], l[1], u) && solve(u, l[0], g - u * dot(u, g), d) && accept(d))
      return true;
    // Rank 1: along the strongest eigenvector only.
    return eigenvector(l[1], l[2], u) && accept(u * (dot(u, g) / l[0]));
  }
};

Quadric sum(const Quadric& a, const Quadric& b) {
  Quadric q = a;
  q.add(b);
  return q;
}

// Squared distance-like error of q at p: the weighted mean of the squared plane distances.
inline double error_at(const Quadric& q, const Vec3d& p) {
  const double e = q.eval(p);
  return q.w > 0 ? std::max(0.0, e) / q.w : std::max(0.0, e);
}

template <typename T>
inline void prefetch(const T* p) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

std::string vertex_name(Vertex v) { return "vertex " + std::to_string(v.idx()); }

void check(const Mesh& m, const DecimateOptions& o) {
  auto non_negative = [](double x, const char* name) {
    if (!(x >= 0) || !std::isfinite(x))
      throw InvalidInputError(std::string("decimate: ") + name + " must be finite and not negative, got " +
                              std::to_string(x));
  };
  if (!(o.max_error >= 0))
    throw InvalidInputError("decimate: max_error must not be negative or NaN, got " +
                            std::to_string(o.max_error));
  non_negative(o.boundary_weight, "boundary_weight");
  non_negative(o.feature_weight, "feature_weight");
  non_negative(o.feature_angle_degrees, "feature_angle_degrees");
  non_negative(o.attribute_weight, "attribute_weight");
  if (!(o.max_normal_change_degrees > 0 && o.max_normal_change_degrees <= 180))
    throw InvalidInputError("decimate: max_normal_change_degrees must be in (0, 180], got " +
                            std::to_string(o.max_normal_change_degrees));
  for (Face f : m.faces())
    if (m.valence(f) != 3)
      throw InvalidInputError("decimate: face " + std::to_string(f.idx()) + " has " +
                              std::to_string(m.valence(f)) +
                              " corners; decimation needs triangles (triangulate first)");
  require_finite_positions(m, "decimate");
  for (Vertex v : m.vertices()) {
    if (!m.is_manifold(v))
      throw InvalidInputError("decimate: " + vertex_name(v) +
                              " is not manifold (its faces form more than one fan)");
  }
}

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
  // may not collapse either way.
  bool best_collapse(Edge e, Halfedge& h, Vec3d& p, double& cost) const;
  bool placement(Halfedge h, Vec3d& p, double& cost) const;
  enum class Check { ok, normal, shape };
  Check check_faces(Halfedge h, const Vec3d& p, bool shape) const;
  void gather_ring(Halfedge h);
  void interpolate_corners(Vertex v, const Vec3d& p);
  void sort_candidates();

  Mesh& m_;
  const DecimateOptions& o_;
  Vec3* pos_;
  HalfedgeProperty<Vec2> uv_;
  EdgeProperty<std::uint8_t> crease_;
  bool seams_ = false;
  double min_cos_ = 0, max_cost_ = 0, tiny_area2_ = 0;

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

  // One collapse's ring: the triangles around both ends before it, their corners' positions and
  // texture coordinates, and which chart (faces joined across non-seam edges) each belongs to.
  struct RingFace {
    Face f;
    std::array<Vec3d, 3> x;
    std::array<Vec2, 3> uv;
    std::uint32_t chart;
  };
  std::vector<RingFace> ring_;
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

// A seam edge: an interior edge whose two faces give one of its ends different texture coordinates.
// The corner of vertex x in face f is stored on the half-edge entering x in f.
bool Decimator::seam(Edge e) const {
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  if (m_.is_boundary(h) || m_.is_boundary(t)) return false;
  const Halfedge hp = m_.next(m_.next(h)), tp = m_.next(m_.next(t));
  return uv_[h] != uv_[tp] || uv_[hp] != uv_[t];
}

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
  p = to_double(to_float(p));
  cost = error_at(q, p);
  return true;
}

bool Decimator::best_collapse(Edge e, Halfedge& h, Vec3d& p, double& cost) const {
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
      return placement(h, p, cost);
    }
    Vec3d p0, p1;
    double c0, c1;
    placement(h0, p0, c0);
    if (!f0) {
      h = p0 == pos(m_.to_vertex(h1)) ? h1 : h0;
      p = p0, cost = c0;
      return true;
    }
    placement(h1, p1, c1);
    if (c1 < c0)
      h = h1, p = p1, cost = c1;
    else
      h = h0, p = p0, cost = c0;
    return true;
  }
  h = go0 ? h0 : h1;
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

// Before collapsing h: the triangles around both ends, their corners, and their charts (faces
// joined across spoke edges that are not seams, with union-find over the ring's slots).
void Decimator::gather_ring(Halfedge h) {
  ring_.clear();
  for (const Halfedge start : {h, Mesh::twin(h)}) {
    Halfedge o = start;
    do {
      const Face f = m_.face(o);
      if (f.is_valid() && (start == h || (f != m_.face(h) && f != m_.face(Mesh::twin(h))))) {
        const Halfedge o1 = m_.next(o), o2 = m_.next(o1);
        RingFace r{f,
                   {pos(m_.to_vertex(o2)), pos(m_.to_vertex(o)), pos(m_.to_vertex(o1))},
                   {uv_[o2], uv_[o], uv_[o1]},
                   std::uint32_t(ring_.size())};
        ring_.push_back(r);
      }
      o = m_.rotate_cw(o);
    } while (o != start);
  }
  auto find = [&](std::uint32_t i) {
    while (ring_[i].chart != i) i = ring_[i].chart = ring_[ring_[i].chart].chart;
    return i;
  };
  auto slot = [&](Face f) -> std::uint32_t {
    for (std::uint32_t i = 0; i < ring_.size(); ++i)
      if (ring_[i].f == f) return i;
    return std::uint32_t(-1);
  };
  // Every spoke edge of both ends (h's edge included): join its faces unless it is a seam.
  for (const Halfedge start : {h, Mesh::twin(h)}) {
    Halfedge o = start;
    do {
      const Face f0 = m_.face(o), f1 = m_.face(Mesh::twin(o));
      if (f0.is_valid() && f1.is_valid() && !seam(Mesh::edge(o))) {
        const std::uint32_t i = slot(f0), j = slot(f1);
        if (i != std::uint32_t(-1) && j != std::uint32_t(-1)) ring_[find(i)].chart = find(j);
      }
      o = m_.rotate_cw(o);
    } while (o != start);
  }
  for (std::uint32_t i = 0; i < ring_.size(); ++i) ring_[i].chart = find(i);
}

// After the collapse: each corner at v gets the texture coordinates at p of the nearest old
// triangle of its own chart (barycentric, clamped to the triangle).
void Decimator::interpolate_corners(Vertex v, const Vec3d& p) {
  const Halfedge start = m_.halfedge(v);
  Halfedge o = start;
  do {
    const Halfedge in = Mesh::twin(o);
    const Face f = m_.face(in);
    if (f.is_valid()) {
      std::uint32_t chart = std::uint32_t(-1);
      for (const RingFace& r : ring_)
        if (r.f == f) chart = r.chart;
      double best = HUGE_VAL;
      Vec2 value = uv_[in];
      for (const RingFace& r : ring_) {
        if (r.chart != chart) continue;
        const Vec3d e1 = r.x[1] - r.x[0], e2 = r.x[2] - r.x[0], d = p - r.x[0];
        const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
        const double det = d11 * d22 - d12 * d12;
        if (!(det > 0)) continue;
        const double t1 = dot(d, e1), t2 = dot(d, e2);
        double b1 = (d22 * t1 - d12 * t2) / det, b2 = (d11 * t2 - d12 * t1) / det, b0 = 1 - b1 - b2;
        b0 = std::max(0.0, b0), b1 = std::max(0.0, b1), b2 = std::max(0.0, b2);
        const double s = b0 + b1 + b2;
        b0 /= s, b1 /= s, b2 /= s;
        const Vec3d q = r.x[0] * b0 + r.x[1] * b1 + r.x[2] * b2 - p;
        const double dist = dot(q, q);
        if (dist < best) {
          best = dist;
          value = Vec2{float(b0 * r.uv[0].x + b1 * r.uv[1].x + b2 * r.uv[2].x),
                       float(b0 * r.uv[0].y + b1 * r.uv[1].y + b2 * r.uv[2].y)};
        }
      }
      uv_[in] = value;
    }
    o = m_.rotate_cw(o);
  } while (o != start);
}

// LSD radix sort of the keys by their upper 32 bits (the costs' float bits, which order like the
// non-negative floats), in three passes of 11 bits.
void Decimator::sort_candidates() {
  scratch_.resize(keys_.size());
  for (int shift = 32; shift < 64; shift += 11) {
    std::array<std::uint32_t, 2048> count{};
    for (const std::uint64_t k : keys_) ++count[(k >> shift) & 2047];
    std::uint32_t total = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t n = c;
      c = total;
      total += n;
    }
    for (const std::uint64_t k : keys_) scratch_[count[(k >> shift) & 2047]++] = k;
    keys_.swap(scratch_);
  }
}

DecimateResult Decimator::run() {
  DecimateResult result;
  report_progress(o_.progress, 0);
  const std::size_t initial = needed();
  if (initial == 0 || m_.n_faces() == 0) {
    result.vertices = m_.n_vertices(), result.faces = m_.n_faces();
    result.stop = initial == 0 ? DecimateStop::target_reached : DecimateStop::no_legal_collapse;
    report_progress(o_.progress, 1);
    return result;
  }
  gather_quadrics();
  stamp_.assign(m_.vertex_slots(), 0);
  edge_key_.assign(m_.edge_slots(), kNoKey);
  double max_cost = 0;
  bool over_error = false;  // a candidate of this pass exceeded max_error
  bool shapely = true;      // the shape check is on (see check_faces)
  const bool endless = o_.target_vertices == 0 && o_.target_faces == 0;
  for (std::uint32_t pass = 1;; ++pass) {
    classify();
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
      if (pass == 1 || stamp_[m_.to_vertex(h0).idx()] == pass - 1 ||
          stamp_[m_.from_vertex(h0).idx()] == pass - 1) {
        Halfedge h;
        Vec3d p;
        double cost;
        key = kNoKey;
        if (best_collapse(e, h, p, cost)) {
          if (cost <= max_cost_)
            key = std::uint64_t(float_bits(static_cast<float>(cost))) << 32 | h.idx();
          else
            key = kOverError;
        }
      }
      if (key == kOverError) {
        over_error = true;
        continue;
      }
      if (key != kNoKey) keys_.push_back(key);
    }
    sort_candidates();
    // Collapse: cheapest first, half of what is still needed, each vertex once.
    // Half of what is still needed, but not less than 1/32 of the whole, so that the tail of
    // ever smaller passes (each a full re-sort) stops after a few.
    const std::size_t budget =
        endless ? keys_.size() : std::max<std::size_t>({1, (needed() + 1) / 2, initial / 32});
    std::size_t done_now = 0, refused_shape_now = 0, refused_normal_now = 0;
    const std::size_t n_keys = keys_.size();
    // Nor beyond 16x the cost of the budget-th cheapest candidate: when locked vertices skip cheap
    // candidates, the pass ends rather than reaching for much dearer ones, which the next pass may
    // not need (a refined flat region, all of whose cheapest collapses cost 0, collapses back
    // exactly this way). Adding 4 to a float's exponent bits multiplies it by 16. Unless nothing was
    // done yet, so that illegal cheap candidates cannot stop the decimation.
    // A candidate the shape check refuses moves the limit on by one: it is not waiting for a locked
    // vertex, and in a flat region, where every cost is 0, the limit would otherwise end the pass
    // at its first refusals.
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
        for (const Vertex v : {to[h8], to[h8 ^ 1u]}) {
          prefetch(pos_ + v.idx());
          prefetch(q_.data() + v.idx());
          prefetch(reinterpret_cast<const char*>(q_.data() + v.idx()) + 64);  // a quadric spans two lines
          prefetch(stamp_.data() + v.idx());
        }
      }
      if ((keys_[k] >> 32) > cost_limit && done_now > 0) break;
      const Halfedge h(static_cast<Index>(keys_[k] & 0xffffffffu));
      if (m_.is_deleted(h)) continue;
      const Vertex a = m_.from_vertex(h), b = m_.to_vertex(h);
      if (stamp_[a.idx()] == pass || stamp_[b.idx()] == pass) continue;
      Vec3d p;
      double cost;
      placement(h, p, cost);
      if (!(cost <= max_cost_)) {
        over_error = true;
        continue;
      }
      if (const Check c = check_faces(h, p, shapely && cost <= kFlat * dot(pos(a) - pos(b), pos(a) - pos(b)));
          c != Check::ok) {
        ++(c == Check::normal ? result.refused.normal : result.refused.shape);
        refused_shape_now += c == Check::shape;
        if (c == Check::shape && limit_index + 1 < n_keys)
          cost_limit = (keys_[++limit_index] >> 32) + (4u << 23);
        refused_normal_now += c == Check::normal;
        continue;
      }
      if (uv_) gather_ring(h);
      if (!collapse(m_, h).is_valid()) {
        ++result.refused.topology;
        continue;
      }
      pos_[b.idx()] = to_float(p);
      q_[b.idx()].add(q_[a.idx()]);
      stamp_[b.idx()] = pass;
      if (uv_) interpolate_corners(b, p);
      max_cost = std::max(max_cost, cost);
      ++result.collapses;
      ++done_now;
      if (done() || done_now >= budget) break;
    }
    if (!endless)
      report_progress(o_.progress, double(initial - std::min(initial, needed())) / double(initial));
    if (done()) break;
    if (done_now == 0 && refused_shape_now > 0) {
      // The shape check alone may stop the decimation short of its target: lift it, and go on.
      shapely = false;
      continue;
    }
    if (done_now == 0 && refused_normal_now > 0 && min_cos_ > 0 && o_.relax_normal_change) {
      // Likewise the turn limit, when it is below 90 degrees: faces may turn up to 90 degrees (never
      // over) for the rest of the run, so that coarse targets are reached.
      min_cos_ = 0;
      continue;
    }
    if (done_now == 0) {
      result.stop = over_error ? DecimateStop::error_bound : DecimateStop::no_legal_collapse;
      break;
    }
  }
  if (result.collapses > 0) {
    m_.garbage_collection();
  }
  result.vertices = m_.n_vertices(), result.faces = m_.n_faces();
  result.max_error = std::sqrt(max_cost);
  report_progress(o_.progress, 1);
  return result;
}

}  // namespace

DecimateResult decimate(SurfaceMesh& mesh, const DecimateOptions& options) {
  check(mesh, options);
  Decimator d(mesh, options);
  return d.run();
}

}  // namespace hedge

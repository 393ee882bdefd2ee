#include "hedge/algorithms/smooth.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/error.h"

namespace hedge {

namespace {

void check(const SurfaceMesh& m, const SmoothOptions& o) {
  if (o.iterations < 0 || o.iterations > 100000)
    throw InvalidInputError("smooth: iterations must be in 0..100000, got " + std::to_string(o.iterations));
  if (o.method == SmoothMethod::implicit) {
    if (!(o.lambda > 0 && std::isfinite(o.lambda)))
      throw InvalidInputError("smooth: the implicit time step lambda must be positive, got " +
                              std::to_string(o.lambda));
  } else if (!(o.lambda > 0 && o.lambda <= 1)) {
    throw InvalidInputError("smooth: lambda must be in (0, 1], got " + std::to_string(o.lambda));
  }
  if (o.method == SmoothMethod::taubin && !(o.mu < -o.lambda && o.mu >= -1))
    throw InvalidInputError("smooth: Taubin's mu must be in [-1, -lambda), got " + std::to_string(o.mu));
  if (!o.mask.empty() && o.mask.size() != m.vertex_slots())
    throw InvalidInputError("smooth: the mask has " + std::to_string(o.mask.size()) + " entries for " +
                            std::to_string(m.vertex_slots()) + " vertex slots");
  if (o.method == SmoothMethod::cotangent || o.method == SmoothMethod::implicit)
    for (Face f : m.faces())
      if (m.valence(f) != 3)
        throw InvalidInputError("smooth: cotangent weights need triangles, and face " +
                                std::to_string(f.idx()) + " has " + std::to_string(m.valence(f)) +
                                " corners (triangulate first)");
}

// Each vertex's stiffness: the sum of the magnitudes of the cotangent weights (geometry.h) of its
// edges, 0 for a vertex whose faces are all degenerate. Dividing a vertex's Laplacian by it gives a
// step relative to the local size, like dividing by its area (a mass), but bounded: the cotangent
// stiffness satisfies x^T L x <= 2 x^T S x, so explicit steps with lambda in (0, 1] never grow
// (in the norm of S), whatever the mesh's angles.
std::vector<double> stiffness(const SurfaceMesh& m, const std::vector<double>& w) {
  std::vector<double> s(m.vertex_slots(), 0);
  for (Edge e : m.edges()) {
    const double a = std::abs(w[e.idx()]);
    s[m.vertex(e, 0).idx()] += a;
    s[m.vertex(e, 1).idx()] += a;
  }
  return s;
}

// The one-rings of some vertices, flattened once so that each explicit step reads them in order
// instead of circulating the half-edges: neighbour and edge of every outgoing half-edge.
struct Rings {
  std::vector<Index> start, vertex, edge;  // start: per vertex slot, plus one for the end
  // The rings of the vertices whose mode is 1 (moving interior vertices); empty ones elsewhere.
  Rings(const SurfaceMesh& m, const std::vector<std::uint8_t>& mode) : start(m.vertex_slots() + 1, 0) {
    vertex.reserve(2 * m.n_edges());
    edge.reserve(2 * m.n_edges());
    for (std::size_t i = 0; i < m.vertex_slots(); ++i) {
      start[i] = Index(vertex.size());
      if (mode[i] != 1) continue;
      for (Halfedge h : m.halfedges(Vertex(Index(i)))) {
        vertex.push_back(m.to_vertex(h).idx());
        edge.push_back(SurfaceMesh::edge(h).idx());
      }
    }
    start.back() = Index(vertex.size());
  }
};

// Keeps every triangle's normal within 90 degrees of its normal before smoothing: a step that
// would turn a triangle further, or collapse it to zero area, is withheld from the triangle's
// corners (they stay where the previous step left them), in rounds until no triangle would. Each
// round reverts the corners of all offending triangles at once, so the result does not depend on
// the numbering; it ends because the previous step's positions pass. Triangles of zero area at the
// start have no direction to keep and are not checked.
class FoldGuard {
 public:
  FoldGuard(const SurfaceMesh& m, const std::vector<Vec3d>& p) : positions_(p) {
    triangles_.reserve(m.n_faces());
    for (Face f : m.faces()) {
      const Halfedge h = m.halfedge(f);
      const Triangle t{{m.from_vertex(h).idx(), m.to_vertex(h).idx(), m.to_vertex(m.next(h)).idx()}, {}};
      const Vec3 n = to_float(unit_or_zero(normal(t, p)));
      if (dot(n, n) > 0) triangles_.push_back({t.corner, n});
    }
  }
  // The last check, on the positions as they will be stored (in float): rounding can still turn a
  // nearly degenerate triangle, whose corners then go back to where they started.
  void apply_rounded(const SurfaceMesh& m, std::vector<Vec3d>& p) {
    for (Vertex v : m.vertices()) p[v.idx()] = rounded_to_float(p[v.idx()]);
    apply(positions_, p);
  }
  void apply(const std::vector<Vec3d>& previous, std::vector<Vec3d>& next) {
    for (;;) {
      revert_.clear();
      for (const Triangle& t : triangles_)
        if (!(dot(to_double(t.start), normal(t, next)) > 0))
          for (Index i : t.corner)
            if (next[i] != previous[i]) revert_.push_back(i);
      if (revert_.empty()) return;
      for (Index i : revert_) next[i] = previous[i];
    }
  }

 private:
  struct Triangle {
    std::array<Index, 3> corner;
    Vec3 start;  // the unit normal at the start (float: it only tells which side is up)
  };
  static Vec3d normal(const Triangle& t, const std::vector<Vec3d>& p) {
    const Vec3d& a = p[t.corner[0]];
    return cross(p[t.corner[1]] - a, p[t.corner[2]] - a);
  }
  std::vector<Vec3d> positions_;     // at the start
  std::vector<Triangle> triangles_;  // those of positive area at the start
  std::vector<Index> revert_;
};

// Backward Euler steps of the cotangent flow with each vertex's time step relative to its own size:
// (S + lambda L) x' = S x over the moving vertices, the fixed ones moved to the right-hand side, with
// the stiffness S (above) as the mass. S + lambda L is symmetric positive definite (L is positive
// semidefinite with any angles), and a plane (L x = 0) is a fixed point.
void smooth_implicit(const SurfaceMesh& m, const SmoothOptions& o, const std::vector<std::uint8_t>& moving,
                     FoldGuard& guard, std::vector<Vec3d>& p) {
  const std::size_t nv = m.vertex_slots();
  std::vector<Index> unknown(nv, kInvalidIndex);
  Index n = 0;
  for (Vertex v : m.vertices())
    if (moving[v.idx()] != 0) unknown[v.idx()] = n++;
  if (n == 0) return;
  const std::vector<double> w = cotangent_weights(m, p);
  std::vector<double> mass = stiffness(m, w);
  for (double& x : mass)
    if (!(x > 0)) x = 1;  // a vertex with no stiffness has no Laplacian either: it stays
  const double t = o.lambda;
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> diagonal(n, 0);
  for (Vertex v : m.vertices()) {
    const Index i = unknown[v.idx()];
    if (i == kInvalidIndex) continue;
    diagonal[i] += mass[v.idx()];
    for (Halfedge h : m.halfedges(v)) {
      const double wij = t * w[SurfaceMesh::edge(h).idx()];
      diagonal[i] += wij;
      const Index j = unknown[m.to_vertex(h).idx()];
      if (j != kInvalidIndex) entries.emplace_back(i, j, -wij);
    }
  }
  for (Index i = 0; i < n; ++i) entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success)
    throw InvalidInputError("smooth: the implicit system could not be factored (degenerate faces?)");
  // The factorisation counts as one step of the work.
  const double steps = double(o.iterations) + 1;
  report_progress(o.progress, 1 / steps);
  Eigen::MatrixXd rhs(n, 3), x(n, 3);
  std::vector<Vec3d> next;
  for (int it = 0; it < o.iterations; ++it) {
    for (Vertex v : m.vertices()) {
      const Index i = unknown[v.idx()];
      if (i == kInvalidIndex) continue;
      Vec3d r = p[v.idx()] * mass[v.idx()];
      for (Halfedge h : m.halfedges(v)) {
        const Vertex u = m.to_vertex(h);
        if (unknown[u.idx()] == kInvalidIndex) r += p[u.idx()] * (t * w[SurfaceMesh::edge(h).idx()]);
      }
      rhs(i, 0) = r.x, rhs(i, 1) = r.y, rhs(i, 2) = r.z;
    }
    x = solver.solve(rhs);
    next = p;
    for (Vertex v : m.vertices()) {
      const Index i = unknown[v.idx()];
      if (i != kInvalidIndex) next[v.idx()] = Vec3d{x(i, 0), x(i, 1), x(i, 2)};
    }
    guard.apply(p, next);
    std::swap(p, next);
    report_progress(o.progress, double(it + 2) / steps);
  }
}

}  // namespace

void smooth(SurfaceMesh& m, const SmoothOptions& o) {
  check(m, o);
  require_finite_positions(m, "smooth");
  if (o.iterations == 0 || m.n_vertices() == 0) return;
  const std::size_t nv = m.vertex_slots();
  std::vector<Vec3d> p(nv), next(nv);
  for (Vertex v : m.vertices()) p[v.idx()] = to_double(m.position(v));
  // Which vertices move, and how: 0 fixed, 1 interior, 2 along the boundary.
  std::vector<std::uint8_t> mode(nv, 0);
  for (Vertex v : m.vertices()) {
    if (m.is_isolated(v) || (!o.mask.empty() && o.mask[v.idx()] == 0)) continue;
    mode[v.idx()] = m.is_boundary(v) ? (o.fix_boundary ? 0 : 2) : 1;
  }
  if (o.method == SmoothMethod::implicit) {
    std::vector<std::uint8_t> moving(nv, 0);
    for (std::size_t i = 0; i < nv; ++i) moving[i] = mode[i] == 1 || mode[i] == 2;
    // A free boundary is solved for with the interior: it follows the cotangent flow of its
    // one-sided neighbourhood rather than the boundary curve alone (see the header).
    FoldGuard guard(m, p);
    smooth_implicit(m, o, moving, guard, p);
    guard.apply_rounded(m, p);
  } else {
    std::vector<double> w;
    std::optional<FoldGuard> guard;
    std::optional<Rings> rings;
    if (o.method == SmoothMethod::cotangent) {
      guard.emplace(m, p);
      rings.emplace(m, mode);
    }
    auto step = [&](double factor) {
      if (o.method == SmoothMethod::cotangent) w = cotangent_weights(m, p);
      for (Vertex v : m.vertices()) {
        const std::size_t i = v.idx();
        next[i] = p[i];
        if (mode[i] == 0) continue;
        if (o.method == SmoothMethod::cotangent && mode[i] == 1) {
          // x += lambda S^-1 L x: linear precision (a plane is a fixed point) with negative
          // weights kept, and a step relative to the vertex's size.
          Vec3d laplacian{0, 0, 0};
          double stiffness = 0;
          for (Index k = rings->start[i]; k < rings->start[i + 1]; ++k) {
            const double wh = w[rings->edge[k]];
            laplacian += (p[rings->vertex[k]] - p[i]) * wh;
            stiffness += std::abs(wh);
          }
          if (stiffness > 0) next[i] = p[i] + laplacian * (factor / stiffness);
          continue;
        }
        Vec3d sum{0, 0, 0};
        double weight = 0;
        for (Halfedge h : m.halfedges(v)) {
          if (mode[i] == 2 && !m.is_boundary(SurfaceMesh::edge(h))) continue;
          sum += p[m.to_vertex(h).idx()];
          weight += 1;
        }
        if (weight > 0) next[i] = p[i] + (sum * (1 / weight) - p[i]) * factor;
      }
      if (guard) guard->apply(p, next);
      std::swap(p, next);
    };
    for (int it = 0; it < o.iterations; ++it) {
      step(o.lambda);
      if (o.method == SmoothMethod::taubin) step(o.mu);
      report_progress(o.progress, double(it + 1) / double(o.iterations));
    }
    if (guard) guard->apply_rounded(m, p);
  }
  // The change log first: recording may allocate (when the mesh is watched), the writes cannot, so
  // a std::bad_alloc leaves the positions as they were.
  for (Vertex v : m.vertices())
    if (mode[v.idx()] != 0) m.mark_changed(v, ChangeEvent::vertices_moved);
  for (Vertex v : m.vertices())
    if (mode[v.idx()] != 0) m.position(v) = to_float(p[v.idx()]);
  m.changes().notify();
}

}  // namespace hedge

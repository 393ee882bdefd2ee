#include "hedge/algorithms/smooth.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
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

// The cotangent weights (geometry.h) clamped to zero, so that every weight pulls: an edge between
// two obtuse angles would otherwise push its ends apart.
void clamped_cotangent_weights(const SurfaceMesh& m, const std::vector<Vec3d>& p, std::vector<double>& w) {
  w = cotangent_weights(m, p);
  for (double& x : w) x = std::max(0.0, x);
}

// Backward Euler steps of the cotangent flow: (M + t L) x' = M x over the moving vertices, the
// fixed ones moved to the right-hand side. M: a third of the areas of the faces around each vertex.
void smooth_implicit(const SurfaceMesh& m, const SmoothOptions& o, const std::vector<std::uint8_t>& moving,
                     std::vector<Vec3d>& p) {
  const std::size_t nv = m.vertex_slots();
  std::vector<Index> unknown(nv, kInvalidIndex);
  Index n = 0;
  for (Vertex v : m.vertices())
    if (moving[v.idx()] != 0) unknown[v.idx()] = n++;
  if (n == 0) return;
  std::vector<double> w;
  clamped_cotangent_weights(m, p, w);
  const std::vector<double> mass = vertex_areas(m, p);
  double edge_sum = 0;
  for (Edge e : m.edges()) {
    const Vec3d d = p[m.vertex(e, 0).idx()] - p[m.vertex(e, 1).idx()];
    edge_sum += std::sqrt(dot(d, d));
  }
  const double mean_edge = edge_sum / double(std::max<std::size_t>(1, m.n_edges()));
  const double t = o.lambda * mean_edge * mean_edge;
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
  for (Index i = 0; i < n; ++i) entries.emplace_back(i, i, diagonal[i] > 0 ? diagonal[i] : 1.0);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success)
    throw InvalidInputError("smooth: the implicit system could not be factored (degenerate faces?)");
  // The factorisation counts as one step of the work.
  const double steps = double(o.iterations) + 1;
  report_progress(o.progress, 1 / steps);
  Eigen::MatrixXd rhs(n, 3), x(n, 3);
  for (int it = 0; it < o.iterations; ++it) {
    for (Vertex v : m.vertices()) {
      const Index i = unknown[v.idx()];
      if (i == kInvalidIndex) continue;
      const double mi = mass[v.idx()] > 0 ? mass[v.idx()] : 1.0;
      Vec3d r = p[v.idx()] * mi;
      for (Halfedge h : m.halfedges(v)) {
        const Vertex u = m.to_vertex(h);
        if (unknown[u.idx()] == kInvalidIndex) r += p[u.idx()] * (t * w[SurfaceMesh::edge(h).idx()]);
      }
      rhs(i, 0) = r.x, rhs(i, 1) = r.y, rhs(i, 2) = r.z;
    }
    x = solver.solve(rhs);
    for (Vertex v : m.vertices()) {
      const Index i = unknown[v.idx()];
      if (i != kInvalidIndex) p[v.idx()] = Vec3d{x(i, 0), x(i, 1), x(i, 2)};
    }
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
    smooth_implicit(m, o, moving, p);
  } else {
    std::vector<double> w;
    auto step = [&](double factor) {
      if (o.method == SmoothMethod::cotangent) clamped_cotangent_weights(m, p, w);
      for (Vertex v : m.vertices()) {
        const std::size_t i = v.idx();
        next[i] = p[i];
        if (mode[i] == 0) continue;
        Vec3d sum{0, 0, 0};
        double weight = 0;
        for (Halfedge h : m.halfedges(v)) {
          if (mode[i] == 2 && !m.is_boundary(SurfaceMesh::edge(h))) continue;
          const double wi =
              o.method == SmoothMethod::cotangent && mode[i] == 1 ? w[SurfaceMesh::edge(h).idx()] : 1.0;
          sum += p[m.to_vertex(h).idx()] * wi;
          weight += wi;
        }
        if (weight > 0) next[i] = p[i] + (sum * (1 / weight) - p[i]) * factor;
      }
      std::swap(p, next);
    };
    for (int it = 0; it < o.iterations; ++it) {
      step(o.lambda);
      if (o.method == SmoothMethod::taubin) step(o.mu);
      report_progress(o.progress, double(it + 1) / double(o.iterations));
    }
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

#include "hedge/algorithms/curvature.h"

#include <array>
#include <cmath>
#include <numbers>

#include "hedge/algorithms/geometry.h"

namespace hedge {

namespace {

//! Calls fn(c, p) for every fan triangle (c0, c[i], c[i+1]) of every face: its corners and their
//! positions.
template <typename Fn>
void for_each_fan_triangle(const SurfaceMesh& m, Fn&& fn) {
  for (Face f : m.faces()) {
    const Halfedge h0 = m.halfedge(f);
    const Vertex c0 = m.to_vertex(h0);
    for (Halfedge h = m.next(h0); m.next(h) != h0; h = m.next(h)) {
      const std::array<Vertex, 3> c = {c0, m.to_vertex(h), m.to_vertex(m.next(h))};
      const std::array<Vec3d, 3> p = {to_double(m.position(c[0])), to_double(m.position(c[1])),
                                      to_double(m.position(c[2]))};
      fn(c, p);
    }
  }
}

}  // namespace

std::vector<double> mean_curvature(const SurfaceMesh& m) {
  require_finite_positions(m, "mean_curvature");
  // The cotangent Laplacian sum_j (cot a + cot b) / 2 (p_j - p_i), gathered per fan triangle.
  std::vector<Vec3d> lap(m.vertex_slots(), Vec3d{0, 0, 0});
  for_each_fan_triangle(m, [&](const std::array<Vertex, 3>& c, const std::array<Vec3d, 3>& p) {
    const std::array<double, 3> cot = triangle_cotangents(p[0], p[1], p[2]);
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;  // the side opposite corner k
      lap[c[i].idx()] += (p[j] - p[i]) * (0.5 * cot[k]);
      lap[c[j].idx()] += (p[i] - p[j]) * (0.5 * cot[k]);
    }
  });
  const std::vector<double> area = vertex_areas(m);
  std::vector<double> h(m.vertex_slots(), 0);
  for (Vertex v : m.vertices()) {
    if (m.is_boundary(v) || !(area[v.idx()] > 0)) continue;
    Vec3d normal{0, 0, 0};
    for (Face f : m.faces(v))
      if (f.is_valid()) normal += area_vector(m, f);
    const Vec3d l = lap[v.idx()] * (1 / area[v.idx()]);
    const double magnitude = 0.5 * norm(l);
    // On a convex bump the Laplacian points inward, against the outward normal.
    h[v.idx()] = dot(l, normal) < 0 ? magnitude : -magnitude;
  }
  return h;
}

std::vector<double> gaussian_curvature(const SurfaceMesh& m) {
  require_finite_positions(m, "gaussian_curvature");
  std::vector<double> angle(m.vertex_slots(), 0);
  for_each_fan_triangle(m, [&](const std::array<Vertex, 3>& c, const std::array<Vec3d, 3>& p) {
    for (int k = 0; k < 3; ++k) angle[c[k].idx()] += corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
  });
  const std::vector<double> area = vertex_areas(m);
  std::vector<double> k(m.vertex_slots(), 0);
  for (Vertex v : m.vertices())
    if (!m.is_boundary(v) && area[v.idx()] > 0)
      k[v.idx()] = (2 * std::numbers::pi - angle[v.idx()]) / area[v.idx()];
  return k;
}

}  // namespace hedge

#include "hedge/algorithms/geometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "hedge/core/face_operations.h"
#include "hedge/core/triangulate.h"
#include "hedge/error.h"

namespace hedge {

namespace {

Vec3d at(const SurfaceMesh& m, Vertex v) { return to_double(m.position(v)); }

void check_positions(const SurfaceMesh& m, std::span<const Vec3d> p, const char* function) {
  if (p.size() != m.vertex_slots())
    throw InvalidInputError(std::string(function) + ": " + std::to_string(p.size()) + " positions for " +
                            std::to_string(m.vertex_slots()) + " vertex slots");
}

//! The mesh's positions per vertex slot, in double, for the call `function` names.
std::vector<Vec3d> positions_of(const SurfaceMesh& m, const char* function) {
  require_finite_positions(m, function);
  std::vector<Vec3d> p(m.vertex_slots(), Vec3d{0, 0, 0});
  for (Vertex v : m.vertices()) p[v.idx()] = at(m, v);
  return p;
}

//! The box of the live vertices, positions unchecked (the callers check them once).
BoundingBox box_of(const SurfaceMesh& mesh) {
  BoundingBox box;
  for (Vertex v : mesh.vertices()) {
    const Vec3& p = mesh.position(v);
    if (box.empty) {
      box.min = box.max = p;
      box.empty = false;
      continue;
    }
    for (int a = 0; a < 3; ++a) {
      box.min[a] = std::min(box.min[a], p[a]);
      box.max[a] = std::max(box.max[a], p[a]);
    }
  }
  return box;
}

}  // namespace

double edge_length(const SurfaceMesh& m, Halfedge h) {
  return norm(at(m, m.to_vertex(h)) - at(m, m.from_vertex(h)));
}

double longest_edge(const SurfaceMesh& m, Face f) {
  double best = 0;
  for (Halfedge h : m.halfedges(f)) best = std::max(best, edge_length(m, h));
  return best;
}

double mean_edge_length(const SurfaceMesh& m, Face f) {
  double sum = 0, n = 0;
  for (Halfedge h : m.halfedges(f)) {
    sum += edge_length(m, h);
    n += 1;
  }
  return n > 0 ? sum / n : 0;
}

Vec3d centroid(const SurfaceMesh& m, Face f) { return face_centroid<double>(m, f); }

double corner_angle(const Vec3d& v, const Vec3d& a, const Vec3d& b) {
  const Vec3d x = a - v, y = b - v;
  const double s = norm(cross(x, y)), c = dot(x, y);
  return (s > 0 || c != 0) ? std::atan2(s, c) : 0.0;
}

double triangle_area(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return 0.5 * norm(cross(b - a, c - a));
}

std::array<double, 3> triangle_cotangents(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2) {
  const double a2 = norm(cross(p1 - p0, p2 - p0));  // twice the area
  if (!(a2 > 0) || !std::isfinite(a2)) return {0, 0, 0};
  return {dot(p1 - p0, p2 - p0) / a2, dot(p2 - p1, p0 - p1) / a2, dot(p0 - p2, p1 - p2) / a2};
}

std::vector<double> cotangent_weights(const SurfaceMesh& m, std::span<const Vec3d> p) {
  check_positions(m, p, "cotangent_weights");
  std::vector<double> w(m.edge_slots(), 0);
  for (Face f : m.faces()) {
    if (m.valence(f) != 3)
      throw InvalidInputError("cotangent_weights: face " + std::to_string(f.idx()) + " has " +
                              std::to_string(m.valence(f)) + " corners, not 3 (triangulate first)");
    // Corner k is where h_k ends; the side opposite it is h_{k+1}'s successor, h_{k+2}.
    const Halfedge h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const std::array<double, 3> cot =
        triangle_cotangents(p[m.to_vertex(h0).idx()], p[m.to_vertex(h1).idx()], p[m.to_vertex(h2).idx()]);
    w[SurfaceMesh::edge(h2).idx()] += 0.5 * cot[0];
    w[SurfaceMesh::edge(h0).idx()] += 0.5 * cot[1];
    w[SurfaceMesh::edge(h1).idx()] += 0.5 * cot[2];
  }
  return w;
}

std::vector<double> cotangent_weights(const SurfaceMesh& m) {
  return cotangent_weights(m, positions_of(m, "cotangent_weights"));
}

std::vector<double> vertex_areas(const SurfaceMesh& m, std::span<const Vec3d> p) {
  check_positions(m, p, "vertex_areas");
  std::vector<double> area(m.vertex_slots(), 0);
  for (Face f : m.faces()) {
    const Halfedge h0 = m.halfedge(f);
    const Vertex c0 = m.to_vertex(h0);
    for (Halfedge h = m.next(h0); m.next(h) != h0; h = m.next(h)) {
      const Vertex c1 = m.to_vertex(h), c2 = m.to_vertex(m.next(h));
      const double third = norm(cross(p[c1.idx()] - p[c0.idx()], p[c2.idx()] - p[c0.idx()])) / 6;
      area[c0.idx()] += third;
      area[c1.idx()] += third;
      area[c2.idx()] += third;
    }
  }
  return area;
}

std::vector<double> vertex_areas(const SurfaceMesh& m) {
  return vertex_areas(m, positions_of(m, "vertex_areas"));
}

Vec3d area_vector(const SurfaceMesh& m, Face f) {
  Vec3d n{0, 0, 0};
  for (Halfedge h : m.halfedges(f)) add_newell_term(n, at(m, m.from_vertex(h)), at(m, m.to_vertex(h)));
  return n;
}

double face_area(const SurfaceMesh& mesh, Face f) {
  const Vec3d n = area_vector(mesh, f);
  return 0.5 * std::sqrt(dot(n, n));
}

double surface_area(const SurfaceMesh& mesh) {
  require_finite_positions(mesh, "surface_area");
  double sum = 0;
  for (Face f : mesh.faces()) sum += face_area(mesh, f);
  return sum;
}

BoundingBox bounding_box(const SurfaceMesh& mesh) {
  require_finite_positions(mesh, "bounding_box");
  return box_of(mesh);
}

double volume(const SurfaceMesh& mesh) {
  std::size_t open = 0;
  for (Halfedge h : mesh.halfedges()) open += mesh.is_boundary(h);
  if (open > 0)
    throw InvalidInputError("volume: the surface is open (" + std::to_string(open) +
                            " boundary half-edges), so it encloses no volume");
  require_finite_positions(mesh, "volume");
  // About the box centre, which keeps the terms small and the cancellation mild.
  const Vec3d c = to_double(box_of(mesh).centre());
  double six_v = 0;
  for (Face f : mesh.faces()) {
    const Halfedge h0 = fan_start(mesh, f);  // the fan the picking tree and solid fracture use
    const Vec3d p0 = to_double(mesh.position(mesh.to_vertex(h0))) - c;
    for (Halfedge g = mesh.next(mesh.next(h0)); g != h0; g = mesh.next(g)) {
      const Vec3d p1 = to_double(mesh.position(mesh.from_vertex(g))) - c;
      const Vec3d p2 = to_double(mesh.position(mesh.to_vertex(g))) - c;
      six_v += dot(p0, cross(p1, p2));
    }
  }
  return six_v / 6;
}

}  // namespace hedge

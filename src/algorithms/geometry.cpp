#include "hedge/algorithms/geometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "hedge/error.h"

namespace hedge {

Vec3d area_vector(const SurfaceMesh& m, Face f) {
  Vec3d n{0, 0, 0};
  for (Halfedge h : m.halfedges(f)) {
    const Vec3d a = to_double(m.position(m.from_vertex(h))), b = to_double(m.position(m.to_vertex(h)));
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

double face_area(const SurfaceMesh& mesh, Face f) {
  const Vec3d n = area_vector(mesh, f);
  return 0.5 * std::sqrt(dot(n, n));
}

double surface_area(const SurfaceMesh& mesh) {
  double sum = 0;
  for (Face f : mesh.faces()) sum += face_area(mesh, f);
  return sum;
}

BoundingBox bounding_box(const SurfaceMesh& mesh) {
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

double volume(const SurfaceMesh& mesh) {
  std::size_t open = 0;
  for (Halfedge h : mesh.halfedges()) open += mesh.is_boundary(h);
  if (open > 0)
    throw InvalidInputError("volume: the surface is open (" + std::to_string(open) +
                            " boundary half-edges), so it encloses no volume");
  // About the box centre, which keeps the terms small and the cancellation mild.
  const Vec3d c = to_double(bounding_box(mesh).centre());
  double six_v = 0;
  for (Face f : mesh.faces()) {
    const Halfedge h0 = mesh.halfedge(f);
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

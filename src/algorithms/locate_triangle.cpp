// Point location without a tree: the public triangle primitives and the linear scans over every
// face. The triangle code itself is in locate_internal.h, shared with FaceBvh's queries.
#include <cmath>
#include <optional>

#include "hedge/algorithms/locate.h"
#include "locate_internal.h"

namespace hedge {

using namespace locate_detail;

// ---- Triangle primitives. ----

TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return closest_on_triangle(to_double(p), to_double(a), to_double(b), to_double(c));
}

std::optional<TriangleHit> intersect_ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a,
                                                  const Vec3& b, const Vec3& c, double t_max) {
  if (!is_finite(origin) || !valid_direction(direction) || std::isnan(t_max)) return std::nullopt;
  return PreparedRay(origin, direction).intersect(a, b, c, t_max);
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

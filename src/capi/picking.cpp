// The C ABI: picking (hedge/algorithms/locate.h) through the mesh's picking tree, built by the first
// query and updated from the mesh's change log by each later one (binding::picking_tree);
// hedge_mesh_fracture (algorithms.cpp) locates its impacts through the same tree.
#include "binding/picking.h"

#include <cstdio>
#include <limits>

#include "capi_internal.h"

using namespace hedge;
using namespace hedge::capi;

namespace {

Vec3 need_vector(const float* xyz, const char* name) {
  need(xyz, name);
  return binding::need_finite(Vec3{xyz[0], xyz[1], xyz[2]}, name);
}

//! A limit that may be +infinity but not NaN or negative.
double need_limit(float value, const char* name, bool allow_infinity) {
  if (std::isnan(value) || value < 0 || (!allow_infinity && std::isinf(value))) {
    char text[96];
    std::snprintf(text, sizeof text, "%s is %g; it must be >= 0%s", name, double(value),
                  allow_infinity ? " (INFINITY for no limit)" : " and finite");
    fail(HEDGE_ERROR_INVALID_ARGUMENT, text);
  }
  return value;
}

void fill_hit(const SurfacePoint& p, float t, float distance, hedge_surface_hit* out) {
  out->face = p.face.idx();
  for (int i = 0; i < 3; ++i) {
    out->corners[i] = p.corners[i].idx();
    out->barycentric[i] = static_cast<float>(p.barycentric[i]);
  }
  out->point[0] = p.point.x;
  out->point[1] = p.point.y;
  out->point[2] = p.point.z;
  out->t = t;
  out->distance = distance;
}

//! Checks the out parameters, runs the query and writes what it found. The query checks its
//! arguments before it asks for the tree, so that bad input builds nothing.
template <typename Query>
hedge_status pick(hedge_mesh* mesh, hedge_surface_hit* out_hit, int32_t* out_found, Query&& query) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_hit, "out_hit");
    need(out_found, "out_found");
    *out_found = query(*object, *out_hit) ? 1 : 0;
  });
}

}  // namespace

extern "C" {

hedge_status hedge_mesh_bvh_update(hedge_mesh* mesh, uint64_t* out_bytes) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const FaceBvh& bvh = picking_tree(*object);
    if (out_bytes != nullptr) *out_bytes = bvh.memory_bytes();
  });
}

hedge_status hedge_mesh_bvh_release(hedge_mesh* mesh) {
  return guard([&] { find_mesh(mesh)->bvh.reset(); });
}

hedge_status hedge_mesh_raycast(hedge_mesh* mesh, const float* origin, const float* direction, float t_max,
                                hedge_surface_hit* out_hit, int32_t* out_found) {
  return pick(mesh, out_hit, out_found, [&](MeshObject& object, hedge_surface_hit& hit) {
    const Vec3 o = need_vector(origin, "origin");
    need(direction, "direction");
    const Vec3 d = binding::need_direction(Vec3{direction[0], direction[1], direction[2]}, "direction");
    const double limit = need_limit(t_max, "t_max", true);
    const auto found = picking_tree(object).first_hit(o, d, limit);
    if (!found) return false;
    const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
    fill_hit(*found, static_cast<float>(found->t), static_cast<float>(found->t * length), &hit);
    return true;
  });
}

hedge_status hedge_mesh_closest_point(hedge_mesh* mesh, const float* point, float max_distance,
                                      hedge_surface_hit* out_hit, int32_t* out_found) {
  return pick(mesh, out_hit, out_found, [&](MeshObject& object, hedge_surface_hit& hit) {
    const Vec3 p = need_vector(point, "point");
    const double limit = need_limit(max_distance, "max_distance", true);
    const auto found = std::isinf(limit) ? picking_tree(object).closest_point(p)
                                         : picking_tree(object).closest_point(p, limit);
    if (!found) return false;
    fill_hit(*found, 0, static_cast<float>(std::sqrt(found->squared_distance)), &hit);
    return true;
  });
}

hedge_status hedge_mesh_face_containing_point(hedge_mesh* mesh, const float* point, float tolerance,
                                              hedge_surface_hit* out_hit, int32_t* out_found) {
  return pick(mesh, out_hit, out_found, [&](MeshObject& object, hedge_surface_hit& hit) {
    const Vec3 p = need_vector(point, "point");
    const double limit = need_limit(tolerance, "tolerance", false);
    const auto found = picking_tree(object).face_containing(p, limit);
    if (!found) return false;
    fill_hit(*found, 0, static_cast<float>(std::sqrt(found->squared_distance)), &hit);
    return true;
  });
}

hedge_status hedge_mesh_face_containing_point_2d(hedge_mesh* mesh, float u, float v, int32_t plane,
                                                 hedge_surface_hit* out_hit, int32_t* out_found) {
  return pick(mesh, out_hit, out_found, [&](MeshObject& object, hedge_surface_hit& hit) {
    if (!std::isfinite(u) || !std::isfinite(v)) {
      char text[96];
      std::snprintf(text, sizeof text, "point (%g, %g) is not finite", double(u), double(v));
      fail(HEDGE_ERROR_INVALID_ARGUMENT, text);
    }
    ProjectionPlane projection = ProjectionPlane::xy;
    switch (plane) {
      case HEDGE_PLANE_XY:
        break;
      case HEDGE_PLANE_XZ:
        projection = ProjectionPlane::xz;
        break;
      case HEDGE_PLANE_YZ:
        projection = ProjectionPlane::yz;
        break;
      default:
        fail(HEDGE_ERROR_INVALID_ARGUMENT,
             "plane is " + std::to_string(plane) + ", not a HEDGE_PLANE_* value");
    }
    const auto found = picking_tree(object).face_containing(Vec2{u, v}, projection);
    if (!found) return false;
    fill_hit(*found, 0, 0, &hit);
    return true;
  });
}

}  // extern "C"

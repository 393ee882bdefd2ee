// The C ABI: the algorithms on a whole mesh: geometry, distance, normals, smoothing, decimation,
// fracture and subdivision (hedge/algorithms/geometry.h, distance.h, normals.h, smooth.h, decimate.h,
// fracture.h, subdivide.h).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "binding/rollback.h"
#include "capi_internal.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/distance.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/mirror.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/reorder.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"

using namespace hedge;
using namespace hedge::capi;

namespace {

NormalWeighting to_weighting(std::int32_t w) {
  static constexpr binding::Constant<NormalWeighting> kWeightings[] = {
      {HEDGE_WEIGHTING_AREA, NormalWeighting::area},
      {HEDGE_WEIGHTING_ANGLE, NormalWeighting::angle},
      {HEDGE_WEIGHTING_UNIFORM, NormalWeighting::uniform}};
  return binding::from_constant(kWeightings, w, "weighting", "HEDGE_WEIGHTING_*");
}

// Copies a Vec3 property, 3 floats per slot (its array holds one value per slot); get(mesh) finds
// it, `missing` says what to do when the mesh has none.
template <typename Get>
hedge_status copy_vec3(const hedge_mesh* mesh, Get&& get, const char* missing, float* buffer,
                       std::uint64_t capacity, std::uint64_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_count, "out_count");
    const auto prop = get(object->mesh);
    if (!prop) fail(HEDGE_ERROR_INVALID_ARGUMENT, missing);
    const auto& values = prop.vector();
    const std::uint64_t needed = 3 * std::uint64_t(values.size());
    *out_count = needed;
    check_capacity(needed, buffer, capacity);
    for (std::size_t i = 0; i < values.size(); ++i) {
      buffer[3 * i] = values[i].x;
      buffer[3 * i + 1] = values[i].y;
      buffer[3 * i + 2] = values[i].z;
    }
  });
}

}  // namespace

extern "C" {

hedge_status hedge_mesh_geometry(const hedge_mesh* mesh, hedge_geometry* out_geometry) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const SurfaceMesh& m = object->mesh;
    hedge_geometry& g = need(out_geometry, "out_geometry");
    const BoundingBox box = bounding_box(m);
    bool closed = true;
    for (Halfedge h : m.halfedges())
      if (m.is_boundary(h)) {
        closed = false;
        break;
      }
    g.area = surface_area(m);
    g.volume = closed ? volume(m) : std::numeric_limits<double>::quiet_NaN();
    g.closed = closed ? 1 : 0;
    g.empty = box.empty ? 1 : 0;
    for (int a = 0; a < 3; ++a) {
      g.box_min[a] = box.min[a];
      g.box_max[a] = box.max[a];
    }
  });
}

hedge_status hedge_face_normal(const hedge_mesh* mesh, uint32_t face, float* out_xyz) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Face f = live_face(object->mesh, face);
    need(out_xyz, "out_xyz");
    const Vec3 n = face_normal(object->mesh, f);
    out_xyz[0] = n.x;
    out_xyz[1] = n.y;
    out_xyz[2] = n.z;
  });
}

hedge_status hedge_face_area(const hedge_mesh* mesh, uint32_t face, double* out_area) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Face f = live_face(object->mesh, face);
    need(out_area, "out_area") = face_area(object->mesh, f);
  });
}

hedge_status hedge_mesh_compute_vertex_normals(hedge_mesh* mesh, int32_t weighting) {
  return guard([&] {
    auto object = find_mesh(mesh);
    compute_vertex_normals(object->mesh, to_weighting(weighting));
  });
}

hedge_status hedge_mesh_compute_corner_normals(hedge_mesh* mesh, double crease_degrees, int32_t weighting) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const NormalWeighting w = to_weighting(weighting);
    if (!(crease_degrees >= 0 && crease_degrees <= 180))
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "crease_degrees must be in 0..180, got " + std::to_string(crease_degrees));
    compute_corner_normals(object->mesh, crease_degrees, w);
  });
}

hedge_status hedge_mesh_copy_vertex_normals(const hedge_mesh* mesh, float* buffer, uint64_t capacity,
                                            uint64_t* out_count) {
  return copy_vec3(
      mesh, [](const SurfaceMesh& m) { return m.get_vertex_property<Vec3>("v:normal"); },
      "the mesh has no vertex normals: compute them first (hedge_mesh_compute_vertex_normals)", buffer,
      capacity, out_count);
}

hedge_status hedge_mesh_copy_corner_normals(const hedge_mesh* mesh, float* buffer, uint64_t capacity,
                                            uint64_t* out_count) {
  return copy_vec3(
      mesh, [](const SurfaceMesh& m) { return m.get_halfedge_property<Vec3>("h:normal"); },
      "the mesh has no corner normals: compute them first (hedge_mesh_compute_corner_normals)", buffer,
      capacity, out_count);
}

hedge_status hedge_mesh_hausdorff(const hedge_mesh* a, const hedge_mesh* b, uint64_t samples, uint64_t seed,
                                  double* out_distance, double* out_mean) {
  return guard([&] {
    auto first = find_mesh(a), second = find_mesh(b);
    double& distance = need(out_distance, "out_distance");
    const HausdorffDistance d =
        hausdorff_distance(first->mesh, second->mesh, {.samples = samples, .seed = seed});
    distance = d.distance;
    if (out_mean != nullptr) *out_mean = d.mean;
  });
}

hedge_status hedge_smooth_options_default(hedge_smooth_options* out_options) {
  return guard([&] {
    hedge_smooth_options& o = need(out_options, "out_options");
    const SmoothOptions d;
    o.method = HEDGE_SMOOTH_UNIFORM;
    o.iterations = d.iterations;
    o.lambda = d.lambda;
    o.mu = d.mu;
    o.fix_boundary = d.fix_boundary ? 1 : 0;
    o.reserved = 0;
  });
}

hedge_status hedge_mesh_smooth(hedge_mesh* mesh, const hedge_smooth_options* options, const uint8_t* mask,
                               uint32_t mask_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    SurfaceMesh& m = object->mesh;
    const hedge_smooth_options o = options_or_defaults(options, hedge_smooth_options_default);
    SmoothOptions s;
    switch (o.method) {
      case HEDGE_SMOOTH_UNIFORM:
        s.method = SmoothMethod::uniform;
        break;
      case HEDGE_SMOOTH_TAUBIN:
        s.method = SmoothMethod::taubin;
        break;
      case HEDGE_SMOOTH_COTANGENT:
        s.method = SmoothMethod::cotangent;
        break;
      case HEDGE_SMOOTH_IMPLICIT:
        s.method = SmoothMethod::implicit;
        break;
      default:
        fail(HEDGE_ERROR_INVALID_ARGUMENT,
             "method must be HEDGE_SMOOTH_UNIFORM, _TAUBIN, _COTANGENT or _IMPLICIT, got " +
                 std::to_string(o.method));
    }
    s.iterations = o.iterations;
    s.lambda = o.lambda;
    s.mu = o.mu;
    s.fix_boundary = need_bool(o.fix_boundary, "fix_boundary");
    if (mask_count != 0) {
      need_array(mask, mask_count, "mask");
      s.mask = std::span<const std::uint8_t>(mask, mask_count);
    }
    smooth(m, s);  // its InvalidInputError becomes HEDGE_ERROR_INVALID_ARGUMENT, the mesh unchanged
  });
}

hedge_status hedge_decimate_options_default(hedge_decimate_options* out_options) {
  return guard([&] {
    hedge_decimate_options& o = need(out_options, "out_options");
    const DecimateOptions d;
    o.target_vertices = d.target_vertices;
    o.target_faces = d.target_faces;
    o.max_error = d.max_error;
    o.boundary_weight = d.boundary_weight;
    o.feature_angle_degrees = d.feature_angle_degrees;
    o.feature_weight = d.feature_weight;
    o.attribute_weight = d.attribute_weight;
    o.max_normal_change_degrees = d.max_normal_change_degrees;
    o.keep_boundary = d.keep_boundary ? 1 : 0;
    o.keep_seams = d.keep_seams ? 1 : 0;
    o.relax_normal_change = d.relax_normal_change ? 1 : 0;
    o.reserved = 0;
  });
}

hedge_status hedge_mesh_decimate(hedge_mesh* mesh, const hedge_decimate_options* options,
                                 hedge_decimate_result* out_result) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const hedge_decimate_options o = options_or_defaults(options, hedge_decimate_options_default);
    DecimateOptions d;
    d.target_vertices = o.target_vertices;
    d.target_faces = o.target_faces;
    d.max_error = o.max_error;
    d.boundary_weight = o.boundary_weight;
    d.feature_angle_degrees = o.feature_angle_degrees;
    d.feature_weight = o.feature_weight;
    d.attribute_weight = o.attribute_weight;
    d.max_normal_change_degrees = o.max_normal_change_degrees;
    d.keep_boundary = need_bool(o.keep_boundary, "keep_boundary");
    d.keep_seams = need_bool(o.keep_seams, "keep_seams");
    d.relax_normal_change = need_bool(o.relax_normal_change, "relax_normal_change");
    if (o.reserved != 0)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "decimate_options.reserved is " + std::to_string(o.reserved) + ", not 0");
    // Its InvalidInputError becomes HEDGE_ERROR_INVALID_ARGUMENT, the mesh unchanged. A failure
    // halfway (memory) would leave a run of collapses cut short: the rollback puts the mesh back.
    SurfaceMesh& m = object->mesh;
    const DecimateResult r = binding::with_rollback(m, [&] { return decimate(m, d); });
    if (out_result != nullptr)
      *out_result = {
          r.vertices,         r.faces,          r.collapses,    r.max_error, binding::constant(r.stop), 0,
          r.refused.topology, r.refused.normal, r.refused.shape};
  });
}

hedge_status hedge_fracture_options_default(int32_t preset, hedge_fracture_options* out_options) {
  return guard([&] {
    hedge_fracture_options& o = need(out_options, "out_options");
    static const char* const names[] = {"glass", "stone", "wood", "ice"};
    if (preset < HEDGE_FRACTURE_GLASS || preset > HEDGE_FRACTURE_ICE)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "preset must be HEDGE_FRACTURE_GLASS, _STONE, _WOOD or _ICE, got " + std::to_string(preset));
    const FractureMaterial m = fracture_material(names[preset]);
    const FractureOptions d;
    o = hedge_fracture_options{};
    o.ring_count = static_cast<std::uint32_t>(m.rings.size());
    for (std::size_t i = 0; i < m.rings.size(); ++i)
      o.rings[i] = {m.rings[i].spacing, m.rings[i].jitter, m.rings[i].points, 0};
    o.units = static_cast<std::int32_t>(m.units);
    o.radius = m.radius;
    o.grain[0] = m.grain.x, o.grain[1] = m.grain.y, o.grain[2] = m.grain.z;
    o.grain_stretch = m.grain_stretch;
    o.refine_edge = m.refine_edge;
    o.seed = d.seed;
    o.thickness = d.thickness;
    o.density = d.density;
    o.tolerance = d.tolerance;
    o.hulls = d.hulls ? 1 : 0;
    o.inner_submesh = d.inner_submesh;
    o.relative_thickness = d.relative_thickness;
    o.shell_thickness = d.shell_thickness;
  });
}

hedge_status hedge_fracture_options_at_radius(hedge_fracture_options* options, double radius) {
  return guard([&] {
    hedge_fracture_options& o = need(options, "options");
    if (o.ring_count > HEDGE_FRACTURE_MAX_RINGS)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "ring_count must be at most HEDGE_FRACTURE_MAX_RINGS (" +
                                             std::to_string(HEDGE_FRACTURE_MAX_RINGS) + "), got " +
                                             std::to_string(o.ring_count));
    FractureMaterial m;
    m.name = "custom";
    for (std::uint32_t i = 0; i < o.ring_count; ++i)
      m.rings.push_back({o.rings[i].points, o.rings[i].spacing, o.rings[i].jitter});
    m.refine_edge = o.refine_edge;
    // Its InvalidInputError (naming the radius or the ring) becomes HEDGE_ERROR_INVALID_ARGUMENT
    // before *options is written.
    const FractureMaterial scaled = fracture_material_at_radius(m, radius);
    for (std::uint32_t i = 0; i < o.ring_count; ++i) o.rings[i].spacing = scaled.rings[i].spacing;
    o.refine_edge = scaled.refine_edge;
    o.units = static_cast<std::int32_t>(scaled.units);
    o.radius = scaled.radius;
  });
}

hedge_status hedge_mesh_fracture(hedge_mesh* mesh, float x, float y, float z,
                                 const hedge_fracture_options* options, hedge_fracture_shard* out_shards,
                                 uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    std::uint32_t& count = need(out_count, "out_count");
    const hedge_fracture_options o = options_or_defaults(options, [](hedge_fracture_options* out) {
      return hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, out);
    });
    if (o.ring_count > HEDGE_FRACTURE_MAX_RINGS)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "ring_count must be at most HEDGE_FRACTURE_MAX_RINGS (" +
                                             std::to_string(HEDGE_FRACTURE_MAX_RINGS) + "), got " +
                                             std::to_string(o.ring_count));
    FractureOptions f;
    f.material.name = "custom";
    f.material.rings.clear();
    for (std::uint32_t i = 0; i < o.ring_count; ++i)
      f.material.rings.push_back({o.rings[i].points, o.rings[i].spacing, o.rings[i].jitter});
    // fracture() refuses (naming the field) units outside the enum and a radius that is not positive.
    f.material.units = static_cast<FractureUnits>(o.units);
    f.material.radius = o.radius;
    f.material.grain = {o.grain[0], o.grain[1], o.grain[2]};
    f.material.grain_stretch = o.grain_stretch;
    f.material.refine_edge = o.refine_edge;
    f.seed = o.seed;
    f.thickness = o.thickness;
    f.density = o.density;
    f.tolerance = o.tolerance;
    f.hulls = need_bool(o.hulls, "hulls");
    f.inner_submesh = o.inner_submesh;
    f.relative_thickness = o.relative_thickness;
    f.shell_thickness = o.shell_thickness;
    const Vec3 impact = need_point(x, y, z, "fracture impact");
    // The library's limits first (rings, break points in all, each field): an illegal material is
    // HEDGE_ERROR_INVALID_ARGUMENT naming the field, before any buffer size is looked at. Within
    // the limits the count fits 32 bits.
    const std::size_t points = fracture_break_points(f);
    count = static_cast<std::uint32_t>(points);
    check_capacity(points, out_shards, capacity, "out_shards");
    // Its InvalidInputError becomes HEDGE_ERROR_INVALID_ARGUMENT, the mesh unchanged. The impact is
    // located through the mesh's picking tree, which fracture() brings up to date before and after
    // its edits: the strike costs the broken area, not a tree over the whole mesh.
    FractureResult r = fracture(object->mesh, impact, f, &picking_tree(*object));
    // Handles are registered only once every shard is ready, so a failure leaves none behind.
    std::vector<std::shared_ptr<MeshObject>> meshes, hulls;
    for (Shard& s : r.shards) {
      meshes.push_back(std::make_shared<MeshObject>());
      meshes.back()->mesh = std::move(s.mesh);
      hulls.push_back(nullptr);
      if (s.hull.mesh.n_faces() > 0) {
        hulls.back() = std::make_shared<MeshObject>();
        hulls.back()->mesh = std::move(s.hull.mesh);
      }
    }
    for (std::size_t i = 0; i < r.shards.size(); ++i) {
      const Shard& s = r.shards[i];
      hedge_fracture_shard& out = out_shards[i];
      out = hedge_fracture_shard{};
      out.centroid[0] = s.centroid.x, out.centroid[1] = s.centroid.y, out.centroid[2] = s.centroid.z;
      out.area = s.area;
      out.volume = s.mass.volume;
      out.mass = s.mass.mass;
      out.centre_of_mass[0] = s.mass.centre_of_mass.x;
      out.centre_of_mass[1] = s.mass.centre_of_mass.y;
      out.centre_of_mass[2] = s.mass.centre_of_mass.z;
      std::copy(s.mass.inertia.begin(), s.mass.inertia.end(), out.inertia);
      if (s.mass.mass > 0) {
        const Vec3d& m = s.mass.principal_moments;
        out.principal_moments[0] = m.x, out.principal_moments[1] = m.y, out.principal_moments[2] = m.z;
        for (int a = 0; a < 3; ++a) {
          const Vec3d& axis = s.mass.principal_axes[a];
          out.principal_axes[3 * a] = axis.x, out.principal_axes[3 * a + 1] = axis.y;
          out.principal_axes[3 * a + 2] = axis.z;
        }
      }
      out.closed = s.closed ? 1 : 0;
      out.hull_dimension = static_cast<std::int32_t>(s.hull.dimension);
      out.mesh = register_mesh(std::move(meshes[i]));
      out.hull = hulls[i] ? register_mesh(std::move(hulls[i])) : nullptr;
    }
    count = static_cast<std::uint32_t>(r.shards.size());
  });
}

hedge_status hedge_mesh_copy_face_submeshes(const hedge_mesh* mesh, int32_t* buffer, uint64_t capacity,
                                            uint64_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const SurfaceMesh& m = object->mesh;
    need(out_count, "out_count");
    *out_count = m.face_slots();
    check_capacity(m.face_slots(), buffer, capacity);
    const FaceProperty<std::int32_t> submesh = m.get_face_property<std::int32_t>(kSubmeshProperty);
    for (std::size_t i = 0; i < m.face_slots(); ++i)
      buffer[i] = submesh ? submesh[Face(static_cast<Index>(i))] : 0;
  });
}

hedge_status hedge_mesh_subdivide(hedge_mesh* mesh, int32_t scheme, int32_t steps) {
  return guard([&] {
    auto object = find_mesh(mesh);
    if (scheme < HEDGE_SUBDIVISION_LOOP || scheme > HEDGE_SUBDIVISION_SPLIT_FACES)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "scheme must be HEDGE_SUBDIVISION_LOOP, _MIDPOINT, _CATMULL_CLARK, _SQRT3 or _SPLIT_FACES, got " +
               std::to_string(scheme));
    if (steps < 0 || steps > 12)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "steps must be in 0..12, got " + std::to_string(steps));
    const Subdivision s = scheme == HEDGE_SUBDIVISION_LOOP          ? Subdivision::loop
                          : scheme == HEDGE_SUBDIVISION_MIDPOINT    ? Subdivision::midpoint
                          : scheme == HEDGE_SUBDIVISION_SQRT3       ? Subdivision::sqrt3
                          : scheme == HEDGE_SUBDIVISION_SPLIT_FACES ? Subdivision::split_faces
                                                                    : Subdivision::catmull_clark;
    subdivide(object->mesh, s, steps);
  });
}

hedge_status hedge_mesh_mirror_x(hedge_mesh* mesh) {
  return guard([&] { mirror_x(find_mesh(mesh)->mesh); });
}

hedge_status hedge_mesh_reorder(hedge_mesh* mesh, int32_t ordering, uint32_t cache_size, uint32_t* vertex_map,
                                uint32_t vertex_capacity, uint32_t* halfedge_map, uint32_t halfedge_capacity,
                                uint32_t* edge_map, uint32_t edge_capacity, uint32_t* face_map,
                                uint32_t face_capacity) {
  return guard([&] {
    auto object = find_mesh(mesh);
    if (ordering != HEDGE_ORDERING_SPATIAL && ordering != HEDGE_ORDERING_VERTEX_CACHE)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "ordering must be HEDGE_ORDERING_SPATIAL or _VERTEX_CACHE, got " + std::to_string(ordering));
    const MapBuffers b{vertex_map, vertex_capacity, halfedge_map, halfedge_capacity,
                       edge_map,   edge_capacity,   face_map,     face_capacity};
    check_map_buffers(object->mesh, b);
    const Ordering o = ordering == HEDGE_ORDERING_VERTEX_CACHE ? Ordering::vertex_cache : Ordering::spatial;
    // reorder() compacts array after array: a failure halfway is rolled back.
    SurfaceMesh& m = object->mesh;
    write_maps(binding::with_rollback(m, [&] { return reorder(m, o, cache_size == 0 ? 16 : cache_size); }),
               b);
  });
}

hedge_status hedge_mesh_cache_miss_ratio(const hedge_mesh* mesh, uint32_t cache_size, double* out_ratio) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_ratio, "out_ratio") = average_cache_miss_ratio(object->mesh, cache_size == 0 ? 16 : cache_size);
  });
}

}  // extern "C"

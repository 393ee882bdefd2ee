#include "mesh_stats.h"

#include "hedge/algorithms/components.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/reorder.h"

namespace hedge::cli {

MeshStats compute_stats(const SurfaceMesh& mesh) {
  MeshStats s;
  s.vertices = mesh.n_vertices();
  s.edges = mesh.n_edges();
  s.faces = mesh.n_faces();
  s.halfedges = mesh.n_halfedges();
  s.problems = mesh.validate();
  s.euler_characteristic = static_cast<std::int64_t>(s.vertices) - static_cast<std::int64_t>(s.edges) +
                           static_cast<std::int64_t>(s.faces);
  s.is_triangle_mesh = s.faces > 0 && mesh.is_triangle_mesh();
  const BoundingBox box = bounding_box(mesh);
  s.box_min = box.min;
  s.box_max = box.max;
  s.is_quad_mesh = s.faces > 0 && mesh.is_quad_mesh();

  // The queries below walk the connectivity; on a broken mesh they could go astray, so they are
  // left at their defaults unless validate() found nothing.
  if (!s.problems.empty()) return s;
  s.boundary_loops = mesh.boundary_loops().size();
  s.components = vertex_components(mesh).count;
  s.is_manifold = true;
  for (Vertex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) {
      ++s.isolated_vertices;
    } else if (!mesh.is_manifold(v)) {
      s.is_manifold = false;
    }
  }
  s.is_closed = s.faces > 0 && s.boundary_loops == 0;
  const std::int64_t surface_chi = s.euler_characteristic - static_cast<std::int64_t>(s.isolated_vertices);
  if (s.is_closed && s.components == 1 && surface_chi <= 2 && surface_chi % 2 == 0) {
    s.genus = (2 - surface_chi) / 2;
  }
  s.area = surface_area(mesh);
  if (s.boundary_loops == 0) s.volume = volume(mesh);
  s.cache_miss_ratio = average_cache_miss_ratio(mesh, 16);
  return s;
}

std::vector<std::pair<const char*, std::size_t>> repair_counts(const BuildReport& r) {
  return {{"welded_vertices", r.welded_vertices},         {"degenerate_faces", r.degenerate_faces},
          {"repeated_corners", r.repeated_corners},       {"reoriented_faces", r.reoriented_faces},
          {"non_manifold_edges", r.non_manifold_edges},   {"non_manifold_vertices", r.non_manifold_vertices},
          {"duplicated_vertices", r.duplicated_vertices}, {"isolated_vertices", r.isolated_vertices}};
}

nlohmann::json repairs_json(const BuildReport& report) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, count] : repair_counts(report)) j[name] = count;
  return j;
}

nlohmann::json stats_json(const MeshStats& s) {
  auto or_null = [](const auto& optional) {
    return optional ? nlohmann::json(*optional) : nlohmann::json(nullptr);
  };
  return {
      {"vertices", s.vertices},
      {"edges", s.edges},
      {"faces", s.faces},
      {"halfedges", s.halfedges},
      {"boundary_loops", s.boundary_loops},
      {"components", s.components},
      {"isolated_vertices", s.isolated_vertices},
      {"euler_characteristic", s.euler_characteristic},
      {"genus", or_null(s.genus)},
      {"is_closed", s.is_closed},
      {"is_triangle_mesh", s.is_triangle_mesh},
      {"is_quad_mesh", s.is_quad_mesh},
      {"is_manifold", s.is_manifold},
      {"area", s.area},
      {"volume", or_null(s.volume)},
      {"cache_miss_ratio", s.cache_miss_ratio},
      {"bounding_box",
       {{"min", {s.box_min.x, s.box_min.y, s.box_min.z}}, {"max", {s.box_max.x, s.box_max.y, s.box_max.z}}}},
      {"valid", s.problems.empty()},
      {"problems", s.problems}};
}

}  // namespace hedge::cli

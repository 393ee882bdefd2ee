// Whole-mesh statistics reported by `hedge info` and `hedge validate`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::cli {

struct MeshStats {
  std::size_t vertices = 0, edges = 0, faces = 0, halfedges = 0;
  std::size_t boundary_loops = 0;
  //! Connected components of the surface; isolated vertices are not counted (see isolated_vertices).
  std::size_t components = 0;
  std::size_t isolated_vertices = 0;
  //! V - E + F over all live elements.
  std::int64_t euler_characteristic = 0;
  //! For a closed, connected surface (half-edge meshes are orientable): chi = 2 - 2g, with the
  //! isolated vertices left out of chi. Empty otherwise.
  std::optional<std::int64_t> genus;
  bool is_closed = false;
  bool is_triangle_mesh = false;
  bool is_quad_mesh = false;
  bool is_manifold = false;
  //! Geometry: the axis-aligned bounding box, and, on a valid mesh, the surface area and the
  //! enclosed (signed) volume of a closed one (empty when the mesh has a boundary or is invalid).
  double area = 0;
  Vec3 box_min{0, 0, 0}, box_max{0, 0, 0};
  std::optional<double> volume;
  //! Vertex loads per triangle when the faces are drawn in file order through a 16-entry FIFO
  //! vertex cache (algorithms/reorder.h); `hedge convert --reorder vertex-cache` lowers it.
  double cache_miss_ratio = 0;
  //! mesh.validate(): one line per broken invariant; empty means valid.
  std::vector<std::string> problems;
};

//! Computes everything in MeshStats. O(#elements).
MeshStats compute_stats(const SurfaceMesh& mesh);

//! The BuildReport counters by name, in a fixed order.
std::vector<std::pair<const char*, std::size_t>> repair_counts(const BuildReport& report);

nlohmann::json repairs_json(const BuildReport& report);

//! The statistics as JSON (without "file" and "repairs").
nlohmann::json stats_json(const MeshStats& stats);

}  // namespace hedge::cli

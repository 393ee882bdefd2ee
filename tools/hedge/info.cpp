// hedge info FILE: load (repairing by default), then report counts, topology and repairs.
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.h"
#include "load.h"
#include "mesh_stats.h"

namespace hedge::cli {

namespace {

const char* yes_no(bool b) { return b ? "yes" : "no"; }

template <typename T>
void row(const char* label, const T& value) {
  std::cout << "  " << std::left << std::setw(22) << label << value << '\n';
}

void print_text(const MeshReportOptions& options, const LoadedMesh& loaded, const MeshStats& s) {
  std::cout << options.file << " (" << format_name(loaded.format) << ")\n";
  row("vertices", s.vertices);
  row("edges", s.edges);
  row("faces", s.faces);
  row("halfedges", s.halfedges);
  row("boundary loops", s.boundary_loops);
  row("components", s.components);
  row("isolated vertices", s.isolated_vertices);
  row("Euler characteristic", s.euler_characteristic);
  if (s.genus) {
    row("genus", *s.genus);
  } else {
    row("genus", "n/a (not closed and connected)");
  }
  row("closed", yes_no(s.is_closed));
  row("triangle mesh", yes_no(s.is_triangle_mesh));
  row("quad mesh", yes_no(s.is_quad_mesh));
  row("manifold", yes_no(s.is_manifold));
  row("area", s.area);
  if (s.volume) {
    row("volume", *s.volume);
  } else {
    row("volume", "n/a (not closed)");
  }
  std::ostringstream box;
  box << "(" << s.box_min.x << ", " << s.box_min.y << ", " << s.box_min.z << ") - (" << s.box_max.x << ", "
      << s.box_max.y << ", " << s.box_max.z << ")";
  row("bounding box", box.str());
  row("cache misses/tri", s.cache_miss_ratio);  // 16-entry FIFO, faces in file order
  row("valid", yes_no(s.problems.empty()));
  if (!s.problems.empty())
    std::cout << "  (boundary loops, components, genus and manifoldness not computed)\n";
  for (const std::string& problem : s.problems) std::cout << "    - " << problem << '\n';

  bool any = false;
  for (const auto& [name, count] : repair_counts(loaded.report)) {
    if (count == 0) continue;
    if (!any) std::cout << "  repairs while loading:\n";
    any = true;
    std::cout << "    " << std::left << std::setw(24) << name << count << '\n';
  }
  if (!any) row("repairs", "none");
}

int run_info(const MeshReportOptions& options) {
  const LoadedMesh loaded = load_mesh(options.file, options.load);
  const MeshStats stats = compute_stats(loaded.mesh);
  if (options.json) {
    nlohmann::json j = stats_json(stats);
    j["file"] = options.file;
    j["format"] = format_name(loaded.format);
    j["repairs"] = repairs_json(loaded.report);
    j["warnings"] = loaded.report.warnings;
    std::cout << j.dump(2) << '\n';
  } else {
    print_text(options, loaded, stats);
  }
  return kExitOk;
}

}  // namespace

const CommandBinder info_command = bind_command<MeshReportOptions, add_mesh_report_arguments, run_info>;

}  // namespace hedge::cli

// hedge render-buffers FILE: what an engine would get from the mesh through RenderBuffers (render
// vertex and index counts, seam splits, layout), then a sample of random local edits with a sync
// after each, comparing the bytes each sync rewrote with a full upload.
#include "hedge/render/render_buffers.h"

#include <algorithm>
#include <iostream>

#include "commands.h"
#include "edits/random_edits.h"
#include "load.h"
#include "memory_budget.h"
#include "mesh_stats.h"
#include "numbers.h"

namespace hedge::cli {

namespace {

struct RenderBuffersOptions : MeshReportOptions {
  std::size_t edits = 100;
  std::uint64_t seed = 1;
  std::string winding = "ccw";
  bool flip_x = false;
  bool separate = false;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int run_render_buffers(const RenderBuffersOptions& options) {
  // The bytes of every sync are kept for the median: 8 bytes an edit.
  check_memory(8.0 * double(options.edits), options.load.memory, std::to_string(options.edits) + " edits",
               "use fewer --edits");
  LoadedMesh loaded = load_mesh(options.file, options.load);
  SurfaceMesh& mesh = loaded.mesh;
  const std::size_t mesh_vertices = mesh.n_vertices(), mesh_faces = mesh.n_faces();
  RenderOptions ro;
  ro.winding = options.winding == "cw" ? Winding::cw : Winding::ccw;
  ro.flip_x = options.flip_x;
  ro.interleaved = !options.separate;
  RenderBuffers rs(mesh, ro);
  const VertexLayout layout = rs.layout();
  const std::size_t seams = rs.seam_splits();
  const std::size_t used_vertices = rs.n_vertices() - seams;
  const std::size_t full_bytes = rs.buffer_bytes();
  const std::size_t start_vertices = rs.n_vertices(), start_triangles = rs.n_triangles();

  // Random edits, one sync after each.
  std::vector<double> bytes;
  std::size_t total = 0, resized = 0, applied = 0;
  RandomEditor editor(mesh, options.seed);
  for (std::size_t i = 0; i < options.edits; ++i) {
    applied += editor.step().applied;  // validated once, after the sample
    const SyncResult& s = rs.sync();
    bytes.push_back(static_cast<double>(s.vertex_bytes + s.index_bytes));
    total += s.vertex_bytes + s.index_bytes;
    resized += s.resized;
  }
  const double med = median(bytes);
  const double worst = bytes.empty() ? 0 : *std::max_element(bytes.begin(), bytes.end());
  const bool valid = mesh.validate().empty();

  if (options.json) {
    nlohmann::json j;
    j["file"] = options.file;
    j["mesh"] = {{"vertices", mesh_vertices}, {"faces", mesh_faces}};
    j["render_vertices"] = start_vertices;
    j["triangles"] = start_triangles;
    j["seam_splits"] = seams;
    j["vertex_stride_bytes"] = layout.stride * sizeof(float);
    j["layout"] = {{"interleaved", layout.interleaved},
                   {"position", layout.position},
                   {"normal", layout.normal},
                   {"texcoord", layout.texcoord},
                   {"color", layout.color}};
    j["full_upload_bytes"] = full_bytes;
    j["edits"] = {
        {"requested", options.edits}, {"applied", applied},
        {"seed", options.seed},       {"median_bytes", med},
        {"max_bytes", worst},         {"total_bytes", total},
        {"buffer_growths", resized},  {"median_fraction_of_full", full_bytes ? med / double(full_bytes) : 0}};
    j["valid"] = valid;
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << options.file << '\n';
    std::cout << "  render vertices: " << start_vertices << " for " << used_vertices << " mesh vertices ("
              << seams << " seam splits)\n";
    std::cout << "  triangles:       " << start_triangles << " (" << 3 * start_triangles << " indices)\n";
    std::cout << "  vertex layout:   " << layout.stride * sizeof(float) << " bytes: position"
              << (layout.normal >= 0 ? ", normal" : "") << (layout.texcoord >= 0 ? ", texcoord" : "")
              << (layout.color >= 0 ? ", color" : "")
              << (layout.interleaved ? " (interleaved)" : " (separate streams)") << '\n';
    std::cout << "  full upload:     " << full_bytes << " bytes\n";
    std::cout << "sample: " << options.edits << " random local edits (" << applied
              << " applied), sync after each\n";
    std::cout << "  bytes per sync:  median " << med << ", max " << worst << ", total " << total << '\n';
    if (full_bytes > 0)
      std::cout << "  median sync is " << (med > 0 ? double(full_bytes) / med : 0)
                << "x smaller than a full upload\n";
    std::cout << "  buffer growths:  " << resized << '\n';
    std::cout << (valid ? "mesh valid after the edits\n" : "mesh INVALID after the edits\n");
  }
  return valid ? kExitOk : kExitDataError;
}

void add_render_buffers_arguments(CLI::App* app, RenderBuffersOptions* options) {
  add_mesh_file_argument(*app, options->file);
  app->add_option("--edits", options->edits, "Random local edits in the sample")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(0, 10000000));
  add_seed_option(*app, options->seed);
  app->add_option("--winding", options->winding, "Index winding: ccw, or cw (Unity, Direct3D)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ccw", "cw"}));
  app->add_flag("--flip-x", options->flip_x, "Negate x (left-handed axes, as Unity)");
  app->add_flag("--separate", options->separate, "One buffer per attribute instead of interleaved vertices");
  add_json_flag(*app, options->json, "Print one JSON object");
}

}  // namespace

const CommandBinder render_buffers_command =
    bind_command<RenderBuffersOptions, add_render_buffers_arguments, run_render_buffers>;

}  // namespace hedge::cli

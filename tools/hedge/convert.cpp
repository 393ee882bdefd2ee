// hedge convert IN OUT: read, build (repairing unless --strict) and write; formats by extension.
#include <iostream>
#include <memory>

#include "commands.h"
#include "hedge/algorithms/reorder.h"
#include "load.h"

namespace hedge::cli {

namespace {

struct ConvertOptions {
  std::string input;
  std::string output;
  bool ascii = false;
  std::string reorder = "none";
  LoadOptions load;
};

int run_convert(const ConvertOptions& options) {
  // Check the output's extension before spending time on the input.
  const FileFormat out_format = format_from_path(options.output);
  LoadedMesh loaded = load_mesh(options.input, options.load);
  if (options.reorder != "none")
    reorder(loaded.mesh, options.reorder == "vertex-cache" ? Ordering::vertex_cache : Ordering::spatial);

  save_mesh(loaded.mesh, options.output, options.ascii);

  const bool has_encoding = out_format == FileFormat::ply || out_format == FileFormat::stl;
  std::cout << "converted " << options.input << " -> " << options.output << " (" << format_name(out_format)
            << (has_encoding ? (options.ascii ? ", ascii" : ", binary") : "")
            << "): " << loaded.mesh.n_vertices() << " vertices, " << loaded.mesh.n_faces() << " faces, "
            << loaded.report.repairs() << " repairs\n";
  return kExitOk;
}

}  // namespace

Command add_convert_command(CLI::App& parent) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* app = parent.add_subcommand(
      "convert", "Convert between OBJ, OFF, PLY, STL and glTF (.gltf, .glb); formats from the extensions");
  app->add_option("IN", options->input, "Input mesh file")->required();
  app->add_option("OUT", options->output, "Output mesh file; missing folders are created")->required();
  app->add_flag("--ascii", options->ascii, "Write PLY and STL as text instead of binary");
  app->add_option("--reorder", options->reorder,
                  "Renumber before writing: spatial (a Morton curve: traversals read memory in order) or "
                  "vertex-cache (faces for a GPU's vertex cache, vertices by first use)")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "spatial", "vertex-cache"}));
  add_load_options(*app, options->load);
  return {app, [options] { return run_convert(*options); }};
}

}  // namespace hedge::cli

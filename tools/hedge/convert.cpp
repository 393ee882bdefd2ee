// hedge convert IN OUT: read, build (repairing unless --strict) and write; formats by extension.
#include <iostream>

#include "commands.h"
#include "hedge/algorithms/reorder.h"
#include "load.h"

namespace hedge::cli {

namespace {

struct ConvertOptions : InOutOptions {
  std::string reorder = "none";
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

void add_convert_arguments(CLI::App* app, ConvertOptions* options) {
  add_in_out_arguments(*app, options->input, options->output);
  add_ascii_flag(*app, options->ascii);
  app->add_option("--reorder", options->reorder,
                  "Renumber before writing: spatial (a Morton curve: traversals read memory in order) or "
                  "vertex-cache (faces for a GPU's vertex cache, vertices by first use)")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "spatial", "vertex-cache"}));
}

}  // namespace

const CommandBinder convert_command = bind_command<ConvertOptions, add_convert_arguments, run_convert>;

}  // namespace hedge::cli

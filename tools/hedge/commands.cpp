#include "commands.h"

#include "numbers.h"

namespace hedge::cli {

Command add_command(CLI::App& parent, const CommandSpec& spec) {
  return spec.bind(*parent.add_subcommand(spec.name, spec.description));
}

void add_mesh_file_argument(CLI::App& app, std::string& file, bool required) {
  CLI::Option* option = app.add_option("FILE", file, "Mesh file (.obj, .off, .ply, .stl, .gltf, .glb)");
  if (required) option->required();
}

void add_mesh_report_arguments(CLI::App* app, MeshReportOptions* options) {
  add_mesh_file_argument(*app, options->file);
  add_json_flag(*app, options->json);
}

LoadedMesh load_input(const InOutOptions& options) {
  format_from_path(options.output);
  return load_mesh(options.input, options.load);
}

void add_in_out_arguments(CLI::App& app, std::string& input, std::string& output, const char* input_help) {
  app.add_option("IN", input, input_help)->required();
  app.add_option("OUT", output, "Output mesh file; missing folders are created")->required();
}

void add_json_flag(CLI::App& app, bool& json, const char* help) { app.add_flag("--json", json, help); }

void add_seed_option(CLI::App& app, std::uint64_t& seed, const char* help) {
  app.add_option("--seed", seed, help)->capture_default_str()->transform(whole_number<std::uint64_t>(0));
}

void add_ascii_flag(CLI::App& app, bool& ascii) {
  app.add_flag("--ascii", ascii, "Write PLY and STL as text instead of binary");
}

}  // namespace hedge::cli

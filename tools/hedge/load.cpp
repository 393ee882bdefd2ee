#include "load.h"

#include <filesystem>
#include <iostream>
#include <map>
#include <utility>

#include "hedge/error.h"
#include "numbers.h"

namespace hedge::cli {

namespace {

const std::map<std::string, Weld>& weld_modes() {
  static const std::map<std::string, Weld> modes{
      {"none", Weld::none}, {"exact", Weld::exact}, {"epsilon", Weld::epsilon}};
  return modes;
}

}  // namespace

void add_load_options(CLI::App& command, LoadOptions& options) {
  command.add_flag("--strict", options.strict,
                   "Reject input that is not a clean oriented 2-manifold instead of repairing it");
  command.add_option("--weld", options.weld, "Merge vertices: none, exact (equal positions) or epsilon")
      ->check(CLI::IsMember({"none", "exact", "epsilon"}));
  command
      .add_option("--weld-eps", options.weld_eps,
                  "Welding tolerance relative to the bounding-box diagonal (implies --weld epsilon)")
      ->transform(real_number(0));
  command.add_flag("--no-external-buffers", options.no_external_buffers,
                   "glTF: refuse buffers kept in separate files (by default they are read from the .gltf's "
                   "folder and below, never from elsewhere)");
  add_max_memory_option(command, options.memory);
}

ReadOptions read_options(const LoadOptions& options) {
  ReadOptions read;
  read.external_buffers = !options.no_external_buffers;
  if (!options.memory.text.empty()) read.max_memory = effective_budget(options.memory);
  return read;
}

BuildOptions build_options(FileFormat format, const LoadOptions& options) {
  BuildOptions build = default_build_options(format);
  if (options.strict) build.policy = TopologyPolicy::strict;
  if (!options.weld.empty()) {
    build.weld = weld_modes().at(options.weld);
  } else if (options.weld_eps >= 0.0) {
    build.weld = Weld::epsilon;
  }
  if (options.weld_eps >= 0.0) build.weld_epsilon = options.weld_eps;
  return build;
}

LoadedMesh load_mesh(const std::string& path, const LoadOptions& options) {
  LoadedMesh loaded;
  loaded.format = format_from_path(path);
  try {
    loaded.mesh =
        read_mesh(path, build_options(loaded.format, options), read_options(options), &loaded.report);
  } catch (const IoError&) {
    throw;  // already names the file
  } catch (const TopologyError& e) {
    throw TopologyError(path + ": " + e.what(), e.vertices(), e.faces());
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(path + ": " + e.what());
  } catch (const Error& e) {
    throw Error(path + ": " + e.what());
  }
  // What the reader kept but found suspect, where the user sees it whatever the command.
  for (const std::string& w : loaded.report.warnings) std::cerr << "hedge: warning: " << w << '\n';
  return loaded;
}

void save_mesh(const SurfaceMesh& mesh, const std::string& path, bool ascii) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  WriteOptions write;
  write.binary = !ascii;
  write_mesh(mesh, path, write);
}

const char* format_name(FileFormat format) {
  static constexpr std::pair<FileFormat, const char*> kNames[] = {
      {FileFormat::obj, "obj"}, {FileFormat::off, "off"},   {FileFormat::ply, "ply"},
      {FileFormat::stl, "stl"}, {FileFormat::gltf, "gltf"}, {FileFormat::glb, "glb"}};
  for (const auto& [f, name] : kNames)
    if (f == format) return name;
  return "unknown";
}

}  // namespace hedge::cli

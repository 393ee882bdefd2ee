// The subcommands of the hedge tool and what their command lines share. Each subcommand lives in its
// own file, which defines its CommandBinder, and is listed once here and once, with its name and
// description, in main.cpp's command table; nothing else needs to change to add one.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "load.h"

namespace hedge::cli {

//! Exit codes shared by every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitDataError = 1;  //!< unreadable or malformed input, invalid mesh
inline constexpr int kExitUsage = 2;      //!< bad command line

//! A registered subcommand: its CLI11 node and what to run when it was chosen. run() returns the
//! exit code and may throw; main() turns exceptions into one "hedge: error: ..." line.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

//! Adds a subcommand's arguments to its CLI11 node and returns what to run (see bind_command).
using CommandBinder = Command (*)(CLI::App& app);

//! A subcommand: the name and description `hedge --help` shows, and its binder.
struct CommandSpec {
  const char* name;
  const char* description;
  CommandBinder bind;
};

//! The binder of a subcommand whose command line fills an `Options` (a struct with a LoadOptions
//! member `load`): `setup` adds the command's own arguments, the load options follow, and the
//! command runs `run` on the options. The options live as long as the returned Command, so `setup`
//! may keep pointers to them and to the subcommand in CLI11 callbacks.
template <typename Options, void (*setup)(CLI::App*, Options*), int (*run)(const Options&)>
Command bind_command(CLI::App& app) {
  auto options = std::make_shared<Options>();
  setup(&app, options.get());
  add_load_options(app, options->load);
  return {&app, [options] { return run(*options); }};
}

//! Adds the subcommand `spec` to `parent`.
Command add_command(CLI::App& parent, const CommandSpec& spec);

//! The command line of the commands that read one mesh and report on it: FILE and --json (info and
//! validate; stress and render-buffers add options of their own).
struct MeshReportOptions {
  std::string file;
  bool json = false;
  LoadOptions load;
};
void add_mesh_report_arguments(CLI::App* app, MeshReportOptions* options);

//! The command line of the commands that read a mesh, change it and write it: IN, OUT and --ascii.
struct InOutOptions {
  std::string input, output;
  bool ascii = false;
  LoadOptions load;
};
//! Checks OUT's format first, so that an unknown extension fails before the work, then loads IN.
LoadedMesh load_input(const InOutOptions& options);

//! The positional FILE: a mesh file of any format the library reads.
void add_mesh_file_argument(CLI::App& app, std::string& file, bool required = true);
//! The positionals IN and OUT of the commands that read a mesh, change it and write it.
void add_in_out_arguments(CLI::App& app, std::string& input, std::string& output,
                          const char* input_help = "Input mesh file");
//! --json, with the command's own description of what it prints.
void add_json_flag(CLI::App& app, bool& json, const char* help = "Print one JSON object instead of text");
//! --seed, a whole number of 0 or more.
void add_seed_option(CLI::App& app, std::uint64_t& seed, const char* help = "Random seed");
//! --ascii, for the commands that write a mesh.
void add_ascii_flag(CLI::App& app, bool& ascii);

//! The binders of the subcommands, each defined in the file of its name; main.cpp's command table
//! gives their names and descriptions.
extern const CommandBinder info_command, validate_command, convert_command, stress_command,
    render_buffers_command, render_command, tour_command, smooth_command, subdivide_command, decimate_command,
    distance_command, fracture_command;

}  // namespace hedge::cli

// The subcommands of the hedge tool and what their command lines share. Each subcommand lives in its
// own file and is listed once here and once in main.cpp's command table; nothing else needs to
// change to add one.
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

//! Makes the subcommand `name` of `parent` whose command line fills an `Options` (a struct with a
//! LoadOptions member `load`): `setup` adds the command's own arguments, the load options follow,
//! and the command runs `run` on the options. The options live as long as the returned Command, so
//! `setup` may keep pointers to them and to the subcommand in CLI11 callbacks.
template <typename Options>
Command make_command(CLI::App& parent, const std::string& name, const std::string& description,
                     void (*setup)(CLI::App*, Options*), int (*run)(const Options&)) {
  auto options = std::make_shared<Options>();
  CLI::App* app = parent.add_subcommand(name, description);
  setup(app, options.get());
  add_load_options(*app, options->load);
  return {app, [options, run] { return run(*options); }};
}

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

Command add_info_command(CLI::App& parent);
Command add_validate_command(CLI::App& parent);
Command add_convert_command(CLI::App& parent);
Command add_stress_command(CLI::App& parent);
Command add_render_buffers_command(CLI::App& parent);
Command add_render_command(CLI::App& parent);
Command add_tour_command(CLI::App& parent);
Command add_smooth_command(CLI::App& parent);
Command add_subdivide_command(CLI::App& parent);
Command add_decimate_command(CLI::App& parent);
Command add_distance_command(CLI::App& parent);
Command add_fracture_command(CLI::App& parent);

}  // namespace hedge::cli

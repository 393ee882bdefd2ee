// The subcommands of the hedge tool. Each one lives in its own file and is listed once here and
// once in main.cpp's command table; nothing else needs to change to add one.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

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

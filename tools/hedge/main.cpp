// hedge: a command-line front end to the library. Errors never escape as exceptions or aborts:
// each becomes one "hedge: error: ..." line on stderr and a non-zero exit status (see commands.h).
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "commands.h"
#include "progress_bar.h"

#ifndef HEDGE_VERSION
#define HEDGE_VERSION "unknown"
#endif

namespace {

//! Messages may carry newlines (e.g. from CLI11); the tool promises one line per error.
std::string one_line(std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!message.empty() && message.back() == ' ') message.pop_back();
  return message;
}

int report_error(const std::string& message, int exit_code) {
  std::cerr << "hedge: error: " << one_line(message) << std::endl;
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hedge::cli;
  CLI::App app{"hedge: inspect, check, convert and edit polygon meshes (OBJ, OFF, PLY, STL, glTF)", "hedge"};
  app.set_version_flag("--version", HEDGE_VERSION);
  app.require_subcommand(1);

  // The command table, in the order `hedge --help` lists the subcommands: name, description, and the
  // binder defined in the command's own file.
  const CommandSpec specs[] = {
      {"info", "Load a mesh (repairing it unless --strict) and report counts, topology and repairs",
       info_command},
      {"validate", "Check every half-edge invariant; exit status 0 when valid, 1 when invalid",
       validate_command},
      {"convert", "Convert between OBJ, OFF, PLY, STL and glTF (.gltf, .glb); formats from the extensions",
       convert_command},
      {"stress", "Apply a seeded random sequence of local operations and check validity", stress_command},
      {"render-buffers", "Show the engine buffers of a mesh and how little a sync after an edit uploads",
       render_buffers_command},
      {"render",
       "Draw a mesh to a PNG picture without a GPU: shaded, with highlighted boundary, feature and "
       "repaired elements; several meshes side by side (--grid); or the half-edge diagram of a small "
       "mesh (--halfedges, PNG or SVG)",
       render_command},
      {"tour",
       "Show what hedge does to a mesh: load and repair, validate, Catmull-Clark, split all faces, "
       "Loop-subdivide and smooth, decimate, break like glass and as a solid, cut a hole and fill it, the "
       "half-edge diagram of one vertex's faces; writes a contact sheet PNG of every stage, the edited "
       "meshes, and prints counts and timings",
       tour_command},
      {"smooth",
       "Smooth a mesh's vertex positions (boundary fixed unless --free-boundary) and write the result",
       smooth_command},
      {"subdivide", "Subdivide a mesh and write the result", subdivide_command},
      {"decimate",
       "Decimate a triangle mesh by quadric-error edge collapses to a vertex or face count or an error, and "
       "write it",
       decimate_command},
      {"distance",
       "Sampled symmetric Hausdorff distance and mean distance between the surfaces of two meshes",
       distance_command},
      {"fracture",
       "Break a mesh at an impact point into shards (--kind solid: a closed mesh into closed pieces); write "
       "the rest, one OBJ per shard or piece and summary.json",
       fracture_command},
  };
  std::vector<Command> commands;
  for (const CommandSpec& spec : specs) commands.push_back(add_command(app, spec));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    return report_error(std::string(e.what()) + " (see 'hedge --help')", kExitUsage);
  }

  if (!ProgressBar::setting())
    return report_error("HEDGE_PROGRESS must be auto, always or never, got '" +
                            std::string(std::getenv("HEDGE_PROGRESS")) + "'",
                        kExitUsage);

  try {
    for (const Command& command : commands) {
      if (command.app->parsed()) return command.run();
    }
    return report_error("no subcommand given (see 'hedge --help')", kExitUsage);
  } catch (const std::bad_alloc&) {
    return report_error("out of memory", kExitDataError);
  } catch (const std::exception& e) {
    return report_error(e.what(), kExitDataError);
  } catch (...) {
    return report_error("unknown error", kExitDataError);
  }
}

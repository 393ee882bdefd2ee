// hedge: a command-line front end to the library. Errors never escape as exceptions or aborts:
// each becomes one "hedge: error: ..." line on stderr and a non-zero exit status (see commands.h).
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>

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

  // The command table: one line per subcommand.
  const Command commands[] = {
      add_info_command(app),     add_validate_command(app),       add_convert_command(app),
      add_stress_command(app),   add_render_buffers_command(app), add_render_command(app),
      add_tour_command(app),     add_smooth_command(app),         add_subdivide_command(app),
      add_decimate_command(app), add_distance_command(app),       add_fracture_command(app),
  };

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

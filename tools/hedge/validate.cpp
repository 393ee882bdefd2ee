// hedge validate FILE: load and check every invariant. Exit 0 when valid, 1 when not. Under
// --strict, input that would need repairs is reported as invalid with the topology error.
#include <iostream>
#include <optional>

#include "commands.h"
#include "hedge/error.h"
#include "load.h"
#include "mesh_stats.h"

namespace hedge::cli {

namespace {

int run_validate(const MeshReportOptions& options) {
  std::vector<std::string> problems;
  std::optional<BuildReport> report;
  try {
    LoadedMesh loaded = load_mesh(options.file, options.load);
    problems = loaded.mesh.validate();
    report = std::move(loaded.report);
  } catch (const TopologyError& e) {
    // Only reachable under --strict: the input is not a clean manifold. That is the answer.
    problems.push_back(std::string("topology error: ") + e.what());
  }
  const bool valid = problems.empty();

  if (options.json) {
    nlohmann::json j;
    j["file"] = options.file;
    j["valid"] = valid;
    j["problems"] = problems;
    j["repairs"] = report ? repairs_json(*report) : nlohmann::json(nullptr);
    std::cout << j.dump(2) << '\n';
  } else if (valid) {
    std::cout << options.file << ": valid";
    if (report && report->repairs() > 0) {
      std::cout << " (after " << report->repairs() << (report->repairs() == 1 ? " repair)" : " repairs)");
    }
    std::cout << '\n';
  } else {
    std::cout << options.file << ": invalid, " << problems.size()
              << (problems.size() == 1 ? " problem\n" : " problems\n");
    for (const std::string& problem : problems) std::cout << "  - " << problem << '\n';
  }
  return valid ? kExitOk : kExitDataError;
}

}  // namespace

const CommandBinder validate_command =
    bind_command<MeshReportOptions, add_mesh_report_arguments, run_validate>;

}  // namespace hedge::cli

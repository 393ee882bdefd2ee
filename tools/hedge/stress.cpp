// hedge stress FILE --ops N --seed S: runs a seeded random sequence of local operations on the
// user's mesh and reports what was applied and refused, and whether the mesh stayed valid.
// Exits 1 if the mesh ever became invalid, so scripts can bisect a failing seed.
#include <iostream>

#include "commands.h"
#include "edits/random_edits.h"
#include "load.h"
#include "mesh_stats.h"
#include "numbers.h"

namespace hedge::cli {

namespace {

struct StressOptions : MeshReportOptions {
  std::size_t ops = 10000;
  std::uint64_t seed = 1;
  std::size_t validate_every = 1;
};

int run_stress(const StressOptions& options) {
  LoadedMesh loaded = load_mesh(options.file, options.load);
  SurfaceMesh& mesh = loaded.mesh;
  RandomEditOptions edit;
  edit.seed = options.seed;
  edit.operations = options.ops;
  edit.validate_every = options.validate_every;
  const RandomEditReport r = random_edits(mesh, edit);

  if (options.json) {
    nlohmann::json applied = nlohmann::json::object(), refused = nlohmann::json::object();
    for (std::size_t k = 0; k < kEditKinds; ++k) {
      applied[edit_name(static_cast<EditKind>(k))] = r.applied[k];
      refused[edit_name(static_cast<EditKind>(k))] = r.refused[k];
    }
    nlohmann::json j;
    j["file"] = options.file;
    j["seed"] = options.seed;
    j["operations"] = options.ops;
    j["applied"] = applied;
    j["refused"] = refused;
    j["euler_mismatches"] = r.euler_mismatches;
    j["valid"] = r.valid;
    j["problems"] = r.problems;
    if (!r.valid) {
      j["first_invalid_operation"] = r.first_invalid_operation;
      j["first_invalid_kind"] = edit_name(r.first_invalid_kind);
    }
    j["vertices"] = mesh.n_vertices();
    j["edges"] = mesh.n_edges();
    j["faces"] = mesh.n_faces();
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << options.file << ": " << options.ops << " random operations, seed " << options.seed << '\n';
    for (std::size_t k = 0; k < kEditKinds; ++k)
      std::cout << "  " << edit_name(static_cast<EditKind>(k)) << ": " << r.applied[k] << " applied, "
                << r.refused[k] << " refused\n";
    std::cout << "final: " << mesh.n_vertices() << " vertices, " << mesh.n_edges() << " edges, "
              << mesh.n_faces() << " faces\n";
    if (r.valid) {
      if (options.validate_every == 1)
        std::cout << "valid after every operation";
      else if (options.validate_every == 0)
        std::cout << "valid at the end";
      else
        std::cout << "valid after every " << options.validate_every << "th operation and at the end";
      std::cout << (r.euler_mismatches ? ", but the Euler characteristic changed unexpectedly " +
                                             std::to_string(r.euler_mismatches) + " times\n"
                                       : "\n");
    } else {
      std::cout << "INVALID after operation " << r.first_invalid_operation << " ("
                << edit_name(r.first_invalid_kind) << "):\n";
      for (const std::string& p : r.problems) std::cout << "  - " << p << '\n';
    }
  }
  return r.valid && r.euler_mismatches == 0 ? kExitOk : kExitDataError;
}

void add_stress_arguments(CLI::App* app, StressOptions* options) {
  add_mesh_file_argument(*app, options->file);
  app->add_option("--ops", options->ops, "Number of operations")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(0, 100000000));
  add_seed_option(*app, options->seed);
  app->add_option("--validate-every", options->validate_every,
                  "Validate after every N-th operation (0: only at the end)")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(0));
  add_json_flag(*app, options->json, "Print one JSON object");
}

}  // namespace

const CommandBinder stress_command = bind_command<StressOptions, add_stress_arguments, run_stress>;

}  // namespace hedge::cli

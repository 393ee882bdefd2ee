// hedge distance A B: how far apart two surfaces are, as the sampled Hausdorff distance.
#include "hedge/algorithms/distance.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/error.h"
#include "load.h"
#include "memory_budget.h"
#include "numbers.h"

namespace hedge::cli {

namespace {

struct DistanceCommandOptions {
  std::string a, b;
  std::size_t samples = 100000;
  std::uint64_t seed = 1;
  bool json = false;
  LoadOptions load;
};

nlohmann::json side_json(const OneSidedDistance& d) {
  return {{"max", d.max},
          {"mean", d.mean},
          {"points", d.points},
          {"farthest", {d.farthest.x, d.farthest.y, d.farthest.z}}};
}

void print_side(const char* label, const OneSidedDistance& d) {
  std::cout << "  " << std::left << std::setw(22) << label << "max " << d.max << ", mean " << d.mean
            << ", farthest at (" << d.farthest.x << ", " << d.farthest.y << ", " << d.farthest.z << "), "
            << d.points << " points\n";
}

int run_distance(const DistanceCommandOptions& o) {
  const LoadedMesh a = load_mesh(o.a, o.load);
  const LoadedMesh b = load_mesh(o.b, o.load);
  // One distance (8 bytes) per point of a surface, one surface at a time.
  const double points = double(std::max(a.mesh.n_vertices(), b.mesh.n_vertices())) + double(o.samples);
  check_memory(8 * points, o.load.memory, std::to_string(o.samples) + " samples", "use fewer --samples");
  HausdorffDistance d;
  try {
    d = hausdorff_distance(a.mesh, b.mesh, {.samples = o.samples, .seed = o.seed});
  } catch (const InvalidInputError& e) {
    throw InvalidInputError(std::string(e.what()) + " (a: " + o.a + ", b: " + o.b + ")");
  }
  // Relative to the size of A, which is what a tolerance is usually stated against.
  const Vec3 size = bounding_box(a.mesh).size();
  const double diagonal =
      std::sqrt(double(size.x) * size.x + double(size.y) * size.y + double(size.z) * size.z);
  const double relative = diagonal > 0 ? d.distance / diagonal : 0;
  if (o.json) {
    const nlohmann::json j = {{"a", o.a},
                              {"b", o.b},
                              {"samples", o.samples},
                              {"seed", o.seed},
                              {"hausdorff", d.distance},
                              {"hausdorff_over_diagonal_of_a", relative},
                              {"mean", d.mean},
                              {"a_to_b", side_json(d.a_to_b)},
                              {"b_to_a", side_json(d.b_to_a)}};
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << o.a << " <-> " << o.b << " (" << o.samples << " face samples on each, seed " << o.seed
              << ")\n";
    std::cout << "  " << std::left << std::setw(22) << "Hausdorff distance" << d.distance << " ("
              << 100 * relative << "% of the bounding-box diagonal of A)\n";
    std::cout << "  " << std::left << std::setw(22) << "mean distance" << d.mean << '\n';
    print_side("A to B", d.a_to_b);
    print_side("B to A", d.b_to_a);
  }
  return kExitOk;
}

void add_distance_arguments(CLI::App* app, DistanceCommandOptions* options) {
  app->add_option("A", options->a, "First mesh file")->required();
  app->add_option("B", options->b, "Second mesh file")->required();
  app->add_option(
         "--samples", options->samples,
         "Points drawn on the faces of each surface, besides its vertices (at most 100000000; 8 bytes each)")
      ->capture_default_str()
      ->transform(whole_number<std::size_t>(0, kMaxDistanceSamples));
  add_seed_option(*app, options->seed, "Seed of the draws");
  add_json_flag(*app, options->json);
}

}  // namespace

const CommandBinder distance_command =
    bind_command<DistanceCommandOptions, add_distance_arguments, run_distance>;

}  // namespace hedge::cli

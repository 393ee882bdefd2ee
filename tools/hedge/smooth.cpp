// hedge smooth IN OUT: read, smooth the positions, write; formats by extension.
#include "hedge/algorithms/smooth.h"

#include <cstdio>
#include <string>
#include <utility>

#include "binding/names.h"
#include "commands.h"
#include "load.h"
#include "numbers.h"
#include "progress_bar.h"

namespace hedge::cli {

namespace {

struct SmoothCommandOptions : InOutOptions {
  std::string method = "uniform";
  int iterations = 10;
  double lambda = 0.5;
  double mu = -0.53;
  bool free_boundary = false;
};

int run_smooth(const SmoothCommandOptions& o) {
  LoadedMesh loaded = load_input(o);
  SmoothOptions s;
  s.method = binding::parse_smooth_method(o.method);
  s.iterations = o.iterations;
  s.lambda = o.lambda;
  s.mu = o.mu;
  s.fix_boundary = !o.free_boundary;
  const double ms = run_with_progress("smooth", [&](Progress progress) {
    s.progress = std::move(progress);
    smooth(loaded.mesh, s);
  });
  save_mesh(loaded.mesh, o.output, o.ascii);
  std::printf("smoothed %s -> %s: %s, %d iterations, %zu vertices, %.1f ms\n", o.input.c_str(),
              o.output.c_str(), o.method.c_str(), o.iterations, loaded.mesh.n_vertices(), ms);
  return kExitOk;
}

void add_smooth_arguments(CLI::App* app, SmoothCommandOptions* o) {
  add_in_out_arguments(*app, o->input, o->output);
  app->add_option(
         "--method", o->method,
         "uniform (umbrella), taubin (lambda|mu, no shrinking), cotangent (cotangent weights, triangles "
         "only; cotan also accepted) or implicit (backward Euler steps of the cotangent flow; lambda is the "
         "time step)")
      ->capture_default_str()
      ->check(CLI::IsMember(binding::smooth_method_spellings()));
  app->add_option("--iterations", o->iterations, "Iterations")
      ->capture_default_str()
      ->transform(whole_number<int>(0, 100000));
  add_real_option(*app, "--lambda", o->lambda,
                  "Step toward the average, in (0, 1]; for implicit, the time step in units of each vertex's "
                  "explicit step",
                  -kInf, kInf);
  add_real_option(*app, "--mu", o->mu, "Taubin's inflating step, below -lambda", -kInf, kInf);
  app->add_flag("--free-boundary", o->free_boundary, "Let boundary vertices move along the boundary");
  add_ascii_flag(*app, o->ascii);
}

}  // namespace

const CommandBinder smooth_command = bind_command<SmoothCommandOptions, add_smooth_arguments, run_smooth>;

}  // namespace hedge::cli

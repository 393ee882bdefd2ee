// Google Benchmark binary for hedge's own operations: one BM_<op>/<mesh> per operation of the hedge
// backend (peer_hedge.cpp) and per mesh, so operations added there show up here too.
//
//   hedge_bench [benchmark flags, e.g. --benchmark_min_time=0.05] [--root DIR] [mesh[:subN] ...]
//
// Without meshes it uses the same default list as `peers` (../shared/meshes, else data/).
#include <benchmark/benchmark.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.h"

namespace {

struct Loaded {
  bench::Input input;
  bench::Scratch scratch;
  std::unique_ptr<bench::MeshBox> reference;
};

void run_op(benchmark::State& state, const bench::OpImpl* impl, Loaded* l) {
  for (auto _ : state) {
    std::unique_ptr<bench::MeshBox> work;
    if (impl->prepare) {
      state.PauseTiming();
      work = impl->prepare(*l->reference);
      state.ResumeTiming();
    }
    bench::Context ctx{l->input, work ? work.get() : l->reference.get(), l->scratch, nullptr};
    benchmark::DoNotOptimize(impl->run(ctx));
    state.PauseTiming();
    ctx.out.reset();
    work.reset();
    state.ResumeTiming();
  }
  state.counters["vertices"] = static_cast<double>(l->input.n_vertices());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  std::string root;
  std::vector<std::string> specs;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--root" && i + 1 < argc) root = argv[++i];
    else specs.push_back(a);
  }
  if (specs.empty()) {
    std::string note;
    specs = bench::default_mesh_specs(bench::find_root(root), note);
    std::cerr << note << "\n";
    if (specs.empty()) return 0;
  }

  static const bench::Backend backend = bench::hedge_backend();
  static std::vector<std::unique_ptr<Loaded>> meshes;
  for (const std::string& spec : specs) {
    auto l = std::make_unique<Loaded>();
    try {
      l->input = bench::load_spec(spec);
      l->scratch.resize(l->input);
      l->reference = backend.build(l->input);
    } catch (const std::exception& e) {
      std::cerr << spec << ": skipped: " << e.what() << "\n";
      continue;
    }
    for (const auto& [key, impl] : backend.ops)
      benchmark::RegisterBenchmark(("BM_" + key + "/" + l->input.name).c_str(), run_op, &impl, l.get())
          ->Unit(benchmark::kMillisecond);
    meshes.push_back(std::move(l));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// Google Benchmark binary for hedge's own operations: one BM_<op>/<mesh> per operation of the hedge
// backend (peer_hedge.cpp) and per mesh, so operations added there show up here too.
//
//   hedge_bench [benchmark flags, e.g. --benchmark_min_time=0.05] [--root DIR] [mesh[:subN] ...]
//
// Without meshes it uses the same default list as `peers` (../shared/meshes, else data/).
//
// BM_one_ring_order/<mesh>/{as_loaded,shuffled,reordered}: one-ring circulation over every vertex of
// the mesh as loaded, after a random renumbering of its vertices, edges and faces, and after
// reorder_spatially() of the shuffled mesh: the cost of a lost element order, and what reordering
// gets back (algorithms/reorder.h).
//
// BM_decimate/<mesh>: quadric decimation to 10% of the vertices (algorithms/decimate.h), the copy of
// the mesh excluded from the time; the counters give the vertices reached and the largest error.
#include <benchmark/benchmark.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/reorder.h"
#include "hedge/core/build.h"

#include <algorithm>
#include <numeric>
#include <random>

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

// A random renumbering of every element.
void shuffle(hedge::SurfaceMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  auto perm = [&](std::size_t n) {
    std::vector<hedge::Index> p(n);
    std::iota(p.begin(), p.end(), 0);
    std::shuffle(p.begin(), p.end(), rng);
    return p;
  };
  m.renumber(perm(m.vertex_slots()), perm(m.edge_slots()), perm(m.face_slots()));
}

void one_ring(benchmark::State& state, const hedge::SurfaceMesh* m) {
  for (auto _ : state) {
    std::size_t sum = 0;
    for (hedge::Vertex v : m->vertices())
      for (hedge::Vertex w : m->vertices(v)) sum += w.idx();
    benchmark::DoNotOptimize(sum);
  }
}

void decimate_tenth(benchmark::State& state, const hedge::SurfaceMesh* input) {
  hedge::DecimateResult r;
  for (auto _ : state) {
    state.PauseTiming();
    auto m = std::make_unique<hedge::SurfaceMesh>(*input);
    state.ResumeTiming();
    r = hedge::decimate(*m, {.target_vertices = input->n_vertices() / 10});
    state.PauseTiming();
    m.reset();
    state.ResumeTiming();
  }
  state.counters["vertices"] = static_cast<double>(r.vertices);
  state.counters["max_error"] = r.max_error;
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
    // The element order's effect on circulation.
    static std::vector<std::unique_ptr<hedge::SurfaceMesh>> orders;
    auto as_loaded = std::make_unique<hedge::SurfaceMesh>(hedge::build_triangles(
        {reinterpret_cast<const hedge::Vec3*>(l->input.xyz.data()), l->input.n_vertices()}, l->input.tri));
    const hedge::SurfaceMesh* loaded_mesh = as_loaded.get();
    auto shuffled = std::make_unique<hedge::SurfaceMesh>(*as_loaded);
    shuffle(*shuffled, 1);
    auto reordered = std::make_unique<hedge::SurfaceMesh>(*shuffled);
    hedge::reorder_spatially(*reordered);
    for (auto* m : {&as_loaded, &shuffled, &reordered}) {
      const char* what = m == &as_loaded ? "as_loaded" : m == &shuffled ? "shuffled" : "reordered";
      benchmark::RegisterBenchmark(("BM_one_ring_order/" + l->input.name + "/" + what).c_str(), one_ring, m->get())
          ->Unit(benchmark::kMillisecond);
      orders.push_back(std::move(*m));
    }
    benchmark::RegisterBenchmark(("BM_decimate/" + l->input.name).c_str(), decimate_tenth, loaded_mesh)
        ->Unit(benchmark::kMillisecond);
    meshes.push_back(std::move(l));
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

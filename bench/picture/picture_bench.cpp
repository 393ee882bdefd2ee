// The rasteriser behind `hedge render` on a mesh of at least a million triangles: armadillo from
// ../shared/meshes subdivided (1.38M triangles), or the repository's spot mesh subdivided when the
// shared meshes are absent. 1024x768 pixels, 4 samples per pixel (supersample 2), smooth shading,
// on 1 thread and on every core. The bar: under a second.
//
//   bench/picture/run [REPETITIONS]
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "hedge/core/build.h"
#include "hedge/io/io.h"
#include "indexed_subdivide.h"
#include "picture/raster.h"

namespace {

using namespace hedge;
using namespace hedge::picture;

struct Scene {
  std::string name;
  SurfaceMesh mesh;
  Camera camera;
};

const Scene& scene() {
  static const Scene s = [] {
    const std::string root = HEDGE_PICTURE_BENCH_ROOT;
    std::string path = root + "/../shared/meshes/armadillo.obj";
    if (!std::filesystem::exists(path)) path = root + "/data/spot_triangulated.obj";
    IndexedMesh in = read_indexed_file(path);
    const int rounds = bench::subdivide_until(in, 1'000'000);
    Scene out;
    out.name =
        std::filesystem::path(path).filename().string() + " subdivided " + std::to_string(rounds) + "x";
    out.mesh = build(in);
    out.camera = frame(out.mesh, View::iso, 1024.0 / 768);
    std::printf("mesh: %s, %zu triangles\n", out.name.c_str(), out.mesh.n_faces());
    // One render first, so that the first benchmark does not pay for the allocator's first growth.
    RenderOptions warm;
    warm.width = 1024;
    warm.height = 768;
    benchmark::DoNotOptimize(render(out.mesh, out.camera, warm));
    return out;
  }();
  return s;
}

void BM_Render(benchmark::State& state, bool wireframe) {
  const Scene& s = scene();
  RenderOptions o;
  o.width = 1024;
  o.height = 768;
  o.supersample = 2;
  o.wireframe = wireframe;
  o.threads = static_cast<unsigned>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(render(s.mesh, s.camera, o));
  state.counters["triangles"] = double(s.mesh.n_faces());
}

void threads(benchmark::internal::Benchmark* b) {
  b->Arg(1);
  const unsigned n = std::thread::hardware_concurrency();
  if (n > 1) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK_CAPTURE(BM_Render, shaded, false)->Apply(threads);
BENCHMARK_CAPTURE(BM_Render, wireframe, true)->Apply(threads);

}  // namespace

BENCHMARK_MAIN();

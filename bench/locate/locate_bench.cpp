// Point location: FaceBvh queries against the linear scans over every face, in the same run, on a
// mesh of 100k+ triangles; FaceBvh build time against hedge::build on the same mesh; update() after
// a local edit against a full rebuild. Google Benchmark prints its table, then a summary of medians
// and ratios. Run it through bench/locate/run.
//
//   hedge_locate_bench [--root DIR] [--mesh FILE] [--min-faces N] [Google Benchmark flags]
//
// The mesh is ../shared/meshes/armadillo.obj next to the repository when present, else
// data/spot_triangulated.obj; it is refined by 1-to-4 midpoint subdivision until it has at least
// --min-faces (default 100000) triangles. The 2D queries use a flat grid plate of the same order.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hedge/algorithms/locate.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/operations.h"
#include "hedge/io/io.h"
#include "indexed_subdivide.h"

namespace {

using namespace hedge;
namespace fs = std::filesystem;

struct Ray {
  Vec3 origin, direction;
};

struct Workload {
  std::string name;
  IndexedMesh indexed;
  SurfaceMesh mesh;
  FaceBvh sah, median;
  std::vector<Vec3> points;  // a third uniform in the grown box, the rest near the surface
  std::vector<Ray> rays;     // from a sphere around the mesh toward points of its box
  IndexedMesh plate_indexed;
  SurfaceMesh plate;
  FaceBvh plate_bvh;
  std::vector<Vec2> plate_points;  // over the plate and a margin around it
};

void make_queries(Workload& w, std::size_t n) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::normal_distribution<float> gauss(0.f, 1.f);
  Vec3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (const Vec3& p : w.indexed.positions)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  const Vec3 size = hi - lo;
  const float diag = norm(size);
  const Vec3 centre = (lo + hi) * 0.5f;
  auto in_box = [&](float grow) {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = lo[a] - grow * size[a] + unit(rng) * (1 + 2 * grow) * size[a];
    return p;
  };
  const std::size_t nt = w.indexed.indices.size() / 3;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 3 == 0) {
      w.points.push_back(in_box(0.1f));
    } else {
      const std::size_t t = std::uniform_int_distribution<std::size_t>(0, nt - 1)(rng);
      float u = unit(rng), v = unit(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      const Vec3& a = w.indexed.positions[w.indexed.indices[3 * t]];
      const Vec3& b = w.indexed.positions[w.indexed.indices[3 * t + 1]];
      const Vec3& c = w.indexed.positions[w.indexed.indices[3 * t + 2]];
      w.points.push_back(a + (b - a) * u + (c - a) * v +
                         Vec3{gauss(rng), gauss(rng), gauss(rng)} * (0.005f * diag));
    }
    const Vec3 eye = centre + normalize(Vec3{gauss(rng), gauss(rng), gauss(rng)}) * diag;
    w.rays.push_back({eye, normalize(in_box(0.f) - eye)});
  }
  std::uniform_real_distribution<float> over(-0.05f, 1.05f);
  const float side = w.plate_indexed.positions.back().x;
  for (std::size_t i = 0; i < n; ++i) w.plate_points.push_back({over(rng) * side, over(rng) * side});
}

Workload load_workload(const fs::path& root, std::string mesh_path, std::size_t min_faces) {
  if (mesh_path.empty()) {
    const fs::path shared = root / ".." / "shared" / "meshes" / "armadillo.obj";
    mesh_path = fs::exists(shared) ? shared.string() : (root / "data" / "spot_triangulated.obj").string();
  }
  Workload w;
  IndexedMesh in = read_indexed_file(mesh_path);
  if (!in.is_triangles()) in = to_indexed(build(in), {.triangulation = Triangulation::fan});
  w.name = fs::path(mesh_path).filename().string();
  const int levels = bench::subdivide_until(in, min_faces);
  if (levels > 0) w.name += " subdivided x" + std::to_string(levels);
  w.indexed = std::move(in);
  w.mesh = build(w.indexed);
  w.sah.build(w.mesh, {.split = BvhSplit::sah});
  w.median.build(w.mesh, {.split = BvhSplit::median});
  const int side = static_cast<int>(std::ceil(std::sqrt(double(min_faces) / 2)));
  w.plate_indexed = bench::plate(side);
  w.plate = build(w.plate_indexed);
  w.plate_bvh.build(w.plate);
  make_queries(w, 4096);
  return w;
}

// ---- Benchmarks: one query per iteration, cycling through the fixed query set. ----

template <typename Fn>
void each_query(benchmark::State& state, std::size_t n, Fn fn) {
  std::size_t i = 0;
  std::size_t found = 0;
  for (auto _ : state) {
    found += fn(i).has_value();
    i = (i + 1 == n) ? 0 : i + 1;
  }
  state.counters["found"] = benchmark::Counter(double(found) / double(state.iterations()));
}

void register_benchmarks(Workload& w) {
  using benchmark::kMicrosecond;
  using benchmark::kMillisecond;
  using benchmark::RegisterBenchmark;
  RegisterBenchmark("build/mesh", [&w](benchmark::State& s) {
    for (auto _ : s) benchmark::DoNotOptimize(build(w.indexed));
  })->Unit(kMillisecond);
  for (BvhSplit split : {BvhSplit::sah, BvhSplit::median}) {
    const std::string name = split == BvhSplit::sah ? "sah" : "median";
    RegisterBenchmark(("build/bvh_" + name).c_str(), [&w, split](benchmark::State& s) {
      for (auto _ : s) benchmark::DoNotOptimize(FaceBvh(w.mesh, {.split = split}));
    })->Unit(kMillisecond);
  }

  for (const FaceBvh* bvh : {&w.sah, &w.median}) {
    const std::string name = bvh == &w.sah ? "sah" : "median";
    RegisterBenchmark(("closest/bvh_" + name).c_str(), [&w, bvh](benchmark::State& s) {
      each_query(s, w.points.size(), [&](std::size_t i) { return bvh->closest_point(w.points[i]); });
    })->Unit(kMicrosecond);
    RegisterBenchmark(("ray/bvh_" + name).c_str(), [&w, bvh](benchmark::State& s) {
      each_query(s, w.rays.size(),
                 [&](std::size_t i) { return bvh->first_hit(w.rays[i].origin, w.rays[i].direction); });
    })->Unit(kMicrosecond);
  }
  RegisterBenchmark("closest/linear", [&w](benchmark::State& s) {
    each_query(s, w.points.size(), [&](std::size_t i) { return closest_point_linear(w.mesh, w.points[i]); });
  })->Unit(kMicrosecond);
  RegisterBenchmark("ray/linear", [&w](benchmark::State& s) {
    each_query(s, w.rays.size(), [&](std::size_t i) {
      return first_hit_linear(w.mesh, w.rays[i].origin, w.rays[i].direction);
    });
  })->Unit(kMicrosecond);
  RegisterBenchmark("plate2d/bvh", [&w](benchmark::State& s) {
    each_query(s, w.plate_points.size(),
               [&](std::size_t i) { return w.plate_bvh.face_containing(w.plate_points[i]); });
  })->Unit(kMicrosecond);
  RegisterBenchmark("plate2d/linear", [&w](benchmark::State& s) {
    each_query(s, w.plate_points.size(),
               [&](std::size_t i) { return face_containing_linear(w.plate, w.plate_points[i]); });
  })->Unit(kMicrosecond);

  // A local edit (split_face at a random point of a random face) followed by update(), or by a full
  // rebuild. Each repetition edits its own copy of the mesh; the copy is made outside the timing.
  for (bool incremental : {true, false}) {
    RegisterBenchmark(incremental ? "edit/split_face+update" : "edit/split_face+rebuild",
                      [&w, incremental](benchmark::State& s) {
                        SurfaceMesh mesh = w.mesh;
                        FaceBvh bvh(mesh);
                        std::mt19937 rng(7);
                        std::vector<Face> changed;
                        for (auto _ : s) {
                          Face f(static_cast<Index>(rng() % mesh.face_slots()));
                          while (mesh.is_deleted(f)) f = Face(static_cast<Index>(rng() % mesh.face_slots()));
                          Vec3 c{0, 0, 0};
                          for (Vertex v : mesh.vertices(f)) c += mesh.position(v);
                          const Vertex v = split_face(mesh, f, c / 3.f);
                          if (incremental) {
                            changed.clear();
                            for (Face g : mesh.faces(v)) changed.push_back(g);
                            bvh.update(changed);
                          } else {
                            bvh.build(mesh);
                          }
                        }
                        s.counters["builds"] = double(bvh.stats().builds);
                      })
        ->Unit(kMicrosecond);
  }
}

// ---- Summary: the median CPU time of each benchmark, then the ratios that matter. ----

class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      const double seconds = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
      const std::string name = r.run_name.str();
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name == "median")
        median_[name] = seconds;
      else if (r.run_type == Run::RT_Iteration && r.repetitions <= 1)
        median_.try_emplace(name, seconds);
    }
  }
  double get(const std::string& name) const {
    auto it = median_.find(name);
    return it == median_.end() ? std::nan("") : it->second;
  }

 private:
  std::map<std::string, double> median_;
};

std::string format_time(double seconds) {
  char buf[32];
  if (std::isnan(seconds)) return "n/a";
  if (seconds >= 1e-3)
    std::snprintf(buf, sizeof buf, "%.2f ms", seconds * 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.2f us", seconds * 1e6);
  return buf;
}

std::string format_ratio(double ratio, const char* format) {
  if (std::isnan(ratio)) return "n/a";
  char buf[32];
  std::snprintf(buf, sizeof buf, format, ratio);
  return buf;
}

void print_summary(const Workload& w, const SummaryReporter& r) {
  const FaceBvh::Stats s = w.sah.stats();
  std::printf("\n## Point location on %s: %zu triangles (median CPU time per call)\n\n", w.name.c_str(),
              w.mesh.n_faces());
  std::printf(
      "SAH tree: %zu nodes, %zu leaves, height %u, %.1f bytes per face; median-split tree: height %u\n\n",
      s.nodes, s.leaves, s.height, double(w.sah.memory_bytes()) / double(w.mesh.n_faces()),
      w.median.stats().height);
  std::printf("| what | FaceBvh | reference | reference / FaceBvh |\n|---|---:|---:|---:|\n");
  auto row = [&](const char* what, const std::string& fast, const std::string& slow) {
    const double a = r.get(fast), b = r.get(slow);
    std::printf("| %s | %s | %s | %s |\n", what, format_time(a).c_str(), format_time(b).c_str(),
                format_ratio(b / a, "%.0fx").c_str());
  };
  row("closest point, SAH tree vs linear scan", "closest/bvh_sah", "closest/linear");
  row("closest point, median tree vs linear scan", "closest/bvh_median", "closest/linear");
  row("first ray hit, SAH tree vs linear scan", "ray/bvh_sah", "ray/linear");
  row("first ray hit, median tree vs linear scan", "ray/bvh_median", "ray/linear");
  char plate_label[96];
  std::snprintf(plate_label, sizeof plate_label, "2D plate (%zu triangles), tree vs linear scan",
                w.plate.n_faces());
  row(plate_label, "plate2d/bvh", "plate2d/linear");
  row("split_face + update() vs split_face + full rebuild", "edit/split_face+update",
      "edit/split_face+rebuild");
  std::printf("\n| build | time | / hedge::build |\n|---|---:|---:|\n");
  const double mesh = r.get("build/mesh");
  std::printf("| hedge::build (half-edge mesh) | %s | 1.00 |\n", format_time(mesh).c_str());
  for (const char* b : {"build/bvh_sah", "build/bvh_median"})
    std::printf("| FaceBvh %s | %s | %s |\n", b + 10, format_time(r.get(b)).c_str(),
                format_ratio(r.get(b) / mesh, "%.2f").c_str());
}

}  // namespace

int main(int argc, char** argv) {
  fs::path root = fs::path(HEDGE_LOCATE_BENCH_ROOT);
  std::string mesh;
  std::size_t min_faces = 100000;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--root" && i + 1 < argc)
      root = argv[++i];
    else if (a == "--mesh" && i + 1 < argc)
      mesh = argv[++i];
    else if (a == "--min-faces" && i + 1 < argc)
      min_faces = std::stoul(argv[++i]);
    else
      rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
  Workload w = load_workload(root, mesh, min_faces);
  std::printf("mesh: %s, %zu vertices, %zu triangles\n", w.name.c_str(), w.mesh.n_vertices(),
              w.mesh.n_faces());
  register_benchmarks(w);
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_summary(w, reporter);
  benchmark::Shutdown();
  return 0;
}

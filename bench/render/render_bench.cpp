// Incremental render buffers against a full re-export, in one run, on meshes of a million triangles
// and more: random local edits (split, collapse, flip, split face, vertex moves), each followed by
// RenderBuffers::sync(), against building the buffers from scratch after every change
// (RenderBuffers::rebuild(); docs/names.md says which call of the original project it stands for). Google
// Benchmark prints its table for the full export and for edit + sync; then a summary gives, from per-edit
// samples, the median bytes rewritten and the median time per edit, with their ratios to a full re-export.
//
//   hedge_render_buffers_bench [--root DIR] [--mesh FILE]... [--min-faces N] [--edits N] [--json FILE]
//                      [Google Benchmark flags]
//
// Default meshes: ../shared/meshes/armadillo.obj (no texcoords: computed normals) and
// data/spot_triangulated.obj (UV seams), each refined by 1-to-4 midpoint subdivision until it has
// at least --min-faces (default 1,000,000) triangles. Run it through bench/render/run.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "hedge/io/io.h"
#include "hedge/render/render_buffers.h"
#include "indexed_subdivide.h"

namespace {

using namespace hedge;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Workload {
  std::string name;
  SurfaceMesh mesh;
};

std::vector<std::unique_ptr<Workload>> g_workloads;

std::unique_ptr<Workload> load(const std::string& path, std::size_t min_faces) {
  IndexedMesh in = read_indexed_file(path);
  in.normals.clear();
  in.normal_indices.clear();
  if (!in.is_triangles()) throw Error(path + ": the render benchmark expects a triangle mesh");
  const int levels = bench::subdivide_until(in, min_faces);
  auto w = std::make_unique<Workload>();
  w->name = fs::path(path).filename().string();
  if (levels > 0) w->name += " x" + std::to_string(1 << (2 * levels));
  BuildOptions o = default_build_options(format_from_path(path));
  w->mesh = build(in, o);
  return w;
}

// One random local edit; returns false if the pick was refused (nothing changed).
bool random_edit(SurfaceMesh& m, std::mt19937_64& rng) {
  const auto pick = [&](std::size_t n) { return static_cast<Index>(rng() % n); };
  const int kind = static_cast<int>(rng() % 100);
  if (kind < 20) {  // move a vertex
    const Vertex v(pick(m.vertex_slots()));
    if (m.is_deleted(v)) return false;
    const float d = 1e-3f * static_cast<float>(static_cast<int>(rng() % 2001) - 1000) / 1000.f;
    m.set_position(v, m.position(v) + Vec3{d, -d, 0.5f * d});
    return true;
  }
  if (kind < 50) {  // split an edge at its midpoint
    const Edge e(pick(m.edge_slots()));
    if (!can_split_edge(m, e)) return false;
    return split_edge(m, e, 0.5f * (m.position(m.vertex(e, 0)) + m.position(m.vertex(e, 1)))).is_valid();
  }
  if (kind < 75) {  // collapse, checked first
    const Halfedge h(pick(m.halfedge_slots()));
    if (m.is_deleted(h) || !can_collapse(m, h)) return false;
    return collapse(m, h).is_valid();
  }
  if (kind < 90) {  // flip
    const Edge e(pick(m.edge_slots()));
    if (m.is_deleted(e) || !can_flip(m, e)) return false;
    return flip(m, e).is_valid();
  }
  const Face f(pick(m.face_slots()));  // split a face at its centroid
  if (!can_split_face(m, f)) return false;
  return split_face(m, f, face_centroid(m, f)).is_valid();
}

void BM_FullExport(benchmark::State& state, Workload* w) {
  RenderBuffers rs(w->mesh);
  for (auto _ : state) {
    rs.rebuild();
    benchmark::DoNotOptimize(rs.indices().data());
  }
  state.counters["bytes"] = static_cast<double>(rs.buffer_bytes());
  state.counters["triangles"] = static_cast<double>(rs.n_triangles());
}

void BM_EditAndSync(benchmark::State& state, Workload* w) {
  SurfaceMesh m = w->mesh;
  RenderBuffers rs(m);
  std::mt19937_64 rng(42);
  std::size_t bytes = 0, edits = 0;
  for (auto _ : state) {
    while (!random_edit(m, rng)) {
    }
    const SyncResult& r = rs.sync();
    bytes += r.vertex_bytes + r.index_bytes;
    ++edits;
  }
  state.counters["bytes_per_edit"] = edits ? static_cast<double>(bytes) / static_cast<double>(edits) : 0;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

struct Summary {
  std::string name;
  std::size_t triangles = 0, render_vertices = 0, seams = 0, edits = 0, refused = 0;
  double full_bytes = 0, full_ms = 0;
  double edit_bytes = 0, edit_us = 0, edit_us_p90 = 0, sync_us = 0;
  double bytes_ratio() const { return edit_bytes / full_bytes; }
  double time_ratio() const { return full_ms * 1000 / edit_us; }
};

// The same-run comparison: full exports before and after the edits (their median), and each of
// `edits` applied edits followed by sync() timed on its own.
Summary measure(Workload& w, std::size_t edits) {
  Summary s;
  s.name = w.name;
  SurfaceMesh m = w.mesh;
  RenderBuffers rs(m);
  s.triangles = rs.n_triangles();
  s.render_vertices = rs.n_vertices();
  s.seams = rs.seam_splits();
  s.full_bytes = static_cast<double>(rs.buffer_bytes());
  std::vector<double> full;
  auto time_full = [&](int n) {
    for (int i = 0; i < n; ++i) {
      const auto t0 = Clock::now();
      rs.rebuild();
      full.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
  };
  time_full(3);
  std::mt19937_64 rng(7);
  std::vector<double> bytes, times, syncs;
  bytes.reserve(edits);
  times.reserve(edits);
  syncs.reserve(edits);
  while (times.size() < edits) {
    const auto t0 = Clock::now();
    if (!random_edit(m, rng)) {
      ++s.refused;
      continue;
    }
    const auto t1 = Clock::now();
    const SyncResult& r = rs.sync();
    const auto t2 = Clock::now();
    times.push_back(std::chrono::duration<double, std::micro>(t2 - t0).count());
    syncs.push_back(std::chrono::duration<double, std::micro>(t2 - t1).count());
    bytes.push_back(static_cast<double>(r.vertex_bytes + r.index_bytes));
  }
  time_full(3);
  s.edits = times.size();
  s.full_ms = median(full);
  s.edit_bytes = median(bytes);
  s.edit_us = median(times);
  s.edit_us_p90 = quantile(times, 0.9);
  s.sync_us = median(syncs);
  if (!m.validate().empty()) std::fprintf(stderr, "render bench: the edited mesh is invalid\n");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  fs::path root = HEDGE_RENDER_BUFFERS_BENCH_ROOT;
  std::vector<std::string> meshes;
  std::size_t min_faces = 1000000, edits = 10000;
  std::string json;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--root" && i + 1 < argc)
      root = argv[++i];
    else if (a == "--mesh" && i + 1 < argc)
      meshes.push_back(argv[++i]);
    else if (a == "--min-faces" && i + 1 < argc)
      min_faces = std::stoul(argv[++i]);
    else if (a == "--edits" && i + 1 < argc)
      edits = std::stoul(argv[++i]);
    else if (a == "--json" && i + 1 < argc)
      json = argv[++i];
    else
      rest.push_back(argv[i]);
  }
  if (meshes.empty()) {
    const fs::path arm = root / ".." / "shared" / "meshes" / "armadillo.obj";
    if (fs::exists(arm))
      meshes.push_back(arm.string());
    else
      std::fprintf(stderr, "render bench: %s not found, skipping it\n", arm.string().c_str());
    meshes.push_back((root / "data" / "spot_triangulated.obj").string());
  }
  for (const std::string& p : meshes) {
    std::fprintf(stderr, "loading %s ...\n", p.c_str());
    g_workloads.push_back(load(p, min_faces));
  }
  for (auto& w : g_workloads) {
    benchmark::RegisterBenchmark(("full_export/" + w->name).c_str(), BM_FullExport, w.get())
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("edit_and_sync/" + w->name).c_str(), BM_EditAndSync, w.get())
        ->Unit(benchmark::kMicrosecond)
        ->Iterations(static_cast<benchmark::IterationCount>(edits));
  }
  int gb_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&gb_argc, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf("\nSame-run comparison, %zu applied edits per mesh, sync() after each (medians):\n", edits);
  std::printf("%-28s %10s %12s %12s %12s %10s %12s %10s %10s\n", "mesh", "triangles", "full bytes",
              "edit bytes", "bytes ratio", "full ms", "edit+sync us", "sync us", "speedup");
  bool pass = true;
  std::string out = "[";
  for (auto& w : g_workloads) {
    const Summary s = measure(*w, edits);
    const bool ok = s.bytes_ratio() <= 1e-3 && s.time_ratio() >= 500;
    pass &= ok;
    std::printf("%-28s %10zu %12.0f %12.0f %12.2e %10.1f %12.2f %10.2f %9.0fx %s\n", s.name.c_str(),
                s.triangles, s.full_bytes, s.edit_bytes, s.bytes_ratio(), s.full_ms, s.edit_us, s.sync_us,
                s.time_ratio(), ok ? "pass" : "FAIL");
    std::printf("%-28s render vertices %zu (seam splits %zu), refused picks %zu, edit+sync p90 %.2f us\n", "",
                s.render_vertices, s.seams, s.refused, s.edit_us_p90);
    char buf[1024];
    std::snprintf(
        buf, sizeof buf,
        "%s{\"mesh\":\"%s\",\"triangles\":%zu,\"render_vertices\":%zu,\"seam_splits\":%zu,\"edits\":%zu,"
        "\"full_bytes\":%.0f,\"median_edit_bytes\":%.0f,\"full_ms\":%.3f,\"median_edit_us\":%.3f,"
        "\"median_sync_us\":%.3f,\"bytes_ratio\":%.3e,\"speedup\":%.1f,\"pass\":%s}",
        out.size() > 1 ? "," : "", s.name.c_str(), s.triangles, s.render_vertices, s.seams, s.edits,
        s.full_bytes, s.edit_bytes, s.full_ms, s.edit_us, s.sync_us, s.bytes_ratio(), s.time_ratio(),
        ok ? "true" : "false");
    out += buf;
  }
  out += "]\n";
  std::printf("Bars: median edit bytes <= 1/1000 of a full export, median edit+sync >= 500x faster: %s\n",
              pass ? "met" : "NOT met");
  if (!json.empty()) std::ofstream(json) << out;
  return pass ? 0 : 1;
}

// Same-process comparison of hedge with OpenMesh and CGAL Surface_mesh on the same meshes, and with
// meshoptimizer's simplifier for the decimation.
//
//   peers [--json] [--quick] [--reps N] [--strict] [--cpu-time] [--only SEL] [--root DIR] [mesh ...]
//
// A mesh is a file path, optionally suffixed ":subN" for N rounds of 1-to-4 subdivision. Without
// meshes: armadillo.obj, igea.ply and armadillo.obj:sub2 from ../shared/meshes (relative to the
// repository root), else the repository's data/ meshes.
//
// Method: every backend gets the same in-memory arrays. For each mesh and operation the backends
// run round-robin (the starting backend rotates every round) after one warm-up run each; runs
// shorter than 1 ms are batched into one sample (same batch size for every backend); the
// medians of the per-run times are compared: ratio = fastest peer's median / hedge's median (> 1: hedge is
// faster). Checksums of every operation are compared across backends. The editing operations (collapse,
// split, flip) run the same seeded sequence of 10^5 random attempts on a private copy of the mesh
// made before the timer starts (see EditRng in bench_common.h); their result is checked untimed
// after the warm-up run with each library's own validity checks and the element counts the
// edits imply. Bytes per vertex are the net heap
// bytes allocated while building (counted by replacing operator new/delete, see alloc_count.cpp),
// divided by the number of vertices. The decimation's quality is measured untimed after the warm-up
// run: the sampled symmetric Hausdorff and mean distances of each result to the input (hedge's
// algorithms/distance.h on the results converted to hedge meshes), and the counts reached.
//
// --only runs a subset (e.g. `--only hedge:split` under a profiler): operations not selected are
// left out of the table, the JSON and the bars; backends not selected for an operation read n/a
// there, and a backend no selected operation uses is not built (its bytes per vertex read n/a).
//
// --cpu-time times the samples by the process's CPU time (user + system) instead of the wall clock.
// On a machine busy with other work, a wall-clock sample also counts the time the other processes
// ran; pinned to one core (taskset -c N, where hedge runs on one thread too) the CPU time is the
// time the process itself ran. Without pinning it adds up the threads of a parallel step.
//
// Adding an operation: one entry in kOps (peers.h) plus one function per backend (bench_common.h).
// The files: peers.h (the operations, their bars and the result types), peers_run.cpp (the timed
// rounds, checksums and quality of one mesh), peers_report.cpp (the text table and the JSON) and
// this one (the command line and the bars over all meshes).
#include "peers.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using bench::Backend;
using bench::Input;
using namespace bench::peers;

namespace {

std::pair<double, long> machine_load() {
  double load = std::numeric_limits<double>::quiet_NaN();
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &load) != 1) load = std::numeric_limits<double>::quiet_NaN();
    std::fclose(f);
  }
  return {load, sysconf(_SC_NPROCESSORS_ONLN)};
}

void usage() {
  std::cerr
      << "usage: peers [--json] [--quick] [--reps N] [--strict] [--cpu-time] [--only SEL] [--root DIR]\n"
         "             [mesh[:subN] ...]\n"
         "  --json    print the figures as one JSON object on stdout\n"
         "  --quick   3 rounds per operation (a smoke run)\n"
         "  --reps N  N rounds per operation\n"
         "  --strict  exit with 1 when a bar fails\n"
         "  --cpu-time  time each sample by the process's CPU time (user + system) instead of the wall\n"
         "            clock: on a loaded machine, pinned to one core (taskset -c N), the time it ran\n"
         "  --only    run only these: comma-separated OP or LIB:OP (e.g. split or hedge:split,cgal:split);\n"
         "            LIB is hedge, openmesh, cgal or meshopt; OP is build, one_ring, vertex_normals,\n"
         "            vertex_normals_builtin, face_normals, face_normals_builtin, corner_normals,\n"
         "            corner_normals_builtin, collapse, split, flip, loop, catmull_clark,\n"
         "            catmull_clark_quads, sqrt3, sqrt3_two, smooth_uniform, smooth_cotan or decimate;\n"
         "            may be repeated\n"
         "  --decimate-ratio R  decimate to this share of the vertices (default 0.1)\n"
         "  --root    repository root (default: found from the working directory)\n"
         "  mesh      a triangle mesh file; ':subN' appends N rounds of 1-to-4 subdivision\n";
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--json")
      opt.json = true;
    else if (a == "--quick")
      opt.quick = true;
    else if (a == "--strict")
      opt.strict = true;
    else if (a == "--cpu-time")
      opt.cpu_time = true;
    else if (a == "--reps" && i + 1 < argc)
      opt.reps = std::atoi(argv[++i]);
    else if (a == "--decimate-ratio" && i + 1 < argc) {
      bench::decimate_ratio = std::atof(argv[++i]);
      if (!(bench::decimate_ratio > 0 && bench::decimate_ratio < 1)) {
        std::cerr << "peers: --decimate-ratio must be in (0, 1), got " << argv[i] << "\n";
        return 64;
      }
    } else if (a == "--root" && i + 1 < argc)
      opt.root = argv[++i];
    else if (a == "--only" && i + 1 < argc) {
      std::string list = argv[++i];
      for (std::size_t start = 0; start <= list.size();) {
        std::size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        const std::string item = list.substr(start, end - start);
        start = end + 1;
        if (item.empty()) continue;
        const std::size_t colon = item.find(':');
        std::pair<std::string, std::string> sel =
            colon == std::string::npos
                ? std::pair<std::string, std::string>{"", item}
                : std::pair<std::string, std::string>{item.substr(0, colon), item.substr(colon + 1)};
        bool known = false;
        for (const OpSpec& spec : kOps) known = known || sel.second == spec.key;
        if (!known) {
          std::cerr << "peers: unknown --only entry '" << item << "'\n";
          usage();
          return 64;
        }
        opt.only.push_back(std::move(sel));
      }
    } else if (a == "-h" || a == "--help") {
      usage();
      return 0;
    } else if (a.rfind("--", 0) == 0) {
      usage();
      return 64;
    } else {
      opt.meshes.push_back(a);
    }
  }

  std::string note = "meshes from the command line";
  if (opt.meshes.empty()) {
    opt.meshes = bench::default_mesh_specs(bench::find_root(opt.root), note);
    std::cerr << note << "\n";
    if (opt.meshes.empty()) {
      std::cerr << "no meshes to run: skipped\n";
      if (opt.json)
        std::cout << json{{"skipped", true}, {"note", note}, {"meshes", json::array()}}.dump(2) << "\n";
      return 0;
    }
  }

  std::vector<Backend> backends;
  backends.push_back(bench::hedge_backend());
  backends.push_back(bench::openmesh_backend());
  backends.push_back(bench::cgal_backend());
  backends.push_back(bench::meshopt_backend());
  for (const auto& sel : opt.only) {
    bool known = sel.first.empty();
    for (const Backend& b : backends) known = known || sel.first == b.key;
    if (!known) {
      std::cerr << "peers: unknown library '" << sel.first << "' in --only\n";
      usage();
      return 64;
    }
  }

  const auto [load, cpus] = machine_load();
  if (!opt.json) {
    std::printf(
        "load average %.2f on %ld processors%s\n", load, cpus,
        load > static_cast<double>(cpus) ? " (busy machine: expect noisy medians; ratios are same-run)" : "");
    if (opt.cpu_time) std::printf("times are the process's CPU time (--cpu-time), not the wall clock\n");
  }

  std::vector<MeshResult> results;
  for (const std::string& spec : opt.meshes) {
    Input in;
    try {
      std::cerr << "loading " << spec << "\n";
      in = bench::load_spec(spec);
    } catch (const std::exception& e) {
      std::cerr << "  skipped: " << e.what() << "\n";
      continue;
    }
    std::cerr << "  " << in.n_vertices() << " vertices, " << in.n_faces() << " triangles: running\n";
    results.push_back(run_mesh(in, backends, opt));
    if (!opt.json) {
      print_table(results.back(), backends);
      std::fflush(stdout);
    }
  }

  // Bars over all meshes.
  bool all_pass = true, checks_ok = true;
  json bars = json::array();
  auto summarize = [&](const std::string& name, const std::string& bar, auto get_ratio, auto get_pass,
                       bool lower_is_better, const char* worst_key = nullptr,
                       const char* worst_format = nullptr) {
    int n = 0, passed = 0;
    double worst = std::numeric_limits<double>::quiet_NaN();
    for (const MeshResult& m : results) {
      std::optional<bool> p = get_pass(m);
      if (!p) continue;
      ++n;
      passed += *p;
      double v = get_ratio(m);
      if (std::isnan(worst) || (lower_is_better ? v > worst : v < worst)) worst = v;
    }
    if (n == 0) return;
    bool ok = passed == n;
    all_pass = all_pass && ok;
    if (!worst_key)
      worst_key = lower_is_better ? "worst_hedge_bytes_per_vertex" : "worst_best_peer_over_hedge";
    if (!worst_format) worst_format = lower_is_better ? "%.1f B/V" : "%.2fx";
    bars.push_back({{"name", name},
                    {"bar", bar},
                    {"pass", ok},
                    {"meshes_passed", passed},
                    {"meshes", n},
                    {worst_key, worst}});
    if (!opt.json)
      std::printf("  %-34s %-16s %s (%d of %d meshes pass; worst %s)\n", name.c_str(), bar.c_str(),
                  ok ? "PASS" : "FAIL", passed, n, fmt(worst_format, worst).c_str());
  };
  if (!opt.json) std::printf("\nBars (hedge against the faster peer, same run):\n");
  for (std::size_t k = 0; k < std::size(kOps); ++k) {
    if (kOps[k].bar == BarKind::none) continue;
    summarize(
        kOps[k].label, bar_text(kOps[k]), [k](const MeshResult& m) { return m.ops[k].ratio; },
        [k](const MeshResult& m) { return m.ops[k].pass; }, false);
    if (kOps[k].own_reference)
      summarize(
          std::string(kOps[k].key) + ": its loop / call", ">= 1x",
          [k](const MeshResult& m) { return m.ops[k].own_ratio; },
          [k](const MeshResult& m) { return m.ops[k].own_pass; }, false, "worst_hedge_loop_over_call");
    if (kOps[k].quality_factor > 0)
      summarize(
          std::string(kOps[k].key) + ": Hausdorff", fmt("<= %gx best", kOps[k].quality_factor),
          [k](const MeshResult& m) { return m.ops[k].quality_ratio; },
          [k](const MeshResult& m) { return m.ops[k].quality_pass; }, true, "worst_hedge_over_best_reference",
          "%.2fx");
  }
  summarize(
      "heap bytes / vertex", "<= 100 B/V", [](const MeshResult& m) { return m.mem[0].bytes_per_vertex; },
      [](const MeshResult& m) { return m.mem_pass; }, true);
  for (const MeshResult& m : results) checks_ok = checks_ok && m.checks_ok;

  if (opt.json) {
    json j;
    j["note"] = note;
    j["method"] =
        "same process; backends run round-robin with a rotating start after one warm-up each; medians of "
        "per-run times (runs shorter than 1 ms are batched into one sample, same batch for all backends); "
        "ratio = fastest peer median / hedge median; heap bytes counted via replaced operator new/delete "
        "(malloc_usable_size) over the build of the structure";
    json bj = json::array();
    for (const Backend& b : backends) bj.push_back({{"key", b.key}, {"label", b.label}, {"notes", b.notes}});
    j["backends"] = bj;
    if (opt.cpu_time) j["clock"] = "process CPU time, user + system (--cpu-time)";
    j["load_average_at_start"] = std::isnan(load) ? json(nullptr) : json(load);
    j["processors"] = cpus;
    json mj = json::array();
    for (const MeshResult& m : results) mj.push_back(to_json(m, backends));
    j["meshes"] = mj;
    j["bars"] = bars;
    j["all_pass"] = all_pass;
    j["checks_ok"] = checks_ok;
    std::cout << j.dump(2) << "\n";
  } else {
    std::printf("\n");
    for (const Backend& b : backends) std::printf("  %s\n", b.notes.c_str());
    if (!checks_ok)
      std::printf("\nCHECK FAILED: a backend disagreed with hedge or failed to build (see above)\n");
  }
  if (!checks_ok) return 2;
  if (opt.strict && !all_pass) return 1;
  return 0;
}

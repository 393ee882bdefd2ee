// Same-process comparison of hedge with OpenMesh and CGAL Surface_mesh on the same meshes, and with
// meshoptimizer's simplifier for the decimation.
//
//   peers [--json] [--quick] [--reps N] [--strict] [--only SEL] [--root DIR] [mesh ...]
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
// Adding an operation: one entry in kOps below plus one function per backend (bench_common.h).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "alloc_count.h"
#include "bench_common.h"

namespace {

using bench::Backend;
using bench::Input;
using json = nlohmann::ordered_json;  // keeps keys in table order

enum class BarKind {
  none,
  faster,          //!< fastest peer / hedge >= factor
  slower_at_most,  //!< hedge / fastest peer <= factor
};

// Allowed relative difference between the numbers of collapses (flips) done by hedge and a peer.
constexpr double kEditWorkTol = 0.02;

struct OpSpec {
  const char* key;    //!< name in the backends' op tables and in the JSON
  const char* label;  //!< row title
  BarKind bar;
  double factor;
  double checksum_rel_tol;     //!< allowed relative checksum difference to hedge (summation order)
  bool compare_vertex_output;  //!< compare Scratch::vertex_normal element-wise with hedge's
  const char* checksum_meaning =
      nullptr;  //!< if set, the checksums are printed under the row with this title
  //! If > 0: the result's distance to the input is measured (OpImpl::result), and hedge's Hausdorff
  //! distance must be at most this times the best of the mesh-structure peers'.
  double quality_factor = 0;
  //! If set: the key of an earlier row timing the same work hand-written over hedge's public API;
  //! hedge's time there over its time here is printed under the row, with the bar >= 1 (the
  //! library call no slower than the loop a user could write).
  const char* own_reference = nullptr;
  //! If true: each peer's result (OpImpl::result) is compared with hedge's, vertex by nearest vertex
  //! (max_vertex_distance: the vertex orders need not agree), and the distance printed under the row.
  bool compare_result = false;
};

// The operations, in table order.
const OpSpec kOps[] = {
    {"build", "build from arrays", BarKind::faster, 3.0, 0.0, false},
    {"one_ring", "one-ring circulation", BarKind::faster, 1.0, 1e-9, false},
    {"vertex_normals", "vertex normals (area-weighted)", BarKind::faster, 1.0, 1e-5, true},
    // Each library's own call: hedge's compute_vertex_normals(area), OpenMesh's update_normals()
    // (face normals, then vertex normals from them) and CGAL's PMP::compute_vertex_normals, into a
    // property requested before the timer. The peers weight their faces differently (OpenMesh sums
    // unit face normals, CGAL weights by angles), so the checksums differ a little. Bar: 2x the
    // faster peer; and hedge's call no slower than its hand-written gather in the row above.
    {"vertex_normals_builtin", "vertex normals, each library's call", BarKind::faster, 2.0, 1e-2, false,
     nullptr, 0, "vertex_normals"},
    // Unit face normals: a loop over each library's API (the cross product of two edges, normalised),
    // then each library's call: hedge's compute_face_normals, OpenMesh's update_face_normals() and
    // CGAL's PMP::compute_face_normals, into a property made before the timer. Bar: 2x the faster
    // peer, and hedge's call no slower than its loop. Both rows (and the corner rows below) run on
    // a private copy made before the timer, so that the loop and the call see memory alike.
    {"face_normals", "face normals, hand-written", BarKind::none, 0, 1e-5, false},
    {"face_normals_builtin", "face normals, each library's call", BarKind::faster, 2.0, 1e-4, false, nullptr,
     0, "face_normals"},
    // Corner normals with a 60-degree crease (kCornerCreaseDegrees), each corner the normalised sum
    // of the unit normals of its wedge's faces: hedge's loop over its API (the reference for its
    // call), then hedge's compute_corner_normals(uniform) against OpenMesh's update_face_normals()
    // + update_halfedge_normals() (CGAL has no corner normals: n/a). The checksum is the sum of
    // |x| + |y| + |z| over the corners; OpenMesh rounds its face normals a little differently.
    {"corner_normals", "corner normals (60 deg), loop", BarKind::none, 0, 1e-5, false},
    {"corner_normals_builtin", "corner normals, each library's call", BarKind::faster, 2.0, 1e-3, false,
     nullptr, 0, "corner_normals"},
    // 10^5 seeded random attempts each (bench_common.h: kEditCount, EditRng). Collapses and flips
    // count attempts; each library's predicate refuses slightly different sets, so the number done
    // may differ by a little (kEditWorkTol) and is printed under the row.
    {"collapse", "random collapses (10^5 checked)", BarKind::faster, 2.0, kEditWorkTol, false,
     "collapses done"},
    {"split", "random edge splits (10^5)", BarKind::faster, 2.0, 0.0, false, "#V + #F after"},
    {"flip", "random flips (10^5 checked)", BarKind::faster, 2.0, kEditWorkTol, false, "flips done"},
    // One step of Loop's scheme on a private copy (algorithms/subdivide.h).
    {"loop", "Loop subdivision, one step", BarKind::faster, 3.0, 0.0, false, "#V + #F after"},
    // Catmull-Clark of the triangle meshes (OpenMesh's CatmullClarkT needs a PolyMesh: n/a).
    {"catmull_clark", "Catmull-Clark, one step", BarKind::faster, 2.0, 0.0, false, "#V + #F after"},
    // Catmull-Clark of a quad mesh: the input made all quads by one untimed step (OpenMesh's
    // CatmullClarkT on its polygon mesh type), then one timed step.
    {"catmull_clark_quads", "Catmull-Clark of quads, one step", BarKind::faster, 2.0, 0.0, false,
     "#V + #F after"},
    // One step of Kobbelt's sqrt(3) scheme: V + F, 3F in every library, open meshes too (the first
    // step of a call leaves boundary edges whole in all three). Then two steps in one call, whose
    // second splits the boundary (in hedge, OpenMesh and CGAL alike). Under each: every peer's
    // result against hedge's, the largest distance from a vertex of one to the nearest of the other.
    {"sqrt3", "sqrt(3) subdivision, one step", BarKind::faster, 2.0, 0.0, false, "#V + #F after", 0, nullptr,
     true},
    {"sqrt3_two", "sqrt(3) subdivision, two steps", BarKind::faster, 2.0, 0.0, false, "#V + #F after", 0,
     nullptr, true},
    // Ten smoothing iterations (CGAL has no explicit Laplacian smoother: n/a). Uniform: the same
    // umbrella step with damping 0.5 in both, so the results agree. Cotangent: both move along the
    // cotangent Laplacian, OpenMesh divided by the sum of the weights, hedge by the sum of their
    // magnitudes and with folding steps withheld, so the sums differ a little.
    {"smooth_uniform", "uniform smoothing, 10 iterations", BarKind::faster, 1.0, 1e-4, false,
     "sum |p| after"},
    {"smooth_cotan", "cotangent smoothing, 10 iterations", BarKind::faster, 1.0, 1e-2, false,
     "sum |p| after"},
    // QEM decimation of a private copy to a share of the vertices (--decimate-ratio, a tenth by
    // default; meshoptimizer: of the indices); the vertex counts reached may differ by a little.
    // Bars: at most 2x meshoptimizer's time, and a Hausdorff distance at most 1.0x the better of
    // OpenMesh's and CGAL's.
    {"decimate", "QEM decimation (--decimate-ratio)", BarKind::slower_at_most, 2.0, 0.1, false,
     "vertices after", 1.0},
};

constexpr double kBytesPerVertexBar = 100.0;
constexpr std::size_t kMemoryBarMinVertices = 1000;
constexpr double kVertexOutputTol = 1e-4;  // max |difference| of unit normal components
constexpr double kMinSampleMs = 1.0;       // shorter runs are batched into one sample

struct Options {
  bool json = false;
  bool quick = false;
  bool strict = false;
  int reps = 0;
  std::string root;
  std::vector<std::string> meshes;
  //! --only: "OP" or "LIB:OP" entries (backend key, operation key); empty runs everything.
  std::vector<std::pair<std::string, std::string>> only;
  bool selected(const std::string& lib, const std::string& op) const {
    if (only.empty()) return true;
    for (const auto& [l, o] : only)
      if (o == op && (l.empty() || l == lib)) return true;
    return false;
  }
  bool selected_op(const std::string& op) const {
    if (only.empty()) return true;
    for (const auto& e : only)
      if (e.second == op) return true;
    return false;
  }
};

std::string bar_text(const OpSpec& op) {
  if (op.bar == BarKind::none) return "-";
  char b[32];
  if (op.bar == BarKind::slower_at_most) {
    std::snprintf(b, sizeof b, "<= %gx slower", op.factor);
    return b;
  }
  if (op.factor == 1.0) return "no slower";
  std::snprintf(b, sizeof b, ">= %gx faster", op.factor);
  return b;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int default_reps(const Input& in, const Options& o) {
  if (o.reps > 0) return o.reps;
  if (o.quick) return 3;
  if (in.n_faces() <= 20000) return 21;
  if (in.n_faces() <= 150000) return 15;
  if (in.n_faces() <= 600000) return 11;
  return 7;
}

struct Cell {
  bool available = false;
  std::string error;
  std::vector<double> ms;
  double median_ms = std::numeric_limits<double>::quiet_NaN();
  double checksum = 0;
  bool checksum_ok = true;
  double max_output_diff = 0;
  std::optional<std::string> check_error;  //!< after the warm-up of an editing op: "" = valid
  std::optional<bench::Quality> quality;   //!< the result's distance to the input (OpSpec::quality_factor)
  std::string quality_error;
  //! OpSpec::compare_result: the largest distance between this result's vertices and hedge's.
  double vertex_distance = std::numeric_limits<double>::quiet_NaN();
};

struct OpResult {
  const OpSpec* spec;
  std::vector<Cell> cells;  // per backend
  double ratio = std::numeric_limits<double>::quiet_NaN();
  int best_peer = -1;
  std::optional<bool> pass;
  std::size_t batch = 1;  //!< runs per sample
  bool skipped = false;   //!< not selected by --only
  //! hedge's Hausdorff distance / the best mesh-structure peer's (< 1: hedge is nearer the input).
  double quality_ratio = std::numeric_limits<double>::quiet_NaN();
  int quality_peer = -1;
  std::optional<bool> quality_pass;
  //! OpSpec::own_reference: hedge's hand-written time over its call's (>= 1: the call is no slower).
  double own_ratio = std::numeric_limits<double>::quiet_NaN();
  std::optional<bool> own_pass;
};

struct MemCell {
  bool available = false;
  double bytes_per_vertex = 0, peak_per_vertex = 0, own_per_vertex = 0;
  std::int64_t allocations = 0;
};

struct MeshResult {
  std::string name;
  std::size_t n_vertices = 0, n_faces = 0;
  bool closed = false;
  int reps = 0;
  std::vector<OpResult> ops;
  std::vector<MemCell> mem;
  std::optional<bool> mem_pass;
  double mem_ratio = std::numeric_limits<double>::quiet_NaN();
  bool checks_ok = true;
};

MeshResult run_mesh(const Input& in, std::vector<Backend>& backends, const Options& opt) {
  const std::size_t nb = backends.size();
  MeshResult res;
  res.name = in.name;
  res.n_vertices = in.n_vertices();
  res.n_faces = in.n_faces();
  res.closed = in.closed;
  res.reps = default_reps(in, opt);
  bench::Scratch scratch;
  scratch.resize(in);

  // Reference meshes, built once per backend with heap counting on: the bytes-per-vertex figures.
  std::vector<std::unique_ptr<bench::MeshBox>> refs(nb);
  std::vector<std::string> build_errors(nb);
  res.mem.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    bool used = false;
    for (const OpSpec& spec : kOps) used = used || opt.selected(backends[b].key, spec.key);
    if (!used) {
      build_errors[b] = "not selected (--only)";
      continue;
    }
    try {
      bench::alloc::start();
      refs[b] = backends[b].build(in);
      bench::alloc::Stats s = bench::alloc::stop();
      MemCell& m = res.mem[b];
      m.available = true;
      const double nv = static_cast<double>(refs[b]->n_vertices());
      m.bytes_per_vertex = static_cast<double>(s.live) / nv;
      m.peak_per_vertex = static_cast<double>(s.peak) / nv;
      m.own_per_vertex = static_cast<double>(refs[b]->own_memory_bytes()) / nv;
      m.allocations = s.allocations;
      m.available = backends[b].mesh_structure;  // flat arrays: nothing to compare
      if (refs[b]->n_vertices() != in.n_vertices() || refs[b]->n_faces() != in.n_faces())
        build_errors[b] = "built " + std::to_string(refs[b]->n_vertices()) + " V / " +
                          std::to_string(refs[b]->n_faces()) + " F, expected " +
                          std::to_string(in.n_vertices()) + " / " + std::to_string(in.n_faces());
    } catch (const std::exception& e) {
      bench::alloc::stop();
      build_errors[b] = e.what();
      refs[b].reset();
      res.mem[b].available = false;
    }
    // Not a check failure: strict hedge rejects non-manifold input, and OpenMesh drops faces it
    // cannot add. That backend's cells read n/a, with the reason in the JSON.
    if (!build_errors[b].empty())
      std::cerr << "  " << backends[b].label << ": build failed: " << build_errors[b] << "\n";
  }
  if (res.mem[0].available) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t b = 1; b < nb; ++b)
      if (res.mem[b].available) best = std::min(best, res.mem[b].bytes_per_vertex);
    if (std::isfinite(best)) res.mem_ratio = best / res.mem[0].bytes_per_vertex;
    // The bar is stated for closed triangle meshes; on tiny meshes fixed overheads dominate.
    if (in.closed && in.n_vertices() >= kMemoryBarMinVertices)
      res.mem_pass = res.mem[0].bytes_per_vertex <= kBytesPerVertexBar;
  }

  std::vector<float> hedge_output;
  for (const OpSpec& spec : kOps) {
    OpResult r;
    r.spec = &spec;
    r.cells.resize(nb);
    if (!opt.selected_op(spec.key)) {
      r.skipped = true;
      for (Cell& c : r.cells) c.error = "not selected (--only)";
      res.ops.push_back(std::move(r));
      continue;
    }
    std::vector<const bench::OpImpl*> impl(nb, nullptr);
    for (std::size_t b = 0; b < nb; ++b) {
      auto it = backends[b].ops.find(spec.key);
      if (!opt.selected(backends[b].key, spec.key)) {
        r.cells[b].error = "not selected (--only)";
      } else if (it != backends[b].ops.end() && refs[b] && build_errors[b].empty()) {
        impl[b] = &it->second;
        r.cells[b].available = true;
      } else {
        r.cells[b].error =
            refs[b] ? (build_errors[b].empty() ? "not implemented" : build_errors[b]) : build_errors[b];
      }
    }
    // One sample: `batch` back-to-back runs (prepared before and cleaned up after the timer), so that
    // a sample of a small mesh is long enough to time. Returns the checksum of the last run.
    std::size_t batch = 1;
    std::vector<double> warmup_ms(nb, std::numeric_limits<double>::infinity());
    std::vector<std::optional<Input>> results(nb);  // OpSpec::compare_result
    auto sample = [&](std::size_t b, bool timed) {
      std::vector<std::unique_ptr<bench::MeshBox>> work(batch), out(batch);
      if (impl[b]->prepare)
        for (auto& w : work) w = impl[b]->prepare(*refs[b]);
      double checksum = 0;
      const std::int64_t t0 = bench::now_ns();
      for (std::size_t i = 0; i < batch; ++i) {
        bench::Context ctx{in, work[i] ? work[i].get() : refs[b].get(), scratch, nullptr};
        checksum = impl[b]->run(ctx);
        out[i] = std::move(ctx.out);
      }
      const std::int64_t t1 = bench::now_ns();
      const double ms = static_cast<double>(t1 - t0) * 1e-6 / static_cast<double>(batch);
      if (timed)
        r.cells[b].ms.push_back(ms);
      else
        warmup_ms[b] = ms;
      if (!timed && impl[b]->check && work[0])
        r.cells[b].check_error = impl[b]->check(*refs[b], *work[0], checksum);
      if (!timed && spec.compare_result && impl[b]->result && work[0]) results[b] = impl[b]->result(*work[0]);
      if (!timed && spec.quality_factor > 0 && impl[b]->result && work[0]) {
        try {
          r.cells[b].quality = bench::surface_distance(in, impl[b]->result(*work[0]));
        } catch (const std::exception& e) {
          r.cells[b].quality_error = e.what();
          std::cerr << "  " << spec.key << ": " << backends[b].label << " result not measured: " << e.what()
                    << "\n";
        }
      }
      return checksum;
    };
    // Warm-up, checksums and output comparison (hedge first: it is the reference).
    for (std::size_t b = 0; b < nb; ++b) {
      if (!impl[b]) continue;
      try {
        r.cells[b].checksum = sample(b, false);
      } catch (const std::exception& e) {
        r.cells[b].available = false;
        r.cells[b].error = e.what();
        impl[b] = nullptr;
        res.checks_ok = false;
        continue;
      }
      if (r.cells[b].check_error && !r.cells[b].check_error->empty()) {
        res.checks_ok = false;
        std::cerr << "  WARNING " << spec.key << ": " << backends[b].label
                  << " mesh not valid after the sequence: " << *r.cells[b].check_error << "\n";
      }
      if (spec.compare_vertex_output) {
        if (b == 0) {
          hedge_output = scratch.vertex_normal;
        } else if (impl[0]) {
          double d = 0;
          for (std::size_t i = 0; i < hedge_output.size(); ++i)
            d = std::max(d, static_cast<double>(std::fabs(hedge_output[i] - scratch.vertex_normal[i])));
          r.cells[b].max_output_diff = d;
          if (d > kVertexOutputTol) r.cells[b].checksum_ok = false;
        }
      }
      if (b > 0 && impl[0]) {
        const double a = r.cells[0].checksum, c = r.cells[b].checksum;
        const double scale = std::max({std::fabs(a), std::fabs(c), 1e-30});
        if (std::fabs(a - c) > spec.checksum_rel_tol * scale) r.cells[b].checksum_ok = false;
      }
      if (!r.cells[b].checksum_ok) {
        res.checks_ok = false;
        std::cerr << "  " << spec.key << ": " << backends[b].label << " disagrees with hedge (checksum "
                  << r.cells[b].checksum << " vs " << r.cells[0].checksum << ", max output diff "
                  << r.cells[b].max_output_diff << ")\n";
      }
    }
    for (std::size_t b = 1; b < nb; ++b)
      if (results[0] && results[b])
        r.cells[b].vertex_distance = bench::max_vertex_distance(*results[0], *results[b]);
    results.clear();
    // Samples of at least kMinSampleMs for the fastest backend (same batch size for all).
    const double fastest = *std::min_element(warmup_ms.begin(), warmup_ms.end());
    if (fastest < kMinSampleMs)
      batch = static_cast<std::size_t>(std::min(10000.0, std::ceil(kMinSampleMs / std::max(fastest, 1e-6))));
    r.batch = batch;
    // Timed rounds, round-robin with a rotating start.
    for (int rep = 0; rep < res.reps; ++rep)
      for (std::size_t k = 0; k < nb; ++k) {
        const std::size_t b = (rep + k) % nb;
        if (impl[b]) sample(b, true);
      }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < nb; ++b) {
      r.cells[b].median_ms = median(r.cells[b].ms);
      if (b > 0 && impl[b] && r.cells[b].median_ms < best) {
        best = r.cells[b].median_ms;
        r.best_peer = static_cast<int>(b);
      }
    }
    if (impl[0] && r.best_peer > 0) {
      r.ratio = best / r.cells[0].median_ms;
      if (spec.bar == BarKind::faster) r.pass = r.ratio >= spec.factor;
      if (spec.bar == BarKind::slower_at_most) r.pass = r.ratio >= 1.0 / spec.factor;
    }
    if (spec.own_reference)
      for (const OpResult& ref : res.ops)
        if (std::string(ref.spec->key) == spec.own_reference && !ref.skipped && ref.cells[0].available &&
            r.cells[0].available) {
          r.own_ratio = ref.cells[0].median_ms / r.cells[0].median_ms;
          r.own_pass = r.own_ratio >= 1.0;
        }
    if (spec.quality_factor > 0 && r.cells[0].quality) {
      for (std::size_t b = 1; b < nb; ++b)
        if (backends[b].mesh_structure && r.cells[b].quality &&
            (r.quality_peer < 0 ||
             r.cells[b].quality->hausdorff < r.cells[r.quality_peer].quality->hausdorff))
          r.quality_peer = static_cast<int>(b);
      if (r.quality_peer > 0) {
        r.quality_ratio = r.cells[0].quality->hausdorff / r.cells[r.quality_peer].quality->hausdorff;
        r.quality_pass = r.quality_ratio <= spec.quality_factor;
      }
    }
    res.ops.push_back(std::move(r));
  }
  return res;
}

std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string fmt_time(double ms) {
  if (std::isnan(ms)) return "n/a";
  if (ms >= 1000) return fmt("%.2f s", ms * 1e-3);
  if (ms >= 1) return fmt("%.2f ms", ms);
  if (ms >= 1e-3) return fmt("%.2f us", ms * 1e3);
  return fmt("%.0f ns", ms * 1e6);
}

std::string pass_text(const std::optional<bool>& p) { return p ? (*p ? "PASS" : "FAIL") : "-"; }

void print_table(const MeshResult& m, const std::vector<Backend>& backends) {
  std::printf("\n%s: %zu vertices, %zu triangles, %s, %d rounds (medians)\n", m.name.c_str(), m.n_vertices,
              m.n_faces, m.closed ? "closed" : "not closed", m.reps);
  std::printf("  %-32s", "operation");
  for (const Backend& b : backends) std::printf(" %10s", b.label.c_str());
  std::printf(" %16s  %-14s %s\n", "best peer/hedge", "bar", "result");
  for (const OpResult& r : m.ops) {
    if (r.skipped) continue;
    std::printf("  %-32s", r.spec->label);
    for (const auto& c : r.cells) std::printf(" %10s", c.available ? fmt_time(c.median_ms).c_str() : "n/a");
    std::string ratio = fmt("%.2fx", r.ratio);
    if (r.best_peer > 0) ratio += " (" + backends[r.best_peer].label.substr(0, 2) + ")";
    std::printf(" %16s  %-14s %s", ratio.c_str(), bar_text(*r.spec).c_str(), pass_text(r.pass).c_str());
    for (std::size_t b = 1; b < r.cells.size(); ++b)
      if (r.cells[b].available && !r.cells[b].checksum_ok)
        std::printf("  [%s checksum mismatch]", backends[b].label.c_str());
    for (std::size_t b = 0; b < r.cells.size(); ++b)
      if (r.cells[b].check_error && !r.cells[b].check_error->empty())
        std::printf("  [WARNING: %s mesh invalid after the sequence]", backends[b].label.c_str());
    std::printf("\n");
    if (r.spec->checksum_meaning) {
      std::printf("  %-32s", (std::string("  ") + r.spec->checksum_meaning).c_str());
      for (const auto& c : r.cells)
        std::printf(" %10s", c.available ? fmt("%.0f", c.checksum).c_str() : "n/a");
      bool checked = false, valid = true;
      for (const auto& c : r.cells)
        if (c.check_error) checked = true, valid = valid && c.check_error->empty();
      if (checked)
        std::printf("   %s",
                    valid ? "(all meshes valid after the sequence)" : "(INVALID mesh, see warnings)");
      std::printf("\n");
    }
    if (r.spec->compare_result) {
      std::printf("  %-32s", "  max vertex distance to hedge");
      for (std::size_t b = 0; b < r.cells.size(); ++b)
        std::printf(" %10s", b == 0 ? "-" : fmt("%.2g", r.cells[b].vertex_distance).c_str());
      std::printf("\n");
    }
    if (r.spec->own_reference && !std::isnan(r.own_ratio)) {
      std::printf("  %-32s %10s", "  hedge: its loop / its call", fmt("%.2fx", r.own_ratio).c_str());
      for (std::size_t b = 1; b < r.cells.size(); ++b) std::printf(" %10s", "");
      std::printf(" %16s  %-14s %s\n", "", ">= 1x its loop", pass_text(r.own_pass).c_str());
    }
    if (r.spec->quality_factor > 0) {
      auto quality_row = [&](const char* title, auto text) {
        std::printf("  %-32s", title);
        for (const auto& c : r.cells) std::printf(" %10s", c.quality ? text(*c.quality).c_str() : "n/a");
      };
      quality_row("  Hausdorff distance to input",
                  [](const bench::Quality& q) { return fmt("%.4g", q.hausdorff); });
      std::string ratio = fmt("%.2fx", r.quality_ratio);
      if (r.quality_peer > 0) ratio += " (" + backends[r.quality_peer].label.substr(0, 2) + ")";
      char bar[32];
      std::snprintf(bar, sizeof bar, "<= %gx best", r.spec->quality_factor);
      std::printf(" %16s  %-14s %s\n", ratio.c_str(), bar, pass_text(r.quality_pass).c_str());
      quality_row("  mean distance to input", [](const bench::Quality& q) { return fmt("%.4g", q.mean); });
      std::printf("\n");
      quality_row("  faces after", [](const bench::Quality& q) { return std::to_string(q.faces); });
      std::printf("\n");
    }
  }
  std::printf("  %-32s", "heap bytes / vertex");
  for (const auto& c : m.mem)
    std::printf(" %10s", c.available ? fmt("%.1f", c.bytes_per_vertex).c_str() : "n/a");
  std::printf(" %16s  %-14s %s\n", fmt("%.2fx", m.mem_ratio).c_str(), "<= 100 B/V",
              pass_text(m.mem_pass).c_str());
  std::printf("  %-32s", "  peak during build / vertex");
  for (const auto& c : m.mem)
    std::printf(" %10s", c.available ? fmt("%.1f", c.peak_per_vertex).c_str() : "n/a");
  std::printf("\n");
  if (m.mem[0].available)
    std::printf("  %-32s %10s   (cross-check of the heap count)\n", "  hedge memory_bytes() / vertex",
                fmt("%.1f", m.mem[0].own_per_vertex).c_str());
}

json cell_map(const std::vector<Backend>& backends, const std::vector<double>& values,
              const std::vector<bool>& ok) {
  json j = json::object();
  for (std::size_t b = 0; b < backends.size(); ++b)
    j[backends[b].key] = ok[b] ? json(values[b]) : json(nullptr);
  return j;
}

json to_json(const MeshResult& m, const std::vector<Backend>& backends) {
  const std::size_t nb = backends.size();
  json j;
  j["name"] = m.name;
  j["vertices"] = m.n_vertices;
  j["faces"] = m.n_faces;
  j["closed"] = m.closed;
  j["rounds"] = m.reps;
  j["checks_ok"] = m.checks_ok;
  json ops = json::object();
  for (const OpResult& r : m.ops) {
    if (r.skipped) continue;
    json o;
    o["label"] = r.spec->label;
    std::vector<double> med(nb), chk(nb);
    std::vector<bool> ok(nb);
    json samples = json::object(), agree = json::object();
    for (std::size_t b = 0; b < nb; ++b) {
      med[b] = r.cells[b].median_ms;
      chk[b] = r.cells[b].checksum;
      ok[b] = r.cells[b].available;
      samples[backends[b].key] = r.cells[b].ms;
      agree[backends[b].key] = r.cells[b].available ? json(r.cells[b].checksum_ok) : json(nullptr);
      if (!r.cells[b].available) o["errors"][backends[b].key] = r.cells[b].error;
    }
    o["median_ms"] = cell_map(backends, med, ok);
    o["samples_ms"] = samples;
    o["runs_per_sample"] = r.batch;
    o["checksum"] = cell_map(backends, chk, ok);
    o["checksum_agrees_with_hedge"] = agree;
    if (r.spec->checksum_meaning) {
      o["checksum_meaning"] = r.spec->checksum_meaning;
      o["checksum_rel_tol"] = r.spec->checksum_rel_tol;
      if (r.spec->quality_factor == 0) {
        o["attempts"] = bench::kEditCount;
        o["seed"] = bench::kEditSeed;
      }
      json valid = json::object();
      for (std::size_t b = 0; b < nb; ++b) {
        const auto& ce = r.cells[b].check_error;
        valid[backends[b].key] = ce ? json(ce->empty()) : json(nullptr);
        if (ce && !ce->empty()) o["check_errors"][backends[b].key] = *ce;
      }
      o["valid_after_sequence"] = valid;
    }
    json per_peer = json::object();
    for (std::size_t b = 1; b < nb; ++b)
      per_peer[backends[b].key] = (ok[b] && ok[0]) ? json(med[b] / med[0]) : json(nullptr);
    o["peer_over_hedge"] = per_peer;
    o["best_peer"] = r.best_peer > 0 ? json(backends[r.best_peer].key) : json(nullptr);
    o["best_peer_over_hedge"] = std::isnan(r.ratio) ? json(nullptr) : json(r.ratio);
    o["bar"] = bar_text(*r.spec);
    o["bar_factor"] = r.spec->factor;
    o["pass"] = r.pass ? json(*r.pass) : json(nullptr);
    if (r.spec->own_reference) {
      o["hedge_loop"] = r.spec->own_reference;
      o["hedge_loop_over_call"] = std::isnan(r.own_ratio) ? json(nullptr) : json(r.own_ratio);
      o["hedge_call_no_slower_than_loop"] = r.own_pass ? json(*r.own_pass) : json(nullptr);
    }
    if (r.spec->compare_result) {
      json d = json::object();
      for (std::size_t b = 1; b < nb; ++b)
        d[backends[b].key] =
            std::isnan(r.cells[b].vertex_distance) ? json(nullptr) : json(r.cells[b].vertex_distance);
      o["max_vertex_distance_to_hedge"] = d;
    }
    if (r.spec->quality_factor > 0) {
      json q = json::object(), hausdorff = json::object(), mean = json::object(), counts = json::object();
      for (std::size_t b = 0; b < nb; ++b) {
        const auto& c = r.cells[b].quality;
        hausdorff[backends[b].key] = c ? json(c->hausdorff) : json(nullptr);
        mean[backends[b].key] = c ? json(c->mean) : json(nullptr);
        counts[backends[b].key] = c ? json{{"vertices", c->vertices}, {"faces", c->faces}} : json(nullptr);
        if (!r.cells[b].quality_error.empty()) q["errors"][backends[b].key] = r.cells[b].quality_error;
      }
      q["hausdorff"] = hausdorff;
      q["mean_distance"] = mean;
      q["after"] = counts;
      q["best_reference"] = r.quality_peer > 0 ? json(backends[r.quality_peer].key) : json(nullptr);
      q["hedge_over_best_reference"] = std::isnan(r.quality_ratio) ? json(nullptr) : json(r.quality_ratio);
      q["bar"] = "hedge's Hausdorff distance <= factor x the best mesh-structure peer's";
      q["bar_factor"] = r.spec->quality_factor;
      q["pass"] = r.quality_pass ? json(*r.quality_pass) : json(nullptr);
      q["method"] =
          "sampled symmetric Hausdorff distance to the input: vertices plus max(10^5, #F of the input) "
          "area-proportional seeded samples on each surface, exact closest points (hedge distance.h)";
      o["quality"] = q;
    }
    ops[r.spec->key] = o;
  }
  j["ops"] = ops;
  json mem;
  std::vector<double> bpv(nb), peak(nb), allocs(nb);
  std::vector<bool> ok(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    bpv[b] = m.mem[b].bytes_per_vertex;
    peak[b] = m.mem[b].peak_per_vertex;
    allocs[b] = static_cast<double>(m.mem[b].allocations);
    ok[b] = m.mem[b].available;
  }
  mem["heap"] = cell_map(backends, bpv, ok);
  mem["peak_during_build"] = cell_map(backends, peak, ok);
  mem["allocations_during_build"] = cell_map(backends, allocs, ok);
  mem["hedge_memory_bytes_per_vertex"] = m.mem[0].available ? json(m.mem[0].own_per_vertex) : json(nullptr);
  mem["best_peer_over_hedge"] = std::isnan(m.mem_ratio) ? json(nullptr) : json(m.mem_ratio);
  mem["bar"] = "<= 100 B/V (closed meshes of 1000+ vertices)";
  mem["pass"] = m.mem_pass ? json(*m.mem_pass) : json(nullptr);
  j["bytes_per_vertex"] = mem;
  return j;
}

//! The 1-minute load average and the number of online processors: the machine's noise, for context.
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
      << "usage: peers [--json] [--quick] [--reps N] [--strict] [--only SEL] [--root DIR] [mesh[:subN] ...]\n"
         "  --json    print the figures as one JSON object on stdout\n"
         "  --quick   3 rounds per operation (a smoke run)\n"
         "  --reps N  N rounds per operation\n"
         "  --strict  exit with 1 when a bar fails\n"
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
  if (!opt.json)
    std::printf(
        "load average %.2f on %ld processors%s\n", load, cpus,
        load > static_cast<double>(cpus) ? " (busy machine: expect noisy medians; ratios are same-run)" : "");

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

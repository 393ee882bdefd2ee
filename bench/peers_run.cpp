// The timed rounds of one mesh: every selected operation on every backend, round-robin after a
// warm-up, with the checksums, the checks of the edited meshes and the quality of the results
// (see peers.cpp for the method).
#include <time.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "alloc_count.h"
#include "peers.h"

namespace bench::peers {

namespace {

// Now, by the wall clock, or (cpu) by the CPU time the process has used, user and system: under
// load the wall clock also counts the time other processes ran, which no library can help.
std::int64_t clock_ns(bool cpu) {
  if (!cpu) return bench::now_ns();
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
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

}  // namespace

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
      const std::int64_t t0 = clock_ns(opt.cpu_time);
      for (std::size_t i = 0; i < batch; ++i) {
        bench::Context ctx{in, work[i] ? work[i].get() : refs[b].get(), scratch, nullptr};
        checksum = impl[b]->run(ctx);
        out[i] = std::move(ctx.out);
      }
      const std::int64_t t1 = clock_ns(opt.cpu_time);
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

}  // namespace bench::peers

// The output of the peer comparison: the text table of a mesh and its JSON.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "peers.h"

namespace bench::peers {

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

std::string fmt(const char* f, double v) {
  if (std::isnan(v)) return "n/a";
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

namespace {

std::string fmt_time(double ms) {
  if (std::isnan(ms)) return "n/a";
  if (ms >= 1000) return fmt("%.2f s", ms * 1e-3);
  if (ms >= 1) return fmt("%.2f ms", ms);
  if (ms >= 1e-3) return fmt("%.2f us", ms * 1e3);
  return fmt("%.0f ns", ms * 1e6);
}

json cell_map(const std::vector<Backend>& backends, const std::vector<double>& values,
              const std::vector<bool>& ok) {
  json j = json::object();
  for (std::size_t b = 0; b < backends.size(); ++b)
    j[backends[b].key] = ok[b] ? json(values[b]) : json(nullptr);
  return j;
}

}  // namespace

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

}  // namespace bench::peers

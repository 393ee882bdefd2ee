#include "report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace hedge::structures {
namespace {

// ---- Number formatting ----

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

//! Three significant digits: 3.42, 34.2, 342.
std::string sig3(double v) {
  if (!std::isfinite(v)) return "–";
  const double a = std::abs(v);
  return fmt(a >= 100 ? "%.0f" : a >= 10 ? "%.1f" : "%.2f", v);
}

//! Two decimals, without the "-0.00" of a slope that rounds to zero.
std::string slope_text(double slope) { return fmt("%.2f", std::abs(slope) < 0.005 ? 0.0 : slope); }

std::string format_time(double ns) {
  if (!std::isfinite(ns)) return "–";
  if (ns >= 1e6) return sig3(ns / 1e6) + " ms";
  if (ns >= 1e3) return sig3(ns / 1e3) + " µs";
  return sig3(ns) + " ns";
}

std::string format_count(std::size_t n) {
  std::string s = std::to_string(n);
  for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<std::size_t>(i), "\u202f");
  return s;
}

constexpr double kFlatBelow = 0.5, kLinearFrom = 0.75, kLinearTo = 1.3;

bool bounded(Growth g) { return g == Growth::constant || g == Growth::valence; }

//! Whether a fit agrees with the expected growth.
bool agrees(const GrowthFit& fit, Growth expected) {
  if (!fit.clear) return false;
  return bounded(expected) ? fit.measured == Growth::constant : fit.measured == expected;
}

std::string fit_label(const GrowthFit& fit) {
  if (!std::isfinite(fit.slope)) return "–";
  const std::string s = slope_text(fit.slope);
  if (!fit.clear) return "slope " + s + ", unclear";
  return "slope " + s + (fit.measured == Growth::linear ? ", linear" : ", flat");
}

const MeshResult* find_mesh(const std::vector<MeshResult>& meshes, const std::string& label) {
  for (const MeshResult& m : meshes)
    if (m.label == label) return &m;
  return nullptr;
}

}  // namespace

GrowthFit fit_growth(const std::vector<MeshResult>& series, std::size_t structure, std::size_t query) {
  std::vector<std::pair<double, double>> points;  // (log n_t, log time)
  for (const MeshResult& m : series) {
    const StructureResult& r = m.structures[structure];
    const double t = query < kQueryCount ? r.queries[query].ns : r.build_ns / static_cast<double>(m.n_faces);
    if (!r.ok || !std::isfinite(t) || t <= 0) continue;
    points.emplace_back(std::log(static_cast<double>(m.n_faces)), std::log(t));
  }
  GrowthFit fit;
  if (points.size() < 3) return fit;
  // Theil-Sen: the median of the slopes between every two sizes. One size disturbed by the noisy
  // machine moves a least-squares fit; it moves only a minority of these pairs.
  std::vector<double> slopes;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (points[j].first != points[i].first)
        slopes.push_back((points[j].second - points[i].second) / (points[j].first - points[i].first));
  if (slopes.empty()) return fit;
  std::sort(slopes.begin(), slopes.end());
  const std::size_t n = slopes.size();
  fit.slope = n % 2 ? slopes[n / 2] : 0.5 * (slopes[n / 2 - 1] + slopes[n / 2]);
  // The series spans three decades. A bounded query still drifts up once as its arrays outgrow the
  // caches (a few-fold over three decades: slope well below 0.5); an exhaustive search grows as n_t.
  if (fit.slope < kFlatBelow) {
    fit.measured = Growth::constant;
    fit.clear = true;
  } else if (fit.slope > kLinearFrom && fit.slope < kLinearTo) {
    fit.measured = Growth::linear;
    fit.clear = true;
  }
  return fit;
}

std::string replace_generated(const std::string& document, const std::string& generated) {
  const std::size_t begin = document.find(kBeginMarker);
  const std::size_t end = document.find(kEndMarker);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
    throw std::runtime_error(std::string("the document has no ") + kBeginMarker + " ... " + kEndMarker +
                             " section");
  const std::size_t after_begin = begin + std::string_view(kBeginMarker).size();
  return document.substr(0, after_begin) + "\n" + generated + document.substr(end);
}

std::string render_markdown(const RunInfo& info, const std::vector<MeshResult>& meshes,
                            const std::vector<MeshResult>& series) {
  std::ostringstream o;
  o << "<!-- Do not edit by hand: bench/structures/run rewrites everything between these markers. -->\n\n";
  o << "_Measured on " << info.cpu << ", " << info.compiler
    << ", Release. Every time is thread CPU time, the median of " << info.repeats << " samples of at least "
    << fmt("%g", info.min_sample_ms)
    << " ms each; exhaustive searches are timed on a seeded random sample of queries._\n\n";

  std::array<std::array<GrowthFit, kQueryCount + 1>, kStructureCount> fits{};
  for (std::size_t s = 0; s < kStructureCount; ++s)
    for (std::size_t q = 0; q <= kQueryCount; ++q) fits[s][q] = fit_growth(series, s, q);

  // ---- Table 1 ----
  const MeshResult* ref = find_mesh(meshes, info.reference);
  if (ref != nullptr) {
    o << "### Table 1, measured\n\n";
    o << "Mesh `" << ref->label << "`: " << format_count(ref->n_vertices) << " vertices, "
      << format_count(ref->n_faces)
      << " triangles (n_t/n_v = " << fmt("%.3f", double(ref->n_faces) / ref->n_vertices) << "), "
      << format_count(ref->boundary_edges) << " boundary edges. "
      << "Each measured query cell: median time per query on this mesh, then ✓ if its growth over the "
         "subdivision series (below) has the class the paper claims, ✗ if not; † marks a query the paper "
         "calls N/A, answered here with an implicit edge (see the text).\n\n";
    o << "| | Indexed: paper | Indexed: measured | TNS: paper | TNS: measured | WEM: paper | WEM: measured | "
         "HEM: paper | hedge: measured |\n";
    o << "|---|---|---|---|---|---|---|---|---|\n";
    o << "| Memory (bytes per vertex) |";
    for (std::size_t s = 0; s < kStructureCount; ++s) {
      const StructureResult& r = ref->structures[s];
      o << " " << fmt("%g", kPaperBytesPerVertex[s]) << " | "
        << (r.ok ? fmt("%.1f", double(r.bytes) / ref->n_vertices) : "–") << " |";
    }
    o << "\n| Build from index arrays |";
    for (std::size_t s = 0; s < kStructureCount; ++s) {
      const StructureResult& r = ref->structures[s];
      o << " – | " << (r.ok ? format_time(r.build_ns) : "–") << " |";
    }
    o << "\n";
    for (std::size_t q = 0; q < kQueryCount; ++q) {
      o << "| " << query_name(kQueries[q]) << " |";
      for (std::size_t s = 0; s < kStructureCount; ++s) {
        const StructureResult& r = ref->structures[s];
        const Growth paper = kPaperGrowth[s][q];
        std::string cell = "–";
        if (r.ok) {
          cell = format_time(r.queries[q].ns);
          cell += agrees(fits[s][q], kExpectedGrowth[s][q]) ? " ✓" : " ✗";
          if (paper == Growth::none) cell += " †";
        }
        o << " " << growth_name(paper) << " | " << cell << " |";
      }
      o << "\n";
    }
    o << "\n";
  }

  // ---- Growth ----
  if (!series.empty()) {
    o << "### Growth over the subdivision series\n\n";
    o << "`" << info.series_base << "` and its 1-to-4 midpoint subdivisions: ";
    for (std::size_t i = 0; i < series.size(); ++i) o << (i ? ", " : "") << format_count(series[i].n_faces);
    o << " triangles. Slope of log(time per query) against log(n_t) over the series (Theil–Sen: the median "
         "of the slopes between every two sizes); "
         "below "
      << kFlatBelow
      << " counts as flat (O(1) or O(n_ev): the mean valence stays 6 under subdivision, so "
         "the two cannot be told apart here), "
      << kLinearFrom << " to " << kLinearTo << " as linear (O(n_t)).\n\n";
    o << "| Query | Indexed | TNS | WEM | hedge |\n|---|---|---|---|---|\n";
    for (std::size_t q = 0; q <= kQueryCount; ++q) {
      o << "| "
        << (q < kQueryCount ? std::string(query_name(kQueries[q])) : std::string("Build (per triangle)"))
        << " |";
      for (std::size_t s = 0; s < kStructureCount; ++s) {
        if (q == kQueryCount) {  // O(n) in total is flat per triangle
          o << " expected O(n) total: " << fit_label(fits[s][q])
            << (agrees(fits[s][q], Growth::constant) ? " ✓" : " ✗") << " |";
          continue;
        }
        const Growth paper = kPaperGrowth[s][q], expected = kExpectedGrowth[s][q];
        o << " paper " << growth_name(paper);
        if (paper == Growth::none) o << ", here " << growth_name(expected);
        o << ": " << fit_label(fits[s][q]) << (agrees(fits[s][q], expected) ? " ✓" : " ✗") << " |";
      }
      o << "\n";
    }
    std::size_t agreeing = 0, with_claim = 0;
    std::string disagreements;
    for (std::size_t s = 0; s < kStructureCount; ++s)
      for (std::size_t q = 0; q < kQueryCount; ++q) {
        const bool ok = agrees(fits[s][q], kExpectedGrowth[s][q]);
        agreeing += ok;
        if (kPaperGrowth[s][q] != Growth::none) with_claim += 1;
        if (!ok)
          disagreements += std::string(disagreements.empty() ? "" : "; ") +
                           std::string(structure_short_name(static_cast<Structure>(s))) + " " +
                           std::string(query_name(kQueries[q])) + " (" + fit_label(fits[s][q]) + ")";
      }
    o << "\n**" << agreeing << " of " << kStructureCount * kQueryCount
      << " measured growth classes agree** with the paper's claim (" << with_claim
      << " cells) or, where the paper has N/A, with the implicit-edge expectation.";
    if (!disagreements.empty()) o << " Not agreeing in this run: " << disagreements << ".";
    o << "\n\n![Query time against mesh size, log-log](structures_scaling.svg)\n\n";
  }

  // ---- Memory and build on every mesh ----
  std::vector<const MeshResult*> all;
  for (const MeshResult& m : meshes) all.push_back(&m);
  for (const MeshResult& m : series) all.push_back(&m);
  o << "### Memory and build time on every mesh\n\n";
  o << "Bytes per vertex: every array each structure holds, capacity × element size, divided by n_v. "
       "Build: median time from the index arrays to the finished structure.\n\n";
  o << "| Mesh | n_v | n_t | n_t/n_v | boundary edges | Indexed B/v | TNS B/v | WEM B/v | hedge B/v | "
       "Indexed "
       "build | TNS build | WEM build | hedge build |\n";
  o << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const MeshResult* m : all) {
    o << "| " << m->label << " | " << format_count(m->n_vertices) << " | " << format_count(m->n_faces)
      << " | " << fmt("%.3f", double(m->n_faces) / m->n_vertices) << " | " << format_count(m->boundary_edges)
      << " |";
    for (const StructureResult& r : m->structures)
      o << " " << (r.ok ? fmt("%.2f", double(r.bytes) / m->n_vertices) : "–") << " |";
    for (const StructureResult& r : m->structures) o << " " << (r.ok ? format_time(r.build_ns) : "–") << " |";
    o << "\n";
  }
  o << "\n";
  for (const MeshResult* m : all)
    for (std::size_t s = 0; s < kStructureCount; ++s)
      if (!m->structures[s].ok)
        o << "- " << structure_name(static_cast<Structure>(s)) << " on `" << m->label
          << "` was not built: " << m->structures[s].error << "\n";

  // ---- Every query on every mesh ----
  o << "<details><summary>Every query on every mesh (median time per query; * = sampled)</summary>\n\n";
  o << "| Mesh | Structure |";
  for (Query q : kQueries) o << " " << query_name(q) << " |";
  o << "\n|---|---|";
  for (std::size_t q = 0; q < kQueryCount; ++q) o << "---:|";
  o << "\n";
  for (const MeshResult* m : all)
    for (std::size_t s = 0; s < kStructureCount; ++s) {
      const StructureResult& r = m->structures[s];
      o << "| " << m->label << " | " << structure_short_name(static_cast<Structure>(s)) << " |";
      for (const QueryTiming& t : r.queries)
        o << " " << (r.ok ? format_time(t.ns) + (t.sampled ? "*" : "") : "–") << " |";
      o << "\n";
    }
  o << "\n</details>\n\n";
  return o.str();
}

// ---- SVG ----

namespace {

struct Panel {
  double x, y, w, h;          // plot area in pixels
  double lx0, lx1, ly0, ly1;  // log10 ranges
  double px(double v) const { return x + (std::log10(v) - lx0) / (lx1 - lx0) * w; }
  double py(double v) const { return y + h - (std::log10(v) - ly0) / (ly1 - ly0) * h; }
};

constexpr std::array<const char*, kStructureCount> kColours = {"#d62728", "#ff7f0e", "#2ca02c", "#1f77b4"};

std::string time_tick(double decade) {
  const double ns = std::pow(10.0, decade);
  if (ns >= 1e6) return fmt("%g ms", ns / 1e6);
  if (ns >= 1e3) return fmt("%g µs", ns / 1e3);
  return fmt("%g ns", ns);
}
std::string size_tick(double decade) {
  const double n = std::pow(10.0, decade);
  if (n >= 1e6) return fmt("%gM", n / 1e6);
  if (n >= 1e3) return fmt("%gk", n / 1e3);
  return fmt("%g", n);
}

void draw_panel(std::ostringstream& o, int id, const Panel& p, const std::string& title,
                const std::string& subtitle, const std::vector<MeshResult>& series, std::size_t query,
                bool per_triangle) {
  o << "<g>\n";
  o << fmt("<text x=\"%.1f\"", p.x) << fmt(" y=\"%.1f\" class=\"title\">", p.y - 22) << title << "</text>\n";
  o << fmt("<text x=\"%.1f\"", p.x) << fmt(" y=\"%.1f\" class=\"sub\">", p.y - 8) << subtitle << "</text>\n";
  o << fmt("<rect x=\"%.1f\"", p.x) << fmt(" y=\"%.1f\"", p.y) << fmt(" width=\"%.1f\"", p.w)
    << fmt(" height=\"%.1f\" class=\"frame\"/>\n", p.h);
  for (double d = std::ceil(p.lx0); d <= p.lx1 + 1e-9; d += 1) {
    const double x = p.px(std::pow(10.0, d));
    o << fmt("<line x1=\"%.1f\"", x) << fmt(" y1=\"%.1f\"", p.y) << fmt(" x2=\"%.1f\"", x)
      << fmt(" y2=\"%.1f\" class=\"grid\"/>\n", p.y + p.h);
    o << fmt("<text x=\"%.1f\"", x)
      << fmt(" y=\"%.1f\" class=\"tick\" text-anchor=\"middle\">", p.y + p.h + 13) << size_tick(d)
      << "</text>\n";
  }
  for (double d = std::ceil(p.ly0); d <= p.ly1 + 1e-9; d += 1) {
    const double y = p.py(std::pow(10.0, d));
    o << fmt("<line x1=\"%.1f\"", p.x) << fmt(" y1=\"%.1f\"", y) << fmt(" x2=\"%.1f\"", p.x + p.w)
      << fmt(" y2=\"%.1f\" class=\"grid\"/>\n", y);
    o << fmt("<text x=\"%.1f\"", p.x - 4) << fmt(" y=\"%.1f\" class=\"tick\" text-anchor=\"end\">", y + 3.5)
      << time_tick(d) << "</text>\n";
  }
  o << "<clipPath id=\"clip" << id << "\">" << fmt("<rect x=\"%.1f\"", p.x) << fmt(" y=\"%.1f\"", p.y)
    << fmt(" width=\"%.1f\"", p.w) << fmt(" height=\"%.1f\"/>", p.h) << "</clipPath>\n";
  o << "<g clip-path=\"url(#clip" << id << ")\">\n";
  auto value = [&](const MeshResult& m, std::size_t s) {
    const StructureResult& r = m.structures[s];
    if (!r.ok) return std::nan("");
    return per_triangle ? r.build_ns / double(m.n_faces) : r.queries[query].ns;
  };
  // Guide: time proportional to n_t, through the indexed mesh's first point.
  if (!per_triangle && !series.empty() && std::isfinite(value(series.front(), 0))) {
    const double n0 = double(series.front().n_faces), t0 = value(series.front(), 0);
    const double n1 = std::pow(10.0, p.lx1);
    o << fmt("<line x1=\"%.1f\"", p.px(n0)) << fmt(" y1=\"%.1f\"", p.py(t0)) << fmt(" x2=\"%.1f\"", p.px(n1))
      << fmt(" y2=\"%.1f\" class=\"guide\"/>\n", p.py(t0 * n1 / n0));
  }
  for (std::size_t s = 0; s < kStructureCount; ++s) {
    std::string points;
    for (const MeshResult& m : series) {
      const double t = value(m, s);
      if (!std::isfinite(t) || t <= 0) continue;
      points += fmt("%.1f,", p.px(double(m.n_faces))) + fmt("%.1f ", p.py(t));
    }
    if (points.empty()) continue;
    o << "<polyline points=\"" << points << "\" fill=\"none\" stroke=\"" << kColours[s]
      << "\" stroke-width=\"1.8\"/>\n";
    for (const MeshResult& m : series) {
      const double t = value(m, s);
      if (!std::isfinite(t) || t <= 0) continue;
      o << fmt("<circle cx=\"%.1f\"", p.px(double(m.n_faces))) << fmt(" cy=\"%.1f\" r=\"2.6\"", p.py(t))
        << " fill=\"" << kColours[s] << "\"/>\n";
    }
  }
  o << "</g>\n</g>\n";
}

}  // namespace

std::string render_svg(const RunInfo& info, const std::vector<MeshResult>& series) {
  // Ranges: sizes over the series; one time range for all query panels so that they compare.
  double n_min = 1e300, n_max = 0, t_min = 1e300, t_max = 0, b_min = 1e300, b_max = 0;
  for (const MeshResult& m : series) {
    n_min = std::min(n_min, double(m.n_faces));
    n_max = std::max(n_max, double(m.n_faces));
    for (const StructureResult& r : m.structures) {
      if (!r.ok) continue;
      for (const QueryTiming& q : r.queries)
        if (std::isfinite(q.ns) && q.ns > 0) t_min = std::min(t_min, q.ns), t_max = std::max(t_max, q.ns);
      const double b = r.build_ns / double(m.n_faces);
      if (std::isfinite(b) && b > 0) b_min = std::min(b_min, b), b_max = std::max(b_max, b);
    }
  }
  if (n_max <= 0 || t_max <= 0)
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"/>\n";
  const double lx0 = std::log10(n_min) - 0.15, lx1 = std::log10(n_max) + 0.15;
  const double ly0 = std::floor(std::log10(t_min)), ly1 = std::ceil(std::log10(t_max));
  const double lb0 = std::floor(std::log10(b_min)), lb1 = std::ceil(std::log10(b_max));

  const double pw = 250, ph = 190, gap_x = 85, gap_y = 75, left = 60, top = 145;
  const double width = left + 3 * pw + 2 * gap_x + 50, height = top + 3 * ph + 2 * gap_y + 45;
  std::ostringstream o;
  o << fmt("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\"", width)
    << fmt(" height=\"%.0f\"", height) << fmt(" viewBox=\"0 0 %.0f", width)
    << fmt(" %.0f\" font-family=\"sans-serif\">\n", height);
  o << "<style>.title{font-size:13px;font-weight:bold}.sub{font-size:10px;fill:#444}"
       ".tick{font-size:9.5px;fill:#333}.frame{fill:none;stroke:#888}.grid{stroke:#e4e4e4}"
       ".guide{stroke:#999;stroke-dasharray:4 3;stroke-width:1.2}.legend{font-size:12px}</style>\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  o << fmt("<text x=\"%.0f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">", left)
    << "Time per query against mesh size (log-log), 1-to-4 subdivisions of " << info.series_base
    << "</text>\n";
  double lx = left;
  for (std::size_t s = 0; s < kStructureCount; ++s) {
    o << fmt("<line x1=\"%.0f\" y1=\"46\"", lx) << fmt(" x2=\"%.0f\" y2=\"46\" stroke=\"", lx + 22)
      << kColours[s] << "\" stroke-width=\"2.5\"/>"
      << fmt("<text x=\"%.0f\" y=\"50\" class=\"legend\">", lx + 28)
      << structure_name(static_cast<Structure>(s)) << "</text>\n";
    lx += 215;
  }
  o << fmt("<line x1=\"%.0f\" y1=\"66\"", left) << fmt(" x2=\"%.0f\" y2=\"66\" class=\"guide\"/>", left + 22)
    << fmt("<text x=\"%.0f\" y=\"70\" class=\"legend\">", left + 28)
    << "time ∝ n_t, through the indexed mesh's first point (query panels)</text>\n";
  o << fmt("<text x=\"%.0f\" y=\"94\" class=\"legend\">", left)
    << "x: triangles n_t; y: median time per query (last panel: build time per triangle)</text>\n";

  for (std::size_t i = 0; i <= kQueryCount; ++i) {
    const bool build = i == kQueryCount;
    Panel p{left + (i % 3) * (pw + gap_x),
            top + (i / 3) * (ph + gap_y),
            pw,
            ph,
            lx0,
            lx1,
            build ? lb0 : ly0,
            build ? lb1 : ly1};
    std::string subtitle = "slopes:";
    for (std::size_t s = 0; s < kStructureCount; ++s) {
      const GrowthFit f = fit_growth(series, s, i);
      subtitle += std::string(" ") + std::string(structure_short_name(static_cast<Structure>(s))) + " " +
                  (std::isfinite(f.slope) ? slope_text(f.slope) : std::string("–"));
    }
    const std::string title = build ? "Build, per triangle" : std::string(query_name(kQueries[i]));
    draw_panel(o, static_cast<int>(i), p, title, subtitle, series, i, build);
  }
  o << "</svg>\n";
  return o.str();
}

}  // namespace hedge::structures

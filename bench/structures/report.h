// Results of the structures benchmark, and their rendering: the markdown section of
// docs/structures.md and the log-log scaling plot (SVG, written by hand: no dependency).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "support/structures/queries.h"

namespace hedge::structures {

struct QueryTiming {
  double ns = std::nan("");  //!< median time per query
  std::size_t queries = 0;   //!< elements queried per pass (all, or the random sample)
  bool sampled = false;      //!< a seeded random sample rather than every element
};

struct StructureResult {
  bool ok = false;
  std::string error;               //!< why the structure could not be built, when !ok
  std::size_t bytes = 0;           //!< every array held, capacity x element size
  double build_ns = std::nan("");  //!< median build time from the index arrays
  std::array<QueryTiming, kQueryCount> queries{};
};

struct MeshResult {
  std::string label;    //!< file name, or "base ×4^k" for the subdivision series
  bool series = false;  //!< part of the subdivision series
  std::size_t n_vertices = 0, n_faces = 0, n_edges = 0, boundary_edges = 0;
  std::array<StructureResult, kStructureCount> structures{};
};

struct RunInfo {
  std::string cpu;
  std::string compiler;
  int repeats = 0;
  double min_sample_ms = 0;
  std::string series_base;  //!< label of the subdivided mesh
  std::string reference;    //!< label of the mesh of the main table
};

//! Theil-Sen slope of log(time) against log(n_t) over the series, per structure and query
//! (query == kQueryCount: build time per triangle).
struct GrowthFit {
  double slope = std::nan("");
  Growth measured = Growth::none;  //!< constant (bounded: O(1) or O(n_ev)) or linear; none if unclear
  bool clear = false;
};
GrowthFit fit_growth(const std::vector<MeshResult>& series, std::size_t structure, std::size_t query);

//! The generated markdown, placed between the markers of docs/structures.md.
std::string render_markdown(const RunInfo& info, const std::vector<MeshResult>& meshes,
                            const std::vector<MeshResult>& series);
//! A 3 x 3 grid of log-log panels: one per query, and build time per triangle.
std::string render_svg(const RunInfo& info, const std::vector<MeshResult>& series);

inline constexpr const char* kBeginMarker = "<!-- BEGIN GENERATED: bench/structures/run -->";
inline constexpr const char* kEndMarker = "<!-- END GENERATED: bench/structures/run -->";
//! Replaces the text between the markers (kept) of `document`. \throw std::runtime_error without them.
std::string replace_generated(const std::string& document, const std::string& generated);

}  // namespace hedge::structures

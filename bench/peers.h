// The peer comparison's operations, their bars and its result types, shared by peers.cpp (the
// command line and the bars over all meshes), peers_run.cpp (the timed rounds of one mesh) and
// peers_report.cpp (the text table and the JSON). See peers.cpp for the method.
#pragma once

#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench_common.h"

namespace bench::peers {

using json = nlohmann::ordered_json;  // keeps keys in table order

enum class BarKind {
  none,
  faster,          //!< fastest peer / hedge >= factor
  slower_at_most,  //!< hedge / fastest peer <= factor
};

// Allowed relative difference between the numbers of collapses (flips) done by hedge and a peer.
inline constexpr double kEditWorkTol = 0.02;

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
inline constexpr OpSpec kOps[] = {
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

inline constexpr double kBytesPerVertexBar = 100.0;
inline constexpr std::size_t kMemoryBarMinVertices = 1000;
inline constexpr double kVertexOutputTol = 1e-4;  // max |difference| of unit normal components
inline constexpr double kMinSampleMs = 1.0;       // shorter runs are batched into one sample

struct Options {
  bool json = false;
  bool quick = false;
  bool strict = false;
  //! --cpu-time: samples timed by the process's CPU time (user + system), not the wall clock.
  bool cpu_time = false;
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

//! The bar of an operation as printed: "-", ">= 2x faster", "no slower" or "<= 2x slower".
std::string bar_text(const OpSpec& op);
//! Runs every selected operation of kOps on one mesh with every backend (peers_run.cpp).
MeshResult run_mesh(const Input& in, std::vector<Backend>& backends, const Options& opt);
//! printf of one number, "n/a" for NaN.
std::string fmt(const char* f, double v);
std::string pass_text(const std::optional<bool>& p);
//! The text table of one mesh, on stdout (peers_report.cpp).
void print_table(const MeshResult& m, const std::vector<Backend>& backends);
//! One mesh's figures as JSON (peers_report.cpp).
json to_json(const MeshResult& m, const std::vector<Backend>& backends);

}  // namespace bench::peers

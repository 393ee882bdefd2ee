// Shared by the peer comparison (peers) and the Google Benchmark binary (hedge_bench).
//
// This header includes no hedge header on purpose: the OpenMesh and CGAL translation units include
// it, and they must not be recompiled when hedge's headers change.
//
// A library taking part ("backend") is a build function plus a table of named operations. Adding an
// operation to the comparison means: one entry in kOps (peers.h), and one function per backend,
// registered in that backend's `ops` map (peer_hedge.cpp, peer_openmesh.cpp, peer_cgal.cpp). A
// backend without the entry shows "n/a" for it.
#pragma once

#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bench {

//! What every structure is built from: the same in-memory arrays for all (file parsing excluded).
struct Input {
  std::string name;
  std::vector<float> xyz;          //!< 3 #V floats
  std::vector<std::uint32_t> tri;  //!< 3 #F vertex indices, counter-clockwise
  bool closed = false;             //!< every edge has exactly two faces, traversed in opposite directions
  std::size_t n_vertices() const { return xyz.size() / 3; }
  std::size_t n_faces() const { return tri.size() / 3; }
};

//! Arrays owned by the runner, sized before timing, so no operation allocates while timed.
struct Scratch {
  std::vector<float> face_normal;    //!< 3 #F
  std::vector<float> vertex_normal;  //!< 3 #V: an operation's per-vertex output, compared across backends
  std::vector<float> corner_normal;  //!< 3 per half-edge slot: 2E <= 6F, as every edge has a face
  void resize(const Input& in) {
    face_normal.assign(3 * in.n_faces(), 0.0f);
    corner_normal.assign(3 * 6 * in.n_faces(), 0.0f);
    vertex_normal.assign(3 * in.n_vertices(), 0.0f);
  }
};

//! A mesh built by one backend, type-erased.
struct MeshBox {
  virtual ~MeshBox() = default;
  virtual std::size_t n_vertices() const = 0;
  virtual std::size_t n_faces() const = 0;
  //! The library's own account of its memory, when it has one (0 otherwise).
  virtual std::size_t own_memory_bytes() const { return 0; }
};

//! What an operation sees.
struct Context {
  const Input& input;
  MeshBox* mesh;  //!< the reference mesh, or the prepared working copy
  Scratch& scratch;
  std::unique_ptr<MeshBox> out;  //!< whatever the timed part produced; destroyed after the timer stops
};

struct OpImpl {
  //! Untimed, before every repetition. May return a private working mesh (e.g. a copy for an
  //! editing operation); null means: run on the reference mesh.
  std::unique_ptr<MeshBox> (*prepare)(const MeshBox& reference) = nullptr;
  //! Timed. Returns a checksum that must agree across backends (see OpSpec in peers.h).
  double (*run)(Context& ctx) = nullptr;
  //! Untimed, after the warm-up run of an editing operation: the library's own validity checks on
  //! the edited mesh, plus its element counts against the reference mesh and `checksum` (what run
  //! returned). Returns an empty string if all is well, else what is wrong.
  std::string (*check)(const MeshBox& reference, const MeshBox& edited, double checksum) = nullptr;
  //! Untimed, after the warm-up run: the edited mesh as arrays (live elements only, compacted), whose
  //! distance to the input is the operation's quality (see OpSpec::quality_factor in peers.h).
  Input (*result)(const MeshBox& edited) = nullptr;
};

struct Backend {
  std::string label;  //!< column title
  std::string key;    //!< JSON key
  std::string notes;  //!< configuration worth stating (kernel, build path, ...)
  std::unique_ptr<MeshBox> (*build)(const Input& input) = nullptr;
  std::map<std::string, OpImpl> ops;
  //! False for a library of flat arrays (meshoptimizer): it has no structure whose memory to
  //! compare, and it is no reference for the quality bars.
  bool mesh_structure = true;
};

Backend hedge_backend();
Backend openmesh_backend();
Backend cgal_backend();
Backend meshopt_backend();

// ---- Decimation: the same target for every library. ----

//! The share of the vertices the decimation keeps (peers' --decimate-ratio; a tenth by default).
inline double decimate_ratio = 0.1;

//! QEM decimation to decimate_ratio of the vertices: the vertex count hedge, OpenMesh and CGAL stop
//! at. (meshoptimizer, which counts indices, is asked for that share of them.)
inline std::size_t decimate_target_vertices(const Input& in) {
  return static_cast<std::size_t>(static_cast<double>(in.n_vertices()) * decimate_ratio);
}

//! The sampled surface distances of a result to the input (bench_quality.cpp, through hedge's
//! algorithms/distance.h): symmetric Hausdorff distance and mean distance, and the result's
//! counts. The result is built with hedge's repairing policy, so a non-manifold result is measured too.
struct Quality {
  double hausdorff = 0, mean = 0;
  std::size_t vertices = 0, faces = 0;
};
Quality surface_distance(const Input& input, const Input& result);
//! The largest distance from a vertex of either mesh to the nearest vertex of the other (the
//! Hausdorff distance between the vertex sets; bench_quality.cpp), so that two libraries' results
//! compare whatever order they number their vertices in.
double max_vertex_distance(const Input& a, const Input& b);

//! The crease angle of the corner normals rows (OpenMesh's update_halfedge_normals takes radians).
constexpr double kCornerCreaseDegrees = 60;

// ---- Arithmetic shared by every backend, so that each computes exactly the same thing. ----

struct F3 {
  float x, y, z;
};
inline F3 operator-(F3 a, F3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline F3& operator+=(F3& a, F3 b) {
  a.x += b.x;
  a.y += b.y;
  a.z += b.z;
  return a;
}
inline F3 cross(F3 a, F3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
//! Twice the area times the unit normal: summing these gives area-weighted vertex normals.
inline F3 area_normal(F3 p0, F3 p1, F3 p2) { return cross(p1 - p0, p2 - p0); }
inline F3 normalized(F3 a) {
  float n = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
  return n > 0.0f ? F3{a.x / n, a.y / n, a.z / n} : a;
}
inline void store(float* out, std::size_t i, F3 v) {
  out[3 * i] = v.x;
  out[3 * i + 1] = v.y;
  out[3 * i + 2] = v.z;
}
inline F3 load(const float* in, std::size_t i) { return {in[3 * i], in[3 * i + 1], in[3 * i + 2]}; }
inline double abs_sum(F3 v) { return std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z); }

//! One-ring accumulation: per vertex, the sum of its neighbours' coordinates (double); the
//! checksum is the total over all vertices. Identical across backends up to summation order.
struct RingSum {
  double x = 0, y = 0, z = 0;
  void add(float px, float py, float pz) {
    x += px;
    y += py;
    z += pz;
  }
  double total() const { return x + y + z; }
};

// ---- Random local edits (collapse, split, flip), shared so every backend draws the same numbers. ----

constexpr std::size_t kEditCount = 100000;  //!< attempts per sequence
constexpr std::uint64_t kEditSeed = 0x5eed0f1a2b3c4d5eull;
constexpr int kEditMaxRedraws = 64;  //!< draws of a deleted element before the attempt is given up

//! splitmix64: a tiny seeded generator with the same output on every platform.
struct EditRng {
  std::uint64_t state = kEditSeed;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  //! Uniform in [0, n) (multiply-shift; n > 0).
  std::size_t below(std::size_t n) {
    return static_cast<std::size_t>((static_cast<unsigned __int128>(next()) * n) >> 64);
  }
  //! An index in [0, n) for which `deleted(i)` is false, redrawing up to kEditMaxRedraws times;
  //! n (out of range) if every draw hit a deleted element. The same draws on every backend as
  //! long as the element arrays agree.
  template <class Deleted>
  std::size_t live_index(std::size_t n, Deleted&& deleted) {
    for (int k = 0; k < kEditMaxRedraws; ++k) {
      const std::size_t i = below(n);
      if (!deleted(i)) return i;
    }
    return n;
  }
};

//! kEditCount attempts of one edit, the same draws on every backend: each attempt draws a live
//! element among the `slots()` there are then (redrawing those `deleted(i)` says are gone) and calls
//! `edit(i)`, which says whether it changed the mesh. Returns the attempts that did.
template <class Slots, class Deleted, class Edit>
std::size_t edit_sequence(Slots&& slots, Deleted&& deleted, Edit&& edit) {
  EditRng rng;
  std::size_t done = 0;
  for (std::size_t k = 0; k < kEditCount; ++k) {
    const std::size_t n = slots();
    const std::size_t i = rng.live_index(n, deleted);
    if (i < n && edit(i)) ++done;
  }
  return done;
}

//! Element counts of a mesh, as its library reports them (live elements only).
struct Counts {
  std::size_t v = 0, e = 0, f = 0;
  long long euler() const {
    return static_cast<long long>(v) - static_cast<long long>(e) + static_cast<long long>(f);
  }
};
enum class EditKind { collapse, split, flip };
//! The element counts an edit sequence implies, whatever the library: every edit keeps the Euler
//! characteristic; a collapse removes one vertex, a split adds one, a flip changes no count; a
//! closed triangle mesh (3F = 2E) stays one. `checksum` is the sequence's: the edits done, except
//! for splits, which all succeed (no edge is ever deleted) and whose checksum is #V + #F. Returns an
//! empty string if `after` agrees.
inline std::string check_edit_counts(EditKind kind, const Counts& before, const Counts& after,
                                     double checksum) {
  const double successes = kind == EditKind::split ? static_cast<double>(kEditCount) : checksum;
  const long long k = std::llround(successes);
  const long long dv = kind == EditKind::collapse ? -k : kind == EditKind::split ? k : 0;
  std::string err;
  auto num = [](long long x) { return std::to_string(x); };
  if (static_cast<long long>(after.v) != static_cast<long long>(before.v) + dv)
    err += "vertices " + num(static_cast<long long>(after.v)) + ", expected " +
           num(static_cast<long long>(before.v) + dv) + "; ";
  if (after.euler() != before.euler())
    err += "V-E+F " + num(after.euler()) + ", expected " + num(before.euler()) + "; ";
  if (3 * before.f == 2 * before.e && 3 * after.f != 2 * after.e)
    err += "3F != 2E (" + num(static_cast<long long>(after.f)) + " faces, " +
           num(static_cast<long long>(after.e)) + " edges); ";
  return err;
}

// ---- Time. ----
inline std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// ---- Inputs (bench_input.cpp; these use hedge's readers). ----

//! Reads a triangle mesh file through hedge::read_indexed_file (PLY tristrips are decoded
//! there). Throws std::runtime_error for a file with non-triangle faces.
Input load_input(const std::string& path);
//! 1-to-4 midpoint subdivision on the index arrays (edge midpoints shared between the two faces).
Input subdivide(const Input& in);
//! True if every edge of `in` has exactly two faces that traverse it in opposite directions.
bool is_closed(const Input& in);
//! A mesh list entry: "file" or "file:subN" (N rounds of subdivision). Sets Input::closed.
Input load_spec(const std::string& spec);
//! The repository root: `hint` if not empty, else the first folder from the working directory
//! upward holding include/hedge, else the source folder this was configured from.
std::string find_root(const std::string& hint);
//! The default mesh list and a note on where it came from: ../shared/meshes relative to the root
//! (armadillo, igea, armadillo subdivided twice), else the repository's data/ meshes. Empty when
//! neither exists.
std::vector<std::string> default_mesh_specs(const std::string& root, std::string& note);

}  // namespace bench

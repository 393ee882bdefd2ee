// The builder behind build() and build_triangles(), shared by its source files:
//  - build.cpp: the overview of the pipeline, run() and the public entry points;
//  - build_input.cpp: input checks, welding, cleaning of faces;
//  - build_pairing.cpp: the fast pairing of clean input;
//  - build_repair.cpp: the general pairing, its strict-mode errors and its repairs;
//  - build_link.cpp: numbering edges, linking, fan checks and vertex splitting, boundary loops.
// The helpers that more than one of them uses live in build_detail; a helper that only one uses
// stays in that file, so that it keeps internal linkage.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "hedge/core/build.h"

namespace hedge {

namespace build_detail {

// Asks for transparent huge pages on a large, not yet touched block: fewer page faults while it
// is first written, fewer TLB misses in the random-access passes. Advisory only.
inline void advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  if (bytes < 4 * kHuge) return;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

constexpr std::size_t kMaxNamed = 8;       // offending elements named in one error message
constexpr Index kReversed = 0x80000000u;   // corner flag: its edge runs from larger to smaller vertex
constexpr Index kNoPartner = 0x7fffffffu;  // a corner whose edge has no twin corner: a boundary edge
constexpr Index kNumbered = 0x80000000u;   // pairing slot already holds a half-edge index

//! The items joined with "; ", and how many of `total` were left out (an error message names
//! at most kMaxNamed offending elements).
std::string list_str(const std::vector<std::string>& items, std::size_t total);

// A per-corner array that is not value-initialised: its passes write every element.
class CornerArray {
 public:
  void resize_for_overwrite(std::size_t n) {
    if (n != size_) {
      data_.reset(new Index[n]);  // default-initialised: no clearing pass
      size_ = n;
    }
    advise_huge_pages(data_.get(), n * sizeof(Index));
  }
  void assign(std::size_t n, Index value) {
    resize_for_overwrite(n);
    std::fill_n(data_.get(), n, value);
  }
  Index* data() { return data_.get(); }
  const Index* data() const { return data_.get(); }
  Index& operator[](std::size_t i) { return data_[i]; }
  Index operator[](std::size_t i) const { return data_[i]; }

 private:
  std::unique_ptr<Index[]> data_;
  std::size_t size_ = 0;
};

// The faces being built: the caller's triangle indices as they are, or cleaned copies.
struct Faces {
  std::span<const Index> corners;    // vertex of each corner
  std::vector<Index> own_corners;    // storage when corners had to be rewritten
  std::vector<Index> start;          // #F + 1 offsets; empty for triangles
  std::vector<Index> face_origin;    // face -> input face (empty: identity)
  std::vector<Index> corner_origin;  // corner -> input corner (empty: identity)
  Index n_faces = 0;

  bool triangles() const { return start.empty(); }
  Index begin(Index f) const { return triangles() ? 3 * f : start[f]; }
  Index end(Index f) const { return triangles() ? 3 * f + 3 : start[f + 1]; }
  Index n_corners() const { return static_cast<Index>(corners.size()); }
  //! The face of corner c (binary search on polygons: for error and repair paths).
  Index face_of(Index c) const {
    if (triangles()) return c / 3;
    return static_cast<Index>(std::upper_bound(start.begin(), start.end(), c) - start.begin()) - 1;
  }
  Index next_corner(Index c) const {
    Index f = face_of(c);
    return c + 1 == end(f) ? begin(f) : c + 1;
  }
  void materialise_origins() {
    if (!corner_origin.empty()) return;
    corner_origin.resize(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) corner_origin[i] = static_cast<Index>(i);
  }
};

// Calls fn(c, next corner, face) for every corner; specialised for triangles.
template <typename Fn>
void for_each_corner(const Faces& F, Fn&& fn) {
  if (F.triangles()) {
    for (Index f = 0, c = 0; f < F.n_faces; ++f, c += 3) {
      fn(c, c + 1, f);
      fn(c + 1, c + 2, f);
      fn(c + 2, c, f);
    }
  } else {
    for (Index f = 0; f < F.n_faces; ++f) {
      const Index b = F.start[f], e = F.start[f + 1];
      for (Index c = b; c + 1 < e; ++c) fn(c, c + 1, f);
      fn(e - 1, b, f);
    }
  }
}

// Corners grouped by undirected edge: bucket v holds keys[offset[v] .. offset[v+1]), each key
// (larger vertex << 32 | corner | kReversed-if-reversed), sorted; a run of equal larger vertices
// is one undirected edge.
struct EdgeGroups {
  std::vector<Index> offset;
  std::vector<std::uint64_t> keys;

  template <typename Fn>
  void for_each_run(Fn&& fn) const {
    const Index nv = static_cast<Index>(offset.size() - 1);
    for (Index v = 0; v < nv; ++v) {
      Index i = offset[v];
      const Index e = offset[v + 1];
      while (i < e) {
        Index j = i + 1;
        while (j < e && (keys[j] >> 32) == (keys[i] >> 32)) ++j;
        fn(keys.data() + i, j - i);
        i = j;
      }
    }
  }
};

inline Index entry_corner(std::uint64_t key) { return static_cast<Index>(key) & ~kReversed; }
inline bool entry_reversed(std::uint64_t key) { return (static_cast<Index>(key) & kReversed) != 0; }

}  // namespace build_detail

//! The builder's input: spans, so that build_triangles() need not copy the caller's arrays.
struct BuildInput {
  std::span<const Vec3> positions;
  std::span<const Index> indices;
  std::span<const Index> face_sizes;
  std::span<const Vec2> texcoords;
  std::span<const Index> texcoord_indices;
  std::span<const Vec3> normals;
  std::span<const Index> normal_indices;
  std::span<const Color> colors;
  std::span<const Index> color_indices;
  std::size_t face_count() const { return face_sizes.empty() ? indices.size() / 3 : face_sizes.size(); }
};

// Friend of SurfaceMesh: writes its arrays directly.
class MeshBuilder {
 public:
  //! want_maps: fill the report's vertex and face maps (not needed when the caller passed no report).
  MeshBuilder(const BuildInput& in, const BuildOptions& opt, BuildReport& rep, bool want_maps)
      : in_(in), opt_(opt), rep_(rep), want_maps_(want_maps) {}
  SurfaceMesh run();

 private:
  void check_input() const;
  void weld();
  bool clean_faces();
  bool triangles_are_clean() const;
  void clean_faces_general();
  enum class Paired { ok, degenerate, not_simple };
  Paired pair_fast(bool unchecked);
  template <bool kTriangles>
  Paired pair_fast_impl(bool unchecked);
  build_detail::EdgeGroups group_edges() const;
  bool pair_corners(const build_detail::EdgeGroups& groups, bool repair);
  void number_edges();
  void reorient(const build_detail::EdgeGroups& groups);
  void link(SurfaceMesh& m);
  bool fans_are_simple(SurfaceMesh& m);
  void split_fans(SurfaceMesh& m);
  //! The half-edge before interior half-edge h in its face: from prev_, or by walking the face.
  Halfedge prev_interior(const SurfaceMesh& m, Halfedge h) const;
  void link_boundaries(SurfaceMesh& m);
  void attach_attributes(SurfaceMesh& m) const;

  Index n_vertices() const {
    return static_cast<Index>(positions_.empty() ? in_.positions.size() : positions_.size());
  }
  //! The input vertex a welded vertex came from (its first occurrence).
  Index input_vertex(Index v) const { return weld_first_.empty() ? v : weld_first_[v]; }

  const BuildInput& in_;
  const BuildOptions& opt_;
  BuildReport& rep_;
  const bool want_maps_;

  std::vector<Vec3> positions_;    // after welding (empty: the input's are used)
  std::vector<Index> weld_map_;    // input vertex -> welded vertex (empty: identity)
  std::vector<Index> weld_first_;  // welded vertex -> first input vertex (empty: identity)
  build_detail::Faces f_;
  // Per corner: first its partner corner (or kNoPartner), then, after number_edges(), its half-edge.
  build_detail::CornerArray corner_he_;
  std::vector<Halfedge> vh_;         // vertex -> half-edge of its last corner (moved into the mesh)
  std::vector<Index> boundary_hes_;  // boundary half-edges, found by fans_are_simple()
  std::vector<Index> prev_;          // polygons: interior half-edge -> the one before it in its face
  bool fans_checked_ = false;        // link() walked the fans already ...
  bool fans_simple_ = false;         // ... and found one fan at every vertex
  Index n_edges_ = 0;
  std::vector<Index> vertex_origin_;  // added vertex (from #V on) -> welded vertex it was split from
  std::string problems_;              // strict-mode description of the defects found
  std::vector<Index> bad_vertices_;   // strict-mode offending input vertices
};

}  // namespace hedge

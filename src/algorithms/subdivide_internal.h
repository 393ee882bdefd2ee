// What the files of subdivision share (subdivide.cpp, subdivide_one_to_four.cpp,
// subdivide_catmull_clark.cpp, subdivide_face_centres.cpp): the old mesh's arrays, the numbering of
// edge halves, the parallel-for of the passes, the builders every scheme uses and one refinement
// step per scheme. See include/hedge/algorithms/subdivide.h for the numbering of new elements.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hedge/algorithms/subdivide.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/threads.h"

namespace hedge::detail::subdivision {

// The halves of old half-edge h = 2e + s, as new half-edges: first(h) runs from h's start to the
// edge's new vertex, second(h) from there to h's end (see the header for the numbering).
inline Index first_half(Index h) { return 4 * (h >> 1) + 3 * (h & 1); }
inline Index second_half(Index h) { return 4 * (h >> 1) + 2 - (h & 1); }

// Every pass writes each new element from a formula of the old ones, so a pass splits between
// threads (include/hedge/core/threads.h) without changing the result; at most 8 of them, as a pass
// streams memory and more threads only queue for it.
constexpr std::size_t kMaxThreads = 8;
template <typename Body>
inline void for_ranges(std::size_t n, Body&& body) {
  detail::parallel_ranges(n, body, std::size_t(1) << 15, kMaxThreads);
}

// The mesh being refined, read-only: the refined one is built in a mesh of its own, so that the
// input stays as it was until the result is complete.
struct Old {
  std::size_t nv = 0, ne = 0, nf = 0;
  const Vertex* to = nullptr;       // per half-edge
  const Halfedge* next = nullptr;   // per half-edge
  const Face* face = nullptr;       // per half-edge
  const Halfedge* vout = nullptr;   // per vertex
  const Halfedge* fhe = nullptr;    // per face
  std::vector<std::uint8_t> sharp;  // per edge: boundary or "e:crease"
};

// ---- builders shared by the schemes (subdivide.cpp) ----

// The arrays of m, read in place, and which of its edges are sharp.
Old read_old(const SurfaceMesh& m);

// An empty mesh of nv vertices, ne edges and nf faces (links invalid) with the properties of
// `src`, whose first `keep_vertices` vertices carry src's vertex properties (positions aside: the
// caller writes them all).
SurfaceMesh refined_like(const SurfaceMesh& src, std::size_t nv, std::size_t ne, std::size_t nf,
                         std::size_t keep_vertices);

// When there is corner data, makes room in out past its nh half-edges for a copy of the old
// half-edges' values, where no write reaches them, and copies them there. Returns the index of
// that copy's first element.
Index keep_old_corners(SurfaceMesh& out, const SurfaceMesh& src, std::size_t nh);

// The halves of every old edge (with the boundary half-edges' links), the outgoing half-edges of
// the old vertices and of the edge vertices V + e.
void write_edge_halves(SurfaceMesh& m, const Old& o);

// The properties of the edge halves: boundary halves' corners (the old corner values sit at
// old_base + h), edge properties of both halves, and the edge vertices' vertex properties (the
// average of the ends; positions are the caller's).
void write_edge_half_properties(SurfaceMesh& m, const SurfaceMesh& src, const Old& o, Index old_base);

// ---- one refinement step per scheme, into a mesh of its own ----

//! Loop's scheme or the midpoint split (subdivide_one_to_four.cpp).
SurfaceMesh refine_1_to_4(const SurfaceMesh& src, Subdivision scheme);
//! Catmull-Clark (subdivide_catmull_clark.cpp).
SurfaceMesh refine_catmull_clark(const SurfaceMesh& src);
//! Kobbelt's sqrt(3) when sqrt3, else the split of every face at its centroid
//! (subdivide_face_centres.cpp). split_boundary: an even sqrt(3) step, which splits the boundary
//! edges in three (Kobbelt's boundary rule).
SurfaceMesh refine_at_centres(const SurfaceMesh& src, bool sqrt3, bool split_boundary = false);

}  // namespace hedge::detail::subdivision

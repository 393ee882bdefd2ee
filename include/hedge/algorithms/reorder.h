// Reordering: renumbers a mesh's elements so that the order in memory serves the work to come.
//
//  - Ordering::spatial sorts vertices and faces along a Morton (Z-order) curve: elements near each
//    other in space are near each other in memory, so traversals (one-ring circulation, per-face
//    loops) read memory in order instead of jumping. A mesh whose order was lost (a shuffled file,
//    many edits) gets back the speed of a well-ordered one (bench/hedge_bench.cpp, BM_one_ring_order).
//  - Ordering::vertex_cache orders the faces for a GPU's post-transform vertex cache (a fan-growing
//    greedy order after Sander, Nehab and Barczak, "Fast triangle reordering for vertex locality and
//    reduced overdraw", 2007), then numbers the vertices as those faces first use them, so that the
//    index buffer an engine draws from re-uses recently shaded vertices and fetches vertices in
//    order. It keeps much of the spatial locality too (faces grow in fans over the surface).
//
// Both number the edges as the faces, in their new order, first meet them (a face's half-edges sit
// together), collect deleted elements at the same time, move every property with its element, and
// record a reset in the change log.
#pragma once

#include <cstddef>

#include "hedge/core/surface_mesh.h"

namespace hedge {

enum class Ordering {
  spatial,       //!< Morton curve through positions (vertices) and centroids (faces); O(n log n)
  vertex_cache,  //!< faces for a vertex cache of `cache_size` entries, vertices by first use; O(n)
};

//! Renumbers vertices, edges (and so half-edges) and faces in the given order. Any mesh: polygons,
//! boundaries, isolated vertices (which go last in the vertex_cache order) and an empty mesh.
//! `cache_size` (vertex_cache only) is the number of vertices the target cache holds: 16 to 32 on
//! current GPUs; values below 3 are taken as 3.
//! \return the old-to-new maps, as garbage_collection() returns them.
//! Spatial order (which reads positions): \throw InvalidInputError naming the first vertex whose position is
//! not finite,
//!   before anything changes (require_finite_positions()).
GarbageMaps reorder(SurfaceMesh& mesh, Ordering ordering = Ordering::spatial, std::size_t cache_size = 16);

//! The average cache miss ratio (ACMR) of drawing the faces in index order, each face as a fan of
//! triangles, through a first-in first-out vertex cache of `cache_size` entries: vertex loads per
//! triangle. 3 is the worst; about 0.5 is the best a large closed triangle mesh allows. Measures
//! what Ordering::vertex_cache improves. O(total face degree). An empty mesh gives 0.
double average_cache_miss_ratio(const SurfaceMesh& mesh, std::size_t cache_size = 16);

}  // namespace hedge

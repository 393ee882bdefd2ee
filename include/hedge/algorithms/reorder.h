// Reordering: renumbers a mesh's elements so that elements near each other in space are near each
// other in memory. Traversals (one-ring circulation, per-face loops) then read memory in order
// instead of jumping: a mesh whose order was lost (a shuffled file, many edits) gets back the speed
// of a well-ordered one. See bench/hedge_bench.cpp (BM_OneRing/*) for the measured effect.
#pragma once

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Sorts the vertices along a Morton (Z-order) curve of their positions (quantised to 2^21 cells a
//! side of the bounding box), the faces along the same curve through their centroids, and numbers
//! the edges as the faces, taken in their new order, first meet them (so a face's half-edges sit
//! together). Deleted elements are collected at the same time. Properties move with their
//! elements; the change log records a reset. O(n log n).
//! \return the old-to-new maps, as garbage_collection() returns them.
GarbageMaps reorder_spatially(SurfaceMesh& mesh);

}  // namespace hedge

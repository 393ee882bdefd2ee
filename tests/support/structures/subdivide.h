// 1-to-4 midpoint subdivision on index arrays: the size series of the growth measurement.
#pragma once

#include <vector>

#include "hedge/core/handles.h"
#include "hedge/core/vec.h"

namespace hedge::structures {

//! A triangle mesh as index arrays: #V positions, 3 #F vertex indices.
struct TriangleArrays {
  std::vector<Vec3> positions;
  std::vector<Index> triangles;

  std::size_t n_vertices() const { return positions.size(); }
  std::size_t n_faces() const { return triangles.size() / 3; }
};

//! Splits every triangle into four at its edge midpoints. Vertex i keeps index i; the midpoint of
//! edge e becomes vertex #V + e (edge ids of match_edges). Triangle t becomes triangles 4t .. 4t+3
//! (three corners, then the middle one), orientation kept. #V' = #V + #E, #F' = 4 #F. O(n).
//! \throw hedge::TopologyError as match_edges().
TriangleArrays subdivide_midpoint(const TriangleArrays& mesh);

}  // namespace hedge::structures

// Edge matching on a triangle index array, shared by the triangle-neighbour structure, the
// winged-edge mesh and the midpoint subdivision. Not part of any structure's memory: builders use
// it and throw it away.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "hedge/core/handles.h"

namespace hedge::structures {

//! Corner edge c = 3 t + k runs from corner k of triangle t to corner (k + 1) % 3.
inline constexpr Index corner_next(Index c) { return c - c % 3 + (c % 3 + 1) % 3; }
inline constexpr Index corner_prev(Index c) { return c - c % 3 + (c % 3 + 2) % 3; }

//! The undirected edges of a triangle mesh, found from its corner edges.
struct EdgeTable {
  //! Per corner edge: the id of its undirected edge, 0 .. n_edges - 1.
  std::vector<Index> edge_of;
  //! Per corner edge: the corner edge running the other way over the same edge, or kInvalidIndex
  //! on the boundary.
  std::vector<Index> opposite;
  //! Per edge: one of its corner edges (the one whose opposite, if any, is larger).
  std::vector<Index> corner_of_edge;

  std::size_t n_edges() const { return corner_of_edge.size(); }
};

//! Matches the corner edges of `triangles` (3 indices per triangle into n_vertices vertices).
//! Buckets the corner edges by their smaller vertex and sorts each (small) bucket: O(n) for
//! bounded valence, no hashing. Edge ids follow the first corner edge of each edge, that is the
//! order in which a walk over the triangles meets the edges.
//! \throw hedge::TopologyError if an index is out of range, a triangle repeats a vertex, an edge
//!        has more than two triangles, or two triangles run over an edge in the same direction
//!        (the structures here need an oriented 2-manifold, possibly with boundary).
EdgeTable match_edges(std::span<const Index> triangles, std::size_t n_vertices);

}  // namespace hedge::structures

#include "triangle_neighbors.h"

namespace hedge::structures {

TriangleNeighbors TriangleNeighbors::build(std::span<const Vec3> positions,
                                           std::span<const Index> triangles) {
  const EdgeTable table = match_edges(triangles, positions.size());
  TriangleNeighbors m;
  m.positions_.assign(positions.begin(), positions.end());
  m.vertex_triangle_.assign(positions.size(), kInvalidIndex);
  const std::size_t n_t = triangles.size() / 3;
  m.triangles_.resize(n_t);
  for (Index t = 0; t < n_t; ++t) {
    Triangle& tri = m.triangles_[t];
    for (Index k = 0; k < 3; ++k) {
      const Index v = triangles[3 * t + k];
      tri.vertices[k] = v;
      const Index o = table.opposite[3 * t + k];
      tri.neighbors[k] = o == kInvalidIndex ? kInvalidIndex : o / 3;
      if (m.vertex_triangle_[v] == kInvalidIndex) m.vertex_triangle_[v] = t;
    }
  }
  return m;
}

std::size_t TriangleNeighbors::memory_bytes() const {
  return positions_.capacity() * sizeof(Vec3) + vertex_triangle_.capacity() * sizeof(Index) +
         triangles_.capacity() * sizeof(Triangle);
}

std::vector<TriangleNeighbors::EdgeRef> TriangleNeighbors::edge_list() const {
  std::vector<EdgeRef> edges;
  edges.reserve(triangles_.size() * 3 / 2 + 3);
  for (Index t = 0; t < triangles_.size(); ++t)
    for (Index k = 0; k < 3; ++k) {
      const Index n = triangles_[t].neighbors[k];
      if (n == kInvalidIndex || t < n) edges.push_back(3 * t + k);
    }
  return edges;
}

}  // namespace hedge::structures

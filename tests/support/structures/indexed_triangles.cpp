#include "indexed_triangles.h"

#include "edge_table.h"

namespace hedge::structures {

IndexedTriangles IndexedTriangles::build(std::span<const Vec3> positions, std::span<const Index> triangles) {
  IndexedTriangles m;
  m.positions_.assign(positions.begin(), positions.end());
  m.triangles_.assign(triangles.begin(), triangles.end());
  return m;
}

std::size_t IndexedTriangles::memory_bytes() const {
  return positions_.capacity() * sizeof(Vec3) + triangles_.capacity() * sizeof(Index);
}

std::vector<VertexPair> IndexedTriangles::edge_list() const {
  const EdgeTable table = match_edges(triangles_, positions_.size());
  std::vector<VertexPair> edges;
  edges.reserve(table.n_edges());
  for (Index c : table.corner_of_edge)
    edges.push_back(VertexPair::ordered(triangles_[c], triangles_[corner_next(c)]));
  return edges;
}

}  // namespace hedge::structures

#include "winged_edge.h"

#include <numeric>

#include "edge_table.h"

namespace hedge::structures {

WingedEdge WingedEdge::build(std::span<const Vec3> positions, std::span<const Index> triangles) {
  const EdgeTable table = match_edges(triangles, positions.size());
  WingedEdge m;
  m.positions_.assign(positions.begin(), positions.end());
  m.vertex_edge_.assign(positions.size(), kInvalidIndex);
  const std::size_t n_t = triangles.size() / 3;
  m.face_edge_.resize(n_t);
  m.edges_.resize(table.n_edges());
  for (Index e = 0; e < table.n_edges(); ++e) {
    WEdge& w = m.edges_[e];
    const Index corners[2] = {table.corner_of_edge[e], table.opposite[table.corner_of_edge[e]]};
    w.vertex = {triangles[corners[0]], triangles[corner_next(corners[0])]};
    for (int s = 0; s < 2; ++s) {
      const Index c = corners[s];
      if (c == kInvalidIndex) {
        w.face[s] = w.next[s] = w.prev[s] = kInvalidIndex;
        continue;
      }
      w.face[s] = c / 3;
      w.next[s] = table.edge_of[corner_next(c)];
      w.prev[s] = table.edge_of[corner_prev(c)];
    }
    for (Index v : w.vertex)
      if (m.vertex_edge_[v] == kInvalidIndex) m.vertex_edge_[v] = e;
  }
  for (Index t = 0; t < n_t; ++t) m.face_edge_[t] = table.edge_of[3 * t];
  return m;
}

std::size_t WingedEdge::memory_bytes() const {
  return positions_.capacity() * sizeof(Vec3) + vertex_edge_.capacity() * sizeof(Index) +
         face_edge_.capacity() * sizeof(Index) + edges_.capacity() * sizeof(WEdge);
}

std::vector<WingedEdge::EdgeRef> WingedEdge::edge_list() const {
  std::vector<EdgeRef> edges(edges_.size());
  std::iota(edges.begin(), edges.end(), Index{0});
  return edges;
}

}  // namespace hedge::structures

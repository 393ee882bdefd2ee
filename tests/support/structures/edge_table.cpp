#include "edge_table.h"

#include <algorithm>
#include <string>

#include "hedge/error.h"

namespace hedge::structures {

EdgeTable match_edges(std::span<const Index> triangles, std::size_t n_vertices) {
  if (triangles.size() % 3 != 0) throw TopologyError("triangle index count is not a multiple of 3");
  const std::size_t n_corners = triangles.size();
  for (std::size_t t = 0; t < n_corners / 3; ++t) {
    const Index a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
    if (a >= n_vertices || b >= n_vertices || c >= n_vertices)
      throw TopologyError("vertex index out of range", {}, {static_cast<Index>(t)});
    if (a == b || b == c || c == a)
      throw TopologyError("triangle repeats a vertex", {}, {static_cast<Index>(t)});
  }

  // Bucket corner edges by their smaller vertex (a counting sort), keyed by (larger vertex, corner).
  std::vector<Index> start(n_vertices + 1, 0);
  for (Index c = 0; c < n_corners; ++c) ++start[std::min(triangles[c], triangles[corner_next(c)]) + 1];
  for (std::size_t v = 0; v < n_vertices; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> keys(n_corners);
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index c = 0; c < n_corners; ++c) {
      const Index a = triangles[c], b = triangles[corner_next(c)];
      keys[fill[std::min(a, b)]++] = (std::uint64_t{std::max(a, b)} << 32) | c;
    }
  }

  EdgeTable table;
  table.opposite.assign(n_corners, kInvalidIndex);
  for (std::size_t v = 0; v < n_vertices; ++v) {
    auto first = keys.begin() + start[v], last = keys.begin() + start[v + 1];
    std::sort(first, last);  // corner ids break ties, so the order is deterministic
    for (auto it = first; it != last;) {
      auto run = it + 1;
      while (run != last && (*run >> 32) == (*it >> 32)) ++run;
      const Index c0 = static_cast<Index>(*it);
      if (run - it > 2)
        throw TopologyError("edge with more than two triangles",
                            {static_cast<Index>(v), static_cast<Index>(*it >> 32)}, {c0 / 3});
      if (run - it == 2) {
        const Index c1 = static_cast<Index>(*(it + 1));
        if (triangles[c0] == triangles[c1])
          throw TopologyError(
              "two triangles run over an edge in the same direction (inconsistent orientation)",
              {static_cast<Index>(v), static_cast<Index>(*it >> 32)}, {c0 / 3, c1 / 3});
        table.opposite[c0] = c1;
        table.opposite[c1] = c0;
      }
      it = run;
    }
  }
  // Number the edges in the order a builder walking the triangles meets them: an edge's id follows
  // its first corner edge, which keeps the edges of nearby triangles near each other in memory.
  table.edge_of.assign(n_corners, kInvalidIndex);
  table.corner_of_edge.reserve(n_corners / 2 + n_vertices);
  for (Index c = 0; c < n_corners; ++c) {
    const Index o = table.opposite[c];
    if (o != kInvalidIndex && o < c) continue;
    const Index e = static_cast<Index>(table.corner_of_edge.size());
    table.corner_of_edge.push_back(c);
    table.edge_of[c] = e;
    if (o != kInvalidIndex) table.edge_of[o] = e;
  }
  table.corner_of_edge.shrink_to_fit();
  return table;
}

}  // namespace hedge::structures

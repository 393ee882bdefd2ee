#include "hedge/algorithms/components.h"

#include <algorithm>
#include <numeric>

namespace hedge {

Components face_components(const SurfaceMesh& m) {
  Components c;
  c.label.assign(m.face_slots(), kInvalidIndex);
  std::vector<Face> stack;
  for (Face seed : m.faces()) {
    if (c.label[seed.idx()] != kInvalidIndex) continue;
    const Index id = static_cast<Index>(c.count++);
    c.label[seed.idx()] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const Face f = stack.back();
      stack.pop_back();
      for (Halfedge h : m.halfedges(f)) {
        const Face g = m.face(SurfaceMesh::twin(h));
        if (g.is_valid() && c.label[g.idx()] == kInvalidIndex) {
          c.label[g.idx()] = id;
          stack.push_back(g);
        }
      }
    }
  }
  return c;
}

// Over the edges rather than around each vertex, so that a vertex whose faces form two fans (which
// an edit can make) still joins both.
Components vertex_components(const SurfaceMesh& m) {
  // Union-find with path halving; the root of a set is its lowest vertex.
  std::vector<Index> parent(m.vertex_slots());
  std::iota(parent.begin(), parent.end(), Index{0});
  auto find = [&](Index i) {
    while (parent[i] != i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  for (Edge e : m.edges()) {
    const Index a = find(m.vertex(e, 0).idx()), b = find(m.vertex(e, 1).idx());
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  Components c;
  c.label.assign(m.vertex_slots(), kInvalidIndex);
  for (Vertex v : m.vertices()) {
    if (m.is_isolated(v)) continue;
    const Index root = find(v.idx());
    // The root comes first in index order, so its label is set before any other member's.
    c.label[v.idx()] = root == v.idx() ? static_cast<Index>(c.count++) : c.label[root];
  }
  return c;
}

}  // namespace hedge

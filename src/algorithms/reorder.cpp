#include "hedge/algorithms/reorder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "hedge/algorithms/geometry.h"

namespace hedge {

namespace {

// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

struct Morton {
  Vec3d lo;
  double scale[3];
  explicit Morton(const BoundingBox& box) : lo(to_double(box.min)) {
    for (int a = 0; a < 3; ++a) {
      const double extent = double(box.max[a]) - double(box.min[a]);
      scale[a] = extent > 0 ? double((1u << 21) - 1) / extent : 0;
    }
  }
  std::uint64_t operator()(const Vec3d& p) const {
    std::uint64_t c[3];
    for (int a = 0; a < 3; ++a) {
      const double q = std::clamp((p[a] - lo[a]) * scale[a], 0.0, double((1u << 21) - 1));
      c[a] = std::isfinite(q) ? std::uint64_t(q) : 0;
    }
    return spread(c[0]) | spread(c[1]) << 1 | spread(c[2]) << 2;
  }
};

// The order of `keyed` (key, old index) pairs, as an old-to-new map of `slots` entries.
std::vector<Index> order_map(std::vector<std::pair<std::uint64_t, Index>>& keyed, std::size_t slots) {
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> map(slots, kInvalidIndex);
  for (std::size_t i = 0; i < keyed.size(); ++i) map[keyed[i].second] = Index(i);
  return map;
}

}  // namespace

GarbageMaps reorder_spatially(SurfaceMesh& m) {
  const Morton code(bounding_box(m));
  std::vector<std::pair<std::uint64_t, Index>> keyed;
  keyed.reserve(m.n_vertices());
  for (Vertex v : m.vertices()) keyed.push_back({code(to_double(m.position(v))), v.idx()});
  std::vector<Index> new_vertex = order_map(keyed, m.vertex_slots());

  keyed.clear();
  for (Face f : m.faces()) {
    Vec3d c{0, 0, 0};
    double n = 0;
    for (Vertex v : m.vertices(f)) c += to_double(m.position(v)), n += 1;
    keyed.push_back({code(c * (1 / n)), f.idx()});
  }
  std::vector<Index> new_face = order_map(keyed, m.face_slots());

  // Edges in the order the faces, in their new order, first meet them.
  std::vector<Face> faces(m.n_faces());
  for (Face f : m.faces()) faces[new_face[f.idx()]] = f;
  std::vector<Index> new_edge(m.edge_slots(), kInvalidIndex);
  Index next = 0;
  for (Face f : faces)
    for (Halfedge h : m.halfedges(f)) {
      Index& slot = new_edge[SurfaceMesh::edge(h).idx()];
      if (slot == kInvalidIndex) slot = next++;
    }
  for (Edge e : m.edges())  // edges of no face (none in a valid mesh), last
    if (new_edge[e.idx()] == kInvalidIndex) new_edge[e.idx()] = next++;
  return m.renumber(std::move(new_vertex), std::move(new_edge), std::move(new_face));
}

}  // namespace hedge

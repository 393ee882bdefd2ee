#include "hedge/algorithms/reorder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

// Edges in the order the faces, taken in their new order, first meet them; edges of no face (none
// in a valid mesh) last.
std::vector<Index> edges_by_faces(const SurfaceMesh& m, const std::vector<Face>& faces) {
  std::vector<Index> new_edge(m.edge_slots(), kInvalidIndex);
  Index next = 0;
  for (Face f : faces)
    for (Halfedge h : m.halfedges(f)) {
      Index& slot = new_edge[SurfaceMesh::edge(h).idx()];
      if (slot == kInvalidIndex) slot = next++;
    }
  for (Edge e : m.edges())
    if (new_edge[e.idx()] == kInvalidIndex) new_edge[e.idx()] = next++;
  return new_edge;
}

GarbageMaps reorder_spatial(SurfaceMesh& m) {
  require_finite_positions(m, "reorder");
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
  std::vector<Face> faces(m.n_faces());
  for (Face f : m.faces()) faces[new_face[f.idx()]] = f;
  std::vector<Index> new_edge = edges_by_faces(m, faces);
  return m.renumber(std::move(new_vertex), std::move(new_edge), std::move(new_face));
}

// The vertex-cache order. A FIFO cache is modelled by time stamps: `clock` counts the vertices
// that entered the cache, and vertex v is still in it while clock - entered[v] <= cache_size (it
// and fewer than cache_size vertices after it entered).
// Faces are emitted in fans: all the faces left around the current vertex, in rotational order;
// the next fan centre is, among the corners just emitted that still have faces left, the one that
// entered the cache longest ago yet will still be in it after its own fan (its fan adds at most
// 2 vertices a face); else the most recent corner with faces left (a stack of dead ends); else the
// next vertex in index order with faces left.
GarbageMaps reorder_vertex_cache(SurfaceMesh& m, std::size_t cache_size) {
  const std::int64_t k = std::int64_t(std::max<std::size_t>(cache_size, 3));
  constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::min() / 2;
  std::vector<std::uint32_t> left(m.vertex_slots(), 0);  // faces not yet emitted, per vertex
  for (Face f : m.faces())
    for (Vertex v : m.vertices(f)) ++left[v.idx()];
  std::vector<std::int64_t> entered(m.vertex_slots(), kNever);
  std::vector<char> emitted(m.face_slots(), 0);
  std::vector<Face> faces;
  faces.reserve(m.n_faces());
  std::vector<Vertex> dead_ends, corners;
  std::int64_t clock = 0;
  std::size_t cursor = 0;  // vertices below it have no faces left

  auto next_by_index = [&]() -> Vertex {
    for (; cursor < left.size(); ++cursor)
      if (left[cursor] > 0) return Vertex(Index(cursor));
    return Vertex();
  };
  Vertex centre = next_by_index();
  while (centre.is_valid()) {
    corners.clear();
    for (Halfedge h : m.halfedges(centre)) {
      const Face f = m.face(h);
      if (!f.is_valid() || emitted[f.idx()]) continue;
      emitted[f.idx()] = 1;
      faces.push_back(f);
      for (Vertex w : m.vertices(f)) {
        --left[w.idx()];
        dead_ends.push_back(w);
        corners.push_back(w);
        if (clock - entered[w.idx()] > k) entered[w.idx()] = clock++;
      }
    }
    // The next centre.
    Vertex best;
    std::int64_t best_priority = -1;
    for (Vertex w : corners) {
      if (left[w.idx()] == 0) continue;
      std::int64_t priority = 0;
      const std::int64_t age = clock - entered[w.idx()];
      if (age + 2 * std::int64_t(left[w.idx()]) <= k) priority = age;
      if (priority > best_priority) best_priority = priority, best = w;
    }
    while (!best.is_valid() && !dead_ends.empty()) {
      const Vertex w = dead_ends.back();
      dead_ends.pop_back();
      if (left[w.idx()] > 0) best = w;
    }
    if (!best.is_valid()) best = next_by_index();
    centre = best;
  }

  // Faces in emission order; vertices by first use, isolated ones last.
  std::vector<Index> new_face(m.face_slots(), kInvalidIndex), new_vertex(m.vertex_slots(), kInvalidIndex);
  for (std::size_t i = 0; i < faces.size(); ++i) new_face[faces[i].idx()] = Index(i);
  Index next = 0;
  for (Face f : faces)
    for (Vertex v : m.vertices(f))
      if (new_vertex[v.idx()] == kInvalidIndex) new_vertex[v.idx()] = next++;
  for (Vertex v : m.vertices())
    if (new_vertex[v.idx()] == kInvalidIndex) new_vertex[v.idx()] = next++;
  std::vector<Index> new_edge = edges_by_faces(m, faces);
  return m.renumber(std::move(new_vertex), std::move(new_edge), std::move(new_face));
}

}  // namespace

GarbageMaps reorder(SurfaceMesh& mesh, Ordering ordering, std::size_t cache_size) {
  return ordering == Ordering::vertex_cache ? reorder_vertex_cache(mesh, cache_size) : reorder_spatial(mesh);
}

double average_cache_miss_ratio(const SurfaceMesh& mesh, std::size_t cache_size) {
  const std::int64_t k = std::int64_t(std::max<std::size_t>(cache_size, 1));
  std::vector<std::int64_t> entered(mesh.vertex_slots(), std::numeric_limits<std::int64_t>::min() / 2);
  std::int64_t misses = 0;
  std::size_t triangles = 0;
  auto load = [&](Vertex v) {
    // In the cache while fewer than k vertices entered after it.
    if (misses - entered[v.idx()] > k) entered[v.idx()] = misses++;
  };
  for (Face f : mesh.faces()) {
    const Halfedge first = mesh.halfedge(f);
    const Vertex v0 = mesh.to_vertex(first);
    for (Halfedge h = mesh.next(first); mesh.next(h) != first; h = mesh.next(h)) {
      load(v0);
      load(mesh.to_vertex(h));
      load(mesh.to_vertex(mesh.next(h)));
      ++triangles;
    }
  }
  return triangles ? double(misses) / double(triangles) : 0.0;
}

}  // namespace hedge

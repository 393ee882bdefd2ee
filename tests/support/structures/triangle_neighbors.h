// The triangle-neighbour structure (TNS) of Table 1: each triangle holds its three corners and the
// three triangles across its edges, each vertex holds one of its triangles. With 32-bit indices
// that is 24 bytes per triangle and 16 per vertex (position included).
//
// Neighbour k of triangle t lies across the corner edge 3t + k, which runs from corner k to corner
// (k + 1) % 3 (see edge_table.h). The structure has no edge elements; an edge is named here by one
// of its corner edges (two names for an interior edge), which is the only handle a TNS user has.
// The paper writes N/A for the edge queries; docs/structures.md reports both.
//
// Walking about a vertex needs consistent orientation: crossing the edge that enters v always
// turns the same way, so no "did I come from there" test is needed. A boundary stops the walk,
// which then goes the other way from its start.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "edge_table.h"
#include "hedge/core/handles.h"
#include "hedge/core/vec.h"
#include "vertex_pair.h"

namespace hedge::structures {

class TriangleNeighbors {
 public:
  using EdgeRef = Index;  //!< a corner edge 3t + k

  struct Triangle {
    std::array<Index, 3> vertices;
    std::array<Index, 3> neighbors;  //!< across corner edge k; kInvalidIndex on the boundary
  };

  //! O(n) (bucketed edge matching). \throw hedge::TopologyError as match_edges().
  static TriangleNeighbors build(std::span<const Vec3> positions, std::span<const Index> triangles);

  std::size_t n_vertices() const { return positions_.size(); }
  std::size_t n_faces() const { return triangles_.size(); }
  std::size_t memory_bytes() const;
  const Triangle& triangle(Index t) const { return triangles_[t]; }
  Index vertex_triangle(Index v) const { return vertex_triangle_[v]; }

  //! One corner edge per edge (the one in the lower-numbered triangle). A helper for benchmarks
  //! and tests, not stored. O(n).
  std::vector<EdgeRef> edge_list() const;
  VertexPair endpoints(EdgeRef c) const {
    const Triangle& t = triangles_[c / 3];
    return VertexPair::ordered(t.vertices[c % 3], t.vertices[(c % 3 + 1) % 3]);
  }

  //! O(1).
  template <typename F>
  void edge_vertices(EdgeRef c, F&& f) const {
    const Triangle& t = triangles_[c / 3];
    f(t.vertices[c % 3]);
    f(t.vertices[(c % 3 + 1) % 3]);
  }
  //! O(1).
  template <typename F>
  void edge_faces(EdgeRef c, F&& f) const {
    f(c / 3);
    const Index n = triangles_[c / 3].neighbors[c % 3];
    if (n != kInvalidIndex) f(n);
  }
  //! O(valence of both ends): the edges about each end, the edge itself left out.
  template <typename F>
  void edge_adjacent_edges(EdgeRef c, F&& f) const {
    const Triangle& t = triangles_[c / 3];
    const Index a = t.vertices[c % 3], b = t.vertices[(c % 3 + 1) % 3];
    vertex_edges_impl(a, [&](EdgeRef x, Index other) {
      if (other != b) f(x);
    });
    vertex_edges_impl(b, [&](EdgeRef x, Index other) {
      if (other != a) f(x);
    });
  }
  //! O(valence). Each edge once: the corner edge leaving v in each triangle, plus on the boundary
  //! the edge entering v in the last triangle.
  template <typename F>
  void vertex_edges(Index v, F&& f) const {
    vertex_edges_impl(v, [&](EdgeRef x, Index) { f(x); });
  }
  //! O(valence).
  template <typename F>
  void vertex_faces(Index v, F&& f) const {
    const Index start = vertex_triangle_[v];
    if (start == kInvalidIndex) return;
    Index t = start;
    for (;;) {  // turn across the edge entering v
      f(t);
      const Index n = triangles_[t].neighbors[(corner_of(t, v) + 2) % 3];
      if (n == start) return;
      if (n == kInvalidIndex) break;
      t = n;
    }
    for (t = triangles_[start].neighbors[corner_of(start, v)]; t != kInvalidIndex;
         t = triangles_[t].neighbors[corner_of(t, v)])
      f(t);  // the other way, across the edge leaving v
  }
  //! O(1).
  template <typename F>
  void face_edges(Index t, F&& f) const {
    f(3 * t);
    f(3 * t + 1);
    f(3 * t + 2);
  }
  //! O(1).
  template <typename F>
  void face_vertices(Index t, F&& f) const {
    for (Index v : triangles_[t].vertices) f(v);
  }
  //! O(1).
  template <typename F>
  void face_faces(Index t, F&& f) const {
    for (Index n : triangles_[t].neighbors)
      if (n != kInvalidIndex) f(n);
  }

 private:
  Index corner_of(Index t, Index v) const {
    const auto& c = triangles_[t].vertices;
    return c[0] == v ? 0 : c[1] == v ? 1 : 2;
  }
  //! Calls f(corner edge, other end) once per edge at v.
  template <typename F>
  void vertex_edges_impl(Index v, F&& f) const {
    const Index start = vertex_triangle_[v];
    if (start == kInvalidIndex) return;
    Index t = start;
    for (;;) {
      const Index k = corner_of(t, v);
      const Triangle& tri = triangles_[t];
      f(3 * t + k, tri.vertices[(k + 1) % 3]);
      const Index n = tri.neighbors[(k + 2) % 3];
      if (n == start) return;
      if (n == kInvalidIndex) {  // boundary: the entering edge has no triangle where it leaves v
        f(3 * t + (k + 2) % 3, tri.vertices[(k + 2) % 3]);
        break;
      }
      t = n;
    }
    for (t = triangles_[start].neighbors[corner_of(start, v)]; t != kInvalidIndex;) {
      const Index k = corner_of(t, v);
      f(3 * t + k, triangles_[t].vertices[(k + 1) % 3]);
      t = triangles_[t].neighbors[k];
    }
  }

  std::vector<Vec3> positions_;
  std::vector<Index> vertex_triangle_;
  std::vector<Triangle> triangles_;
};

}  // namespace hedge::structures

// The indexed mesh of Table 1: a position array and three vertex indices per triangle, nothing
// else. It is what engines and files hold, and the baseline the other structures are measured
// against.
//
// It has no edges. Here an edge is named as a user of an index buffer would name it: by its two
// vertices (VertexPair). So edge -> vertices is free, and everything that needs to find the
// triangles about a vertex or an edge is an exhaustive search over the index array, O(n_t).
// The paper writes N/A for the edge queries; docs/structures.md reports both.
//
// Every query calls f once per answer element. The exhaustive searches rely on consistent
// orientation only where noted; all need triangles without repeated vertices.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "hedge/core/handles.h"
#include "hedge/core/vec.h"
#include "vertex_pair.h"

namespace hedge::structures {

class IndexedTriangles {
 public:
  using EdgeRef = VertexPair;

  //! Copies the arrays. O(n).
  static IndexedTriangles build(std::span<const Vec3> positions, std::span<const Index> triangles);

  std::size_t n_vertices() const { return positions_.size(); }
  std::size_t n_faces() const { return triangles_.size() / 3; }
  //! Bytes of every array held (capacity x element size).
  std::size_t memory_bytes() const;
  const std::vector<Vec3>& positions() const { return positions_; }
  const std::vector<Index>& triangles() const { return triangles_; }

  //! All edges as vertex pairs (a < b). A helper for benchmarks and tests, not part of the
  //! structure: the indexed mesh would have to be given its edges. O(n).
  std::vector<VertexPair> edge_list() const;
  static VertexPair endpoints(VertexPair e) { return e; }

  //! O(1): the edge is its vertex pair.
  template <typename F>
  void edge_vertices(VertexPair e, F&& f) const {
    f(e.a);
    f(e.b);
  }
  //! O(n_t): every triangle holding both vertices.
  template <typename F>
  void edge_faces(VertexPair e, F&& f) const {
    const Index* idx = triangles_.data();
    const std::size_t n = triangles_.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (idx[i] != e.a) continue;
      const std::size_t t = i / 3;
      if (idx[3 * t] == e.b || idx[3 * t + 1] == e.b || idx[3 * t + 2] == e.b) f(static_cast<Index>(t));
    }
  }
  //! O(n_t): the edges of every triangle holding either vertex, deduplicated.
  template <typename F>
  void edge_adjacent_edges(VertexPair e, F&& f) const {
    std::vector<VertexPair> found;
    const Index* idx = triangles_.data();
    const std::size_t n = triangles_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Index x = idx[i];
      if (x != e.a && x != e.b) continue;
      const Index other = x == e.a ? e.b : e.a;
      const Index t3 = static_cast<Index>(i - i % 3);
      for (Index k = 0; k < 3; ++k) {
        const Index w = idx[t3 + k];
        if (w != x && w != other) found.push_back(VertexPair::ordered(x, w));
      }
    }
    emit_unique(found, f);
  }
  //! O(n_t): the other two corners of every triangle holding v, deduplicated.
  template <typename F>
  void vertex_edges(Index v, F&& f) const {
    std::vector<VertexPair> found;
    const Index* idx = triangles_.data();
    const std::size_t n = triangles_.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (idx[i] != v) continue;
      const Index t3 = static_cast<Index>(i - i % 3);
      found.push_back(VertexPair::ordered(v, idx[t3 + (i + 1) % 3]));
      found.push_back(VertexPair::ordered(v, idx[t3 + (i + 2) % 3]));
    }
    emit_unique(found, f);
  }
  //! O(n_t): every triangle holding v (at most once each: no repeated corners).
  template <typename F>
  void vertex_faces(Index v, F&& f) const {
    const Index* idx = triangles_.data();
    const std::size_t n = triangles_.size();
    for (std::size_t i = 0; i < n; ++i)
      if (idx[i] == v) f(static_cast<Index>(i / 3));
  }
  //! O(1).
  template <typename F>
  void face_edges(Index t, F&& f) const {
    const Index* c = triangles_.data() + 3 * std::size_t{t};
    f(VertexPair::ordered(c[0], c[1]));
    f(VertexPair::ordered(c[1], c[2]));
    f(VertexPair::ordered(c[2], c[0]));
  }
  //! O(1).
  template <typename F>
  void face_vertices(Index t, F&& f) const {
    const Index* c = triangles_.data() + 3 * std::size_t{t};
    f(c[0]);
    f(c[1]);
    f(c[2]);
  }
  //! O(n_t): a neighbour across edge x -> y of t runs y -> x, so look for corners y followed by x.
  //! Relies on consistent orientation, which every structure here requires anyway.
  template <typename F>
  void face_faces(Index t, F&& f) const {
    const Index* c = triangles_.data() + 3 * std::size_t{t};
    const Index a = c[0], b = c[1], d = c[2];
    const Index* idx = triangles_.data();
    const std::size_t n = triangles_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Index y = idx[i];
      // Which vertex must follow y for the corner edge to be a reversed edge of t.
      const Index want = y == b ? a : y == d ? b : y == a ? d : kInvalidIndex;
      if (want == kInvalidIndex) continue;
      if (idx[i - i % 3 + (i + 1) % 3] == want) f(static_cast<Index>(i / 3));
    }
  }

 private:
  template <typename F>
  static void emit_unique(std::vector<VertexPair>& found, F&& f) {
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    for (const VertexPair& p : found) f(p);
  }

  std::vector<Vec3> positions_;
  std::vector<Index> triangles_;
};

}  // namespace hedge::structures

// The winged-edge mesh (WEM) of Table 1. Each edge holds its two vertices, its two faces, and for
// each face the next and the previous edge around that face; each vertex and each face holds one
// edge. With 32-bit indices that is 32 bytes per edge, 16 per vertex (position included) and 4
// per face.
//
// Side 0 of an edge is the face in which the edge runs vertex[0] -> vertex[1]; side 1 the face in
// which it runs back. Every step of a walk must first find out on which side of the next edge it
// stands: the bookkeeping the half-edge mesh removes.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "hedge/core/handles.h"
#include "hedge/core/vec.h"
#include "vertex_pair.h"

namespace hedge::structures {

class WingedEdge {
 public:
  using EdgeRef = Index;

  struct WEdge {
    std::array<Index, 2> vertex;  //!< side 0 runs vertex[0] -> vertex[1]
    std::array<Index, 2> face;    //!< kInvalidIndex on a boundary side
    std::array<Index, 2> next;    //!< next edge around face[s]
    std::array<Index, 2> prev;    //!< previous edge around face[s]
  };

  //! O(n) (bucketed edge matching). \throw hedge::TopologyError as match_edges().
  static WingedEdge build(std::span<const Vec3> positions, std::span<const Index> triangles);

  std::size_t n_vertices() const { return positions_.size(); }
  std::size_t n_faces() const { return face_edge_.size(); }
  std::size_t n_edges() const { return edges_.size(); }
  std::size_t memory_bytes() const;
  const WEdge& edge(Index e) const { return edges_[e]; }

  std::vector<EdgeRef> edge_list() const;
  VertexPair endpoints(EdgeRef e) const {
    return VertexPair::ordered(edges_[e].vertex[0], edges_[e].vertex[1]);
  }

  //! O(1).
  template <typename F>
  void edge_vertices(EdgeRef e, F&& f) const {
    f(edges_[e].vertex[0]);
    f(edges_[e].vertex[1]);
  }
  //! O(1).
  template <typename F>
  void edge_faces(EdgeRef e, F&& f) const {
    for (Index x : edges_[e].face)
      if (x != kInvalidIndex) f(x);
  }
  //! O(valence of both ends).
  template <typename F>
  void edge_adjacent_edges(EdgeRef e, F&& f) const {
    for (Index v : edges_[e].vertex)
      vertex_edges(v, [&](EdgeRef x) {
        if (x != e) f(x);
      });
  }
  //! O(valence).
  template <typename F>
  void vertex_edges(Index v, F&& f) const {
    walk_about(v, [&](EdgeRef e, Index) { f(e); });
  }
  //! O(valence).
  template <typename F>
  void vertex_faces(Index v, F&& f) const {
    walk_about(v, [&](EdgeRef, Index face) {
      if (face != kInvalidIndex) f(face);
    });
  }
  //! O(face degree): 3 steps on a triangle.
  template <typename F>
  void face_edges(Index t, F&& f) const {
    walk_face(t, [&](EdgeRef e, int) { f(e); });
  }
  //! O(face degree).
  template <typename F>
  void face_vertices(Index t, F&& f) const {
    walk_face(t, [&](EdgeRef e, int s) { f(edges_[e].vertex[s]); });
  }
  //! O(face degree).
  template <typename F>
  void face_faces(Index t, F&& f) const {
    walk_face(t, [&](EdgeRef e, int s) {
      const Index other = edges_[e].face[1 - s];
      if (other != kInvalidIndex) f(other);
    });
  }

 private:
  //! Calls f(edge, side of t) for each edge of t in order; vertex[side] is the edge's first corner.
  template <typename F>
  void walk_face(Index t, F&& f) const {
    const Index start = face_edge_[t];
    Index e = start;
    do {
      const int s = edges_[e].face[0] == t ? 0 : 1;
      f(e, s);
      e = edges_[e].next[s];
    } while (e != start);
  }
  //! Calls f(edge, face) once per edge at v, face being the face swept when leaving that edge
  //! (kInvalidIndex for the edge that closes a boundary fan). Turns one way until it is back or
  //! hits the boundary, then the other way from the start.
  template <typename F>
  void walk_about(Index v, F&& f) const {
    const Index start = vertex_edge_[v];
    if (start == kInvalidIndex) return;
    Index e = start;
    for (;;) {
      const WEdge& w = edges_[e];
      const int s = w.vertex[0] == v ? 0 : 1;  // the side in which e leaves v
      f(e, w.face[s]);
      if (w.face[s] == kInvalidIndex) break;
      e = w.prev[s];  // enters v in face[s]
      if (e == start) return;
    }
    e = start;
    for (;;) {
      const WEdge& w = edges_[e];
      const int s = w.vertex[0] == v ? 1 : 0;  // the side in which e enters v
      if (w.face[s] == kInvalidIndex) return;
      e = w.next[s];  // leaves v in face[s]
      const WEdge& n = edges_[e];
      const int ns = n.vertex[0] == v ? 0 : 1;
      f(e, n.face[ns]);
    }
  }

  std::vector<Vec3> positions_;
  std::vector<Index> vertex_edge_;
  std::vector<Index> face_edge_;
  std::vector<WEdge> edges_;
};

}  // namespace hedge::structures

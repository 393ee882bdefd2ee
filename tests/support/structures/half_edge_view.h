// hedge's SurfaceMesh behind the same query interface as the other three structures, so that one
// benchmark and one test drive all four. Every query is the SurfaceMesh call a user would write.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"
#include "vertex_pair.h"

namespace hedge::structures {

class HalfEdgeView {
 public:
  using EdgeRef = Index;

  //! Builds with hedge::build_triangles (strict, no welding, no corner attributes). If `report`
  //! is given it receives the build's input-to-mesh element maps.
  static HalfEdgeView build(std::span<const Vec3> positions, std::span<const Index> triangles,
                            BuildReport* report = nullptr);
  //! Releases spare capacity (the other structures hold none), before memory is counted.
  void shrink_to_fit() { mesh_.shrink_to_fit(); }

  const SurfaceMesh& mesh() const { return mesh_; }
  std::size_t n_vertices() const { return mesh_.n_vertices(); }
  std::size_t n_faces() const { return mesh_.n_faces(); }
  //! SurfaceMesh::memory_bytes(): connectivity, deletion flags and properties, by capacity.
  std::size_t memory_bytes() const { return mesh_.memory_bytes(); }

  std::vector<EdgeRef> edge_list() const;
  VertexPair endpoints(EdgeRef e) const {
    return VertexPair::ordered(mesh_.vertex(Edge(e), 0).idx(), mesh_.vertex(Edge(e), 1).idx());
  }

  template <typename F>
  void edge_vertices(EdgeRef e, F&& f) const {
    for (Vertex v : mesh_.vertices(Edge(e))) f(v.idx());
  }
  template <typename F>
  void edge_faces(EdgeRef e, F&& f) const {
    for (Face x : mesh_.faces(Edge(e))) f(x.idx());
  }
  template <typename F>
  void edge_adjacent_edges(EdgeRef e, F&& f) const {
    for (Edge x : mesh_.adjacent_edges(Edge(e))) f(x.idx());
  }
  template <typename F>
  void vertex_edges(Index v, F&& f) const {
    for (Edge x : mesh_.edges(Vertex(v))) f(x.idx());
  }
  template <typename F>
  void vertex_faces(Index v, F&& f) const {
    for (Face x : mesh_.faces(Vertex(v))) f(x.idx());
  }
  template <typename F>
  void face_edges(Index t, F&& f) const {
    for (Edge x : mesh_.edges(Face(t))) f(x.idx());
  }
  template <typename F>
  void face_vertices(Index t, F&& f) const {
    for (Vertex x : mesh_.vertices(Face(t))) f(x.idx());
  }
  template <typename F>
  void face_faces(Index t, F&& f) const {
    for (Face x : mesh_.faces(Face(t))) f(x.idx());
  }

 private:
  SurfaceMesh mesh_;
};

}  // namespace hedge::structures

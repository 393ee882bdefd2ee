// The C ABI: adjacency queries (hedge_halfedge_*, hedge_vertex_*, hedge_face_*, hedge_edge_*), each
// checking its handle, its element and its out parameters; ring queries copy into caller buffers.
#include <type_traits>

#include "capi_internal.h"

using namespace hedge;
using namespace hedge::capi;

namespace {

//! Slots of element type H, deleted ones included.
template <typename H>
std::size_t slot_count(const SurfaceMesh& m) {
  if constexpr (std::is_same_v<H, Vertex>)
    return m.vertex_slots();
  else if constexpr (std::is_same_v<H, Halfedge>)
    return m.halfedge_slots();
  else if constexpr (std::is_same_v<H, Edge>)
    return m.edge_slots();
  else
    return m.face_slots();
}

//! Whether element `index` of type H is deleted; any index in range is accepted.
template <typename H>
hedge_status deleted_query(const hedge_mesh* mesh, std::uint32_t index, std::int32_t* out, const char* what) {
  return guard([&] {
    auto object = find_mesh(mesh);
    check_range(what, index, slot_count<H>(object->mesh));
    need(out, "out_deleted") = object->mesh.is_deleted(H(index)) ? 1 : 0;
  });
}

//! Copies what a circulator about a live element yields, as indices, into a caller buffer. Two passes
//! (count, then copy) instead of a temporary list: nothing is allocated.
template <typename H, typename Ring>
hedge_status ring_query(const hedge_mesh* mesh, std::uint32_t index, std::uint32_t* buffer,
                        std::uint32_t capacity, std::uint32_t* out_count, Ring&& ring) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const SurfaceMesh& m = object->mesh;
    const H h = live_element<H>(m, index);
    need(out_count, "out_count");
    if constexpr (std::is_same_v<H, Vertex>) {
      if (m.is_isolated(h)) {
        *out_count = 0;
        return;
      }
    }
    const auto range = ring(m, h);
    *out_count = to_u32(range.count(), "ring size");
    check_capacity(*out_count, buffer, capacity);
    for (auto x : range) *buffer++ = x.idx();
  });
}

}  // namespace

extern "C" {

// ---------------------------------------------------------------------------------------------
// Adjacency
// ---------------------------------------------------------------------------------------------

hedge_status hedge_halfedge_twin(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge) {
  return element_query<Halfedge>(mesh, halfedge, out_halfedge, "out_halfedge",
                                 [](const SurfaceMesh&, Halfedge h) { return SurfaceMesh::twin(h).idx(); });
}

hedge_status hedge_halfedge_next(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge) {
  return element_query<Halfedge>(mesh, halfedge, out_halfedge, "out_halfedge",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.next(h).idx(); });
}

hedge_status hedge_halfedge_prev(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge) {
  return element_query<Halfedge>(mesh, halfedge, out_halfedge, "out_halfedge",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.prev(h).idx(); });
}

hedge_status hedge_halfedge_to_vertex(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_vertex) {
  return element_query<Halfedge>(mesh, halfedge, out_vertex, "out_vertex",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.to_vertex(h).idx(); });
}

hedge_status hedge_halfedge_from_vertex(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_vertex) {
  return element_query<Halfedge>(mesh, halfedge, out_vertex, "out_vertex",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.from_vertex(h).idx(); });
}

hedge_status hedge_halfedge_face(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_face) {
  return element_query<Halfedge>(mesh, halfedge, out_face, "out_face",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.face(h).idx(); });
}

hedge_status hedge_halfedge_edge(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_edge) {
  return element_query<Halfedge>(mesh, halfedge, out_edge, "out_edge",
                                 [](const SurfaceMesh&, Halfedge h) { return SurfaceMesh::edge(h).idx(); });
}

hedge_status hedge_vertex_halfedge(const hedge_mesh* mesh, uint32_t vertex, uint32_t* out_halfedge) {
  return element_query<Vertex>(mesh, vertex, out_halfedge, "out_halfedge",
                               [](const SurfaceMesh& m, Vertex v) { return m.halfedge(v).idx(); });
}

hedge_status hedge_face_halfedge(const hedge_mesh* mesh, uint32_t face, uint32_t* out_halfedge) {
  return element_query<Face>(mesh, face, out_halfedge, "out_halfedge",
                             [](const SurfaceMesh& m, Face f) { return m.halfedge(f).idx(); });
}

hedge_status hedge_edge_halfedge(const hedge_mesh* mesh, uint32_t edge, uint32_t i, uint32_t* out_halfedge) {
  return element_query<Edge>(mesh, edge, out_halfedge, "out_halfedge", [&](const SurfaceMesh&, Edge e) {
    if (i > 1) fail(HEDGE_ERROR_INVALID_ARGUMENT, "i is " + std::to_string(i) + ", not 0 or 1");
    return SurfaceMesh::halfedge(e, i).idx();
  });
}

hedge_status hedge_vertex_is_boundary(const hedge_mesh* mesh, uint32_t vertex, int32_t* out_boundary) {
  return element_query<Vertex>(mesh, vertex, out_boundary, "out_boundary",
                               [](const SurfaceMesh& m, Vertex v) { return m.is_boundary(v) ? 1 : 0; });
}

hedge_status hedge_halfedge_is_boundary(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_boundary) {
  return element_query<Halfedge>(mesh, halfedge, out_boundary, "out_boundary",
                                 [](const SurfaceMesh& m, Halfedge h) { return m.is_boundary(h) ? 1 : 0; });
}

hedge_status hedge_edge_is_boundary(const hedge_mesh* mesh, uint32_t edge, int32_t* out_boundary) {
  return element_query<Edge>(mesh, edge, out_boundary, "out_boundary",
                             [](const SurfaceMesh& m, Edge e) { return m.is_boundary(e) ? 1 : 0; });
}

hedge_status hedge_face_is_boundary(const hedge_mesh* mesh, uint32_t face, int32_t* out_boundary) {
  return element_query<Face>(mesh, face, out_boundary, "out_boundary",
                             [](const SurfaceMesh& m, Face f) { return m.is_boundary(f) ? 1 : 0; });
}

hedge_status hedge_vertex_valence(const hedge_mesh* mesh, uint32_t vertex, uint32_t* out_valence) {
  return element_query<Vertex>(mesh, vertex, out_valence, "out_valence", [](const SurfaceMesh& m, Vertex v) {
    return to_u32(m.valence(v), "valence");
  });
}

hedge_status hedge_face_valence(const hedge_mesh* mesh, uint32_t face, uint32_t* out_valence) {
  return element_query<Face>(mesh, face, out_valence, "out_valence",
                             [](const SurfaceMesh& m, Face f) { return to_u32(m.valence(f), "valence"); });
}

hedge_status hedge_mesh_find_halfedge(const hedge_mesh* mesh, uint32_t from, uint32_t to,
                                      uint32_t* out_halfedge) {
  return element_query<Vertex>(mesh, from, out_halfedge, "out_halfedge", [&](const SurfaceMesh& m, Vertex a) {
    return m.find_halfedge(a, live_vertex(m, to)).idx();
  });
}

hedge_status hedge_vertex_is_deleted(const hedge_mesh* mesh, uint32_t vertex, int32_t* out_deleted) {
  return deleted_query<Vertex>(mesh, vertex, out_deleted, "vertex");
}

hedge_status hedge_halfedge_is_deleted(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_deleted) {
  return deleted_query<Halfedge>(mesh, halfedge, out_deleted, "halfedge");
}

hedge_status hedge_edge_is_deleted(const hedge_mesh* mesh, uint32_t edge, int32_t* out_deleted) {
  return deleted_query<Edge>(mesh, edge, out_deleted, "edge");
}

hedge_status hedge_face_is_deleted(const hedge_mesh* mesh, uint32_t face, int32_t* out_deleted) {
  return deleted_query<Face>(mesh, face, out_deleted, "face");
}

hedge_status hedge_vertex_halfedges(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer,
                                    uint32_t capacity, uint32_t* out_count) {
  return ring_query<Vertex>(mesh, vertex, buffer, capacity, out_count,
                            [](const SurfaceMesh& m, Vertex v) { return m.halfedges(v); });
}

hedge_status hedge_vertex_vertices(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer,
                                   uint32_t capacity, uint32_t* out_count) {
  return ring_query<Vertex>(mesh, vertex, buffer, capacity, out_count,
                            [](const SurfaceMesh& m, Vertex v) { return m.vertices(v); });
}

hedge_status hedge_vertex_faces(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer, uint32_t capacity,
                                uint32_t* out_count) {
  return ring_query<Vertex>(mesh, vertex, buffer, capacity, out_count,
                            [](const SurfaceMesh& m, Vertex v) { return m.faces(v); });
}

hedge_status hedge_face_vertices(const hedge_mesh* mesh, uint32_t face, uint32_t* buffer, uint32_t capacity,
                                 uint32_t* out_count) {
  return ring_query<Face>(mesh, face, buffer, capacity, out_count,
                          [](const SurfaceMesh& m, Face f) { return m.vertices(f); });
}

hedge_status hedge_face_halfedges(const hedge_mesh* mesh, uint32_t face, uint32_t* buffer, uint32_t capacity,
                                  uint32_t* out_count) {
  return ring_query<Face>(mesh, face, buffer, capacity, out_count,
                          [](const SurfaceMesh& m, Face f) { return m.halfedges(f); });
}

}  // extern "C"

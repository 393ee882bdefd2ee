// The C ABI: local operations (hedge/core/operations.h), the edits of whole regions beside them
// (hedge/algorithms/: fill_hole, split_all_faces, detach_faces) and garbage collection.
// Every edit checks its handles, its out parameters and its predicate before it changes anything.
#include "hedge/core/operations.h"

#include <unordered_set>

#include "binding/face_attributes.h"
#include "binding/rollback.h"
#include "capi_internal.h"
#include "hedge/algorithms/detach_faces.h"
#include "hedge/algorithms/fill_hole.h"
#include "hedge/algorithms/split_all_faces.h"

using namespace hedge;
using namespace hedge::capi;

namespace {
// A predicate's answer: 1 when the edit is allowed, else 0 with its refusal recorded for
// hedge_last_refusal(), so that a caller asking "why not?" after a predicate gets this edit's reason.
std::int32_t allowed(const char* refusal) {
  set_refusal(refusal);
  return refusal == nullptr ? 1 : 0;
}

// A predicate's entry point: checks the handles, then writes whether the edit is allowed to *out_ok.
template <typename H>
hedge_status predicate(const hedge_mesh* mesh, std::uint32_t index, std::int32_t* out_ok,
                       const char* (*refusal)(const SurfaceMesh&, H)) {
  return element_query<H>(mesh, index, out_ok, "out_ok",
                          [refusal](const SurfaceMesh& m, H x) { return allowed(refusal(m, x)); });
}
}  // namespace

void hedge::capi::check_map_buffers(const SurfaceMesh& m, const MapBuffers& b) {
  if (b.vertex != nullptr) check_capacity(m.vertex_slots(), b.vertex, b.vertex_capacity, "vertex_map");
  if (b.halfedge != nullptr)
    check_capacity(m.halfedge_slots(), b.halfedge, b.halfedge_capacity, "halfedge_map");
  if (b.edge != nullptr) check_capacity(m.edge_slots(), b.edge, b.edge_capacity, "edge_map");
  if (b.face != nullptr) check_capacity(m.face_slots(), b.face, b.face_capacity, "face_map");
}

void hedge::capi::write_maps(const GarbageMaps& maps, const MapBuffers& b) {
  auto put = [](const std::vector<Index>& from, std::uint32_t* to) {
    if (to != nullptr) std::copy(from.begin(), from.end(), to);
  };
  put(maps.vertices, b.vertex);
  put(maps.halfedges, b.halfedge);
  put(maps.edges, b.edge);
  put(maps.faces, b.face);
}

extern "C" {

hedge_status hedge_can_split_edge(const hedge_mesh* mesh, uint32_t edge, int32_t* out_ok) {
  return predicate<Edge>(mesh, edge, out_ok, split_refusal);
}

hedge_status hedge_split_edge(hedge_mesh* mesh, uint32_t edge, float x, float y, float z,
                              uint32_t* out_vertex) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_vertex, "out_vertex");
    *out_vertex = binding::split_edge(object->mesh, edge, Vec3{x, y, z}).idx();
  });
}

hedge_status hedge_can_collapse(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_ok) {
  return predicate<Halfedge>(mesh, halfedge, out_ok, collapse_refusal);
}

hedge_status hedge_collapse(hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_vertex) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_vertex, "out_vertex");
    *out_vertex = binding::collapse(object->mesh, halfedge).idx();
  });
}

hedge_status hedge_can_flip(const hedge_mesh* mesh, uint32_t edge, int32_t* out_ok) {
  return predicate<Edge>(mesh, edge, out_ok, flip_refusal);
}

hedge_status hedge_flip(hedge_mesh* mesh, uint32_t edge) {
  return guard([&] { binding::flip(find_mesh(mesh)->mesh, edge); });
}

hedge_status hedge_can_split_face(const hedge_mesh* mesh, uint32_t face, int32_t* out_ok) {
  return predicate<Face>(mesh, face, out_ok, split_face_refusal);
}

hedge_status hedge_split_face(hedge_mesh* mesh, uint32_t face, float x, float y, float z,
                              uint32_t* out_vertex) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_vertex, "out_vertex");
    *out_vertex = binding::split_face(object->mesh, face, Vec3{x, y, z}).idx();
  });
}

hedge_status hedge_can_cut_face(const hedge_mesh* mesh, uint32_t halfedge0, uint32_t halfedge1,
                                int32_t* out_ok) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Halfedge h0 = live_halfedge(object->mesh, halfedge0);
    const Halfedge h1 = live_halfedge(object->mesh, halfedge1);
    need(out_ok, "out_ok") = allowed(cut_face_refusal(object->mesh, h0, h1));
  });
}

hedge_status hedge_cut_face(hedge_mesh* mesh, uint32_t halfedge0, uint32_t halfedge1,
                            uint32_t* out_halfedge) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_halfedge, "out_halfedge");
    *out_halfedge = binding::cut_face(object->mesh, halfedge0, halfedge1).idx();
  });
}

hedge_status hedge_mesh_split_all_faces(hedge_mesh* mesh, uint32_t* buffer, uint32_t capacity,
                                        uint32_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    SurfaceMesh& m = object->mesh;
    need(out_count, "out_count");
    const std::uint32_t faces = to_u32(m.n_faces(), "face count");
    if (buffer != nullptr) {
      *out_count = faces;
      check_capacity(faces, buffer, capacity);
    }
    const std::vector<Vertex> added = split_all_faces(m);
    if (buffer != nullptr)
      for (std::size_t i = 0; i < added.size(); ++i) buffer[i] = added[i].idx();
    *out_count = to_u32(added.size(), "new vertex count");
  });
}

hedge_status hedge_can_add_face(const hedge_mesh* mesh, const uint32_t* vertices, uint32_t count,
                                int32_t* out_ok) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need_array(vertices, count, "vertices");
    const std::vector<Vertex> corners =
        binding::live_vertices(object->mesh, std::span<const std::uint32_t>(vertices, count));
    need(out_ok, "out_ok") = allowed(add_face_refusal(object->mesh, corners));
  });
}

hedge_status hedge_add_face(hedge_mesh* mesh, const uint32_t* vertices, uint32_t count, uint32_t* out_face) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need_array(vertices, count, "vertices");
    const std::vector<Vertex> corners =
        binding::live_vertices(object->mesh, std::span<const std::uint32_t>(vertices, count));
    need(out_face, "out_face");
    *out_face = binding::add_face(object->mesh, corners).idx();
  });
}

hedge_status hedge_add_face_with_attributes(hedge_mesh* mesh, const uint32_t* vertices, uint32_t count,
                                            const float* texcoords, int32_t submesh, uint32_t* out_face) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need_array(vertices, count, "vertices");
    const std::vector<Vertex> corners =
        binding::live_vertices(object->mesh, std::span<const std::uint32_t>(vertices, count));
    need(out_face, "out_face");
    std::vector<Vec2> uv;
    if (texcoords != nullptr)
      for (uint32_t i = 0; i < count; ++i) uv.push_back({texcoords[2 * i], texcoords[2 * i + 1]});
    binding::FaceAttributes attributes;
    attributes.texcoords = uv;
    if (submesh != -1) attributes.submesh = submesh;
    *out_face = binding::add_face(object->mesh, corners, attributes).idx();
  });
}

hedge_status hedge_can_remove_face(const hedge_mesh* mesh, uint32_t face, int32_t* out_ok) {
  return predicate<Face>(mesh, face, out_ok, remove_face_refusal);
}

hedge_status hedge_remove_face(hedge_mesh* mesh, uint32_t face) {
  return guard([&] { binding::remove_face(find_mesh(mesh)->mesh, face); });
}

hedge_status hedge_can_remove_vertex(const hedge_mesh* mesh, uint32_t vertex, int32_t* out_ok) {
  return predicate<Vertex>(mesh, vertex, out_ok, remove_vertex_refusal);
}

hedge_status hedge_remove_vertex(hedge_mesh* mesh, uint32_t vertex) {
  return guard([&] { binding::remove_vertex(find_mesh(mesh)->mesh, vertex); });
}

hedge_status hedge_can_fill_hole(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_ok) {
  return predicate<Halfedge>(mesh, halfedge, out_ok, fill_hole_refusal);
}

hedge_status hedge_fill_hole(hedge_mesh* mesh, uint32_t halfedge, uint32_t* buffer, uint32_t capacity,
                             uint32_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    SurfaceMesh& m = object->mesh;
    need(out_count, "out_count");
    // The refusal comes first: the buffer check below walks the loop, which the refusal has found
    // sound, and a refusal takes precedence over a small buffer.
    const Halfedge h = binding::require_fill_hole(m, halfedge);
    if (buffer != nullptr) {
      std::size_t length = 0;
      for ([[maybe_unused]] Halfedge g : m.loop(h)) ++length;
      *out_count = to_u32(length - 2, "face count");
      check_capacity(length - 2, buffer, capacity);
    }
    const std::vector<Face> faces = fill_hole(m, h);
    if (buffer != nullptr)
      for (std::size_t i = 0; i < faces.size(); ++i) buffer[i] = faces[i].idx();
    *out_count = to_u32(faces.size(), "face count");
  });
}

hedge_status hedge_detach_faces(hedge_mesh* mesh, const uint32_t* faces, uint32_t count,
                                uint32_t* out_vertex_origin, uint32_t origin_capacity,
                                uint32_t* out_origin_count, hedge_mesh** out_mesh) {
  return guard([&] {
    auto object = find_mesh(mesh);
    SurfaceMesh& m = object->mesh;
    need_array(faces, count, "faces");
    need(out_mesh, "out_mesh");
    if (out_vertex_origin != nullptr) need(out_origin_count, "out_origin_count");
    std::vector<Face> chosen;
    chosen.reserve(count);
    std::unordered_set<Face> seen;
    std::uint64_t corners = 0;
    for (std::uint32_t i = 0; i < count; ++i) {
      const Face f = live_face(m, faces[i]);
      if (seen.insert(f).second) {
        chosen.push_back(f);
        corners += m.valence(f);
      }
    }
    if (out_vertex_origin != nullptr) {
      *out_origin_count = to_u32(corners, "corner count");
      check_capacity(corners, out_vertex_origin, origin_capacity, "out_vertex_origin");
    }
    auto detached = std::make_shared<MeshObject>();
    std::vector<Vertex> origin;
    detached->mesh = detach_faces(m, chosen, &origin);
    const std::uint32_t n = to_u32(detached->mesh.vertex_slots(), "vertex count");
    if (out_vertex_origin != nullptr)
      for (std::uint32_t v = 0; v < n; ++v)
        out_vertex_origin[v] = v < origin.size() ? origin[v].idx() : HEDGE_INVALID_INDEX;
    if (out_origin_count != nullptr) *out_origin_count = n;
    *out_mesh = register_mesh(std::move(detached));
  });
}

hedge_status hedge_mesh_garbage_collection(hedge_mesh* mesh, uint32_t* vertex_map, uint32_t vertex_capacity,
                                           uint32_t* halfedge_map, uint32_t halfedge_capacity,
                                           uint32_t* edge_map, uint32_t edge_capacity, uint32_t* face_map,
                                           uint32_t face_capacity) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const MapBuffers b{vertex_map, vertex_capacity, halfedge_map, halfedge_capacity,
                       edge_map,   edge_capacity,   face_map,     face_capacity};
    check_map_buffers(object->mesh, b);
    // garbage_collection() compacts array after array: a failure halfway is rolled back.
    SurfaceMesh& m = object->mesh;
    write_maps(binding::with_rollback(m, [&] { return m.garbage_collection(); }), b);
  });
}

}  // extern "C"

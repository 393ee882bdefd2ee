// The C ABI: render buffers (hedge/render/render_buffers.h) and engine-mesh import
// (hedge/render/engine_mesh.h).
#include "capi_internal.h"
#include "hedge/render/engine_mesh.h"

using namespace hedge;
using namespace hedge::capi;

namespace {

hedge_render_buffers_options default_render_options() {
  return {HEDGE_NORMALS_AUTOMATIC, 1, 1, 1, HEDGE_WINDING_CCW, 0};
}

RenderOptions to_render_options(const hedge_render_buffers_options& o) {
  RenderOptions r;
  static constexpr binding::Constant<NormalSource> kNormals[] = {
      {HEDGE_NORMALS_NONE, NormalSource::none},
      {HEDGE_NORMALS_ATTRIBUTE, NormalSource::attribute},
      {HEDGE_NORMALS_COMPUTED, NormalSource::computed},
      {HEDGE_NORMALS_AUTOMATIC, NormalSource::automatic}};
  r.normals = binding::from_constant(kNormals, o.normals, "normals", "HEDGE_NORMALS_*");
  r.texcoords = need_bool(o.texcoords, "texcoords");
  r.colors = need_bool(o.colors, "colors");
  r.interleaved = need_bool(o.interleaved, "interleaved");
  r.winding = to_winding(o.winding);
  r.flip_x = need_bool(o.flip_x, "flip_x");
  return r;
}

void fill_result(const SyncResult& r, hedge_sync_result* out) {
  if (out == nullptr) return;
  out->vertex_bytes = r.vertex_bytes;
  out->index_bytes = r.index_bytes;
  out->vertex_range_count = to_u32(r.vertex_ranges.size(), "range count");
  out->index_range_count = to_u32(r.index_ranges.size(), "range count");
  out->faces_synced = to_u32(r.faces_synced, "faces_synced");
  out->vertices_synced = to_u32(r.vertices_synced, "vertices_synced");
  out->resized = r.resized ? 1 : 0;
  out->full = r.full ? 1 : 0;
}

std::span<const float> stream_of(const RenderBuffers& sync, std::int32_t stream) {
  switch (stream) {
    case HEDGE_STREAM_VERTICES:
      return sync.vertices();
    case HEDGE_STREAM_NORMALS:
      return sync.normals();
    case HEDGE_STREAM_TEXCOORDS:
      return sync.texcoords();
    case HEDGE_STREAM_COLORS:
      return sync.colors();
    case HEDGE_STREAM_TANGENTS:
      return sync.tangents();
    case HEDGE_STREAM_TEXCOORDS1:
      return sync.texcoords1();
    default:
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "stream is " + std::to_string(stream) + ", not a HEDGE_STREAM_* value");
  }
}

void copy_ranges(const std::vector<SlotRange>& ranges, hedge_range* buffer, std::uint32_t capacity,
                 std::uint32_t* out_count) {
  need(out_count, "out_count");
  *out_count = to_u32(ranges.size(), "range count");
  check_capacity(ranges.size(), buffer, capacity);
  for (std::size_t i = 0; i < ranges.size(); ++i) buffer[i] = {ranges[i].first, ranges[i].count};
}

// Copies a source-index property (engine_mesh.h kVertexSource, kCornerSource) into a caller buffer.
template <typename Property>
void copy_sources(const Property& p, int32_t* buffer, uint64_t capacity, uint64_t* out_count) {
  if (!p)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         "the mesh has no source indices: only a mesh made by hedge_mesh_from_engine_mesh() has them");
  copy_out(std::span<const std::int32_t>(p.vector()), buffer, capacity, out_count);
}

EngineImportOptions to_engine_import_options(const hedge_engine_import_options* options) {
  hedge_engine_import_options o{HEDGE_WELD_EXACT, HEDGE_POLICY_REPAIR, 1e-6, HEDGE_WINDING_CCW, 0};
  if (options != nullptr) o = *options;
  EngineImportOptions import;
  import.weld = to_weld(o.weld);
  import.policy = to_policy(o.policy);
  if (!std::isfinite(o.weld_epsilon) || o.weld_epsilon < 0)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         "weld_epsilon is " + std::to_string(o.weld_epsilon) + ", not a finite number >= 0");
  import.weld_epsilon = o.weld_epsilon;
  import.winding = to_winding(o.winding);
  import.flip_x = need_bool(o.flip_x, "flip_x");
  return import;
}
}  // namespace

extern "C" {

hedge_status hedge_render_buffers_options_default(hedge_render_buffers_options* out_options) {
  return guard([&] { need(out_options, "out_options") = default_render_options(); });
}

hedge_status hedge_render_buffers_create(hedge_mesh* mesh, const hedge_render_buffers_options* options,
                                         hedge_render_buffers** out_render) {
  return guard([&] {
    auto mesh_object = find_mesh(mesh);
    need(out_render, "out_render");
    const RenderOptions render_options =
        to_render_options(options != nullptr ? *options : default_render_options());
    auto object = std::make_shared<RenderObject>();
    object->mesh = mesh_object.shared();
    object->sync = std::make_unique<RenderBuffers>(mesh_object->mesh, render_options);
    *out_render = register_render(std::move(object), mesh);
  });
}

hedge_status hedge_render_buffers_destroy(hedge_render_buffers* render) {
  return guard([&] {
    // Destroying the render object detaches it from its mesh's change log: the mesh is used.
    const RenderUse use = find_render(render);
    unregister_render(render).reset();
  });
}

hedge_status hedge_render_buffers_sync(hedge_render_buffers* render, hedge_sync_result* out_result) {
  return guard([&] {
    auto object = find_render(render);
    fill_result(object->sync->sync(), out_result);
  });
}

hedge_status hedge_render_buffers_begin(hedge_render_buffers* render) {
  return guard([&] { find_render(render)->sync->begin(); });
}

hedge_status hedge_render_buffers_commit(hedge_render_buffers* render, hedge_sync_result* out_result) {
  return guard([&] {
    auto object = find_render(render);
    if (!object->sync->in_transaction())
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "commit without an open transaction (no matching hedge_render_buffers_begin)");
    fill_result(object->sync->commit(), out_result);
  });
}

hedge_status hedge_render_buffers_rebuild(hedge_render_buffers* render, hedge_sync_result* out_result) {
  return guard([&] {
    auto object = find_render(render);
    fill_result(object->sync->rebuild(), out_result);
  });
}

hedge_status hedge_render_buffers_last_result(const hedge_render_buffers* render,
                                              hedge_sync_result* out_result) {
  return guard([&] {
    auto object = find_render(render);
    need(out_result, "out_result");
    fill_result(object->sync->last_result(), out_result);
  });
}

hedge_status hedge_render_buffers_dirty_vertex_ranges(const hedge_render_buffers* render, hedge_range* buffer,
                                                      uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    copy_ranges(object->sync->last_result().vertex_ranges, buffer, capacity, out_count);
  });
}

hedge_status hedge_render_buffers_dirty_index_ranges(const hedge_render_buffers* render, hedge_range* buffer,
                                                     uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    copy_ranges(object->sync->last_result().index_ranges, buffer, capacity, out_count);
  });
}

hedge_status hedge_render_buffers_compact(hedge_render_buffers* render, uint32_t* vertex_map,
                                          uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                          uint32_t* triangle_map, uint32_t triangle_capacity,
                                          uint32_t* out_triangle_count) {
  return guard([&] {
    auto object = find_render(render);
    RenderBuffers& sync = *object->sync;
    // compact() syncs first; do it here so that the map sizes are known before compacting.
    if (!sync.in_transaction()) sync.sync();
    // The maps have one entry per slot, free ones included.
    const std::size_t vertex_slots = sync.vertex_slots();
    const std::size_t triangle_slots = sync.triangle_slots();
    if (out_vertex_count != nullptr) *out_vertex_count = to_u32(vertex_slots, "vertex count");
    if (out_triangle_count != nullptr) *out_triangle_count = to_u32(triangle_slots, "triangle count");
    if (vertex_map != nullptr) check_capacity(vertex_slots, vertex_map, vertex_capacity, "vertex_map");
    if (triangle_map != nullptr)
      check_capacity(triangle_slots, triangle_map, triangle_capacity, "triangle_map");
    const RenderRemap remap = sync.compact();
    if (vertex_map != nullptr) std::copy(remap.vertices.begin(), remap.vertices.end(), vertex_map);
    if (triangle_map != nullptr) std::copy(remap.triangles.begin(), remap.triangles.end(), triangle_map);
  });
}

hedge_status hedge_render_buffers_counts(const hedge_render_buffers* render,
                                         hedge_buffer_counts* out_counts) {
  return guard([&] {
    auto object = find_render(render);
    const RenderBuffers& sync = *object->sync;
    hedge_buffer_counts& c = need(out_counts, "out_counts");
    c.vertex_slots = to_u32(sync.vertex_slots(), "vertex slots");
    c.index_count = to_u32(sync.index_count(), "index count");
    c.vertices = to_u32(sync.n_vertices(), "render vertices");
    c.triangles = to_u32(sync.n_triangles(), "triangles");
    c.seam_splits = to_u32(sync.seam_splits(), "seam splits");
    c.free_triangle_slots = to_u32(sync.free_triangle_slots(), "free triangle slots");
    c.buffer_bytes = sync.buffer_bytes();
    c.vertex_capacity = to_u32(sync.vertex_capacity(), "vertex capacity");
    c.index_capacity = to_u32(sync.index_capacity(), "index capacity");
  });
}

hedge_status hedge_render_buffers_layout(const hedge_render_buffers* render,
                                         hedge_vertex_layout* out_layout) {
  return guard([&] {
    auto object = find_render(render);
    const VertexLayout& l = object->sync->layout();
    hedge_vertex_layout& out = need(out_layout, "out_layout");
    out.stride = l.stride;
    out.position = l.position;
    out.normal = l.normal;
    out.texcoord = l.texcoord;
    out.color = l.color;
    out.interleaved = l.interleaved ? 1 : 0;
    out.tangent = l.tangent;
    out.texcoord1 = l.texcoord1;
  });
}

hedge_status hedge_render_buffers_vertex_data(const hedge_render_buffers* render, int32_t stream,
                                              const float** out_data, uint64_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    const std::span<const float> data = stream_of(*object->sync, stream);
    need(out_data, "out_data");
    need(out_count, "out_count");
    *out_data = data.empty() ? nullptr : data.data();
    *out_count = data.size();
  });
}

hedge_status hedge_render_buffers_copy_vertex_data(const hedge_render_buffers* render, int32_t stream,
                                                   float* buffer, uint64_t capacity, uint64_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    copy_out(stream_of(*object->sync, stream), buffer, capacity, out_count);
  });
}

hedge_status hedge_render_buffers_index_data(const hedge_render_buffers* render, const uint32_t** out_data,
                                             uint64_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    const std::span<const std::uint32_t> data = object->sync->indices();
    need(out_data, "out_data");
    need(out_count, "out_count");
    *out_data = data.empty() ? nullptr : data.data();
    *out_count = data.size();
  });
}

hedge_status hedge_render_buffers_copy_index_data(const hedge_render_buffers* render, uint32_t* buffer,
                                                  uint64_t capacity, uint64_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    copy_out(object->sync->indices(), buffer, capacity, out_count);
  });
}

hedge_status hedge_render_buffers_vertex_source(const hedge_render_buffers* render, uint32_t* buffer,
                                                uint32_t capacity, uint32_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    const std::span<const Vertex> source = object->sync->render_vertex_source();
    need(out_count, "out_count") = to_u32(source.size(), "render vertex count");
    check_capacity(source.size(), buffer, capacity);
    for (std::size_t i = 0; i < source.size(); ++i) buffer[i] = source[i].idx();
  });
}

hedge_status hedge_render_buffers_corner_vertex(const hedge_render_buffers* render, uint32_t halfedge,
                                                uint32_t* out_render_vertex) {
  return guard([&] {
    auto object = find_render(render);
    const Halfedge h = live_halfedge(object->mesh->mesh, halfedge);
    need(out_render_vertex, "out_render_vertex") = object->sync->render_vertex(h);
  });
}

hedge_status hedge_render_buffers_face_triangles(const hedge_render_buffers* render, uint32_t face,
                                                 uint32_t* out_first, uint32_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    const Face f = live_face(object->mesh->mesh, face);
    need(out_first, "out_first");
    need(out_count, "out_count");
    const SlotRange r = object->sync->triangles(f);
    *out_first = r.first;
    *out_count = r.count;
  });
}

hedge_status hedge_render_buffers_triangle_face(const hedge_render_buffers* render, uint32_t triangle,
                                                uint32_t* out_face) {
  return guard([&] {
    auto object = find_render(render);
    const RenderBuffers& sync = *object->sync;
    check_range("triangle", triangle, sync.triangle_slots());
    need(out_face, "out_face");
    const Face f = sync.triangle_face(triangle);
    *out_face = f.is_valid() && !object->mesh->mesh.is_deleted(f) ? f.idx() : HEDGE_INVALID_INDEX;
  });
}

hedge_status hedge_engine_import_options_default(hedge_engine_import_options* out_options) {
  return guard([&] {
    need(out_options, "out_options") = {HEDGE_WELD_EXACT, HEDGE_POLICY_REPAIR, 1e-6, HEDGE_WINDING_CCW, 0};
  });
}

hedge_status hedge_mesh_from_engine_mesh(const float* positions, uint32_t vertex_count,
                                         const uint32_t* indices, uint32_t index_count, const float* normals,
                                         const float* texcoords, const float* colors,
                                         const hedge_engine_import_options* options,
                                         hedge_build_report* out_report, hedge_mesh** out_mesh) {
  return hedge_mesh_from_engine_mesh_with_submeshes(positions, vertex_count, indices, index_count, normals,
                                                    texcoords, colors, nullptr, options, out_report,
                                                    out_mesh);
}

hedge_status hedge_mesh_from_engine_mesh_with_submeshes(
    const float* positions, uint32_t vertex_count, const uint32_t* indices, uint32_t index_count,
    const float* normals, const float* texcoords, const float* colors, const int32_t* triangle_submeshes,
    const hedge_engine_import_options* options, hedge_build_report* out_report, hedge_mesh** out_mesh) {
  hedge_engine_streams streams{};
  streams.vertex_count = vertex_count;
  streams.index_count = index_count;
  streams.positions = positions;
  streams.indices = indices;
  streams.normals = normals;
  streams.texcoords = texcoords;
  streams.colors = colors;
  streams.triangle_submeshes = triangle_submeshes;
  return hedge_mesh_from_engine_streams(&streams, options, out_report, out_mesh);
}

hedge_status hedge_mesh_from_engine_streams(const hedge_engine_streams* streams,
                                            const hedge_engine_import_options* options,
                                            hedge_build_report* out_report, hedge_mesh** out_mesh) {
  return guard([&] {
    const hedge_engine_streams& s = need(streams, "streams");
    need(out_mesh, "out_mesh");
    need_array(s.positions, std::uint64_t(s.vertex_count) * 3, "positions");
    need_array(s.indices, s.index_count, "indices");
    const EngineImportOptions import = to_engine_import_options(options);

    const std::size_t n = s.vertex_count;
    std::vector<Vec3> p(n), nrm(s.normals != nullptr ? n : 0);
    std::vector<Vec2> uv(s.texcoords != nullptr ? n : 0), uv1(s.texcoords1 != nullptr ? n : 0);
    std::vector<Color> rgba(s.colors != nullptr ? n : 0);
    std::vector<Vec4> tan(s.tangents != nullptr ? n : 0);
    const float* f = s.positions;
    for (std::size_t i = 0; i < n; ++i) p[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
    for (std::size_t i = 0; i < nrm.size(); ++i)
      nrm[i] = {s.normals[3 * i], s.normals[3 * i + 1], s.normals[3 * i + 2]};
    for (std::size_t i = 0; i < uv.size(); ++i) uv[i] = {s.texcoords[2 * i], s.texcoords[2 * i + 1]};
    for (std::size_t i = 0; i < rgba.size(); ++i)
      rgba[i] = {s.colors[4 * i], s.colors[4 * i + 1], s.colors[4 * i + 2], s.colors[4 * i + 3]};
    for (std::size_t i = 0; i < tan.size(); ++i)
      tan[i] = {s.tangents[4 * i], s.tangents[4 * i + 1], s.tangents[4 * i + 2], s.tangents[4 * i + 3]};
    for (std::size_t i = 0; i < uv1.size(); ++i) uv1[i] = {s.texcoords1[2 * i], s.texcoords1[2 * i + 1]};
    EngineMeshView view;
    view.positions = p;
    view.indices = std::span<const std::uint32_t>(s.indices, s.index_count);
    view.normals = nrm;
    view.texcoords = uv;
    view.colors = rgba;
    view.tangents = tan;
    view.texcoords1 = uv1;
    if (s.triangle_submeshes != nullptr)
      view.submeshes = std::span<const std::int32_t>(s.triangle_submeshes, s.index_count / 3);

    BuildReport report;
    auto object = std::make_shared<MeshObject>();
    object->mesh = from_engine_mesh(view, import, out_report != nullptr ? &report : nullptr);
    if (out_report != nullptr) fill_report(report, out_report);
    *out_mesh = register_mesh(std::move(object));
  });
}

hedge_status hedge_mesh_vertex_source_indices(const hedge_mesh* mesh, int32_t* buffer, uint64_t capacity,
                                              uint64_t* out_count) {
  return guard([&] {
    const SurfaceMesh& m = find_mesh(mesh)->mesh;
    copy_sources(m.get_vertex_property<std::int32_t>(kVertexSource), buffer, capacity, out_count);
  });
}

hedge_status hedge_mesh_corner_source_indices(const hedge_mesh* mesh, int32_t* buffer, uint64_t capacity,
                                              uint64_t* out_count) {
  return guard([&] {
    const SurfaceMesh& m = find_mesh(mesh)->mesh;
    copy_sources(m.get_halfedge_property<std::int32_t>(kCornerSource), buffer, capacity, out_count);
  });
}

// ---- Submeshes ------------------------------------------------------------------------------------
hedge_status hedge_render_buffers_submesh_count(const hedge_render_buffers* render, uint32_t* out_count) {
  return guard([&] {
    auto object = find_render(render);
    need(out_count, "out_count") = to_u32(object->sync->submesh_count(), "submesh count");
  });
}

hedge_status hedge_render_buffers_submesh(const hedge_render_buffers* render, uint32_t submesh,
                                          hedge_submesh_range* out_range) {
  return guard([&] {
    auto object = find_render(render);
    check_range("submesh", submesh, object->sync->submesh_count());
    need(out_range, "out_range");
    const SubmeshRange r = object->sync->submesh(submesh);
    *out_range = {r.index_start,
                  r.index_count,
                  r.first_vertex,
                  r.vertex_count,
                  {r.min.x, r.min.y, r.min.z},
                  {r.max.x, r.max.y, r.max.z}};
  });
}

hedge_status hedge_face_submesh(const hedge_mesh* mesh, uint32_t face, int32_t* out_submesh) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Face f = live_face(object->mesh, face);
    auto prop = object->mesh.get_face_property<std::int32_t>(kSubmeshProperty);
    need(out_submesh, "out_submesh") = prop ? prop[f] : 0;
  });
}

hedge_status hedge_set_face_submesh(hedge_mesh* mesh, uint32_t face, int32_t submesh) {
  return guard([&] {
    auto object = find_mesh(mesh);
    SurfaceMesh& m = object->mesh;
    const Face f = live_face(m, face);
    if (submesh < 0 || submesh > kMaxSubmesh)
      fail(HEDGE_ERROR_INVALID_ARGUMENT,
           "submesh is " + std::to_string(submesh) + ", outside [0, " + std::to_string(kMaxSubmesh) + "]");
    auto prop = m.get_face_property<std::int32_t>(kSubmeshProperty);
    if (!prop) prop = m.add_face_property<std::int32_t>(kSubmeshProperty, 0);
    prop[f] = submesh;
    m.changes().mark(f, ChangeEvent::faces_changed);
    m.changes().notify();
  });
}

}  // extern "C"

// The C ABI: registry, errors, version, mesh creation, positions, files and validation. Adjacency
// queries are in queries.cpp, local operations in operations.cpp, render buffers in render.cpp.
#include <cstdio>
#include <cstring>
#include <mutex>
#include <shared_mutex>
#include <thread>
#include <type_traits>
#include <unordered_map>

#include "capi_internal.h"
#include "hedge/io/io.h"

namespace hedge::capi {

// ---------------------------------------------------------------------------------------------
// Registry
// ---------------------------------------------------------------------------------------------
namespace {

struct Registry {
  std::shared_mutex mutex;
  std::unordered_map<std::uintptr_t, std::shared_ptr<MeshObject>> meshes;
  std::unordered_map<std::uintptr_t, std::shared_ptr<RenderObject>> renders;
  std::unordered_map<std::uintptr_t, std::shared_ptr<const SolidFractureObject>> solid_fractures;
  std::uintptr_t last_id = 0;
};

// Never destroyed: a binding may release handles from a finalizer while the process exits, after
// static destructors have run. Objects still alive at exit are reachable from here.
Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

// Ids are multiples of 16 from 0x10010 on and never reused, so that NULL, small integers and a
// destroyed handle name nothing. Called under the exclusive lock.
std::uintptr_t new_id(Registry& r) {
  r.last_id += 16;
  return 0x10000 + r.last_id;
}

std::uintptr_t id_of(const void* handle) { return reinterpret_cast<std::uintptr_t>(handle); }

[[noreturn]] void bad_handle(const char* kind, const void* handle) {
  if (handle == nullptr) fail(HEDGE_ERROR_BAD_HANDLE, std::string(kind) + " handle is NULL");
  char text[32];
  std::snprintf(text, sizeof text, "%#llx", static_cast<unsigned long long>(id_of(handle)));
  fail(HEDGE_ERROR_BAD_HANDLE,
       std::string(kind) + " handle " + text + " is not a live " + kind + " (destroyed, or never created)");
}

}  // namespace

hedge_mesh* register_mesh(std::shared_ptr<MeshObject> mesh) {
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  const std::uintptr_t id = new_id(r);
  r.meshes.emplace(id, std::move(mesh));
  return reinterpret_cast<hedge_mesh*>(id);
}

hedge_render_buffers* register_render(std::shared_ptr<RenderObject> render, const hedge_mesh* mesh) {
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  // The mesh may have been destroyed by another thread since the caller looked it up.
  auto m = r.meshes.find(id_of(mesh));
  if (m == r.meshes.end() || m->second != render->mesh) bad_handle("mesh", mesh);
  const std::uintptr_t id = new_id(r);
  m->second->renders.reserve(m->second->renders.size() + 1);
  r.renders.emplace(id, std::move(render));
  m->second->renders.push_back(id);  // cannot throw: reserved
  return reinterpret_cast<hedge_render_buffers*>(id);
}

hedge_solid_fracture* register_solid_fracture(std::shared_ptr<const SolidFractureObject> result) {
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  const std::uintptr_t id = new_id(r);
  r.solid_fractures.emplace(id, std::move(result));
  return reinterpret_cast<hedge_solid_fracture*>(id);
}

namespace {
// The live object a handle names in `objects`. \throw BindingError (HEDGE_ERROR_BAD_HANDLE) if none.
template <typename T>
std::shared_ptr<T> lookup(const std::unordered_map<std::uintptr_t, std::shared_ptr<T>>& objects,
                          const void* handle, const char* kind) {
  Registry& r = registry();
  std::shared_ptr<T> found;
  {
    std::shared_lock lock(r.mutex);
    auto it = objects.find(id_of(handle));
    if (it != objects.end()) found = it->second;
  }
  if (!found) bad_handle(kind, handle);
  return found;
}
}  // namespace

MeshUse find_mesh(const hedge_mesh* handle) { return MeshUse(lookup(registry().meshes, handle, "mesh")); }

RenderUse find_render(const hedge_render_buffers* handle) {
  return RenderUse(lookup(registry().renders, handle, "render"));
}

std::shared_ptr<const SolidFractureObject> find_solid_fracture(const hedge_solid_fracture* handle) {
  return lookup(registry().solid_fractures, handle, "solid fracture");
}

std::pair<std::shared_ptr<MeshObject>, std::vector<std::shared_ptr<RenderObject>>> unregister_mesh(
    const hedge_mesh* handle) {
  Registry& r = registry();
  std::pair<std::shared_ptr<MeshObject>, std::vector<std::shared_ptr<RenderObject>>> out;
  std::unique_lock lock(r.mutex);
  auto it = r.meshes.find(id_of(handle));
  if (it == r.meshes.end()) {
    lock.unlock();
    bad_handle("mesh", handle);
  }
  out.second.reserve(it->second->renders.size());  // may throw: nothing changed yet
  for (std::uintptr_t id : it->second->renders) {
    auto rit = r.renders.find(id);
    if (rit == r.renders.end()) continue;
    out.second.push_back(std::move(rit->second));
    r.renders.erase(rit);
  }
  it->second->renders.clear();
  out.first = std::move(it->second);
  r.meshes.erase(it);
  return out;
}

std::shared_ptr<RenderObject> unregister_render(const hedge_render_buffers* handle) {
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  auto it = r.renders.find(id_of(handle));
  if (it == r.renders.end()) {
    lock.unlock();
    bad_handle("render", handle);
  }
  std::shared_ptr<RenderObject> out = std::move(it->second);
  r.renders.erase(it);
  auto& ids = out->mesh->renders;
  ids.erase(std::remove(ids.begin(), ids.end(), id_of(handle)), ids.end());
  return out;
}

std::shared_ptr<const SolidFractureObject> unregister_solid_fracture(const hedge_solid_fracture* handle) {
  Registry& r = registry();
  std::unique_lock lock(r.mutex);
  auto it = r.solid_fractures.find(id_of(handle));
  if (it == r.solid_fractures.end()) {
    lock.unlock();
    bad_handle("solid fracture", handle);
  }
  std::shared_ptr<const SolidFractureObject> out = std::move(it->second);
  r.solid_fractures.erase(it);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Errors and checks
// ---------------------------------------------------------------------------------------------
namespace {
thread_local std::string t_error;
thread_local const char* t_static_error = nullptr;  // used when copying the message ran out of memory
thread_local const char* t_refusal = "";            // static strings only
}  // namespace

void clear_error() noexcept {
  t_error.clear();
  t_static_error = nullptr;
  t_refusal = "";
}

void set_refusal(const char* refusal) noexcept { t_refusal = refusal != nullptr ? refusal : ""; }

void set_error(const binding::Failure& failure) noexcept {
  t_refusal = failure.refusal;
  try {
    t_error = failure.message;
    t_static_error = nullptr;
  } catch (...) {
    t_static_error = "out of memory (while recording an error message)";
  }
}

Vec3 need_point(float x, float y, float z, const char* what) {
  return binding::need_point(Vec3{x, y, z}, what);
}

bool need_bool(std::int32_t value, const char* name) {
  if (value != 0 && value != 1)
    fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string(name) + " is " + std::to_string(value) + ", not 0 or 1");
  return value == 1;
}

std::uint32_t to_u32(std::size_t n, const char* what) {
  if (n > 0xFFFFFFFFu)
    fail(HEDGE_ERROR_INTERNAL, std::string(what) + " is " + std::to_string(n) + ", beyond 32 bits");
  return static_cast<std::uint32_t>(n);
}

void check_capacity_impl(std::uint64_t needed, const void* buffer, std::uint64_t capacity, const char* name) {
  if (buffer == nullptr && capacity > 0)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         std::string(name) + " is NULL but its capacity is " + std::to_string(capacity));
  if (needed > capacity)
    fail(HEDGE_ERROR_BUFFER_TOO_SMALL, std::string(name) + " holds " + std::to_string(capacity) + ", " +
                                           std::to_string(needed) + " needed");
}

void copy_string(const std::string& text, char* buffer, std::uint32_t capacity, std::uint32_t* out_size) {
  need(out_size, "out_size");
  *out_size = to_u32(text.size() + 1, "the text size");
  check_capacity(text.size() + 1, buffer, capacity);
  std::memcpy(buffer, text.c_str(), text.size() + 1);
}

void fill_report(const BuildReport& r, hedge_build_report* out) {
  out->welded_vertices = to_u32(r.welded_vertices, "welded_vertices");
  out->degenerate_faces = to_u32(r.degenerate_faces, "degenerate_faces");
  out->repeated_corners = to_u32(r.repeated_corners, "repeated_corners");
  out->reoriented_faces = to_u32(r.reoriented_faces, "reoriented_faces");
  out->non_manifold_edges = to_u32(r.non_manifold_edges, "non_manifold_edges");
  out->non_manifold_vertices = to_u32(r.non_manifold_vertices, "non_manifold_vertices");
  out->duplicated_vertices = to_u32(r.duplicated_vertices, "duplicated_vertices");
  out->isolated_vertices = to_u32(r.isolated_vertices, "isolated_vertices");
  out->repairs = to_u32(r.repairs(), "repairs");
}

BuildOptions to_build_options(const hedge_build_options& o) {
  BuildOptions b;
  b.policy = to_policy(o.policy);
  b.weld = to_weld(o.weld);
  if (!std::isfinite(o.weld_epsilon) || o.weld_epsilon < 0)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         "weld_epsilon is " + std::to_string(o.weld_epsilon) + ", not a finite number >= 0");
  b.weld_epsilon = o.weld_epsilon;
  return b;
}

}  // namespace hedge::capi

using namespace hedge;
using namespace hedge::capi;

namespace {

hedge_build_options default_build_options() { return {HEDGE_POLICY_REPAIR, HEDGE_WELD_NONE, 1e-6}; }

}  // namespace

// ---------------------------------------------------------------------------------------------
// Errors and version
// ---------------------------------------------------------------------------------------------
extern "C" {

const char* hedge_last_error(void) { return t_static_error != nullptr ? t_static_error : t_error.c_str(); }

const char* hedge_last_refusal(void) { return t_refusal; }

hedge_refusal hedge_last_refusal_code(void) { return static_cast<hedge_refusal>(refusal_code(t_refusal)); }

const char* hedge_refusal_text(hedge_refusal code) { return refusal_text(static_cast<Refusal>(code)); }

const char* hedge_refusal_name(hedge_refusal code) {
  return binding::refusal_name(static_cast<Refusal>(code));
}

const char* hedge_status_string(hedge_status code) { return binding::status_name(code); }

hedge_status hedge_version(int32_t* out_major, int32_t* out_minor, int32_t* out_patch) {
  return guard([&] {
    need(out_major, "out_major");
    need(out_minor, "out_minor");
    need(out_patch, "out_patch");
    *out_major = HEDGE_VERSION_MAJOR;
    *out_minor = HEDGE_VERSION_MINOR;
    *out_patch = HEDGE_VERSION_PATCH;
  });
}

// ---------------------------------------------------------------------------------------------
// Creation and destruction
// ---------------------------------------------------------------------------------------------

hedge_status hedge_build_options_default(hedge_build_options* out_options) {
  return guard([&] { need(out_options, "out_options") = default_build_options(); });
}

hedge_status hedge_mesh_create(const float* positions, uint32_t vertex_count, const uint32_t* indices,
                               uint32_t index_count, const uint32_t* face_sizes, uint32_t face_count,
                               const hedge_build_options* options, hedge_build_report* out_report,
                               uint32_t* out_vertex_map, uint32_t* out_face_map, hedge_mesh** out_mesh) {
  return guard([&] {
    need(out_mesh, "out_mesh");
    need_array(positions, std::uint64_t(vertex_count) * 3, "positions");
    need_array(indices, index_count, "indices");
    need_array(face_sizes, face_count, "face_sizes");
    const BuildOptions build_options =
        to_build_options(options != nullptr ? *options : default_build_options());

    std::size_t input_faces = 0;
    if (face_sizes == nullptr) {
      if (index_count % 3 != 0)
        fail(HEDGE_ERROR_INVALID_ARGUMENT, "index_count " + std::to_string(index_count) +
                                               " is not a multiple of 3 (face_sizes is NULL: triangles)");
      input_faces = index_count / 3;
      if (face_count != 0 && face_count != input_faces)
        fail(HEDGE_ERROR_INVALID_ARGUMENT, "face_count " + std::to_string(face_count) + " does not match " +
                                               std::to_string(input_faces) + " triangles");
    } else {
      std::uint64_t corners = 0;
      for (std::uint32_t f = 0; f < face_count; ++f) corners += face_sizes[f];
      if (corners != index_count)
        fail(HEDGE_ERROR_INVALID_ARGUMENT, "face_sizes add up to " + std::to_string(corners) +
                                               " corners, but index_count is " + std::to_string(index_count));
      input_faces = face_count;
    }

    std::vector<Vec3> points(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i)
      points[i] = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
    BuildReport report;
    BuildReport* want =
        (out_report != nullptr || out_vertex_map != nullptr || out_face_map != nullptr) ? &report : nullptr;
    auto object = std::make_shared<MeshObject>();
    if (face_sizes == nullptr) {
      object->mesh =
          build_triangles(points, std::span<const std::uint32_t>(indices, index_count), build_options, want);
    } else {
      IndexedMesh input;
      input.positions = std::move(points);
      input.indices.assign(indices, indices + index_count);
      input.face_sizes.assign(face_sizes, face_sizes + face_count);
      object->mesh = build(input, build_options, want);
    }
    if (out_report != nullptr) fill_report(report, out_report);
    if (out_vertex_map != nullptr)
      for (std::size_t i = 0; i < vertex_count; ++i)
        out_vertex_map[i] = i < report.vertex_map.size() ? report.vertex_map[i] : HEDGE_INVALID_INDEX;
    if (out_face_map != nullptr)
      for (std::size_t i = 0; i < input_faces; ++i)
        out_face_map[i] = i < report.face_map.size() ? report.face_map[i] : HEDGE_INVALID_INDEX;
    *out_mesh = register_mesh(std::move(object));
  });
}

hedge_status hedge_mesh_destroy(hedge_mesh* mesh) {
  return guard([&] {
    // Held until the objects are gone: destroying render objects touches the mesh's change log.
    const MeshUse use = find_mesh(mesh);
    auto objects = unregister_mesh(mesh);
    // Render objects first (they detach from the mesh's change log), then the mesh, unless a call
    // on another thread still holds them.
    objects.second.clear();
    objects.first.reset();
  });
}

// ---------------------------------------------------------------------------------------------
// Counts and positions
// ---------------------------------------------------------------------------------------------

hedge_status hedge_mesh_counts(const hedge_mesh* mesh, hedge_counts* out_counts) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const SurfaceMesh& m = object->mesh;
    hedge_counts& c = need(out_counts, "out_counts");
    c.vertices = to_u32(m.n_vertices(), "vertex count");
    c.halfedges = to_u32(m.n_halfedges(), "half-edge count");
    c.edges = to_u32(m.n_edges(), "edge count");
    c.faces = to_u32(m.n_faces(), "face count");
    c.vertex_slots = to_u32(m.vertex_slots(), "vertex slot count");
    c.halfedge_slots = to_u32(m.halfedge_slots(), "half-edge slot count");
    c.edge_slots = to_u32(m.edge_slots(), "edge slot count");
    c.face_slots = to_u32(m.face_slots(), "face slot count");
  });
}

hedge_status hedge_vertex_position(const hedge_mesh* mesh, uint32_t vertex, float* out_xyz) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Vec3& p = object->mesh.position(live_vertex(object->mesh, vertex));
    need(out_xyz, "out_xyz");
    out_xyz[0] = p.x;
    out_xyz[1] = p.y;
    out_xyz[2] = p.z;
  });
}

hedge_status hedge_set_vertex_position(hedge_mesh* mesh, uint32_t vertex, float x, float y, float z) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const Vertex v = live_vertex(object->mesh, vertex);
    object->mesh.set_position(v, need_point(x, y, z, "set_vertex_position"));
  });
}

hedge_status hedge_mesh_copy_positions(const hedge_mesh* mesh, float* buffer, uint64_t capacity,
                                       uint64_t* out_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const SurfaceMesh& m = object->mesh;
    need(out_count, "out_count");
    const std::uint64_t needed = 3 * std::uint64_t(m.vertex_slots());
    *out_count = needed;
    check_capacity(needed, buffer, capacity);
    for (std::size_t i = 0; i < m.vertex_slots(); ++i) {
      const Vec3& p = m.position(Vertex(static_cast<Index>(i)));
      buffer[3 * i] = p.x;
      buffer[3 * i + 1] = p.y;
      buffer[3 * i + 2] = p.z;
    }
  });
}

// ---------------------------------------------------------------------------------------------
// Files
// ---------------------------------------------------------------------------------------------

namespace {

ReadOptions to_read_options(const hedge_read_options* options, bool external_default) {
  ReadOptions out;
  out.external_buffers = external_default;
  if (options == nullptr) return out;
  out.external_buffers = need_bool(options->external_buffers, "read_options.external_buffers");
  if (options->reserved != 0)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         "read_options.reserved is " + std::to_string(options->reserved) + ", not 0");
  out.max_memory = options->max_memory;
  return out;
}

// Builds what a reader gave, with the file's default build options unless the caller's.
void build_read(const IndexedMesh& in, FileFormat format, const hedge_build_options* options,
                hedge_build_report* out_report, hedge_mesh** out_mesh) {
  const BuildOptions build_options =
      options != nullptr ? to_build_options(*options) : default_build_options(format);
  BuildReport report;
  auto object = std::make_shared<MeshObject>();
  object->mesh = build_read(in, build_options, &report);
  if (out_report != nullptr) fill_report(report, out_report);
  *out_mesh = register_mesh(std::move(object));
}

}  // namespace

hedge_status hedge_read_options_default(hedge_read_options* out_options) {
  return guard([&] {
    need(out_options, "out_options");
    *out_options = hedge_read_options{1, 0, 0};
  });
}

hedge_status hedge_mesh_read(const char* path, const hedge_build_options* options,
                             hedge_build_report* out_report, hedge_mesh** out_mesh) {
  return hedge_mesh_read_with(path, options, nullptr, out_report, out_mesh);
}

hedge_status hedge_mesh_read_with(const char* path, const hedge_build_options* options,
                                  const hedge_read_options* read_options, hedge_build_report* out_report,
                                  hedge_mesh** out_mesh) {
  return guard([&] {
    need(path, "path");
    need(out_mesh, "out_mesh");
    const ReadOptions read = to_read_options(read_options, true);
    const FileFormat format = format_from_path(path);
    build_read(read_indexed_file(path, read), format, options, out_report, out_mesh);
  });
}

hedge_status hedge_mesh_read_memory(const void* bytes, uint64_t size, const char* name,
                                    const hedge_build_options* options,
                                    const hedge_read_options* read_options, hedge_build_report* out_report,
                                    hedge_mesh** out_mesh) {
  return guard([&] {
    if (size > 0) need(static_cast<const char*>(bytes), "bytes");
    need(name, "name");
    need(out_mesh, "out_mesh");
    if (size > std::numeric_limits<std::size_t>::max())
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "size " + std::to_string(size) + " does not fit in memory");
    const ReadOptions read = to_read_options(read_options, false);
    const FileFormat format = format_from_path(name);
    const std::string_view data(static_cast<const char*>(bytes), static_cast<std::size_t>(size));
    build_read(read_indexed(data, format, name, read), format, options, out_report, out_mesh);
  });
}

hedge_status hedge_mesh_write(const hedge_mesh* mesh, const char* path, int32_t binary, int32_t precision) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(path, "path");
    WriteOptions options;
    options.binary = need_bool(binary, "binary");
    if (precision < 0 || precision > 17)
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "precision is " + std::to_string(precision) + ", not in 0..17");
    if (precision > 0) options.precision = precision;
    write_mesh(object->mesh, path, options);
  });
}

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

hedge_status hedge_mesh_validate(hedge_mesh* mesh, uint32_t* out_problem_count) {
  return guard([&] {
    auto object = find_mesh(mesh);
    need(out_problem_count, "out_problem_count");
    object->problems = object->mesh.validate();
    *out_problem_count = to_u32(object->problems.size(), "problem count");
  });
}

hedge_status hedge_mesh_validation_problem(const hedge_mesh* mesh, uint32_t index, char* buffer,
                                           uint32_t capacity, uint32_t* out_size) {
  return guard([&] {
    auto object = find_mesh(mesh);
    if (index >= object->problems.size())
      fail(HEDGE_ERROR_INVALID_ARGUMENT, "problem " + std::to_string(index) +
                                             " does not exist (the last validation found " +
                                             std::to_string(object->problems.size()) + ")");
    copy_string(object->problems[index], buffer, capacity, out_size);
  });
}

hedge_status hedge_mesh_validation_report(const hedge_mesh* mesh, char* buffer, uint32_t capacity,
                                          uint32_t* out_size) {
  return guard([&] {
    auto object = find_mesh(mesh);
    std::string text;
    for (std::size_t i = 0; i < object->problems.size(); ++i) {
      if (i > 0) text += '\n';
      text += object->problems[i];
    }
    copy_string(text, buffer, capacity, out_size);
  });
}

}  // extern "C"

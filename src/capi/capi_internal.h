// Shared machinery of the C ABI: the registry of live objects, the error channel and the checks
// every entry point makes before touching the library. What every binding shares (handle checks,
// error kinds, refusals, the picking tree, the busy check) is the binding core's (src/binding/).
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "binding/edits.h"
#include "binding/errors.h"
#include "binding/handles.h"
#include "binding/mesh_state.h"
#include "binding/names.h"
#include "hedge/algorithms/locate.h"
#include "hedge/c_api.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/error.h"
#include "hedge/render/render_buffers.h"

namespace hedge::capi {

using binding::check_range;
using binding::fail;
using binding::live_edge;
using binding::live_element;
using binding::live_face;
using binding::live_halfedge;
using binding::live_vertex;
using binding::picking_tree;

//! What a hedge_mesh handle names: the mesh with its picking tree and busy check (MeshState), and
//! what the C ABI keeps beside them.
struct MeshObject : binding::MeshState {
  //! Problems found by the last hedge_mesh_validate().
  std::vector<std::string> problems;
  //! Ids of the render objects made for this mesh (guarded by the registry's lock).
  std::vector<std::uintptr_t> renders;
};

//! What a hedge_render_buffers handle names. It shares ownership of its mesh object, so a call that is
//! running on it keeps the mesh alive even if another thread destroys the mesh meanwhile.
struct RenderObject {
  std::shared_ptr<MeshObject> mesh;  // declared first: destroyed after `sync`
  std::unique_ptr<RenderBuffers> sync;
};

//! A call's use of a mesh object: while it lives, the mesh belongs to the calling thread. Taking a
//! mesh that another thread is using fails at once (HEDGE_ERROR_BUSY) rather than racing it.
using MeshUse = binding::MeshUse<MeshObject>;

//! A call's use of a render object, and so of its mesh.
class RenderUse {
 public:
  explicit RenderUse(std::shared_ptr<RenderObject> object)
      : mesh_(object->mesh), object_(std::move(object)) {}
  RenderObject* operator->() const { return object_.get(); }
  RenderObject& operator*() const { return *object_; }

 private:
  MeshUse mesh_;
  std::shared_ptr<RenderObject> object_;
};

//! What a hedge_solid_fracture handle names: a strike's result, as the C ABI gives it out. It
//! never changes after the strike, so any thread may read it.
struct SolidFractureObject {
  hedge_solid_fracture_summary summary{};
  std::vector<hedge_solid_piece> pieces;
  std::vector<hedge_solid_bond> bonds;
};

// ---- Registry: handles are ids (never addresses, never reused) mapped to live objects. ----
hedge_mesh* register_mesh(std::shared_ptr<MeshObject> mesh);
hedge_solid_fracture* register_solid_fracture(std::shared_ptr<const SolidFractureObject> result);
hedge_render_buffers* register_render(std::shared_ptr<RenderObject> render, const hedge_mesh* mesh);
//! The object a handle names, in use by the calling thread until the result is destroyed.
//! \throw BindingError: HEDGE_ERROR_BAD_HANDLE if it names none, HEDGE_ERROR_BUSY if another thread
//!   is using the mesh.
MeshUse find_mesh(const hedge_mesh* handle);
RenderUse find_render(const hedge_render_buffers* handle);
std::shared_ptr<const SolidFractureObject> find_solid_fracture(const hedge_solid_fracture* handle);
//! Removes a mesh and its render objects from the registry; returns them (destroyed by the caller,
//! outside the lock). \throw BindingError if the handle names no mesh.
std::pair<std::shared_ptr<MeshObject>, std::vector<std::shared_ptr<RenderObject>>> unregister_mesh(
    const hedge_mesh* handle);
std::shared_ptr<RenderObject> unregister_render(const hedge_render_buffers* handle);
std::shared_ptr<const SolidFractureObject> unregister_solid_fracture(const hedge_solid_fracture* handle);

// ---- Error channel. ----
void clear_error() noexcept;
//! Records a failure for hedge_last_error() and hedge_last_refusal().
void set_error(const binding::Failure& failure) noexcept;
//! Records a predicate's answer for hedge_last_refusal(): why the edit it checked would be refused
//! (a static string of core/refusal.h), or nullptr for "allowed". Not an error: the call succeeds.
void set_refusal(const char* refusal) noexcept;

//! Runs `body` (returning void) and converts every exception into a status code and a message
//! (binding/errors.h maps them).
template <typename Body>
hedge_status guard(Body&& body) noexcept {
  try {
    clear_error();
    body();
    return HEDGE_OK;
  } catch (...) {
    const binding::Failure failure = binding::current_failure();
    set_error(failure);
    return failure.status;
  }
}

// ---- Argument checks; each throws a BindingError. ----
template <typename T>
T& need(T* p, const char* name) {
  if (p == nullptr) fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string(name) + " is NULL");
  return *p;
}
//! An input array: may be NULL only when empty.
template <typename T>
void need_array(const T* p, std::uint64_t count, const char* name) {
  if (p == nullptr && count > 0)
    fail(HEDGE_ERROR_INVALID_ARGUMENT,
         std::string(name) + " is NULL but its count is " + std::to_string(count));
}
Vec3 need_point(float x, float y, float z, const char* what);
bool need_bool(std::int32_t value, const char* name);
std::uint32_t to_u32(std::size_t n, const char* what);

//! Caller buffers for old-to-new maps (each optional: NULL), as garbage collection and reordering
//! fill them.
struct MapBuffers {
  std::uint32_t* vertex;
  std::uint32_t vertex_capacity;
  std::uint32_t* halfedge;
  std::uint32_t halfedge_capacity;
  std::uint32_t* edge;
  std::uint32_t edge_capacity;
  std::uint32_t* face;
  std::uint32_t face_capacity;
};
//! \throw BindingError (HEDGE_ERROR_BUFFER_TOO_SMALL) unless every given buffer holds a map of m's slots.
void check_map_buffers(const SurfaceMesh& m, const MapBuffers& b);
//! Copies the maps into the given buffers.
void write_maps(const GarbageMaps& maps, const MapBuffers& b);

//! The caller's options, or, when the caller passed none, the defaults that fill_defaults writes.
template <typename Options, typename Fill>
Options options_or_defaults(const Options* options, Fill&& fill_defaults) {
  Options o{};
  if (options != nullptr)
    o = *options;
  else
    fill_defaults(&o);
  return o;
}

//! One query about one live element: checks the handles, then writes fn(mesh, element) to *out.
template <typename H, typename Out, typename Fn>
hedge_status element_query(const hedge_mesh* mesh, std::uint32_t index, Out* out, const char* out_name,
                           Fn&& fn) {
  return guard([&] {
    auto object = find_mesh(mesh);
    const H h = live_element<H>(object->mesh, index);
    need(out, out_name) = fn(object->mesh, h);
  });
}

//! Fails with HEDGE_ERROR_BUFFER_TOO_SMALL (or INVALID_ARGUMENT for a NULL buffer with a capacity)
//! unless `buffer` can hold `needed` entries.
void check_capacity_impl(std::uint64_t needed, const void* buffer, std::uint64_t capacity, const char* name);
template <typename T, typename Cap>
void check_capacity(std::uint64_t needed, const T* buffer, Cap capacity, const char* name = "buffer") {
  check_capacity_impl(needed, buffer, static_cast<std::uint64_t>(capacity), name);
}
//! Copies `data` into a caller buffer (see "Caller buffers" in c_api.h): sets *out_count to the size
//! needed and fails with HEDGE_ERROR_BUFFER_TOO_SMALL if it exceeds the capacity.
template <typename T, typename Count, typename Cap>
void copy_out(std::span<const T> data, T* buffer, Cap capacity, Count* out_count) {
  need(out_count, "out_count");
  if (data.size() > static_cast<std::uint64_t>(static_cast<Count>(-1)))
    fail(HEDGE_ERROR_INTERNAL,
         "the result has " + std::to_string(data.size()) + " entries, too many to count");
  *out_count = static_cast<Count>(data.size());
  check_capacity(data.size(), buffer, capacity);
  if (!data.empty()) std::copy(data.begin(), data.end(), buffer);
}
//! Copies a string with its NUL into a caller buffer; *out_size gets the bytes needed.
void copy_string(const std::string& text, char* buffer, std::uint32_t capacity, std::uint32_t* out_size);

//! Fills a C build report from the library's.
void fill_report(const BuildReport& report, hedge_build_report* out);
BuildOptions to_build_options(const hedge_build_options& options);
using binding::to_policy;
using binding::to_weld;
using binding::to_winding;

}  // namespace hedge::capi

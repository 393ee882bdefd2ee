// The WebAssembly binding's shared machinery: the error slot and guarded(), the conversions between
// JS values and the library's types, and the state a mesh object shares with its render objects.
// The binding sits on the binding core (src/binding/), as the C ABI does: handle checks, error
// kinds, refusals, the picking tree and the enum names are the core's.
//
// Errors. No exception crosses into JavaScript: every bound function runs its body in guarded(),
// which catches the C++ exception, records its status (the C ABI's hedge_status: the one list of
// error kinds), message and refusal in the error slot and returns a placeholder. The JS layer reads
// the slot's flag straight from wasm memory after each call and throws a HedgeError whose kind is
// the status's name (binding::kind_name). A JS exception thrown through wasm frames would skip
// their destructors and leave the stack pointer lowered, so the binding never does that.
//
// Objects. A Mesh holds its SurfaceMesh (and the picking tree) through a shared state, which each
// RenderBuffers shares too: disposing a Mesh before its RenderBuffers leaves the RenderBuffers working.
#pragma once

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "binding/errors.h"
#include "binding/mesh_state.h"
#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"

namespace hedge::wasm {

using emscripten::val;

// ---- Errors ------------------------------------------------------------------------------------

//! Read by the JS layer through HEAP32 at errorSlotAddress(): [pending, status].
struct ErrorSlot {
  std::int32_t pending = 0;
  std::int32_t status = HEDGE_OK;
};
extern ErrorSlot g_error;

//! Records the failure of the exception being handled in the error slot.
void record_failure() noexcept;
//! The message of the recorded error, clearing the slot (the refusal stays for take_refusal()).
std::string take_error_message();
//! The refusal of the last recorded error ("" if it was no refusal), clearing it.
std::string take_refusal();

//! Runs body(); on an exception records it in the error slot and returns a placeholder
//! (undefined for a val, a default value otherwise), which the JS layer discards.
template <typename Body>
auto guarded(Body&& body) -> decltype(body()) {
  using R = decltype(body());
  try {
    return body();
  } catch (...) {
    record_failure();
  }
  if constexpr (std::is_void_v<R>) {
    return;
  } else if constexpr (std::is_same_v<R, val>) {
    return val::undefined();
  } else {
    return R{};
  }
}

// ---- Conversions -------------------------------------------------------------------------------

//! An element index for JS: -1 for "none".
double js_index(Index i);

template <typename Handle>
val js_index_array(const std::vector<Handle>& handles) {
  val out = val::array();
  for (std::size_t i = 0; i < handles.size(); ++i) out.set(i, js_index(handles[i].idx()));
  return out;
}

val js_vec3(const Vec3& p);
val js_vec3d(const Vec3d& p);
//! A finite point from a JS [x, y, z] array. \throw InvalidInputError naming `what` otherwise.
Vec3 point_from_js(const val& p, const std::string& what);
//! A point from a JS [x, y, z] array, finite or not (an edit of the binding core checks it), or
//! none for undefined or null. \throw InvalidInputError naming `what` if it is no such array.
std::optional<Vec3> optional_vec3_from_js(const val& p, const std::string& what);

//! Copies a JS typed array (or array) of numbers into `out` (resized to `count` elements of T).
template <typename T>
void copy_from_js(const val& source, std::vector<T>& out, std::size_t count) {
  out.resize(count);
  if (count == 0) return;
  val view{emscripten::typed_memory_view(count, out.data())};
  view.call<void>("set", source);
}

//! The length of a JS array (0 for undefined or null). \throw InvalidInputError if it has none.
std::uint32_t js_length(const val& array, const char* what);

//! Copies of native arrays as JS typed arrays.
val js_doubles(const double* data, std::size_t n);
val js_floats(const float* data, std::size_t n);
val js_uints(const std::uint32_t* data, std::size_t n);

// ---- The shared state of a mesh ----------------------------------------------------------------

//! The binding core's mesh state (the mesh and its picking tree) and the report of its build.
struct MeshState : binding::MeshState {
  BuildReport report;
};

}  // namespace hedge::wasm

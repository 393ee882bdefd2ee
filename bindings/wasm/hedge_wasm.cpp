// The WebAssembly binding of hedge (embind). bindings/wasm/hedge.js wraps it into the public JS API;
// these files are its native half and are not meant to be called directly:
//   wasm_support.*   the error slot, guarded(), conversions, the shared state of a mesh
//   wasm_mesh.*      NativeMesh: construction, queries, picking
//   wasm_edits.cpp   NativeMesh: local edits and whole-mesh algorithms
//   wasm_fracture.cpp NativeMesh: fracture
//   wasm_fracture_solid.cpp NativeMesh: fractureSolid, solidFractureCheck
//   wasm_render.cpp  NativeRenderBuffers
//   wasm_engine.cpp  meshFromEngineStreams (engine arrays with their attributes and submeshes)
//   hedge_wasm.cpp   module-level functions and NativeMesh's registration
// The binding sits on the binding core (src/binding/), as the C ABI does.
#include <malloc.h>

#include <cstdint>
#include <string>

#include "binding/errors.h"
#include "wasm_mesh.h"

namespace hedge::wasm {
namespace {

std::uintptr_t error_slot_address() { return reinterpret_cast<std::uintptr_t>(&g_error); }
std::uintptr_t pick_scratch_address() { return reinterpret_cast<std::uintptr_t>(&g_pick[0]); }

//! The JS API's name of a status (HedgeError.kind): binding::kind_name.
std::string error_kind(std::int32_t status) { return binding::kind_name(status); }

//! Bytes the allocator has handed out and not got back: what a leak would make grow.
double heap_bytes_in_use() {
  const struct mallinfo info = mallinfo();
  return double(info.uordblks);
}

// The project version (CMakeLists.txt), which the npm package shares (package.json).
std::string version() { return HEDGE_VERSION_STRING; }

}  // namespace
}  // namespace hedge::wasm

EMSCRIPTEN_BINDINGS(hedge) {
  using namespace emscripten;
  using namespace hedge::wasm;
  function("errorSlotAddress", &error_slot_address);
  function("takeErrorMessage", &take_error_message);
  function("takeRefusal", &take_refusal);
  function("errorKind", &error_kind);
  function("pickScratchAddress", &pick_scratch_address);
  function("heapBytesInUse", &heap_bytes_in_use);
  function("version", &version);

  class_<WasmMesh>("NativeMesh")
      .constructor<>()
      .class_function("fromBuffers", &WasmMesh::from_buffers)
      .class_function("fromFile", &WasmMesh::from_file)
      .function("clone", &WasmMesh::clone)
      .function("buildReport", &WasmMesh::build_report)
      .function("counts", &WasmMesh::counts)
      .function("validate", &WasmMesh::validate)
      .function("isTriangleMesh", &WasmMesh::is_triangle_mesh)
      .function("positionsView", &WasmMesh::positions_view)
      .function("position", &WasmMesh::position)
      .function("setPosition", &WasmMesh::set_position)
      .function("halfedge", &WasmMesh::halfedge)
      .function("vertex", &WasmMesh::vertex)
      .function("edge", &WasmMesh::edge)
      .function("face", &WasmMesh::face)
      .function("oneRing", &WasmMesh::one_ring)
      .function("pick", &WasmMesh::pick)
      .function("pickMany", &WasmMesh::pick_many)
      .function("refusal", &WasmMesh::refusal)
      .function("splitEdge", &WasmMesh::split_edge)
      .function("flip", &WasmMesh::flip)
      .function("collapse", &WasmMesh::collapse)
      .function("splitFace", &WasmMesh::split_face)
      .function("cutFace", &WasmMesh::cut_face)
      .function("fillHole", &WasmMesh::fill_hole)
      .function("garbageCollection", &WasmMesh::garbage_collection)
      .function("subdivide", &WasmMesh::subdivide)
      .function("smooth", &WasmMesh::smooth)
      .function("decimate", &WasmMesh::decimate)
      .function("computeCornerNormals", &WasmMesh::compute_corner_normals)
      .function("fracture", &WasmMesh::fracture)
      .function("fractureSolid", &WasmMesh::fracture_solid)
      .function("solidFractureCheck", &WasmMesh::solid_fracture_check)
      .function("toArrays", &WasmMesh::to_arrays)
      .function("toFile", &WasmMesh::to_file)
      .function("memoryBytes", &WasmMesh::memory_bytes);
}

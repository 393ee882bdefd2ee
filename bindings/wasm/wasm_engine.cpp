// Engine meshes in the JS API: Hedge.fromEngineStreams (an engine's per-vertex arrays with their
// normals, texcoords, colours and one submesh per triangle, as a three.js BufferGeometry holds
// them), the counterpart of the C ABI's hedge_mesh_from_engine_streams. Both build through the
// library's from_engine_mesh(), which checks every stream (sizes, finite values, indices in range,
// submesh ids) and names the stream and entry of a bad one.
#include <cstdint>
#include <string>
#include <vector>

#include "binding/names.h"
#include "hedge/error.h"
#include "hedge/render/engine_mesh.h"
#include "wasm_mesh.h"

namespace hedge::wasm {
namespace {

//! Copies an optional per-vertex stream of `width` floats a vertex into `out` (T: `width` floats).
//! Absent (undefined or null): out stays empty. \throw InvalidInputError if its length is not
//! width floats per vertex.
template <typename T>
void stream_from_js(const val& source, const char* name, std::uint32_t width, std::size_t vertices,
                    std::vector<T>& out) {
  static_assert(sizeof(T) % sizeof(float) == 0);
  const std::uint32_t n = js_length(source, name);
  if (source.isUndefined() || source.isNull()) return;
  if (n != vertices * width)
    throw InvalidInputError(std::string(name) + ": " + std::to_string(n) + " floats is not " +
                            std::to_string(width) + " per vertex for " + std::to_string(vertices) +
                            " vertices");
  out.resize(vertices);
  if (n == 0) return;
  val view{emscripten::typed_memory_view(n, reinterpret_cast<float*>(out.data()))};
  view.call<void>("set", source);
}

WasmMesh from_engine_streams(val positions, val indices, val normals, val texcoords, val colors,
                             val submeshes, int policy, int weld) {
  return guarded([&] {
    const std::uint32_t n_floats = js_length(positions, "positions");
    if (n_floats % 3 != 0)
      throw InvalidInputError("positions: " + std::to_string(n_floats) + " floats is not 3 per vertex");
    const std::size_t n = n_floats / 3;
    std::vector<Vec3> p;
    std::vector<Vec3> nrm;
    std::vector<Vec2> uv;
    std::vector<Color> rgba;
    stream_from_js(positions, "positions", 3, n, p);
    stream_from_js(normals, "normals", 3, n, nrm);
    stream_from_js(texcoords, "texcoords", 2, n, uv);
    stream_from_js(colors, "colors", 4, n, rgba);
    std::vector<std::uint32_t> idx;
    copy_from_js(indices, idx, js_length(indices, "indices"));
    if (idx.size() % 3 != 0)
      throw InvalidInputError("indices: " + std::to_string(idx.size()) + " entries is not 3 per triangle");
    std::vector<std::int32_t> sub;
    if (!submeshes.isUndefined() && !submeshes.isNull()) {
      const std::uint32_t count = js_length(submeshes, "submeshes");
      if (count != idx.size() / 3)
        throw InvalidInputError("submeshes: " + std::to_string(count) + " ids is not one per triangle for " +
                                std::to_string(idx.size() / 3) + " triangles");
      copy_from_js(submeshes, sub, count);
    }
    EngineMeshView view;
    view.positions = p;
    view.indices = idx;
    view.normals = nrm;
    view.texcoords = uv;
    view.colors = rgba;
    view.submeshes = sub;
    EngineImportOptions options;
    options.policy = binding::to_policy(policy);
    options.weld = binding::to_weld(weld);
    auto state = std::make_shared<MeshState>();
    state->mesh = from_engine_mesh(view, options, &state->report);
    return WasmMesh(std::move(state));
  });
}

}  // namespace
}  // namespace hedge::wasm

EMSCRIPTEN_BINDINGS(hedge_engine) {
  emscripten::function("meshFromEngineStreams", &hedge::wasm::from_engine_streams);
}

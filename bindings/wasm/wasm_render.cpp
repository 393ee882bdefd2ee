// NativeRenderBuffers, the native half of the JS API's RenderBuffers (hedge.js): a RenderBuffers of a mesh,
// sharing the mesh's state (wasm_support.h).
#include <algorithm>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "binding/handles.h"
#include "binding/names.h"
#include "hedge/algorithms/locate.h"
#include "hedge/error.h"
#include "hedge/render/render_buffers.h"
#include "wasm_mesh.h"

namespace hedge::wasm {

namespace {

using binding::live_face;

val ranges_to_js(const std::vector<SlotRange>& ranges) {
  val out = val::global("Uint32Array").new_(double(ranges.size() * 2));
  if (!ranges.empty()) {
    static_assert(sizeof(SlotRange) == 8);
    out.call<void>("set", val(emscripten::typed_memory_view(
                              ranges.size() * 2, reinterpret_cast<const std::uint32_t*>(ranges.data()))));
  }
  return out;
}

val sync_result_to_js(const SyncResult& r) {
  val out = val::object();
  out.set("vertexRanges", ranges_to_js(r.vertex_ranges));
  out.set("indexRanges", ranges_to_js(r.index_ranges));
  out.set("vertexBytes", double(r.vertex_bytes));
  out.set("indexBytes", double(r.index_bytes));
  out.set("facesSynced", double(r.faces_synced));
  out.set("verticesSynced", double(r.vertices_synced));
  out.set("resized", r.resized);
  out.set("full", r.full);
  return out;
}

class WasmRenderBuffers {
 public:
  WasmRenderBuffers() = default;

  static WasmRenderBuffers create(const WasmMesh& mesh, const std::string& normals, bool interleaved,
                                  bool texcoords, bool colors) {
    return guarded([&] {
      WasmRenderBuffers r;
      r.s_ = mesh.state();
      RenderOptions options;
      options.normals = binding::parse_normal_source(normals);
      options.interleaved = interleaved;
      options.texcoords = texcoords;
      options.colors = colors;
      r.sync_ = std::make_shared<RenderBuffers>(r.s_->mesh, options);
      return r;
    });
  }

  val layout() const {
    return guarded([&] {
      const VertexLayout& l = sync().layout();
      val out = val::object();
      out.set("stride", double(l.stride));
      out.set("position", double(l.position));
      out.set("normal", double(l.normal));
      out.set("texcoord", double(l.texcoord));
      out.set("color", double(l.color));
      out.set("interleaved", l.interleaved);
      return out;
    });
  }

  val sizes() const {
    return guarded([&] {
      const RenderBuffers& r = sync();
      val out = val::object();
      out.set("vertexSlots", double(r.vertex_slots()));
      out.set("triangleSlots", double(r.triangle_slots()));
      out.set("indexCount", double(r.index_count()));
      out.set("vertices", double(r.n_vertices()));
      out.set("triangles", double(r.n_triangles()));
      out.set("vertexCapacity", double(r.vertex_capacity()));
      out.set("indexCapacity", double(r.index_capacity()));
      out.set("freeTriangleSlots", double(r.free_triangle_slots()));
      out.set("bufferBytes", double(r.buffer_bytes()));
      return out;
    });
  }

  //! Views into wasm memory (no copy). stream: 0 vertices (interleaved, or positions), 1 normals,
  //! 2 texcoords, 3 colours.
  val stream_view(int stream) const {
    return guarded([&] {
      const RenderBuffers& r = sync();
      std::span<const float> s;
      switch (stream) {
        case 0:
          s = r.vertices();
          break;
        case 1:
          s = r.normals();
          break;
        case 2:
          s = r.texcoords();
          break;
        case 3:
          s = r.colors();
          break;
        default:
          throw InvalidInputError("unknown stream " + std::to_string(stream));
      }
      return val(emscripten::typed_memory_view(s.size(), s.data()));
    });
  }

  val indices_view() const {
    return guarded([&] {
      const auto s = sync().indices();
      return val(emscripten::typed_memory_view(s.size(), s.data()));
    });
  }

  //! Render vertex -> mesh vertex (0xFFFFFFFF for a free slot), a view.
  val vertex_source_view() const {
    return guarded([&] {
      const auto s = sync().render_vertex_source();
      static_assert(sizeof(Vertex) == sizeof(std::uint32_t));
      return val(emscripten::typed_memory_view(s.size(), reinterpret_cast<const std::uint32_t*>(s.data())));
    });
  }

  //! [first triangle slot, count] of face f.
  val face_triangles(std::uint32_t f) const {
    return guarded([&] {
      const SlotRange range = sync().triangles(live_face(s_->mesh, f));
      val out = val::array();
      out.set(0, double(range.first));
      out.set(1, double(range.count));
      return out;
    });
  }

  //! The first face along a ray, through the mesh's picking tree (binding::picking_tree, as
  //! NativeMesh.pick), and its triangle slots as of the last sync: returns the face or -1 and
  //! writes [face, t, px, py, pz, first slot, slot count] into g_pick (count 0 for a face the last
  //! sync has not seen). One call per ray and no JS object: what a raycast per pointer move needs.
  double pick_triangles(double ox, double oy, double oz, double dx, double dy, double dz) {
    return guarded([&]() -> double {
      const RenderBuffers& r = sync();
      const std::optional<RayHit> hit = binding::picking_tree(*s_).first_hit(
          Vec3{float(ox), float(oy), float(oz)}, Vec3{float(dx), float(dy), float(dz)});
      if (!hit) return -1.0;
      const SlotRange slots = r.triangles(hit->face);
      const double values[7] = {double(hit->face.idx()), hit->t,
                                double(hit->point.x),    double(hit->point.y),
                                double(hit->point.z),    double(slots.first),
                                double(slots.count)};
      std::copy(values, values + 7, g_pick);
      return values[0];
    });
  }

  //! Each submesh's part of the buffers as of the last sync (RenderBuffers::submesh), in submesh
  //! order: [{indexStart, indexCount, firstVertex, vertexCount, empty}] (index ranges include spare
  //! room; empty: no live triangle since the last full build, or only ones at the origin).
  val submeshes() const {
    return guarded([&] {
      const RenderBuffers& r = sync();
      val out = val::array();
      for (std::size_t i = 0; i < r.submesh_count(); ++i) {
        const SubmeshRange range = r.submesh(i);
        val s = val::object();
        s.set("indexStart", double(range.index_start));
        s.set("indexCount", double(range.index_count));
        s.set("firstVertex", double(range.first_vertex));
        s.set("vertexCount", double(range.vertex_count));
        // No live triangle since the last full build: the box of its triangles stayed empty.
        s.set("empty", range.min == Vec3{0, 0, 0} && range.max == Vec3{0, 0, 0});
        out.set(i, s);
      }
      return out;
    });
  }

  val do_sync() {
    return guarded([&] { return sync_result_to_js(sync().sync()); });
  }
  val rebuild() {
    return guarded([&] { return sync_result_to_js(sync().rebuild()); });
  }
  void compact() {
    guarded([&] { sync().compact(); });
  }
  void begin() {
    guarded([&] { sync().begin(); });
  }
  val commit() {
    return guarded([&] { return sync_result_to_js(sync().commit()); });
  }

 private:
  RenderBuffers& sync() const {
    if (!sync_) throw InvalidInputError("this render object was not created");
    return *sync_;
  }
  // The state first: members are destroyed in reverse order, so the RenderBuffers detaches from the
  // mesh's change log before the mesh can go.
  std::shared_ptr<MeshState> s_;
  std::shared_ptr<RenderBuffers> sync_;
};

}  // namespace

}  // namespace hedge::wasm

EMSCRIPTEN_BINDINGS(hedge_render_buffers) {
  using namespace emscripten;
  using hedge::wasm::WasmRenderBuffers;
  class_<WasmRenderBuffers>("NativeRenderBuffers")
      .class_function("create", &WasmRenderBuffers::create)
      .function("layout", &WasmRenderBuffers::layout)
      .function("sizes", &WasmRenderBuffers::sizes)
      .function("streamView", &WasmRenderBuffers::stream_view)
      .function("indicesView", &WasmRenderBuffers::indices_view)
      .function("vertexSourceView", &WasmRenderBuffers::vertex_source_view)
      .function("faceTriangles", &WasmRenderBuffers::face_triangles)
      .function("submeshes", &WasmRenderBuffers::submeshes)
      .function("pickTriangles", &WasmRenderBuffers::pick_triangles)
      .function("sync", &WasmRenderBuffers::do_sync)
      .function("rebuild", &WasmRenderBuffers::rebuild)
      .function("compact", &WasmRenderBuffers::compact)
      .function("begin", &WasmRenderBuffers::begin)
      .function("commit", &WasmRenderBuffers::commit);
}

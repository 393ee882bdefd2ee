// NativeMesh: construction, queries and picking (the JS API's Mesh, see wasm_mesh.h).
#include "wasm_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>

#include "binding/handles.h"
#include "binding/names.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"

namespace hedge::wasm {

using binding::element_name;
using binding::live_edge;
using binding::live_face;
using binding::live_halfedge;
using binding::live_vertex;

double g_pick[16];

namespace {

double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + ab * t));
}

val report_to_js(const BuildReport& r) {
  val out = val::object();
  out.set("weldedVertices", double(r.welded_vertices));
  out.set("degenerateFaces", double(r.degenerate_faces));
  out.set("repeatedCorners", double(r.repeated_corners));
  out.set("reorientedFaces", double(r.reoriented_faces));
  out.set("nonManifoldEdges", double(r.non_manifold_edges));
  out.set("nonManifoldVertices", double(r.non_manifold_vertices));
  out.set("duplicatedVertices", double(r.duplicated_vertices));
  out.set("isolatedVertices", double(r.isolated_vertices));
  out.set("repairs", double(r.repairs()));
  val warnings = val::array();
  for (std::size_t i = 0; i < r.warnings.size(); ++i) warnings.set(i, r.warnings[i]);
  out.set("warnings", warnings);
  return out;
}

//! {halfedges, vertices (their targets), edges, faces} of a list of half-edges; the faces are those
//! of the twins (across) or of the half-edges themselves, -1 for none.
val halfedge_lists(const SurfaceMesh& m, const std::vector<Halfedge>& hs, bool faces_across) {
  std::vector<Vertex> vs;
  std::vector<Edge> es;
  std::vector<Face> fs;
  for (const Halfedge h : hs) {
    vs.push_back(m.to_vertex(h));
    es.push_back(SurfaceMesh::edge(h));
    fs.push_back(m.face(faces_across ? SurfaceMesh::twin(h) : h));
  }
  val out = val::object();
  out.set("halfedges", js_index_array(hs));
  out.set("vertices", js_index_array(vs));
  out.set("edges", js_index_array(es));
  out.set("faces", js_index_array(fs));
  return out;
}

}  // namespace

WasmMesh WasmMesh::from_buffers(val positions, val indices, val face_sizes, int policy, int weld) {
  return guarded([&] {
    IndexedMesh in;
    const std::uint32_t n_floats = js_length(positions, "positions");
    if (n_floats % 3 != 0)
      throw InvalidInputError("positions: " + std::to_string(n_floats) + " floats is not 3 per vertex");
    in.positions.resize(n_floats / 3);
    if (n_floats > 0) {
      val view{emscripten::typed_memory_view(n_floats, &in.positions[0].x)};
      view.call<void>("set", positions);
    }
    copy_from_js(indices, in.indices, js_length(indices, "indices"));
    copy_from_js(face_sizes, in.face_sizes, js_length(face_sizes, "faceSizes"));
    BuildOptions options;
    options.policy = binding::to_policy(policy);
    options.weld = binding::to_weld(weld);
    auto state = std::make_shared<MeshState>();
    state->mesh = build(in, options, &state->report);
    return WasmMesh(std::move(state));
  });
}

WasmMesh WasmMesh::from_file(const std::string& bytes, const std::string& name) {
  return guarded([&] {
    const FileFormat format = format_from_path(name);
    const IndexedMesh in = read_indexed(std::string_view(bytes), format, name);
    auto state = std::make_shared<MeshState>();
    state->mesh = build(in, default_build_options(format), &state->report);
    for (const ReadWarning& w : in.warnings) state->report.warnings.push_back(w.text());
    return WasmMesh(std::move(state));
  });
}

WasmMesh WasmMesh::clone() const {
  return guarded([&] {
    auto state = std::make_shared<MeshState>();
    state->mesh = s_->mesh;
    return WasmMesh(std::move(state));
  });
}

val WasmMesh::build_report() const {
  return guarded([&] { return report_to_js(s_->report); });
}

val WasmMesh::counts() const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    val out = val::object();
    out.set("vertices", double(m.n_vertices()));
    out.set("edges", double(m.n_edges()));
    out.set("halfedges", double(m.n_halfedges()));
    out.set("faces", double(m.n_faces()));
    out.set("vertexSlots", double(m.vertex_slots()));
    out.set("halfedgeSlots", double(m.halfedge_slots()));
    out.set("edgeSlots", double(m.edge_slots()));
    out.set("faceSlots", double(m.face_slots()));
    return out;
  });
}

val WasmMesh::validate() const {
  return guarded([&] {
    const std::vector<std::string> messages = s_->mesh.validate();
    val out = val::array();
    for (std::size_t i = 0; i < messages.size(); ++i) out.set(i, messages[i]);
    return out;
  });
}

bool WasmMesh::is_triangle_mesh() const {
  return guarded([&] { return s_->mesh.is_triangle_mesh(); });
}

val WasmMesh::positions_view() const {
  return guarded([&] {
    const auto& p = s_->mesh.positions().vector();
    return val(emscripten::typed_memory_view(p.size() * 3, p.empty() ? nullptr : &p[0].x));
  });
}

val WasmMesh::position(std::uint32_t v) const {
  return guarded([&] { return js_vec3(s_->mesh.position(live_vertex(s_->mesh, v))); });
}

void WasmMesh::set_position(std::uint32_t v, val p) {
  guarded([&] {
    const Vertex vh = live_vertex(s_->mesh, v);
    s_->mesh.set_position(vh, point_from_js(p, "setPosition of " + element_name("vertex", v)));
  });
}

val WasmMesh::halfedge(std::uint32_t h) const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    const Halfedge hh = live_halfedge(m, h);
    val out = val::object();
    out.set("halfedge", double(h));
    out.set("origin", js_index(m.from_vertex(hh).idx()));
    out.set("target", js_index(m.to_vertex(hh).idx()));
    out.set("twin", js_index(SurfaceMesh::twin(hh).idx()));
    out.set("face", js_index(m.face(hh).idx()));
    out.set("next", js_index(m.next(hh).idx()));
    out.set("prev", js_index(m.prev(hh).idx()));
    out.set("edge", js_index(SurfaceMesh::edge(hh).idx()));
    out.set("boundary", m.is_boundary(hh));
    return out;
  });
}

val WasmMesh::vertex(std::uint32_t v) const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    const Vertex vh = live_vertex(m, v);
    val out = val::object();
    out.set("vertex", double(v));
    out.set("halfedge", js_index(m.halfedge(vh).idx()));
    out.set("position", js_vec3(m.position(vh)));
    out.set("valence", double(m.valence(vh)));
    out.set("boundary", m.is_boundary(vh));
    out.set("isolated", m.is_isolated(vh));
    return out;
  });
}

val WasmMesh::edge(std::uint32_t e) const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    const Edge eh = live_edge(m, e);
    val out = val::object();
    out.set("edge", double(e));
    out.set("halfedges", js_index_array(std::vector<Halfedge>{SurfaceMesh::halfedge(eh, 0),
                                                              SurfaceMesh::halfedge(eh, 1)}));
    out.set("vertices", js_index_array(std::vector<Vertex>{m.vertex(eh, 0), m.vertex(eh, 1)}));
    out.set("faces", js_index_array(std::vector<Face>{m.face(eh, 0), m.face(eh, 1)}));
    out.set("boundary", m.is_boundary(eh));
    return out;
  });
}

val WasmMesh::face(std::uint32_t f) const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    const Face fh = live_face(m, f);
    std::vector<Halfedge> hs;
    for (const Halfedge h : m.halfedges(fh)) hs.push_back(h);
    val out = halfedge_lists(m, hs, true);
    out.set("face", double(f));
    out.set("halfedge", js_index(m.halfedge(fh).idx()));
    out.set("boundary", m.is_boundary(fh));
    return out;
  });
}

val WasmMesh::one_ring(std::uint32_t v) const {
  return guarded([&] {
    const SurfaceMesh& m = s_->mesh;
    const Vertex vh = live_vertex(m, v);
    std::vector<Halfedge> hs;
    if (!m.is_isolated(vh))
      for (const Halfedge h : m.halfedges(vh)) hs.push_back(h);
    val out = halfedge_lists(m, hs, false);
    out.set("vertex", double(v));
    return out;
  });
}

double WasmMesh::pick(double ox, double oy, double oz, double dx, double dy, double dz) {
  return guarded([&]() -> double {
    FaceBvh& bvh = binding::picking_tree(*s_);
    const std::optional<RayHit> hit =
        bvh.first_hit(Vec3{float(ox), float(oy), float(oz)}, Vec3{float(dx), float(dy), float(dz)});
    if (!hit) return -1.0;
    const SurfaceMesh& m = s_->mesh;
    const Vec3d p = to_double(hit->point);
    Halfedge best_h;
    double best_h_d = std::numeric_limits<double>::infinity();
    Vertex best_v;
    double best_v_d = std::numeric_limits<double>::infinity();
    for (const Halfedge h : m.halfedges(hit->face)) {
      const Vec3d a = to_double(m.position(m.from_vertex(h))), b = to_double(m.position(m.to_vertex(h)));
      const double dh = distance_to_segment(p, a, b);
      if (dh < best_h_d) best_h_d = dh, best_h = h;
      const double dv = norm(p - b);
      if (dv < best_v_d) best_v_d = dv, best_v = m.to_vertex(h);
    }
    const double values[16] = {double(hit->face.idx()),
                               hit->t,
                               p.x,
                               p.y,
                               p.z,
                               double(best_h.idx()),
                               double(SurfaceMesh::edge(best_h).idx()),
                               double(best_v.idx()),
                               best_h_d,
                               best_v_d,
                               double(hit->corners[0].idx()),
                               double(hit->corners[1].idx()),
                               double(hit->corners[2].idx()),
                               hit->barycentric[0],
                               hit->barycentric[1],
                               hit->barycentric[2]};
    std::copy(values, values + 16, g_pick);
    return double(hit->face.idx());
  });
}

std::uint32_t WasmMesh::pick_many(val rays, val out) {
  return guarded([&]() -> std::uint32_t {
    std::vector<float> r;
    const std::uint32_t n_floats = js_length(rays, "rays");
    if (n_floats % 6 != 0)
      throw InvalidInputError("rays: " + std::to_string(n_floats) + " floats is not 6 per ray");
    const std::uint32_t n = n_floats / 6;
    if (js_length(out, "out") != n)
      throw InvalidInputError("out: expected " + std::to_string(n) + " entries, one per ray");
    copy_from_js(rays, r, n_floats);
    FaceBvh& bvh = binding::picking_tree(*s_);
    std::vector<std::int32_t> faces(n);
    std::uint32_t hits = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const float* q = &r[6 * std::size_t(i)];
      const auto hit = bvh.first_hit(Vec3{q[0], q[1], q[2]}, Vec3{q[3], q[4], q[5]});
      faces[i] = hit ? std::int32_t(hit->face.idx()) : -1;
      hits += hit ? 1 : 0;
    }
    if (n > 0) out.call<void>("set", val(emscripten::typed_memory_view(faces.size(), faces.data())));
    return hits;
  });
}

val WasmMesh::to_arrays(bool triangulate) const {
  return guarded([&] {
    ExportOptions options;
    options.triangulation = triangulate ? Triangulation::ear : Triangulation::none;
    options.corner_attributes = false;
    const IndexedMesh out = to_indexed(s_->mesh, options);
    val result = val::object();
    const val f32 = val::global("Float32Array"), u32 = val::global("Uint32Array");
    result.set("positions",
               f32.new_(val(emscripten::typed_memory_view(
                   out.positions.size() * 3, out.positions.empty() ? nullptr : &out.positions[0].x))));
    result.set("indices",
               u32.new_(val(emscripten::typed_memory_view(out.indices.size(), out.indices.data()))));
    result.set("faceSizes", out.face_sizes.empty() ? val::null()
                                                   : u32.new_(val(emscripten::typed_memory_view(
                                                         out.face_sizes.size(), out.face_sizes.data()))));
    return result;
  });
}

val WasmMesh::to_file(const std::string& name) const {
  return guarded([&] {
    const FileFormat format = format_from_path(name);
    ExportOptions options;
    if (format == FileFormat::stl) options.triangulation = Triangulation::fan;
    const std::string bytes = write_indexed(to_indexed(s_->mesh, options), format);
    return val::global("Uint8Array")
        .new_(val(emscripten::typed_memory_view(bytes.size(),
                                                reinterpret_cast<const std::uint8_t*>(bytes.data()))));
  });
}

double WasmMesh::memory_bytes() const {
  return guarded([&] { return double(binding::memory_bytes(*s_)); });
}

}  // namespace hedge::wasm

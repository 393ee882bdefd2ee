// NativeMesh: local edits and whole-mesh algorithms (the JS API's Mesh, see wasm_mesh.h). Every
// edit goes through the binding core (binding/edits.h): handles checked, then the library's
// refusal, then the edit, exactly as the C ABI does it. decimate() and garbage_collection() run
// under binding::with_rollback(), so that running out of wasm memory halfway leaves the mesh as it was.
#include <string>
#include <vector>

#include "binding/edits.h"
#include "binding/names.h"
#include "binding/rollback.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/error.h"
#include "wasm_mesh.h"

namespace hedge::wasm {

std::string WasmMesh::refusal(const std::string& edit, val elements) const {
  return guarded([&]() -> std::string {
    std::vector<std::uint32_t> indices;
    copy_from_js(elements, indices, js_length(elements, "elements"));
    const char* why =
        binding::refusal(s_->mesh, binding::parse_edit(edit, binding::EditNaming::camel_case), indices);
    return why != nullptr ? why : "";
  });
}

double WasmMesh::split_edge(std::uint32_t e, val point) {
  return guarded([&] {
    return double(
        binding::split_edge(s_->mesh, e, optional_vec3_from_js(point, "splitEdge: the point")).idx());
  });
}

double WasmMesh::flip(std::uint32_t e) {
  return guarded([&] { return double(binding::flip(s_->mesh, e).idx()); });
}

double WasmMesh::collapse(std::uint32_t h, val point) {
  return guarded([&] {
    // The point is checked before the collapse, which cannot be undone.
    const std::optional<Vec3> p = optional_vec3_from_js(point, "collapse: the point");
    if (p) binding::need_point(*p, "collapse");
    const Vertex v = binding::collapse(s_->mesh, h);
    if (p) s_->mesh.set_position(v, *p);
    return double(v.idx());
  });
}

double WasmMesh::split_face(std::uint32_t f, val point) {
  return guarded([&] {
    return double(
        binding::split_face(s_->mesh, f, optional_vec3_from_js(point, "splitFace: the point")).idx());
  });
}

double WasmMesh::cut_face(std::uint32_t h0, std::uint32_t h1) {
  return guarded([&] { return double(binding::cut_face(s_->mesh, h0, h1).idx()); });
}

val WasmMesh::fill_hole(std::uint32_t h) {
  return guarded([&] { return js_index_array(binding::fill_hole(s_->mesh, h)); });
}

void WasmMesh::garbage_collection() {
  guarded([&] { binding::with_rollback(s_->mesh, [&] { s_->mesh.garbage_collection(); }); });
}

void WasmMesh::subdivide(const std::string& scheme, int steps) {
  // subdivide() leaves the mesh as it was if it throws (memory included): no copy needed.
  guarded([&] { hedge::subdivide(s_->mesh, binding::parse_subdivision(scheme), steps); });
}

void WasmMesh::smooth(const std::string& method, int iterations, double lambda, double mu,
                      bool fix_boundary) {
  guarded([&] {
    SmoothOptions options;
    options.method = binding::parse_smooth_method(method);
    options.iterations = iterations;
    options.lambda = lambda;
    options.mu = mu;
    options.fix_boundary = fix_boundary;
    hedge::smooth(s_->mesh, options);
  });
}

void WasmMesh::compute_corner_normals(double crease_degrees) {
  guarded([&] {
    if (!(crease_degrees >= 0 && crease_degrees <= 180))
      throw InvalidInputError("computeCornerNormals: the crease angle must be in 0..180 degrees, got " +
                              std::to_string(crease_degrees));
    hedge::compute_corner_normals(s_->mesh, crease_degrees);
  });
}

val WasmMesh::decimate(double target_faces, double target_vertices, double max_error,
                       bool relax_normal_change) {
  return guarded([&] {
    if (!(target_faces >= 0) || !(target_vertices >= 0))
      throw InvalidInputError("decimate: the targets must be counts (0 or more)");
    DecimateOptions options;
    options.target_faces = std::size_t(target_faces);
    options.target_vertices = std::size_t(target_vertices);
    if (max_error >= 0) options.max_error = max_error;
    options.relax_normal_change = relax_normal_change;
    const DecimateResult r =
        binding::with_rollback(s_->mesh, [&] { return hedge::decimate(s_->mesh, options); });
    val out = val::object();
    out.set("vertices", double(r.vertices));
    out.set("faces", double(r.faces));
    out.set("collapses", double(r.collapses));
    out.set("maxError", r.max_error);
    out.set("stop", std::string(binding::name(r.stop)));
    val refused = val::object();
    refused.set("topology", double(r.refused.topology));
    refused.set("normal", double(r.refused.normal));
    refused.set("shape", double(r.refused.shape));
    out.set("refused", refused);
    return out;
  });
}

}  // namespace hedge::wasm

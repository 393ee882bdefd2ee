#include "binding/edits.h"

#include <string>

#include "binding/errors.h"
#include "binding/handles.h"
#include "binding/picking.h"
#include "hedge/algorithms/fill_hole.h"
#include "hedge/core/face_operations.h"
#include "hedge/core/operations.h"

namespace hedge::binding {

namespace {
struct EditNames {
  Edit edit;
  const char* name;     // the library's
  const char* js_name;  // the JS API's method (null: the JS API has no such edit)
  std::size_t arity;
};
constexpr EditNames kEdits[] = {
    {Edit::split_edge, "split_edge", "splitEdge", 1},
    {Edit::collapse, "collapse", "collapse", 1},
    {Edit::flip, "flip", "flip", 1},
    {Edit::split_face, "split_face", "splitFace", 1},
    {Edit::cut_face, "cut_face", "cutFace", 2},
    {Edit::fill_hole, "fill_hole", "fillHole", 1},
    {Edit::remove_face, "remove_face", nullptr, 1},
};
const EditNames& names(Edit edit) { return kEdits[static_cast<int>(edit)]; }

// "flip of edge 3", "cut_face of halfedge 1 and halfedge 4".
template <typename H>
std::string what(Edit edit, std::uint32_t index) {
  return std::string(edit_name(edit)) + " of " + element_name(element_kind<H>(), index);
}

// A live element whose edit the library allows. \throw BindingError otherwise.
template <typename H>
H allowed(const SurfaceMesh& m, Edit edit, std::uint32_t index) {
  const H h = live_element<H>(m, index);
  require_allowed(refusal(m, edit, std::span<const std::uint32_t>(&index, 1)), what<H>(edit, index));
  return h;
}

// Fails with HEDGE_ERROR_INTERNAL: the edit refused after all, though its refusal allowed it (the
// refusal and the edit disagree, a bug).
[[noreturn]] void refused_after_all(const char* edit) {
  fail(HEDGE_ERROR_INTERNAL, std::string(edit) + " refused an edit its refusal allowed");
}

// The edit's result, which the refusal promised. \throw BindingError (HEDGE_ERROR_INTERNAL) if the
// edit refused after all.
template <typename R>
R done(R result, Edit edit) {
  if (!result.is_valid()) refused_after_all(edit_name(edit));
  return result;
}
}  // namespace

const char* edit_name(Edit edit) noexcept { return names(edit).name; }
std::size_t edit_arity(Edit edit) noexcept { return names(edit).arity; }

Edit parse_edit(std::string_view name, EditNaming naming) {
  const auto spelling = [naming](const EditNames& n) {
    return naming == EditNaming::snake_case ? n.name : n.js_name;
  };
  // The JS API took the library's names as well from the start; it keeps them.
  for (const EditNames& n : kEdits)
    if ((spelling(n) != nullptr && name == spelling(n)) ||
        (naming == EditNaming::camel_case && name == n.name))
      return n.edit;
  std::string known;
  for (const EditNames& n : kEdits)
    if (spelling(n) != nullptr) known += std::string(known.empty() ? "" : ", ") + spelling(n);
  fail(HEDGE_ERROR_INVALID_ARGUMENT, "unknown edit '" + std::string(name) + "' (" + known + ")");
}

const char* refusal(const SurfaceMesh& m, Edit edit, std::span<const std::uint32_t> elements) {
  if (elements.size() != edit_arity(edit))
    fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string(edit_name(edit)) + " takes " +
                                           std::to_string(edit_arity(edit)) + " element(s), not " +
                                           std::to_string(elements.size()));
  const std::uint32_t a = elements[0];
  switch (edit) {
    case Edit::split_edge:
      return split_refusal(m, Edge(a));
    case Edit::collapse:
      return collapse_refusal(m, Halfedge(a));
    case Edit::flip:
      return flip_refusal(m, Edge(a));
    case Edit::split_face:
      return split_face_refusal(m, Face(a));
    case Edit::cut_face:
      return cut_face_refusal(m, Halfedge(a), Halfedge(elements[1]));
    case Edit::fill_hole:
      return fill_hole_refusal(m, Halfedge(a));
    case Edit::remove_face:
      return remove_face_refusal(m, Face(a));
  }
  return nullptr;
}

Vec3 need_point(const Vec3& p, const char* what) { return need_finite(p, std::string(what) + ": point"); }

Vertex split_edge(SurfaceMesh& m, std::uint32_t edge, const std::optional<Vec3>& point) {
  const Edge e = allowed<Edge>(m, Edit::split_edge, edge);
  const Vec3 p = point ? need_point(*point, "split_edge")
                       : (m.position(m.vertex(e, 0)) + m.position(m.vertex(e, 1))) * 0.5f;
  return done(hedge::split_edge(m, e, p), Edit::split_edge);
}

Vertex collapse(SurfaceMesh& m, std::uint32_t halfedge) {
  return done(hedge::collapse(m, allowed<Halfedge>(m, Edit::collapse, halfedge)), Edit::collapse);
}

Edge flip(SurfaceMesh& m, std::uint32_t edge) {
  return done(hedge::flip(m, allowed<Edge>(m, Edit::flip, edge)), Edit::flip);
}

Vertex split_face(SurfaceMesh& m, std::uint32_t face, const std::optional<Vec3>& point) {
  const Face f = allowed<Face>(m, Edit::split_face, face);
  const Vec3 p = point ? need_point(*point, "split_face") : face_centroid(m, f);
  return done(hedge::split_face(m, f, p), Edit::split_face);
}

Halfedge cut_face(SurfaceMesh& m, std::uint32_t halfedge0, std::uint32_t halfedge1) {
  const Halfedge h0 = live_halfedge(m, halfedge0), h1 = live_halfedge(m, halfedge1);
  require_allowed(cut_face_refusal(m, h0, h1),
                  what<Halfedge>(Edit::cut_face, halfedge0) + " and " + element_name("halfedge", halfedge1));
  return done(hedge::cut_face(m, h0, h1), Edit::cut_face);
}

Halfedge require_fill_hole(const SurfaceMesh& m, std::uint32_t halfedge) {
  return allowed<Halfedge>(m, Edit::fill_hole, halfedge);
}

std::vector<Face> fill_hole(SurfaceMesh& m, std::uint32_t halfedge) {
  std::vector<Face> faces = hedge::fill_hole(m, require_fill_hole(m, halfedge));
  if (faces.empty()) refused_after_all("fill_hole");
  return faces;
}

std::vector<Vertex> live_vertices(const SurfaceMesh& m, std::span<const std::uint32_t> vertices) {
  std::vector<Vertex> out;
  out.reserve(vertices.size());
  for (const std::uint32_t v : vertices) out.push_back(live_vertex(m, v));
  return out;
}

Face add_face(SurfaceMesh& m, std::span<const Vertex> corners) {
  std::string what = "add_face of";
  for (const Vertex v : corners) what.append(" ").append(std::to_string(v.idx()));
  require_allowed(add_face_refusal(m, corners), what);
  const Face f = hedge::add_face(m, corners);
  if (!f.is_valid()) refused_after_all("add_face");
  return f;
}

void remove_face(SurfaceMesh& m, std::uint32_t face) {
  const Face f = live_face(m, face);
  require_allowed(remove_face_refusal(m, f), "remove_face of " + element_name("face", face));
  if (!hedge::remove_face(m, f)) refused_after_all("remove_face");
}

void remove_vertex(SurfaceMesh& m, std::uint32_t vertex) {
  const Vertex v = live_vertex(m, vertex);
  require_allowed(remove_vertex_refusal(m, v), "remove_vertex of " + element_name("vertex", vertex));
  if (!hedge::remove_vertex(m, v)) refused_after_all("remove_vertex");
}

}  // namespace hedge::binding

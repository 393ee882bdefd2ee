// The refusable edits of the Python Mesh and their can_* predicates. Every edit goes through the
// binding core (binding/edits.h): handles checked (BadHandleError), then the library's refusal,
// then the edit, as the C ABI and the WebAssembly module do it. A refusal is no exception here:
// the edit returns None (False for remove_face) and keeps the reason in Mesh.last_refusal.
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "binding/edits.h"
#include "binding/errors.h"
#include "binding/handles.h"
#include "binding/rollback.h"
#include "hedge/core/face_operations.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

using Point = std::optional<std::array<float, 3>>;

std::optional<Vec3> vec3(const Point& p) {
  if (!p) return std::nullopt;
  return Vec3{(*p)[0], (*p)[1], (*p)[2]};
}

//! Runs an edit: its result, or none if the library refused it (the reason goes to last_refusal;
//! the mesh is unchanged). `grows`: the edit adds elements, so it needs the views released first.
template <typename Body>
auto edit(const Mesh& self, const std::string& what, bool grows, Body&& body)
    -> std::optional<decltype(body(std::declval<SurfaceMesh&>()))> {
  const auto use = self.use();
  if (grows) require_no_views(*use, what);
  try {
    auto result = body(use->mesh);
    use->last_refusal.clear();
    return result;
  } catch (const binding::BindingError& e) {
    if (e.status != HEDGE_ERROR_REFUSED) throw;
    use->last_refusal = e.refusal != nullptr ? e.refusal : e.message;
    return std::nullopt;
  }
}

//! An index in a refusal query, as the C ABI and the JS API see it: one out of 32-bit range
//! (-1, 10**12) names no slot, like any index past the slots, so the core refuses it as "not live"
//! instead of raising.
std::vector<std::uint32_t> query_indices(const std::vector<std::int64_t>& elements) {
  std::vector<std::uint32_t> ids;
  for (const std::int64_t i : elements)
    ids.push_back(i < 0 || i > 0xffffffffLL ? 0xffffffffu : static_cast<std::uint32_t>(i));
  return ids;
}

//! Whether the edit is allowed on these elements: the core's refusal, none for a bad handle too.
bool can(const Mesh& self, binding::Edit e, const std::vector<std::int64_t>& elements) {
  const auto use = self.use();
  return binding::refusal(use->mesh, e, query_indices(elements)) == nullptr;
}

std::optional<std::string> refusal_of(const Mesh& self, const std::string& name, const py::object& elements) {
  const binding::Edit e = binding::parse_edit(name, binding::EditNaming::snake_case);
  const std::vector<std::int64_t> list = index_list(elements, "refusal", "elements");
  const auto use = self.use();
  const char* why = binding::refusal(use->mesh, e, query_indices(list));
  if (why == nullptr) return std::nullopt;
  return std::string(why);
}

std::size_t remove_faces_of(const Mesh& self, const py::object& faces) {
  const auto use = self.use();
  SurfaceMesh& m = use->mesh;
  const std::vector<std::int64_t> list = index_list(faces, "remove_faces", "faces", m.face_slots());
  require_no_views(*use, "remove_faces");
  // Every face is checked before any is removed, so a bad one leaves the mesh as it was.
  std::vector<Face> chosen;
  chosen.reserve(list.size());
  for (const std::int64_t f : list) chosen.push_back(binding::live_face(m, element_index(f, "face")));
  const std::size_t before = m.n_faces();
  // The library's remove_faces() gives no strong guarantee: memory running out after some faces
  // went would leave them gone. The binding core's rollback puts the mesh back (a copy per call).
  binding::with_rollback(m, [&] { remove_faces(m, chosen); });
  use->last_refusal.clear();
  return before - m.n_faces();
}

}  // namespace

void bind_edits(py::class_<Mesh>& mesh) {
  using binding::Edit;
  mesh.def(
          "can_split_edge", [](const Mesh& self, std::int64_t e) { return can(self, Edit::split_edge, {e}); },
          py::arg("edge"), "True if split_edge(edge) is allowed (False for a dead or out-of-range edge too).")
      .def(
          "split_edge",
          [](const Mesh& self, std::int64_t e, const Point& point) {
            return edit(self, "split_edge", true, [&](SurfaceMesh& m) {
              return binding::split_edge(m, element_index(e, "edge"), vec3(point)).idx();
            });
          },
          py::arg("edge"), py::arg("point") = py::none(),
          "Splits the edge at point (default: its midpoint). Returns the new vertex, or None if the "
          "library refuses (the reason is in last_refusal). Raises BadHandleError for a dead or "
          "out-of-range edge, InvalidArgumentError for a point that is not finite.")
      .def(
          "can_collapse", [](const Mesh& self, std::int64_t h) { return can(self, Edit::collapse, {h}); },
          py::arg("halfedge"), "True if collapse(halfedge) is allowed.")
      .def(
          "collapse",
          [](const Mesh& self, std::int64_t h, const Point& point) {
            return edit(self, "collapse", false, [&](SurfaceMesh& m) {
              // The point is checked before the collapse, which cannot be undone.
              const std::optional<Vec3> p = vec3(point);
              if (p) binding::need_point(*p, "collapse");
              const Vertex v = binding::collapse(m, element_index(h, "halfedge"));
              if (p) m.set_position(v, *p);
              return v.idx();
            });
          },
          py::arg("halfedge"), py::arg("point") = py::none(),
          "Merges the half-edge's origin into its target, which moves to point if given. Returns the "
          "surviving vertex, or None if refused (reason in last_refusal).")
      .def(
          "can_flip", [](const Mesh& self, std::int64_t e) { return can(self, Edit::flip, {e}); },
          py::arg("edge"), "True if flip(edge) is allowed.")
      .def(
          "flip",
          [](const Mesh& self, std::int64_t e) {
            return edit(self, "flip", false,
                        [&](SurfaceMesh& m) { return binding::flip(m, element_index(e, "edge")).idx(); });
          },
          py::arg("edge"), "Flips the edge between two triangles. Returns the edge, or None if refused.")
      .def(
          "can_split_face", [](const Mesh& self, std::int64_t f) { return can(self, Edit::split_face, {f}); },
          py::arg("face"), "True if split_face(face) is allowed.")
      .def(
          "split_face",
          [](const Mesh& self, std::int64_t f, const Point& point) {
            return edit(self, "split_face", true, [&](SurfaceMesh& m) {
              return binding::split_face(m, element_index(f, "face"), vec3(point)).idx();
            });
          },
          py::arg("face"), py::arg("point") = py::none(),
          "Splits the face into a fan around a new vertex at point (default: the centroid). Returns "
          "the new vertex, or None if refused.")
      .def(
          "can_cut_face",
          [](const Mesh& self, std::int64_t h0, std::int64_t h1) {
            return can(self, Edit::cut_face, {h0, h1});
          },
          py::arg("halfedge0"), py::arg("halfedge1"), "True if cut_face(halfedge0, halfedge1) is allowed.")
      .def(
          "cut_face",
          [](const Mesh& self, std::int64_t h0, std::int64_t h1) {
            return edit(self, "cut_face", true, [&](SurfaceMesh& m) {
              return binding::cut_face(m, element_index(h0, "halfedge"), element_index(h1, "halfedge")).idx();
            });
          },
          py::arg("halfedge0"), py::arg("halfedge1"),
          "Cuts the face of both half-edges from the target of halfedge0 to the target of halfedge1. "
          "Returns the new half-edge, or None if refused.")
      .def(
          "can_fill_hole", [](const Mesh& self, std::int64_t h) { return can(self, Edit::fill_hole, {h}); },
          py::arg("halfedge"), "True if fill_hole(halfedge) is allowed.")
      .def(
          "fill_hole",
          [](const Mesh& self, std::int64_t h) {
            return edit(self, "fill_hole", true, [&](SurfaceMesh& m) {
              std::vector<std::int64_t> faces;
              for (const Face f : binding::fill_hole(m, element_index(h, "halfedge")))
                faces.push_back(f.idx());
              return faces;
            });
          },
          py::arg("halfedge"),
          "Fills the hole whose boundary loop holds the half-edge. Returns the new faces, or None if "
          "refused.")
      .def(
          "can_remove_face",
          [](const Mesh& self, std::int64_t f) { return can(self, Edit::remove_face, {f}); }, py::arg("face"),
          "True if remove_face(face) is allowed.")
      .def(
          "remove_face",
          [](const Mesh& self, std::int64_t f) {
            return edit(self, "remove_face", false,
                        [&](SurfaceMesh& m) {
                          binding::remove_face(m, element_index(f, "face"));
                          return true;
                        })
                .has_value();
          },
          py::arg("face"),
          "Removes the face, and the edges and vertices it leaves unused. Returns False if refused "
          "(reason in last_refusal).")
      .def("remove_faces", &remove_faces_of, py::arg("faces"),
           "Removes several faces at once (an array of integer indices, repeats are fine, or a bool mask "
           "of face_slots entries), and the edges and "
           "vertices they leave unused. Never refused: a vertex the removal would leave pinched is "
           "split, one copy per fan, so the mesh stays manifold (which adds vertices, so it raises "
           "ViewsExportedError while views are alive). Returns how many faces were removed. Raises "
           "BadHandleError, before removing any, for a deleted or out-of-range face.")
      .def("refusal", &refusal_of, py::arg("edit"), py::arg("elements"),
           "Why the edit ('split_edge', 'collapse', 'flip', 'split_face', 'cut_face', 'fill_hole', "
           "'remove_face') of these elements is refused, or None if it is allowed. An index that "
           "names no live element (deleted, past the slots, negative) is refused as not live, as "
           "in the C ABI and the JS API; an unknown edit raises InvalidArgumentError.")
      .def_property_readonly(
          "last_refusal",
          [](const Mesh& self) -> std::optional<std::string> {
            const auto use = self.use();
            if (use->last_refusal.empty()) return std::nullopt;
            return use->last_refusal;
          },
          "The library's reason for the last refused edit on this mesh, None if the last edit was done.");
}

}  // namespace hedge::python

// The numpy views of a mesh's arrays, without copies (see py_support.h for their guard), and
// positions_changed(), which tells the change log about writes through mesh.positions.
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "binding/errors.h"
#include "binding/handles.h"
#include "hedge/core/color.h"
#include "hedge/error.h"
#include "hedge/render/tangent.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

static_assert(sizeof(Vertex) == sizeof(std::int32_t) && sizeof(Halfedge) == sizeof(std::int32_t) &&
                  sizeof(Face) == sizeof(std::int32_t),
              "handles are viewed as int32");

//! The base of every view: keeps the mesh state alive and counts as an exported view while it
//! lives (State::views; created and destroyed with the GIL held).
class ViewOwner {
 public:
  explicit ViewOwner(std::shared_ptr<State> state) : state_(std::move(state)) { ++state_->views; }
  ViewOwner(const ViewOwner&) = delete;
  ViewOwner& operator=(const ViewOwner&) = delete;
  ~ViewOwner() { --state_->views; }

 private:
  std::shared_ptr<State> state_;
};

py::object owner(const Mesh& self) {
  return py::cast(new ViewOwner(self.state()), py::return_value_policy::take_ownership);
}

//! A read-only int32 view of the handle array that get(mesh) returns (kInvalidIndex reads as -1).
template <typename Get>
py::array index_view(const Mesh& self, Get get) {
  const auto use = self.use();
  const auto& handles = get(std::as_const(use->mesh));
  static_assert(sizeof(handles[0]) == sizeof(std::int32_t), "handles are viewed as int32");
  py::array a = py::array_t<std::int32_t>({static_cast<py::ssize_t>(handles.size())},
                                          reinterpret_cast<const std::int32_t*>(handles.data()), owner(self));
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::array positions_view(const Mesh& self) {
  const auto use = self.use();
  auto& p = use->mesh.positions().vector();
  const auto n = static_cast<py::ssize_t>(p.size());
  return py::array_t<float>({n, py::ssize_t(3)}, {py::ssize_t(sizeof(Vec3)), py::ssize_t(sizeof(float))},
                            reinterpret_cast<float*>(p.data()), owner(self));
}

//! Checks that v's position is finite, naming v otherwise.
void need_finite(const SurfaceMesh& m, Vertex v) {
  const Vec3& p = m.position(v);
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw InvalidInputError("positions_changed: vertex " + std::to_string(v.idx()) +
                            " has a position that is not finite (" + std::to_string(p.x) + ", " +
                            std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
}

void positions_changed(const Mesh& self, const py::object& vertices) {
  const auto use = self.use();
  SurfaceMesh& m = use->mesh;
  std::vector<Vertex> moved;
  if (!vertices.is_none()) {
    for (const std::int64_t v : index_list(vertices, "positions_changed", "vertices", m.vertex_slots()))
      moved.push_back(binding::live_vertex(m, element_index(v, "vertex")));
  } else {
    for (const Vertex v : m.vertices()) moved.push_back(v);
  }
  // Every position is checked before any is marked, so a bad one leaves the log as it was.
  for (const Vertex v : moved) need_finite(m, v);
  for (const Vertex v : moved) m.mark_changed(v, ChangeEvent::vertices_moved);
  m.changes().notify();
}

//! The arrays of the four kinds of element, in the order property_names() lists them.
struct Kind {
  const char* name;
  const PropertyContainer& (SurfaceMesh::*container)() const;
};
constexpr Kind kKinds[] = {{"vertex", &SurfaceMesh::vertex_properties},
                           {"halfedge", &SurfaceMesh::halfedge_properties},
                           {"edge", &SurfaceMesh::edge_properties},
                           {"face", &SurfaceMesh::face_properties}};

//! The property `name` of the given kind (any kind if none), or an error that says what exists.
BasePropertyArray* find_property(const SurfaceMesh& m, const std::string& name,
                                 const std::optional<std::string>& kind) {
  BasePropertyArray* found = nullptr;
  std::string kinds;
  bool known_kind = !kind;
  for (const Kind& k : kKinds) {
    if (kind && *kind != k.name) continue;
    known_kind = true;
    if (BasePropertyArray* a = (m.*k.container)().find_base(name)) {
      if (found)
        throw InvalidInputError("property: '" + name + "' is a property of " + kinds + " and " + k.name +
                                " elements; pass kind= to choose");
      found = a;
      kinds = k.name;
    }
  }
  if (!known_kind)
    throw InvalidInputError("property: kind must be 'vertex', 'halfedge', 'edge' or 'face', not '" + *kind +
                            "'");
  if (!found)
    throw InvalidInputError("property: the mesh has no " + (kind ? *kind + " " : std::string()) +
                            "property named '" + name + "' (see property_names())");
  return found;
}

//! A view of `a` if its values are T, made of `columns` scalars S each; none otherwise.
template <typename T, typename S>
std::optional<py::array> view_as(const Mesh& self, BasePropertyArray* a, int columns) {
  if (a->type() != typeid(T)) return std::nullopt;
  static_assert(sizeof(T) % sizeof(S) == 0, "a value is a row of scalars");
  auto& values = static_cast<PropertyArray<T>*>(a)->vector();
  S* data = reinterpret_cast<S*>(values.data());
  const auto n = static_cast<py::ssize_t>(values.size());
  if (columns == 1) return py::array_t<S>({n}, {py::ssize_t(sizeof(T))}, data, owner(self));
  return py::array_t<S>({n, py::ssize_t(columns)}, {py::ssize_t(sizeof(T)), py::ssize_t(sizeof(S))}, data,
                        owner(self));
}

py::array property_view(const Mesh& self, const std::string& name, const std::optional<std::string>& kind) {
  const auto use = self.use();
  BasePropertyArray* a = find_property(use->mesh, name, kind);
  std::optional<py::array> v;
  if (!v) v = view_as<std::int32_t, std::int32_t>(self, a, 1);
  if (!v) v = view_as<std::uint32_t, std::uint32_t>(self, a, 1);
  if (!v) v = view_as<std::uint8_t, std::uint8_t>(self, a, 1);
  if (!v) v = view_as<float, float>(self, a, 1);
  if (!v) v = view_as<double, double>(self, a, 1);
  if (!v) v = view_as<Vec2, float>(self, a, 2);
  if (!v) v = view_as<Vec3, float>(self, a, 3);
  if (!v) v = view_as<Vec3d, double>(self, a, 3);
  if (!v) v = view_as<Vec4, float>(self, a, 4);
  if (!v) v = view_as<Color, float>(self, a, 4);
  if (!v)
    throw InvalidInputError("property: '" + name + "' holds values numpy cannot view (" + a->type().name() +
                            "); viewable are int32, uint32, uint8, float, double and 2, 3 or 4 floats");
  return *v;
}

//! A fresh bool array, one entry per slot of the kind H: true for a live one.
template <typename H>
py::array_t<bool> live_mask(const Mesh& self, std::size_t (SurfaceMesh::*slots)() const) {
  const auto use = self.use();
  const SurfaceMesh& m = use->mesh;
  py::array_t<bool> out(static_cast<py::ssize_t>((m.*slots)()));
  bool* p = out.mutable_data();
  for (std::size_t i = 0; i < (m.*slots)(); ++i) p[i] = !m.is_deleted(H(static_cast<Index>(i)));
  return out;
}

py::dict property_names(const Mesh& self) {
  const auto use = self.use();
  py::dict d;
  for (const Kind& k : kKinds) d[k.name] = (use->mesh.*k.container)().names();
  return d;
}

}  // namespace

void bind_views(py::module_& m, py::class_<Mesh>& mesh) {
  py::class_<ViewOwner>(m, "_ViewOwner",
                        "The base of a numpy view of a mesh's array: keeps the mesh alive while the view "
                        "lives, and blocks edits that add elements meanwhile.");
  mesh.def_property_readonly("positions", &positions_view,
                             "The positions as a writable (vertex_slots, 3) float32 numpy array over the "
                             "mesh's own memory (no copy; deleted slots included). After writing through it, "
                             "call positions_changed() so that the change log, and what follows it (the "
                             "picking tree), sees the move. While the array (or a slice of it) lives, edits "
                             "that add elements raise ViewsExportedError.")
      .def("positions_changed", &positions_changed, py::arg("vertices") = py::none(),
           "Tells the mesh that positions were written through mesh.positions: the given vertices "
           "(an array of integer indices, or a bool mask of vertex_slots entries), or every live vertex if "
           "None. Each is checked to be live and "
           "finite first; on an error nothing is marked.")
      .def_property_readonly(
          "halfedge_vertex_array",
          [](const Mesh& self) {
            return index_view(
                self, [](const SurfaceMesh& m) -> const auto& { return m.halfedge_vertex_array(); });
          },
          "Each half-edge's target vertex: a read-only int32 view (halfedge_slots,), no copy. The twin "
          "of half-edge h is h ^ 1 and its edge h >> 1; no array is stored for them.")
      .def_property_readonly(
          "halfedge_next_array",
          [](const Mesh& self) {
            return index_view(
                self, [](const SurfaceMesh& m) -> const auto& { return m.halfedge_next_array(); });
          },
          "Each half-edge's next half-edge in its face or boundary loop: a read-only int32 view, no copy.")
      .def_property_readonly(
          "halfedge_face_array",
          [](const Mesh& self) {
            return index_view(
                self, [](const SurfaceMesh& m) -> const auto& { return m.halfedge_face_array(); });
          },
          "Each half-edge's face, -1 on a boundary half-edge: a read-only int32 view, no copy.")
      .def_property_readonly(
          "vertex_halfedge_array",
          [](const Mesh& self) {
            return index_view(
                self, [](const SurfaceMesh& m) -> const auto& { return m.vertex_halfedge_array(); });
          },
          "Each vertex's outgoing half-edge (a boundary one on a boundary vertex, -1 for an isolated "
          "vertex): a read-only int32 view (vertex_slots,), no copy.")
      .def_property_readonly(
          "face_halfedge_array",
          [](const Mesh& self) {
            return index_view(
                self, [](const SurfaceMesh& m) -> const auto& { return m.face_halfedge_array(); });
          },
          "Each face's half-edge (the face's corners start at its target): a read-only int32 view "
          "(face_slots,), no copy.")
      .def("property", &property_view, py::arg("name"), py::arg("kind") = py::none(),
           "The property `name` (e.g. 'f:submesh', 'h:texcoord', 'v:normal') as a writable numpy view "
           "over the mesh's memory, no copy: one row per slot of its kind, (n,) for a scalar, (n, k) "
           "for k floats (Vec2, Vec3, Vec4, Color). kind ('vertex', 'halfedge', 'edge', 'face') "
           "chooses when the name exists on several kinds. It counts as a view: edits that add "
           "elements raise ViewsExportedError while it lives. Writes are not marked in the change "
           "log. Raises InvalidArgumentError for an unknown name or a type numpy cannot view.")
      .def(
          "live_vertices",
          [](const Mesh& self) { return live_mask<Vertex>(self, &SurfaceMesh::vertex_slots); },
          "Which vertex slots hold a live vertex: a fresh bool array (vertex_slots,). The views keep "
          "stale entries for deleted elements until garbage_collection(); index them with this mask.")
      .def(
          "live_halfedges",
          [](const Mesh& self) { return live_mask<Halfedge>(self, &SurfaceMesh::halfedge_slots); },
          "Which half-edge slots hold a live half-edge: a fresh bool array (halfedge_slots,).")
      .def(
          "live_edges", [](const Mesh& self) { return live_mask<Edge>(self, &SurfaceMesh::edge_slots); },
          "Which edge slots hold a live edge: a fresh bool array (edge_slots,); edge e has the "
          "half-edges 2e and 2e + 1.")
      .def(
          "live_faces", [](const Mesh& self) { return live_mask<Face>(self, &SurfaceMesh::face_slots); },
          "Which face slots hold a live face: a fresh bool array (face_slots,).")
      .def("property_names", &property_names,
           "The names of the mesh's properties: a dict from kind ('vertex', 'halfedge', 'edge', "
           "'face') to a list of names.");
}

}  // namespace hedge::python

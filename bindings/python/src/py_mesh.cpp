// Mesh construction, files, arrays, counts and validate (the Python Mesh, see py_support.h).
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "binding/errors.h"
#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(float), "positions are read as 3 packed floats");

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i > 0 ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

//! V as an (n, 3) float32 array (a copy only if V is of another type or layout).
py::array_t<float, py::array::c_style> positions_array(const py::object& V) {
  auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(V);
  if (!a) throw InvalidInputError("from_arrays: V must be an (n, 3) array of floats");
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw InvalidInputError("from_arrays: V must be an (n, 3) array of floats, not of shape " +
                            shape_text(a));
  return a;
}

bool in_range(std::int64_t v, std::size_t n) { return v >= 0 && static_cast<std::uint64_t>(v) < n; }

//! \throw InvalidInputError: the face index at `where` ("F[4, 2]"), v, names none of n vertices.
[[noreturn]] void bad_index(std::int64_t v, std::size_t n, const std::string& where) {
  throw InvalidInputError("from_arrays: " + where + " = " + std::to_string(v) +
                          " is not a vertex index (V has " + std::to_string(n) + " rows)");
}

//! F (an (m, k) integer array, or a sequence of polygons) as flat indices and face sizes (empty
//! for triangles), checked against n vertices.
void face_indices(const py::object& F, std::size_t n, std::vector<std::uint32_t>& indices,
                  std::vector<std::uint32_t>& sizes) {
  // A rectangular F converts to an (m, k) array; a list of polygons of several sizes does not.
  const py::array_t<std::int64_t, py::array::c_style> a = integer_array(F, "from_arrays", "F");
  if (a && a.ndim() == 2) {
    const auto m = static_cast<std::size_t>(a.shape(0)), k = static_cast<std::size_t>(a.shape(1));
    if (k < 3)
      throw InvalidInputError("from_arrays: F must have at least 3 columns, not " + std::to_string(k));
    const std::int64_t* p = a.data();
    indices.reserve(m * k);
    for (std::size_t i = 0; i < m * k; ++i) {
      const std::int64_t v = p[i];
      if (!in_range(v, n)) bad_index(v, n, "F[" + std::to_string(i / k) + ", " + std::to_string(i % k) + "]");
      indices.push_back(static_cast<std::uint32_t>(v));
    }
    if (k != 3) sizes.assign(m, static_cast<std::uint32_t>(k));
    return;
  }
  if (!py::isinstance<py::sequence>(F) || py::isinstance<py::str>(F))
    throw InvalidInputError("from_arrays: F must be an (m, k) array of integers or a list of polygons");
  const auto polygons = py::reinterpret_borrow<py::sequence>(F);
  bool triangles = true;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const py::object row = polygons[i];
    if (!py::isinstance<py::sequence>(row))
      throw InvalidInputError("from_arrays: F[" + std::to_string(i) +
                              "] is not a sequence of vertex indices");
    const std::string name = "F[" + std::to_string(i) + "]";
    const std::vector<std::int64_t> corners = index_list(row, "from_arrays", name.c_str());
    for (std::size_t j = 0; j < corners.size(); ++j) {
      if (!in_range(corners[j], n)) bad_index(corners[j], n, name + "[" + std::to_string(j) + "]");
      indices.push_back(static_cast<std::uint32_t>(corners[j]));
    }
    sizes.push_back(static_cast<std::uint32_t>(corners.size()));
    triangles = triangles && corners.size() == 3;
  }
  if (triangles) sizes.clear();
}

py::dict report_dict(const BuildReport& r) {
  py::dict d;
  d["welded_vertices"] = r.welded_vertices;
  d["degenerate_faces"] = r.degenerate_faces;
  d["repeated_corners"] = r.repeated_corners;
  d["reoriented_faces"] = r.reoriented_faces;
  d["non_manifold_edges"] = r.non_manifold_edges;
  d["non_manifold_vertices"] = r.non_manifold_vertices;
  d["duplicated_vertices"] = r.duplicated_vertices;
  d["isolated_vertices"] = r.isolated_vertices;
  d["repairs"] = r.repairs();
  d["warnings"] = r.warnings;
  return d;
}

//! A numpy array of Elem that takes over `v` (no copy): the vector moves into a capsule, the array's
//! base. T holds whole Elems (Vec3: 3 floats; uint32 indices read as int32).
template <typename Elem, typename T>
py::array adopt(std::vector<T>&& v, std::vector<py::ssize_t> shape) {
  static_assert(sizeof(T) % sizeof(Elem) == 0);
  auto* owned = new std::vector<T>(std::move(v));
  py::capsule base(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<Elem>(shape, reinterpret_cast<const Elem*>(owned->data()), base);
}

Mesh from_arrays(const py::object& V, const py::object& F, bool repair) {
  const auto positions = positions_array(V);
  const auto n = static_cast<std::size_t>(positions.shape(0));
  std::vector<std::uint32_t> indices, sizes;
  face_indices(F, n, indices, sizes);
  BuildOptions options;
  options.policy = repair ? TopologyPolicy::repair : TopologyPolicy::strict;
  auto state = std::make_shared<State>();
  {
    const std::span<const Vec3> points(reinterpret_cast<const Vec3*>(positions.data()), n);
    py::gil_scoped_release unlocked;
    if (sizes.empty()) {
      state->mesh = build_triangles(points, indices, options, &state->report);
    } else {
      IndexedMesh in;
      in.positions.assign(points.begin(), points.end());
      in.indices = std::move(indices);
      in.face_sizes = std::move(sizes);
      state->mesh = build(in, options, &state->report);
    }
  }
  return Mesh(std::move(state));
}

Mesh read(const py::object& path_like) {
  const std::string path = fspath(path_like);
  auto state = std::make_shared<State>();
  py::gil_scoped_release unlocked;
  state->mesh = read_mesh(path, &state->report);
  return Mesh(std::move(state));
}

void write(const Mesh& self, const py::object& path_like) {
  const std::string path = fspath(path_like);
  const auto use = self.use();
  py::gil_scoped_release unlocked;
  write_mesh(use->mesh, path);
}

//! A deep copy: the mesh and its build report; no picking tree (the copy builds its own on use).
Mesh clone(const Mesh& self) {
  const auto use = self.use();
  auto state = std::make_shared<State>();
  state->mesh = use->mesh;
  state->report = use->report;
  return Mesh(std::move(state));
}

py::tuple to_arrays(const Mesh& self) {
  const auto use = self.use();
  IndexedMesh out = to_indexed(use->mesh, ExportOptions{.corner_attributes = false});
  const auto nv = static_cast<py::ssize_t>(out.positions.size());
  py::array V = adopt<float>(std::move(out.positions), {nv, 3});
  // Faces of one degree k (triangles: no sizes) make an (m, k) array; a list only for mixed degrees.
  const std::uint32_t k0 = out.face_sizes.empty() ? 3 : out.face_sizes.front();
  if (std::all_of(out.face_sizes.begin(), out.face_sizes.end(), [k0](std::uint32_t k) { return k == k0; })) {
    const auto nf = static_cast<py::ssize_t>(out.indices.size() / k0);
    return py::make_tuple(V, adopt<std::int32_t>(std::move(out.indices), {nf, py::ssize_t(k0)}));
  }
  py::list polygons;
  std::size_t at = 0;
  for (const std::uint32_t k : out.face_sizes) {
    std::vector<std::int32_t> idx(out.indices.begin() + at, out.indices.begin() + at + k);
    polygons.append(adopt<std::int32_t>(std::move(idx), {static_cast<py::ssize_t>(k)}));
    at += k;
  }
  return py::make_tuple(V, polygons);
}

}  // namespace

void bind_mesh(py::module_& m, py::class_<Mesh>& mesh) {
  m.def("read", &read, py::arg("path"),
        "Reads a mesh file (OBJ, OFF, PLY, STL, glTF/GLB by extension) and builds it with repairs, "
        "as the CLI does; what was repaired is in Mesh.build_report. Raises IoError for a file that "
        "cannot be read or parsed.");
  mesh.def(py::init<>(), "An empty mesh.")
      .def_static("from_arrays", &from_arrays, py::arg("V"), py::arg("F"), py::arg("repair") = true,
                  "Builds a mesh from an (n, 3) float array of positions and an (m, k) integer array of "
                  "faces (k >= 3) or a list of polygons. With repair=True, input a half-edge mesh "
                  "cannot hold is repaired and counted in build_report; with repair=False it raises "
                  "TopologyError. Raises InvalidArgumentError for malformed arrays or an index out of "
                  "range. Releases the GIL while building.")
      .def("write", &write, py::arg("path"),
           "Writes the mesh in the format of the path's extension, atomically (a failed write leaves "
           "no partial file). Raises IoError.")
      .def("clone", &clone,
           "A deep copy of the mesh (with its build report), independent of this one; copy.copy() and "
           "copy.deepcopy() give the same.")
      .def("__copy__", &clone)
      .def(
          "__deepcopy__", [](const Mesh& self, const py::object&) { return clone(self); }, py::arg("memo"))
      .def("to_arrays", &to_arrays,
           "The live mesh as (V, F): V an (n, 3) float32 array, F an (m, k) int32 array when every "
           "face has k corners (k = 3 for a triangle mesh), a list of int32 arrays, one per polygon, "
           "only when the degrees differ. Deleted elements are skipped, "
           "so indices are compacted. Fresh arrays that own their memory.")
      .def_property_readonly(
          "build_report", [](const Mesh& self) { return report_dict(self.use()->report); },
          "What building the mesh repaired and warned about (a dict of counts and 'warnings').")
      .def_property_readonly(
          "n_vertices", [](const Mesh& self) { return self.use()->mesh.n_vertices(); }, "Live vertices.")
      .def_property_readonly(
          "n_edges", [](const Mesh& self) { return self.use()->mesh.n_edges(); }, "Live edges.")
      .def_property_readonly(
          "n_halfedges", [](const Mesh& self) { return self.use()->mesh.n_halfedges(); },
          "Live half-edges (twice the edges).")
      .def_property_readonly(
          "n_faces", [](const Mesh& self) { return self.use()->mesh.n_faces(); }, "Live faces.")
      .def_property_readonly(
          "vertex_slots", [](const Mesh& self) { return self.use()->mesh.vertex_slots(); },
          "Vertex slots, deleted ones included: the length of the per-vertex views.")
      .def_property_readonly(
          "halfedge_slots", [](const Mesh& self) { return self.use()->mesh.halfedge_slots(); },
          "Half-edge slots, deleted ones included: the length of the per-half-edge views.")
      .def_property_readonly(
          "face_slots", [](const Mesh& self) { return self.use()->mesh.face_slots(); },
          "Face slots, deleted ones included: the length of the per-face views.")
      .def(
          "is_triangle_mesh", [](const Mesh& self) { return self.use()->mesh.is_triangle_mesh(); },
          "True if every live face is a triangle.")
      .def(
          "validate", [](const Mesh& self) { return self.use()->mesh.validate(); },
          "Every broken invariant of the half-edge structure, one line each; an empty list means "
          "the mesh is valid.")
      .def("__repr__", [](const Mesh& self) -> std::string {
        // repr never raises: a debugger or a REPL may ask while another thread is in a call.
        try {
          const auto use = self.use();
          return "<hedge.Mesh: " + std::to_string(use->mesh.n_vertices()) + " vertices, " +
                 std::to_string(use->mesh.n_faces()) + " faces>";
        } catch (const binding::BindingError& e) {
          if (e.status != HEDGE_ERROR_BUSY) throw;
          return "<hedge.Mesh: busy, another thread is in a call on it>";
        }
      });
  m.attr("__version__") = HEDGE_VERSION;
}

}  // namespace hedge::python

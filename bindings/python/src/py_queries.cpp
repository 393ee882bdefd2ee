// The scalar queries of one element (next, twin, to_vertex, ...) and the one-ring of a vertex, as
// the C ABI's hedge_halfedge_* and hedge_vertex_* queries give them: every index checked first
// (BadHandleError), -1 for "none". For many elements at once, the array views are the fast path.
#include <cstdint>
#include <vector>

#include "binding/handles.h"
#include "hedge/error.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

namespace {

std::int64_t index_or_none(Index i) { return i == kInvalidIndex ? -1 : static_cast<std::int64_t>(i); }

//! Binds `name` as a query of one live half-edge: get(mesh, h) gives the answer's index.
template <typename Get>
void halfedge_query(py::class_<Mesh>& mesh, const char* name, Get get, const char* doc) {
  mesh.def(
      name,
      [get](const Mesh& self, std::int64_t h) {
        const auto use = self.use();
        const SurfaceMesh& m = use->mesh;
        return index_or_none(get(m, binding::live_halfedge(m, element_index(h, "halfedge"))));
      },
      py::arg("halfedge"), doc);
}

//! The elements get(mesh, h) of v's outgoing half-edges, clockwise, as an int32 array.
template <typename Get>
py::array_t<std::int32_t> around(const Mesh& self, std::int64_t v, Get get) {
  const auto use = self.use();
  const SurfaceMesh& m = use->mesh;
  const Vertex vh = binding::live_vertex(m, element_index(v, "vertex"));
  std::vector<std::int32_t> out;
  for (const Halfedge h : m.halfedges(vh)) {
    const Index i = get(m, h);
    if (i != kInvalidIndex) out.push_back(static_cast<std::int32_t>(i));
  }
  py::array_t<std::int32_t> a(static_cast<py::ssize_t>(out.size()));
  std::copy(out.begin(), out.end(), a.mutable_data());
  return a;
}

//! The one-rings of `vertices` (every vertex slot if None) as (offsets, neighbours): vertex i's
//! ring is neighbours[offsets[i]:offsets[i + 1]], clockwise as one_ring() gives it; a deleted or
//! isolated vertex has an empty ring. Two passes over the rings, with the GIL released.
py::tuple one_rings(const Mesh& self, const py::object& vertices) {
  const auto use = self.use();
  const SurfaceMesh& m = use->mesh;
  std::vector<Vertex> list;
  if (vertices.is_none()) {
    list.reserve(m.vertex_slots());
    for (Index v = 0; v < m.vertex_slots(); ++v) list.push_back(Vertex(v));
  } else {
    for (const std::int64_t v : index_list(vertices, "one_rings", "vertices", m.vertex_slots()))
      list.push_back(binding::live_vertex(m, element_index(v, "vertex")));
  }
  py::array_t<std::int64_t> offsets(static_cast<py::ssize_t>(list.size() + 1));
  std::int64_t* off = offsets.mutable_data();
  std::size_t total = 0;
  {
    py::gil_scoped_release unlocked;
    off[0] = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (!m.is_deleted(list[i]) && !m.is_isolated(list[i]))
        for ([[maybe_unused]] const Halfedge h : m.halfedges(list[i])) ++total;
      off[i + 1] = static_cast<std::int64_t>(total);
    }
  }
  py::array_t<std::int32_t> neighbours(static_cast<py::ssize_t>(total));
  std::int32_t* out = neighbours.mutable_data();
  {
    py::gil_scoped_release unlocked;
    for (const Vertex v : list) {
      if (m.is_deleted(v) || m.is_isolated(v)) continue;
      for (const Halfedge h : m.halfedges(v)) *out++ = static_cast<std::int32_t>(m.to_vertex(h).idx());
    }
  }
  return py::make_tuple(offsets, neighbours);
}

}  // namespace

void bind_queries(py::class_<Mesh>& mesh) {
  halfedge_query(
      mesh, "next", [](const SurfaceMesh& m, Halfedge h) { return m.next(h).idx(); },
      "The next half-edge in the face (or boundary loop) of the half-edge.");
  halfedge_query(
      mesh, "prev", [](const SurfaceMesh& m, Halfedge h) { return m.prev(h).idx(); },
      "The previous half-edge in the face (or boundary loop); O(face degree), as prev is not stored.");
  halfedge_query(
      mesh, "twin", [](const SurfaceMesh&, Halfedge h) { return SurfaceMesh::twin(h).idx(); },
      "The opposite half-edge: h ^ 1.");
  halfedge_query(
      mesh, "to_vertex", [](const SurfaceMesh& m, Halfedge h) { return m.to_vertex(h).idx(); },
      "The vertex the half-edge points to.");
  halfedge_query(
      mesh, "from_vertex", [](const SurfaceMesh& m, Halfedge h) { return m.from_vertex(h).idx(); },
      "The vertex the half-edge leaves: its twin's target.");
  halfedge_query(
      mesh, "face", [](const SurfaceMesh& m, Halfedge h) { return m.face(h).idx(); },
      "The face of the half-edge, -1 on the boundary.");
  halfedge_query(
      mesh, "edge", [](const SurfaceMesh&, Halfedge h) { return SurfaceMesh::edge(h).idx(); },
      "The edge of the half-edge: h >> 1.");
  mesh.def(
          "vertex_halfedge",
          [](const Mesh& self, std::int64_t v) {
            const auto use = self.use();
            const SurfaceMesh& m = use->mesh;
            return index_or_none(m.halfedge(binding::live_vertex(m, element_index(v, "vertex"))).idx());
          },
          py::arg("vertex"),
          "The vertex's outgoing half-edge (a boundary one on a boundary vertex), -1 if isolated.")
      .def(
          "face_halfedge",
          [](const Mesh& self, std::int64_t f) {
            const auto use = self.use();
            const SurfaceMesh& m = use->mesh;
            return index_or_none(m.halfedge(binding::live_face(m, element_index(f, "face"))).idx());
          },
          py::arg("face"), "The face's half-edge: its corners start at this half-edge's target.")
      .def(
          "one_ring",
          [](const Mesh& self, std::int64_t v) {
            return around(self, v, [](const SurfaceMesh& m, Halfedge h) { return m.to_vertex(h).idx(); });
          },
          py::arg("vertex"),
          "The vertex's neighbours, clockwise, from the target of vertex_halfedge(vertex): an int32 array.")
      .def(
          "vertex_faces",
          [](const Mesh& self, std::int64_t v) {
            return around(self, v, [](const SurfaceMesh& m, Halfedge h) { return m.face(h).idx(); });
          },
          py::arg("vertex"),
          "The faces around the vertex, clockwise (the face of each outgoing half-edge; a boundary gap "
          "has none): an int32 array.")
      .def("one_rings", &one_rings, py::arg("vertices") = py::none(),
           "The one-rings of many vertices in one call (every vertex slot if vertices is None): "
           "(offsets, neighbours), int64 and int32 arrays; vertex i's ring, clockwise as one_ring() "
           "gives it, is neighbours[offsets[i]:offsets[i + 1]]. A deleted or isolated vertex slot has "
           "an empty ring; a listed vertex must be live (BadHandleError).")
      .def(
          "is_boundary",
          [](const Mesh& self, std::int64_t v) {
            const auto use = self.use();
            const SurfaceMesh& m = use->mesh;
            return m.is_boundary(binding::live_vertex(m, element_index(v, "vertex")));
          },
          py::arg("vertex"), "True if the vertex is on a boundary, or isolated (it has no face all around).")
      .def(
          "boundary_vertices",
          [](const Mesh& self) {
            const auto use = self.use();
            const SurfaceMesh& m = use->mesh;
            py::array_t<bool> out(static_cast<py::ssize_t>(m.vertex_slots()));
            bool* p = out.mutable_data();
            for (std::size_t i = 0; i < m.vertex_slots(); ++i) {
              const Vertex v(static_cast<Index>(i));
              p[i] = !m.is_deleted(v) && m.is_boundary(v);
            }
            return out;
          },
          "is_boundary() of every vertex slot at once: a bool array (vertex_slots,), False for deleted "
          "slots. np.flatnonzero() of it lists the boundary vertices.");
}

}  // namespace hedge::python

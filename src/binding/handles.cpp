#include "binding/handles.h"

#include "binding/errors.h"

namespace hedge::binding {

std::string element_name(const char* kind, std::uint32_t index) {
  return std::string(kind) + " " + std::to_string(index);
}

void check_range(const char* kind, std::uint32_t i, std::size_t slots) {
  if (i >= slots) {
    if (i == kInvalidIndex)
      fail(HEDGE_ERROR_BAD_HANDLE, std::string(kind) + " is the invalid index (HEDGE_INVALID_INDEX, -1)");
    fail(HEDGE_ERROR_BAD_HANDLE, element_name(kind, i) + " is out of range (the mesh has " +
                                     std::to_string(slots) + " " + kind + " slots)");
  }
}

namespace {
// A live element, or the failure that says why i names none.
template <typename H>
H live(const SurfaceMesh& m, std::uint32_t i, std::size_t slots) {
  if (m.is_live(H(i))) return H(i);
  check_range(element_kind<H>(), i, slots);
  fail(HEDGE_ERROR_BAD_HANDLE, element_name(element_kind<H>(), i) + " is deleted");
}
}  // namespace

Vertex live_vertex(const SurfaceMesh& m, std::uint32_t v) { return live<Vertex>(m, v, m.vertex_slots()); }
Halfedge live_halfedge(const SurfaceMesh& m, std::uint32_t h) {
  return live<Halfedge>(m, h, m.halfedge_slots());
}
Edge live_edge(const SurfaceMesh& m, std::uint32_t e) { return live<Edge>(m, e, m.edge_slots()); }
Face live_face(const SurfaceMesh& m, std::uint32_t f) { return live<Face>(m, f, m.face_slots()); }

}  // namespace hedge::binding

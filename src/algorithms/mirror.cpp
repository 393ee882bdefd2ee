// mirror_x(): see include/hedge/algorithms/mirror.h.
#include "hedge/algorithms/mirror.h"

#include <vector>

namespace hedge {

namespace {
void negate_x(Vec3& v) { v.x = -v.x; }
}  // namespace

void mirror_x(SurfaceMesh& mesh) {
  const std::size_t slots = mesh.halfedge_slots();
  // Reversing a face loop turns half-edge h around: it now enters the corner its predecessor
  // entered (from_vertex(h)), and its next is its old prev. Boundary loops turn the same way.
  std::vector<Halfedge> prev(slots);
  std::vector<Vertex> from(slots);
  for (Halfedge h : mesh.halfedges()) {
    from[h.idx()] = mesh.from_vertex(h);
    prev[mesh.next(h).idx()] = h;
  }
  // A corner's attributes live on the half-edge that enters it: they move from prev(h) to h.
  const PropertyContainer old = mesh.halfedge_properties();
  for (Halfedge h : mesh.halfedges()) {
    mesh.set_vertex(h, from[h.idx()]);
    mesh.set_next(h, prev[h.idx()]);
    mesh.halfedge_properties().copy_element_from(old, prev[h.idx()].idx(), h.idx());
  }
  // A vertex's outgoing half-edge is now incoming; its twin goes out (a boundary one if any).
  for (Vertex v : mesh.vertices())
    if (!mesh.is_isolated(v)) {
      mesh.set_halfedge(v, SurfaceMesh::twin(mesh.halfedge(v)));
      mesh.adjust_outgoing_halfedge(v);
    }

  for (Vertex v : mesh.vertices()) {
    Vec3 p = mesh.position(v);
    negate_x(p);
    mesh.set_position(v, p);
  }
  if (auto n = mesh.get_vertex_property<Vec3>("v:normal"))
    for (Vertex v : mesh.vertices()) negate_x(n[v]);
  if (auto n = mesh.get_halfedge_property<Vec3>("h:normal"))
    for (Halfedge h : mesh.halfedges()) negate_x(n[h]);
  if (auto n = mesh.get_face_property<Vec3>("f:normal"))
    for (Face f : mesh.faces()) negate_x(n[f]);
  mesh.changes().mark_reset();
  mesh.changes().notify();
}

}  // namespace hedge

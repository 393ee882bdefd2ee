// Helpers shared by the local operations of core/operations.h, which live in two sources:
// edge_operations.cpp (split_edge, collapse, flip) and face_operations.cpp (split_face, cut_face,
// add, remove). Not installed.
#pragma once

#include "hedge/core/surface_mesh.h"

namespace hedge::operations_detail {

using Mesh = SurfaceMesh;

// Change log: every face with a corner at v changed (its corners, or the corner data there).
inline void mark_faces_around(Mesh& m, Vertex v, ChangeEvent events) {
  if (!m.changes().active()) return;
  for (Face f : m.faces(v)) m.mark_changed(f, events);
}

// The change-log marks of a split that made v: every face around v changed or is new.
inline void mark_split(Mesh& m, Vertex v) {
  if (m.changes().active()) {  // nothing to mark or tell when nobody listens
    mark_faces_around(m, v,
                      ChangeEvent::faces_changed | ChangeEvent::faces_added | ChangeEvent::vertices_added);
    m.changes().notify();
  }
}

}  // namespace hedge::operations_detail

// Connected components of a mesh: the pieces it falls into, by faces that share an edge or by
// vertices that share an edge. The shards of a fracture, the islands of a scan.
#pragma once

#include <cstddef>
#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

struct Components {
  //! The component of each element slot (of faces or of vertices, by the function), numbered
  //! 0..count-1 in the order of each component's lowest element index; kInvalidIndex for deleted
  //! elements and for what belongs to no component (isolated vertices).
  std::vector<Index> label;
  //! The number of components.
  std::size_t count = 0;
};

//! The faces joined across edges: two faces are in one component when a path of faces, each
//! sharing an edge with the next, joins them. Faces touching only at a vertex are apart. One label
//! per face slot. O(F + E).
Components face_components(const SurfaceMesh& mesh);

//! The vertices joined by edges. One label per vertex slot; an isolated vertex (no edge) belongs
//! to no component: its label is kInvalidIndex and it is not counted. O(V + E).
Components vertex_components(const SurfaceMesh& mesh);

}  // namespace hedge

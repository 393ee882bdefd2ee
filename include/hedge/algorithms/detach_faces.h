// Detaching a piece: a set of faces leaves its mesh as a new mesh.
#pragma once

#include <span>
#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Copies `faces` out as a new SurfaceMesh with all their properties, and removes them from
//! `mesh`. Vertices of `mesh` that the removal leaves pinched (two fans) are split, so both
//! meshes stay manifold. `vertex_origin`, if given, receives new-mesh vertex -> source vertex.
//! Deleted or repeated faces are ignored. O(size of the set + its one-ring).
SurfaceMesh detach_faces(SurfaceMesh& mesh, std::span<const Face> faces,
                         std::vector<Vertex>* vertex_origin = nullptr);

}  // namespace hedge

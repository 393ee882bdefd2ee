// Closing a hole: the boundary loop through a half-edge is filled with new faces.
#pragma once

#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Fills the boundary loop of boundary half-edge h with triangles, choosing each time the shortest
//! diagonal that does not exist yet; a loop that cannot be triangulated that way keeps one
//! polygon for its rest. \return the new faces, empty if h is not a live boundary half-edge.
//! O(loop length^2).
std::vector<Face> fill_hole(SurfaceMesh& mesh, Halfedge h);

}  // namespace hedge

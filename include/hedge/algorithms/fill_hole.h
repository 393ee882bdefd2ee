// Closing a hole: the boundary loop through a half-edge is filled with new faces.
#pragma once

#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! True if fill_hole_refusal(mesh, h) is null: h is a live boundary half-edge whose boundary loop
//! has at least 3 edges (a loop of 2, which repaired input may hold, has no room for a face).
//! O(loop length).
bool can_fill_hole(const SurfaceMesh& mesh, Halfedge h);
//! Why can_fill_hole(mesh, h) is false, in a few words ("the half-edge is not on a boundary", ...);
//! null if the hole can be filled. The string is static. Same cost as can_fill_hole().
const char* fill_hole_refusal(const SurfaceMesh& mesh, Halfedge h);
//! Fills the boundary loop of boundary half-edge h with triangles, choosing each time the shortest
//! diagonal that does not exist yet; a loop that cannot be triangulated that way keeps one
//! polygon for its rest. \return the new faces, at least one; empty if refused (see
//! can_fill_hole), and then the mesh is unchanged. O(loop length^2).
std::vector<Face> fill_hole(SurfaceMesh& mesh, Halfedge h);

}  // namespace hedge

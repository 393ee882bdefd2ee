// Splitting every face of a mesh at its centroid, in one pass.
#pragma once

#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Splits every live face of n corners into n triangles about a new vertex at its centroid; nothing
//! moves. \return the new vertices, one per face in face order. O(n).
//! On a mesh without deleted elements this is one step of subdivide(mesh, Subdivision::split_faces)
//! (algorithms/subdivide.h), built by index arithmetic: vertex, edge and half-edge indices are kept,
//! face f's vertex is vertex_slots() + f, and faces are renumbered (face f's triangles are numbered
//! by its corners, face by face); the change log records a reset. With deleted elements present
//! it splits face by face instead (core/operations.h split_face), so that every index, and the
//! garbage, stays where it was.
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
std::vector<Vertex> split_all_faces(SurfaceMesh& mesh);

}  // namespace hedge

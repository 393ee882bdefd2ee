// Mirroring a mesh in a coordinate plane: the change between right-handed files (OBJ, PLY, glTF,
// ...) and a left-handed engine's space (Unity's importers negate x).
#pragma once

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! Mirrors the mesh in the plane x = 0 and reverses every face, so that faces keep facing out:
//! negates x of the positions and of the normals ("v:normal", "h:normal", "f:normal"), and reverses
//! each face's corner order, its corner attributes (every half-edge property) staying with their
//! corners. Indices of vertices, edges and faces are kept; the change log records a reset. It is
//! its own inverse: applied twice it gives the mesh back bit for bit. O(n).
//!
//! This is the rule of Unity's model importers (OBJ, FBX): x negated in positions and normals,
//! triangles reversed, texture coordinates unchanged. Reading a file with it gives what Unity's
//! importer gives; applying it again before writing gives the file's own space back.
void mirror_x(SurfaceMesh& mesh);

}  // namespace hedge

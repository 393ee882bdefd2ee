// Exporting a SurfaceMesh back to index buffers: the inverse of build() (core/build.h).
#pragma once

#include <vector>

#include "hedge/core/indexed_mesh.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

//! The orientation of faces in an index buffer, seen from the side their normals point to. Also
//! used by the render layer, for engine index buffers in both directions.
enum class Winding { ccw, cw };

enum class Triangulation {
  none,  //!< polygons as they are
  fan,   //!< fan from each face's first corner (from fan_start()'s where that fan folds)
  ear,   //!< ear clipping in the face's best-fit plane (robust on concave faces)
};

struct ExportOptions {
  Triangulation triangulation = Triangulation::none;
  //! cw reverses every face: Unity and Direct3D conventions.
  Winding winding = Winding::ccw;
  //! Write "h:texcoord" / "h:normal" / "h:color" corner properties into the attribute pools when
  //! present.
  bool corner_attributes = true;
};

//! Exports live faces to an indexed mesh. Vertex order follows the mesh, deleted vertices skipped.
//! Faces follow the mesh's face order and each starts at its first corner (the one halfedge(f)
//! enters), so clean input built without welding comes back with the same indices. face_sizes stays
//! empty when every output face is a triangle. "h:texcoord" (Vec2), "h:normal" (Vec3) and "h:color"
//! (Color) corner properties become pools of their distinct values with one index per corner; a property of
//! that name with another type is treated as absent. The face property "f:submesh" (std::int32_t) becomes
//! face_submeshes, one per output face (each triangle of a triangulated face gets the face's). With
//! Winding::cw each face keeps its first corner and lists the others in reverse. \param vertex_map if given,
//! receives mesh vertex -> output vertex (kInvalidIndex for deleted). \pre mesh is valid (mesh.validate() is
//! empty); this is not checked, and an invalid mesh gives
//!      undefined results.
//! Throws only std::bad_alloc. O(vertex slots + corners) time, plus an expected O(1) hash lookup
//! per corner attribute and O(n^2) per n-gon with Triangulation::ear.
IndexedMesh to_indexed(const SurfaceMesh& mesh, const ExportOptions& options = {},
                       std::vector<Index>* vertex_map = nullptr);

}  // namespace hedge

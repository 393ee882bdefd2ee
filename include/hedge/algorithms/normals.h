// Normals: of faces, of vertices (weighted by area, angle or uniformly), and of corners with a
// crease angle, which is what an engine needs to draw hard edges on an otherwise smooth surface.
//
// All of them read positions only and work on any polygon mesh; a degenerate face (zero area) has
// a zero normal and adds nothing. Results are stored as properties, so that RenderBuffers
// (NormalSource::attribute), the writers and the C ABI find them: the writes are marked in the
// change log (vertex data, or face corners), so that a RenderBuffers watching the mesh updates them.
#pragma once

#include <string_view>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! How the faces around a vertex are weighted in its normal.
enum class NormalWeighting {
  area,     //!< by face area: cheap and robust; the usual choice for smooth vertex normals
  angle,    //!< by the face's angle at the vertex: independent of how the faces are tessellated
  uniform,  //!< every face alike
};

//! The unit normal of face f, by Newell's method (exact for planar polygons, a best fit for others),
//! oriented by the face's winding (counter-clockwise seen from the front). Zero for a degenerate
//! face. O(face degree).
Vec3 face_normal(const SurfaceMesh& mesh, Face f);

//! Unit face normals of every live face into face property `name` (created if missing). O(F).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
FaceProperty<Vec3> compute_face_normals(SurfaceMesh& mesh, std::string_view name = "f:normal");

//! Unit vertex normals into vertex property `name` (created if missing): the weighted sum of the
//! normals of the faces around each vertex, normalised. Isolated vertices, and vertices whose faces
//! cancel out, get a zero normal. O(V + F).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
VertexProperty<Vec3> compute_vertex_normals(SurfaceMesh& mesh,
                                            NormalWeighting weighting = NormalWeighting::area,
                                            std::string_view name = "v:normal");

//! Corner normals into half-edge property `name` (created if missing), for the corner of face(h) at
//! to_vertex(h). Around each vertex the faces fall into wedges separated by boundary gaps and by
//! crease edges, where the two faces' normals differ by more than `crease_degrees`; every corner of
//! a wedge gets the wedge's weighted normal. crease_degrees = 0 gives face normals at every corner
//! (flat shading), 180 the vertex normal (smooth); about 30-60 is typical for hard-surface models.
//! A vertex with neither a boundary edge nor a crease edge gets at every corner exactly what
//! compute_vertex_normals(weighting) gives it, bit for bit (the faces are summed in face order);
//! the wedges of the other vertices are summed around the vertex from a wedge end.
//! Boundary half-edges (no face) get zero. O(V + F).
//! \throw InvalidInputError if crease_degrees is not in [0, 180].
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
HalfedgeProperty<Vec3> compute_corner_normals(SurfaceMesh& mesh, double crease_degrees,
                                              NormalWeighting weighting = NormalWeighting::angle,
                                              std::string_view name = "h:normal");

}  // namespace hedge

// Local edits of edges on a SurfaceMesh: split_edge, collapse and flip. The contract shared by
// every local edit (refusals and their can_* predicates, how properties follow an edit) is in
// core/operations.h, which includes this header and core/face_operations.h.
//
// The corner rule of a collapse: a collapse keeps each chart seamless. Around the two ends, faces
// joined across an edge that is no seam form one chart (a seam edge: its two faces hold different
// corner values, in any corner property, at either end; the corner of vertex x in face f is stored
// on the half-edge entering x in f). Every corner of the vertex merged away takes the values of the
// survivor's corners in its chart: the survivor keeps its own corner values, as it keeps its
// position. A collapse along a seam therefore keeps both sides consistent; one that would pull a
// seam vertex off its seam (a chart of the merged vertex without a survivor corner), join two sides
// of a seam at the survivor, or shorten a seam that ends at the merged vertex, is refused.
#pragma once

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! True if e can be split (e is live): split_refusal(mesh, e) is null. O(1).
bool can_split_edge(const SurfaceMesh& mesh, Edge e);
//! Why split_edge(mesh, e, ...) is refused ("the edge is not live"); null if it is allowed. The
//! string is static. O(1).
const char* split_refusal(const SurfaceMesh& mesh, Edge e);
//! Inserts a vertex at `point` on e. A triangle on either side is split into two triangles; a
//! polygon simply gains the vertex. `point` may lie anywhere, even off the segment; interpolation
//! uses its projection onto the edge, clamped to the segment.
//! \return the new vertex; halfedge(e, 0) now runs from vertex(e, 0) to it. Invalid if refused.
Vertex split_edge(SurfaceMesh& mesh, Edge e, const Vec3& point);

//! True if collapse_refusal(mesh, h) is null: collapsing h keeps the mesh a valid, manifold surface: the link
//! condition holds (the ends share no neighbour but the tips of the triangles on h), the faces on h are
//! distinct, no interior vertex is left with valence below 3 (which also refuses the collapse of a
//! tetrahedron), no edge is left with a boundary on both sides, an interior edge does not join
//! two boundary vertices, and, when the mesh has corner properties, the collapse keeps every chart
//! seamless (see the corner rule at the top of this file). O(valence), O(valence^2 + valence x
//! corner properties) with corner properties.
bool can_collapse(const SurfaceMesh& mesh, Halfedge h);
//! Why can_collapse(mesh, h) is false, in a few words ("the surviving vertex would be left with too
//! few edges", "it would pull a seam vertex off its seam", ...); null if the collapse is allowed.
//! The string is static. Same cost as can_collapse().
const char* collapse_refusal(const SurfaceMesh& mesh, Halfedge h);
//! Merges from_vertex(h) into to_vertex(h); the caller chooses the survivor by choosing the
//! direction of h, and keeps or sets its position. Triangles on h vanish and their two other edges
//! merge. The merged vertex's corners take the survivor's corner values in their chart (the corner
//! rule above). \return the surviving vertex, invalid if refused. O(valence).
Vertex collapse(SurfaceMesh& mesh, Halfedge h);

//! True if flip_refusal(mesh, e) is null: e is interior, both its faces are triangles, its tips
//! differ and are not joined by an edge already, and neither end is an interior vertex of valence 3.
//! O(valence).
bool can_flip(const SurfaceMesh& mesh, Edge e);
//! Why can_flip(mesh, e) is false, in a few words ("the edge is on the boundary", ...); null if the
//! flip is allowed. The string is static. Same cost as can_flip().
const char* flip_refusal(const SurfaceMesh& mesh, Edge e);
//! Turns e to join the two tips of its triangles. \return e, invalid if refused.
Edge flip(SurfaceMesh& mesh, Edge e);

}  // namespace hedge

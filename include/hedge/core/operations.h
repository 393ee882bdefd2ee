// Local topology edits on a SurfaceMesh.
//
// Every operation that can be illegal has a public predicate (can_*) and returns an empty result
// (an invalid handle, false, or an empty list) when refused; a refused operation leaves the mesh
// exactly as it was. Each such edit also has a refusal (*_refusal): why the edit is refused, in a
// few words, as a static string, or null if it is allowed. Its can_* is exactly "the refusal is
// null", so the two cannot disagree; the bindings report the refusal as the reason. Each costs
// O(1) or O(valence) unless noted.
// Properties follow the edits:
//  - vertex properties of a new vertex are interpolated from the vertices around it (blended for
//    float-like types, taken from the nearest source otherwise; see BasePropertyArray::interpolate),
//    or by a policy of the user's set per property with Property::set_interpolator();
//  - corner (half-edge) properties such as "h:texcoord" are interpolated along a split edge and
//    copied to the corners a face is split into, so a split inside a chart (see below) gives the
//    new vertex one value and keeps the chart seamless;
//  - a collapse keeps each chart seamless: around the two ends, faces joined across an edge that is
//    no seam form one chart (a seam edge: its two faces hold different corner values, in any corner
//    property, at either end; the corner of vertex x in face f is stored on the half-edge entering
//    x in f). Every corner of the vertex merged away takes the values of the survivor's corners in
//    its chart: the survivor keeps its own corner values, as it keeps its position. A collapse along
//    a seam therefore keeps both sides consistent; one that would pull a seam vertex off its seam
//    (a chart of the merged vertex without a survivor corner), join two sides of a seam at the
//    survivor, or shorten a seam that ends at the merged vertex, is refused;
//  - face properties are copied to the faces a face is split into; edge properties are copied to
//    the two halves of a split edge.
// Deleted elements stay in storage until garbage_collection().
#pragma once

#include <span>

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

//! True if f is live: split_face_refusal(mesh, f) is null. O(1).
bool can_split_face(const SurfaceMesh& mesh, Face f);
//! Why split_face(mesh, f, ...) is refused ("the face is not live"); null if it is allowed. The
//! string is static. O(1).
const char* split_face_refusal(const SurfaceMesh& mesh, Face f);
//! Inserts a vertex at `point` into f and connects it to every corner: a triangle becomes 3
//! triangles, an n-gon n triangles. The new vertex's properties are
//! interpolated with barycentric weights on a triangle and equal weights on a polygon.
//! \return the new vertex, invalid if refused. O(face degree).
Vertex split_face(SurfaceMesh& mesh, Face f, const Vec3& point);

//! True if cut_face_refusal(mesh, h0, h1) is null: h0 and h1 are two half-edges of the same live
//! face, their targets are not adjacent in it, and no edge joins them yet. O(face degree + valence).
bool can_cut_face(const SurfaceMesh& mesh, Halfedge h0, Halfedge h1);
//! Why can_cut_face(mesh, h0, h1) is false, in a few words; null if the cut is allowed. The string
//! is static. Same cost as can_cut_face().
const char* cut_face_refusal(const SurfaceMesh& mesh, Halfedge h0, Halfedge h1);
//! Cuts the face of h0 and h1 in two along a new edge (a diagonal) from to_vertex(h0) to
//! to_vertex(h1); no vertex is added.
//! \return the new half-edge from to_vertex(h0) to to_vertex(h1), invalid if refused. O(face degree).
Halfedge cut_face(SurfaceMesh& mesh, Halfedge h0, Halfedge h1);

//! The mean of f's corner positions (accumulated in double). O(face degree).
Vec3 face_centroid(const SurfaceMesh& mesh, Face f);

//! True if add_face_refusal(mesh, vertices) is null: a face with these corners can be added while
//! every vertex and edge stays manifold: at least 3 distinct live vertices; each existing edge free
//! on the new face's side; each non-isolated vertex on a boundary, with the new face entering its
//! boundary gap. O(n valence).
bool can_add_face(const SurfaceMesh& mesh, std::span<const Vertex> vertices);
//! Why can_add_face(mesh, vertices) is false, in a few words; null if the face can be added. The
//! string is static. Same cost as can_add_face().
const char* add_face_refusal(const SurfaceMesh& mesh, std::span<const Vertex> vertices);
//! Adds a face with the given corners (counter-clockwise); boundaries are relinked.
//! \attention Vertices stay manifold, so a face that would meet the mesh at a vertex only (no
//! shared edge there) is refused. Building face by face therefore needs an order in which each
//! face meets the faces before it along edges (breadth-first over adjacency); for bulk input in any
//! order, use build(), which is also O(n) instead of O(n valence).
//! \return the new face, invalid if refused.
Face add_face(SurfaceMesh& mesh, std::span<const Vertex> vertices);

//! True if remove_face_refusal(mesh, f) is null: f is live and removing it leaves every vertex
//! manifold (a vertex already on a boundary must share a boundary edge with f). O(face degree).
bool can_remove_face(const SurfaceMesh& mesh, Face f);
//! Why can_remove_face(mesh, f) is false, in a few words; null if f can be removed. Static string.
const char* remove_face_refusal(const SurfaceMesh& mesh, Face f);
//! Removes f; edges left with no face are removed, and so are vertices left with no edge.
//! \return false if refused.
bool remove_face(SurfaceMesh& mesh, Face f);

//! True if remove_vertex_refusal(mesh, v) is null: v is live and removing it with its faces leaves
//! every remaining vertex manifold. O(valence^2).
bool can_remove_vertex(const SurfaceMesh& mesh, Vertex v);
//! Why can_remove_vertex(mesh, v) is false, in a few words; null if v can be removed. Static string.
const char* remove_vertex_refusal(const SurfaceMesh& mesh, Vertex v);
//! Removes v, its faces, and what they leave unused. \return false if refused.
bool remove_vertex(SurfaceMesh& mesh, Vertex v);

//! Removes the live faces among `faces` (deleted, invalid and repeated handles are ignored); edges
//! left with no face are removed, and so are vertices left with no edge. Never refused: unlike
//! remove_face(), it splits a vertex that the removal leaves pinched (two or more fans meeting at
//! it alone), giving each fan but the first a copy of the vertex with its properties, so the mesh
//! stays manifold. O(n log n + the one-rings of their corners) for n faces.
void remove_faces(SurfaceMesh& mesh, std::span<const Face> faces);

}  // namespace hedge

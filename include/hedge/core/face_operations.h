// Local edits of faces on a SurfaceMesh: split_face, cut_face, add_face and the removals
// (remove_face, remove_vertex, remove_faces), with the face centroid they place vertices at. The
// contract shared by every local edit (refusals and their can_* predicates, how properties follow
// an edit) is in core/operations.h, which includes this header and core/edge_operations.h.
#pragma once

#include <span>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

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

//! The mean of f's corner positions, accumulated in double and returned as VecN<T, 3> (T is float
//! or double; the origin for a face without corners). The geometry toolkit's centroid()
//! (algorithms/geometry.h) is face_centroid<double>. O(face degree).
template <typename T = float>
VecN<T, 3> face_centroid(const SurfaceMesh& mesh, Face f);
extern template Vec3 face_centroid<float>(const SurfaceMesh&, Face);
extern template Vec3d face_centroid<double>(const SurfaceMesh&, Face);

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
//! stays manifold. O(n log n + the one-rings of their corners) for n faces. Keeps, for the
//! calling thread's life, a byte of scratch per vertex slot of the largest mesh it was given.
void remove_faces(SurfaceMesh& mesh, std::span<const Face> faces);

}  // namespace hedge

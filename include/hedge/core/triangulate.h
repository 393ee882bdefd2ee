// Triangulation of one polygon face, shared by export and render buffers; and the fan that
// stands for a polygon face in volume(), the picking tree (FaceBvh), export's fan and solid
// fracture, so that they all see the same triangles.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "hedge/core/handles.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! Adds the term of polygon edge a -> b to a Newell normal; summed over the edges of a polygon this
//! gives twice its area times its unit normal (exact for planar polygons).
inline void add_newell_term(Vec3d& n, const Vec3d& a, const Vec3d& b) {
  n.x += (a.y - b.y) * (a.z + b.z);
  n.y += (a.z - b.z) * (a.x + b.x);
  n.z += (a.x - b.x) * (a.y + b.y);
}

//! Ear clipping of one polygon (corner positions p, in order) in its best-fit (Newell) plane, so
//! concave faces triangulate correctly. Appends n - 2 corner-index triples to `tris` (none for
//! n < 3), in the polygon's orientation: each time the ear of the smallest corner index, the first
//! a scan from corner 0 finds (an ear: a strictly convex corner whose triangle with its neighbours
//! holds, not even on its border, no other corner that is not strictly convex; in a simple polygon,
//! no other corner at all). Where no ear is found (self-intersecting input) the corners left are
//! fanned from the smallest. O(n^2) for n corners in the worst case: a clip tests only the two
//! corners beside it again, an ear test looks only at the corners that are not strictly convex,
//! through a grid over the polygon, and a self-intersecting polygon is searched again for ears at
//! most a few times n corners in all. Typical polygons cost far less: 10,000 corners take about
//! 20 ms on a jittered circle, 30 ms as a comb, 1 ms as a zigzag strip.
void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris);

//! The corner k whose fan, the triangles (p[k], p[k+i], p[k+i+1]) for i = 1..n-2 (indices modulo
//! n), stands for the polygon: 0, unless a triangle of the fan from corner 0 folds (its normal
//! points against the polygon's Newell normal, as where a non-planar quad is split along the wrong
//! diagonal); then the corner whose fan's most tilted triangle (smallest cosine of the angle
//! between its normal and the Newell normal, a degenerate triangle counting 0) is least tilted,
//! the smallest such k on ties. Planar convex polygons keep corner 0. Polygons of more than 64
//! corners choose among 64 corners spread evenly, k = j n / 64 for j = 0..63, so that the cost stays
//! O(n), as the faces of a hostile file may be huge. O(n) for n <= 64, O(64 n) above; O(1) for n = 3.
std::size_t fan_apex(std::span<const Vec3d> p);

//! The half-edge of face f that points to its fan's apex (fan_apex() of its corners in the order
//! of halfedges(f)): halfedge(f) for triangles and for every polygon whose first-corner fan does
//! not fold. The fan is (to_vertex(h), to_vertex(next(h)), to_vertex(next(next(h)))), ...
Halfedge fan_start(const SurfaceMesh& mesh, Face f);

}  // namespace hedge

// Triangulation of one polygon face, shared by export and render buffers.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "hedge/core/handles.h"
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
//! concave faces triangulate correctly. Appends n - 2 corner-index triples to `tris`, in the
//! polygon's orientation; falls back to a fan where no ear is found (self-intersecting input).
//! O(n^2) for n corners.
void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris);

}  // namespace hedge

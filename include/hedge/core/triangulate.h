// Triangulation of one polygon face, shared by export and render buffers.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "hedge/core/handles.h"
#include "hedge/core/vec.h"

namespace hedge {

//! Ear clipping of one polygon (corner positions p, in order) in its best-fit (Newell) plane, so
//! concave faces triangulate correctly. Appends n - 2 corner-index triples to `tris`, in the
//! polygon's orientation; falls back to a fan where no ear is found (self-intersecting input).
//! O(n^2) for n corners.
void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris);

}  // namespace hedge

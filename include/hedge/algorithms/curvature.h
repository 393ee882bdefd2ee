// Discrete curvature per vertex, from the cotangent Laplacian (mean curvature) and the angle
// defect (Gaussian curvature), with barycentric vertex areas (geometry.h). Any polygons: a face
// counts as the fan triangles (c0, c[i], c[i+1]) of its first corner, as in render buffers.
#pragma once

#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge {

//! The signed mean curvature of every vertex slot: half the length of the cotangent Laplacian of
//! the positions, divided by the vertex's barycentric area (so 1/r on a sphere of radius r),
//! positive where the surface bends away from its normals (a convex bump of a surface with outward
//! normals), negative where it bends toward them. 0 on boundary vertices, isolated or deleted ones,
//! and vertices of zero area. The normal is the area-weighted sum of the faces' Newell vectors.
//! O(V + F).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
std::vector<double> mean_curvature(const SurfaceMesh& mesh);

//! The Gaussian curvature of every vertex slot: the angle defect 2 pi minus the sum of the corner
//! angles of the fan triangles at the vertex, divided by its barycentric area (so 1/r^2 on a sphere
//! of radius r; summed with the areas over a closed surface, 2 pi times its Euler characteristic).
//! 0 on boundary vertices, isolated or deleted ones, and vertices of zero area. O(V + F).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
std::vector<double> gaussian_curvature(const SurfaceMesh& mesh);

}  // namespace hedge

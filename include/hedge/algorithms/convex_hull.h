// The convex hull of a point set, as a closed triangle mesh a physics engine can use as a collider.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! How many dimensions the point set spans, at the hull's tolerance.
enum class HullDimension {
  empty,    //!< no point at all
  point,    //!< all points coincide
  segment,  //!< all points lie on one line
  flat,     //!< all points lie in one plane: the hull is given a thickness (see ConvexHullOptions)
  solid,    //!< the points span a volume
};

struct ConvexHullOptions {
  //! Points within this distance of a face's plane count as on it; relative to the length of the
  //! point set's bounding-box diagonal. Never finer than two float steps of the largest coordinate,
  //! the rounding float input already carries (points of a tilted plane are coplanar only to
  //! that). Must be finite and in [0, 0.01].
  double relative_tolerance = 1e-9;
  //! The full thickness given to a flat (coplanar) set, relative to the bounding-box diagonal: the
  //! hull is the prism of the flat polygon offset by half of it to each side of its plane. It is
  //! raised where needed to 16 float steps of the largest coordinate, so that the two sides stay
  //! apart after rounding to float. Must be finite and in (0, 1].
  double flat_thickness = 1e-3;
  //! At most this many hull vertices; 0 for no limit, otherwise at least 4 (PhysX caps convex
  //! meshes at 255). When the hull of all points would have more, the hull of a subset is returned
  //! (see convex_hull()).
  std::size_t max_vertices = 0;
};

struct ConvexHull {
  //! The hull: a closed, valid triangle mesh with outward (counter-clockwise seen from outside)
  //! faces, Euler characteristic 2, every vertex an input point (or, for a flat set, an input point
  //! moved off its plane by half the thickness). Empty for dimension empty, point and segment.
  SurfaceMesh mesh;
  HullDimension dimension = HullDimension::empty;
  //! Hull vertex index -> the input point it is (for a flat set: the point it was offset from).
  std::vector<std::uint32_t> input_index;
  //! The absolute tolerance used: every input point lies inside the hull or within this distance
  //! of it, unless the vertex limit cut the hull (see max_outside_distance).
  double tolerance = 0;
  //! The thickness given to a flat set (0 otherwise), absolute.
  double thickness = 0;
  //! With a vertex limit, the largest distance of an input point outside the returned hull (0 when
  //! the limit was not reached).
  double max_outside_distance = 0;
};

//! The convex hull of `points`, by quickhull (Barber, Dobkin, Huhdanpaa 1996): from the tetrahedron
//! of four extreme points, the point farthest outside the current hull, over all faces, is added
//! next, replacing the faces it sees by a fan to their horizon. Computed in double relative to the
//! bounding-box centre, so coordinates far from the origin (1e6 with small extents) keep their
//! digits. Duplicate points are fine. The result does not depend on anything but the input.
//!
//! Degenerate sets, decided at the tolerance:
//!  - no point, all points coincident, or all on one line: `mesh` is empty and `dimension` says
//!    which. No solid collider can be made honestly; an engine wants a sphere or a capsule there.
//!  - all points in one plane (three non-collinear points included): a thin closed prism, `thickness`
//!    thick, and dimension `flat`. Engines (PhysX, and Unity's MeshCollider on it) refuse to cook a
//!    planar convex mesh, yet a flat shard must still collide, so it gets a thickness it can use.
//!
//! Vertex limit: the hull grows by the farthest point first and stops when it has max_vertices
//! vertices, so the result is the hull of the most extreme points chosen greedily; it lies inside
//! the true hull, and `max_outside_distance` says how far the rest stick out.
//!
//! Cost: O(n log n) expected for n points, O(n^2) in the worst case.
//! \throw InvalidInputError on a non-finite coordinate (naming the point's index) or an illegal
//!   option (naming it).
ConvexHull convex_hull(std::span<const Vec3> points, const ConvexHullOptions& options = {});

}  // namespace hedge

// What decimate.cpp checks outside its collapse loop: the input and options (before anything
// changes), and the distance of the positions a collapse removes to the faces it leaves.
#pragma once

#include <limits>

#include "hedge/algorithms/decimate.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge::detail::decimation {

// Near the target (the greedy order), a collapse's cost is at least kRemovedWeight times
// removed_distance2(). Plane quadrics underrate
// removing a thin feature (the planes of a horn or a spike run almost through its base, so its tip
// collapses cheaply) and bridging a notch (the new face keeps to the planes at its corners but
// passes over the gap); the distance measures both where they happen. On a flat region the removed
// point lies on the new faces and adds nothing. 1/5 (the distance counts sqrt(1/5) ~ 0.45 of
// itself, so it decides only where it is over twice the quadric's error): a larger weight kept more
// features of the peers' meshes but turned faces over next to thin parts (README: decimation).
// Counted in every pass too, it passed one more of the 26 cases of the README's table (18, against
// 17) but made turbine at 10% 1.85 times CGAL's distance instead of 1.43, for 2.2 times the
// instructions; counted near the target only, it costs about 1.28 times.
constexpr double kRemovedWeight = 0.2;

// Near the target, a collapse's cost is also at least kBridgeWeight times bridge_distance2(): the
// squared distance of the new faces from the surface they replace. Plane quadrics and the removed
// positions see only vertices, so a new face whose corners all lie on the surface can still bridge
// a concave gap (a fillet of a CAD part, the fold under an ear) with its interior, which is what the
// distance from the result back to the input measures. It is added when a candidate comes up in
// the greedy order, not when it is ranked (a lower bound is enough to order a lazy heap): counted
// at every ranking it took bunny to 10% from 538M to 747M instructions, counted when taken from
// 538M to 529M; CAD parts pay more, their flat regions giving collapses a cost near zero that the
// distance must confirm (fandisk to 10%: 292M before it, 352M with it). Weight 1 must stay exact
// for bridge_distance2()'s early stop: a value at most the limit, times the weight, must not
// exceed the cost the limit came from. Weight 1 passed 20 of the 26 cases of the README's table against 17
// (turbine at 10% 0.96 times CGAL's distance instead of 1.43, at 1% 1.10 instead of 1.48); weight 2 passed 22
// but made turbine at 1% 1.72 times, weight 3 passed 21 with turbine at 1% 1.89 times (and counted
// at every ranking, weight 0.5 passed 19).
constexpr double kBridgeWeight = 1.0;

// Throws InvalidInputError, naming what and where, for a face that is not a triangle, a position
// that is not finite, a vertex that is not manifold, or an illegal option.
void check_input(const SurfaceMesh& mesh, const DecimateOptions& options);

// Collapsing h (from_vertex merged into to_vertex, which moves to p): the larger of the squared
// distances from the merged-away end's position and, if the survivor moves, its old position to
// the nearest of the faces around both ends as they will be (the two faces on the edge vanish).
// 0 if no face is left around the edge. It stops once both are known to be at most `limit` (the
// faces around the merged-away end first): the answer is then some value at most `limit`.
double removed_distance2(const SurfaceMesh& mesh, Halfedge h, const Vec3d& p,
                         double limit = std::numeric_limits<double>::infinity());

// Collapsing h (from_vertex merged into to_vertex, which moves to p): the largest squared distance
// from the centroid of a new face around the survivor to the nearest face around either end as
// they are now (the two faces on the edge included): how far the new faces stand off the surface
// they replace. 0 if the survivor does not move off a flat region. It stops once every centroid is
// known to be within `limit`: the answer is then some value at most `limit`.
double bridge_distance2(const SurfaceMesh& mesh, Halfedge h, const Vec3d& p,
                        double limit = std::numeric_limits<double>::infinity());

}  // namespace hedge::detail::decimation

// Decimation: removes vertices by edge collapses, cheapest first, ranked by Garland and Heckbert's
// quadric error metric, until a target vertex or face count is reached or the next collapse would
// move the surface by more than a given distance.
//
//  - Each face contributes the quadric of its plane, weighted by its area; a vertex's quadric is the
//    sum over its faces, and a collapse's is the sum of its two ends'. The error of a collapse is
//    sqrt(Q(p) / W): the root-mean-square distance, in model units, of the surviving point p from
//    the planes the two ends gathered (W: their total weight), or, if larger and near the target
//    (in the greedy order below), sqrt(1/5) times the distance from each position the collapse
//    removes (the merged-away end's, and the survivor's if it moves) to the nearest new face
//    around the survivor, or the squared distance from the centroid of each new face to the
//    nearest face it replaces (counted when the greedy order takes the candidate). Plane quadrics
//    underrate removing a thin feature (the planes of a horn run almost through its base) and
//    bridging a notch or a fillet with a face whose corners all lie on the surface; these terms
//    measure both, and are 0 on a flat region.
//  - The surviving point minimises the quadric in the directions it determines: from the edge's
//    midpoint, along the eigenvectors of the quadric's 3x3 matrix whose eigenvalue is at least 1e-3
//    of the largest (a truncated pseudo-inverse, as in Lindstrom and Turk's placement); along the
//    others (the plane of a flat patch, the axis of a cylinder, the tangent plane of a gently curved
//    one) it stays at the midpoint. The test is a ratio, so the placement does not depend on the
//    mesh's scale. A point farther than an edge length from the midpoint drops the weakest direction
//    kept. The point is taken only if clearly better than the two ends and the midpoint, else the
//    best of those, so planar regions keep their vertices exactly and do not fold.
//  - Boundary edges add the plane through the edge perpendicular to its face, weighted by
//    boundary_weight x length^2, which keeps open outlines in place; keep_boundary pins them.
//    Feature edges (the edge property "e:crease" nonzero, or a dihedral angle above
//    feature_angle_degrees) add the same planes for both faces, weighted by feature_weight.
//  - A collapse is done only if can_collapse() allows it (the link condition: no boundary loop
//    shrinks below 3 vertices, no two boundaries are joined), no face around either end would turn
//    by more than max_normal_change_degrees, turn more than 90 degrees away from its own normal in
//    the input (so that small turns cannot add up to a flip), or lose its area, and, with
//    keep_seams, it does not break a UV seam.
//  - Shape: in flat regions (a collapse whose error is at most 1/1000 of its edge's length), a
//    collapse may not make a sliver, a face of quality 4 sqrt(3) area / (sum of squared edge
//    lengths) below 0.1 (1: equilateral; 0.1: a needle of about 3.3 degrees), unless a face around
//    the edge already is one and the new faces are no worse. There every collapse is (nearly) free
//    and the error cannot choose; elsewhere the error alone ranks collapses (the check has no weight
//    in the cost, so it never trades distance for shape). When it alone would stop the decimation
//    short of its target, it is lifted for the rest of the run.
//  - Order: while the mesh has more than 3 times the target's vertices (or faces), in passes: each
//    ranks and sorts the candidates and collapses the cheapest half of what is still needed, each
//    vertex at most once. The rest goes in true greedy order: the cheapest collapse first, the
//    edges around its survivor re-ranked after each (a lazy heap), which keeps features a pass
//    would lose near the target.
//  - A collapse refused by a check is tried again later (in the next pass, or in the greedy order
//    when a neighbour collapses); the result says why the decimation stopped and how many attempts
//    each check refused.
//  - Corner texture coordinates ("h:texcoord", Vec2) follow: each corner at the surviving vertex
//    gets the value interpolated at the new position, barycentric in the triangle of its own side
//    of a seam that the point projects into. A seam edge (the corners on its two sides differ) is
//    collapsed only along itself, and only when both of its ends stay seam corners consistently;
//    an edge that would pull a seam vertex off the seam is refused. With attribute_weight > 0 the
//    UVs enter the quadric (the plane quadric is extended with the UV gradient), so collapses that
//    stretch the texture cost more.
//
// Isolated vertices (no face) count toward the vertex target but are never removed.
// Other vertex properties keep the survivor's value; face and edge properties of surviving elements
// are kept. Deleted elements are garbage-collected at the end, so the result is compact (indices
// change; the change log records a reset).
#pragma once

#include <cstddef>
#include <limits>

#include "hedge/core/progress.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

struct DecimateOptions {
  //! Stop when at most this many vertices are left (0: no vertex target).
  std::size_t target_vertices = 0;
  //! Stop when at most this many faces are left (0: no face target).
  std::size_t target_faces = 0;
  //! Stop before a collapse whose error (a distance in model units, as the file comment defines it)
  //! exceeds this. Infinity: no limit.
  double max_error = std::numeric_limits<double>::infinity();
  //! Weight of the boundary-keeping planes, relative to the faces' area weights (they are scaled by
  //! the squared edge length, so 1 makes a boundary edge as stiff as a face of its size). 0: none.
  double boundary_weight = 1.0;
  //! Edges whose faces meet at a dihedral angle (between their normals) above this, or marked in
  //! "e:crease", are feature edges. 180 or more: only "e:crease" edges.
  double feature_angle_degrees = 60.0;
  //! Weight of the feature-keeping planes, scaled like boundary_weight. 0: features are not kept.
  double feature_weight = 1.0;
  //! True: boundary vertices never move and are never removed.
  bool keep_boundary = false;
  //! True: never collapse across a UV seam or in a way that breaks it ("h:texcoord" corners).
  //! False lifts only this rule's own limits: can_collapse() still refuses a collapse that would pull
  //! a seam vertex off its seam (the corner rule of core/edge_operations.h).
  bool keep_seams = true;
  //! >0: corner UVs enter the quadric with this weight (UV units per model unit). 0: geometry only.
  double attribute_weight = 0;
  //! Refuse collapses that turn a face around either end by more than this (prevents flips). When
  //! this limit (below 90) alone stops the decimation short of its target and relax_normal_change
  //! is true, it is raised to 90 degrees for the rest of the run, so that coarse targets are
  //! reached; no face turns over.
  double max_normal_change_degrees = 60.0;
  //! false: max_normal_change_degrees holds to the end, and a run it stops short of its target says
  //! so (DecimateStop::no_legal_collapse, with the refusals counted).
  bool relax_normal_change = true;
  //! Called with the fraction of the work done (the share of the needed collapses done, about 64
  //! times in a run with a target; with none, only at the start and the end).
  Progress progress{};
};

//! Why decimate() stopped.
enum class DecimateStop {
  //! The vertex and face targets are met (also when they were met at once).
  target_reached,
  //! Every collapse left would exceed max_error.
  error_bound,
  //! No legal collapse is left: each remaining one is refused by a check (counted in
  //! DecimateResult::refused), or there is none (no target: everything removable was removed).
  no_legal_collapse,
};

//! Collapse attempts refused, by check. A refused edge is tried again later (its neighbours may
//! have moved), so an edge may count more than once.
struct DecimateRefusals {
  //! The link condition or another rule of can_collapse() (topology).
  std::size_t topology = 0;
  //! A face around the edge would turn too far, turn away from its input normal, or lose its area.
  std::size_t normal = 0;
  //! A new face would be a sliver (see DecimateOptions::min_quality).
  std::size_t shape = 0;
};

struct DecimateResult {
  //! Achieved counts of live elements.
  std::size_t vertices = 0, faces = 0;
  //! Collapses done.
  std::size_t collapses = 0;
  //! The largest error (a distance) of a collapse done, 0 if none.
  double max_error = 0;
  //! Why it stopped.
  DecimateStop stop = DecimateStop::target_reached;
  //! Attempts refused by each check.
  DecimateRefusals refused{};
};

//! Decimates the triangle mesh by quadric-ranked edge collapses until it has at most
//! target_vertices vertices and at most target_faces faces (each when nonzero), or the next
//! collapse's error would exceed max_error, or no legal collapse is left. A target at or above the
//! mesh's count is met at once (no change). With no target and an infinite max_error it removes
//! what it can. O(E log E) time, O(V + E) memory.
//! \pre the mesh is a triangle mesh with finite positions.
//! \throw InvalidInputError, with the mesh unchanged, for a face that is not a triangle (the message
//!   names it; triangulate first), a position that is not finite (named), or illegal options:
//!   a negative or NaN max_error, weight or angle.
DecimateResult decimate(SurfaceMesh& mesh, const DecimateOptions& options);

}  // namespace hedge

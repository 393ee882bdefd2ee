// Smoothing: moves vertices toward a weighted average of their neighbours, a given number of times.
//
//  - uniform: the average of the neighbours (the umbrella operator). Shrinks a closed surface a
//    little with every iteration.
//  - taubin: Taubin's lambda|mu filter, a shrinking step (lambda > 0) then an inflating one
//    (mu < -lambda) per iteration: it removes noise without the shrinkage.
//  - cotangent: the cotangent-weighted Laplacian L, which follows the surface's geometry rather than
//    its tessellation: a flat region stays where it is (every weight is kept, negative ones of
//    obtuse angles included, so a plane is a fixed point), and vertices slide less along the
//    surface. Each vertex steps by lambda (L x)_i / s_i, where s_i, the sum of the magnitudes of
//    its edges' weights, scales the step to the vertex's own size (a vertex whose faces all have
//    zero area stays). With S the diagonal of the s_i, x^T L x <= 2 x^T S x, so for any lambda in
//    (0, 1] the steps never amplify anything, whatever the angles. Needs triangles.
//  - implicit: backward Euler steps of the same flow, (S + lambda L) x' = S x, solved by a sparse
//    Cholesky factorisation (Eigen). The time step is relative to each vertex's size (lambda times
//    its explicit step), so thin features much smaller than the mean edge thin gradually instead of
//    collapsing, and it does not depend on the mesh's scale. Unconditionally stable: one step with
//    a large lambda smooths as much as many explicit ones. Needs triangles. A free boundary
//    (fix_boundary = false) follows the same flow, not the boundary curve alone.
//
// Both cotangent methods keep every triangle's normal within 90 degrees of its normal before the
// call: a step that would turn a triangle further, or collapse it to zero area, is withheld from
// the triangle's corners for that step (on a coarse mesh with thin parts the flow itself would
// fold them). Uniform and Taubin steps are not checked (uniform matches the common umbrella
// smoother).
//
// The first three are explicit (Jacobi) steps: every vertex moves from the positions of the previous
// step. Boundary vertices stay fixed unless asked otherwise; then they move along the boundary only
// (the average of their two boundary neighbours), so that an open surface keeps its outline's shape.
// A mask restricts the smoothing to some vertices. The positions' changes are marked in the change
// log (ChangeEvent::vertices_moved), once per call.
#pragma once

#include <cstdint>
#include <span>

#include "hedge/core/progress.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

enum class SmoothMethod { uniform, taubin, cotangent, implicit };

struct SmoothOptions {
  SmoothMethod method = SmoothMethod::uniform;
  //! Iterations; a Taubin iteration is its two steps.
  int iterations = 10;
  //! The step toward the average, in (0, 1]. For the implicit method, the time step in units of
  //! each vertex's explicit step (any positive value; 0.5 is one gentle step, 20 a strong one).
  double lambda = 0.5;
  //! Taubin's inflating step: negative, with |mu| > lambda (the default gives a pass band of about
  //! 0.1 with lambda = 0.5).
  double mu = -0.53;
  //! Keep boundary vertices where they are; otherwise they move along the boundary.
  bool fix_boundary = true;
  //! Empty: every vertex may move. Else one entry per vertex slot; only vertices whose entry is
  //! nonzero move (their neighbours still count in the averages).
  std::span<const std::uint8_t> mask{};
  //! Told the fraction done after each iteration (core/progress.h). The positions are written
  //! only at the end, so a callback that throws leaves the mesh unchanged.
  Progress progress{};
};

//! Smooths the positions of the live vertices. O(iterations x (V + E)), the cotangent methods'
//! check of the triangles' normals included (a few rounds of O(F) where a step is withheld).
//! The implicit method costs a sparse factorisation, O(V^1.5) for a surface, then O(V) per step.
//! \throw InvalidInputError, leaving the mesh unchanged, for iterations outside 0..100000, lambda
//!   outside (0, 1] (positive and finite for the implicit method), a Taubin mu that is not below
//!   -lambda, a mask of the wrong size, or cotangent weights (cotangent, implicit) on a mesh with a
//!   face that is not a triangle (the message names it).
//! \throw std::bad_alloc, with the positions unchanged, if memory runs out (a watched mesh's change
//!   log may then hold marks for vertices that did not move).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
void smooth(SurfaceMesh& mesh, const SmoothOptions& options = {});

}  // namespace hedge

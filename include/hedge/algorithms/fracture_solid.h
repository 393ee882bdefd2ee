// Solid fracture: a closed mesh struck at a point breaks into closed pieces, and the rest of the
// object stays closed.
//
// The steps, all local to the broken region:
//  1. locate: the face nearest to the impact, within `tolerance` of it (FaceBvh). The impact is
//     moved onto the surface.
//  2. break points: the material (fracture.h) in model units, its outer ring at the break radius
//     (fracture_material_at_radius()). Ring k's points lie on a sphere about the impact at the
//     ring's radius, spread evenly over it (a Fibonacci lattice, turned by a seeded rotation), each
//     moved by the ring's jitter in direction and in radius. Points outside the object are kept:
//     their cells hold nothing or a little of it, and empty cells make no piece.
//  3. cells: the broken region P is a convex polyhedron of 26 planes (normals along the axes, the
//     face and the body diagonals of a cube) about the impact, circumscribing the sphere of the
//     break radius plus half the outer ring's spacing. Each break point's cell is P clipped by the
//     bisector planes of the other break points (its Voronoi cell within P).
//  4. clip: the triangles whose boxes meet a cell's box (a FaceBvh box query; polygon faces are
//     split into the fan of fan_start() in core/triangulate.h, from their first corner unless that
//     fan folds, as volume() and the tree see them) are clipped by the cell's planes (a triangle
//     whose corners all lie inside the cell, or all outside the first of its planes that any
//     corner leaves, is kept whole or dropped without clipping: the same result), and each of the
//     cell's faces
//     gets a cap, the part of it inside the object: its loops (several, holes included) are
//     triangulated in the face's plane. A piece is the clipped surface and its caps. The cells are
//     independent: they are clipped and capped on worker threads (core/threads.h:
//     set_max_threads(1) keeps the strike on the calling thread), beside the remaining object's
//     patch (step 5), and the pieces are taken in cell order, so the result does not depend on the
//     number of threads.
//  5. remaining object: the faces that meet P leave the mesh, and their parts outside P come back
//     with P's caps turned inwards, so the mesh stays closed. Only the faces that meet P are
//     touched: the cost follows the broken region, not the mesh.
//
// Robustness: every new point has a symbolic key (a mesh edge cut by a plane, a triangle pierced
// by the edge of two planes, a vertex of three planes) and its position is computed from its key
// alone, so two triangles (or two cell faces) that share it agree on it bit for bit. A point is
// classified against a plane by one function that never answers "on" (each plane has a fixed
// orientation, and a point on it counts on its positive side), so an edge crosses a plane exactly when its
// ends are classified differently, and a plane through vertices or along edges makes zero-length edges, never
// a contradiction. Should a piece still come out open or invalid (a surface folded within rounding of a cell
// edge), the break points and the region's planes are moved by a small seeded amount (1e-5 of the
// break radius) and the strike is computed again, at most 6 times in all; the mesh is edited only
// once every piece and the patch of the remaining object are known to be closed and manifold, so a
// refused strike leaves it as it was. None of 10^4 random strikes was refused (docs/fracture.md).
//
// Properties: outer faces of a piece keep their face properties ("f:submesh" included); vertex and
// corner properties (UVs, normals) are interpolated at new points, linearly along an edge and
// barycentrically inside a triangle, as the splits of core/operations.h do; "h:normal" corners so
// blended are made unit length again. Cap faces get the face property "f:inner" (std::uint8_t, 1
// on caps, 0 elsewhere), "f:submesh" = inner_submesh and, when the mesh has "h:texcoord" corners,
// UVs by planar projection in model units: u along the unit vector of the cap plane's normal
// crossed with the coordinate axis least aligned with it (x, then y, then z on ties), v = normal x
// u, both measured from the origin. When the mesh has "h:normal" corners, a cap's corners get the
// cap plane's unit normal pointing out of the piece (flat shading, as a cut face is); the remaining
// object's caps likewise, out of it. Vertices only caps use (cell vertices) take the default values
// of vertex properties.
//
// Determinism: the library's seeded generator (SplitMix64), no hashed container iterated, ties
// broken by key: the same mesh, impact, options and seed give the same pieces bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hedge/algorithms/convex_hull.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/mass_properties.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! The face property that marks cap (inner) faces: std::uint8_t, 1 on caps.
inline constexpr const char* kInnerProperty = "f:inner";

struct SolidFractureOptions {
  //! How the object breaks: its rings become spherical shells of break points (see the file
  //! comment). At most kFractureMaxPoints break points.
  FractureMaterial material = fracture_material("stone");
  //! The break radius in model units: the outer ring's radius. 0: radius_fraction times the
  //! diagonal of the mesh's bounding box (from the FaceBvh's root box: no pass over the mesh).
  double radius = 0;
  //! Used when radius is 0; in (0, 10].
  double radius_fraction = 0.25;
  //! Seed of the break points' generator.
  std::uint64_t seed = 0;
  //! "f:submesh" of the cap faces. -1: one more than the largest "f:submesh" of the mesh's faces
  //! (an O(F) pass), or 1 when the mesh has no such property (as FractureOptions::inner_submesh).
  std::int32_t inner_submesh = -1;
  //! Mass per unit volume, for the pieces' mass properties. Positive.
  double density = 1;
  //! Largest distance (model units) from the impact to the surface. 0: 1e-3 times the longest edge
  //! of the nearest face.
  double tolerance = 0;
  //! Compute each piece's convex hull.
  bool hulls = true;
  ConvexHullOptions hull_options{};
};

//! Names the remaining object (the struck mesh) as an end of a bond.
inline constexpr std::size_t kSolidRemaining = SIZE_MAX;

//! Two pieces (or a piece and the remaining object, b == kSolidRemaining) that touch: they share
//! `area` of cap, the area of the piece a's cap on their common face. a < b.
struct SolidBond {
  std::size_t a = 0, b = 0;
  double area = 0;
};

struct SolidPiece {
  //! A closed, manifold triangle mesh with outward faces; see the file comment for properties.
  SurfaceMesh mesh;
  //! Centre of mass (uniform density), as mass.centre_of_mass.
  Vec3d centroid;
  //! Enclosed volume, positive.
  double volume = 0;
  //! Area of the cap faces.
  double cap_area = 0;
  //! At the options' density.
  MassProperties mass;
  //! Of the piece's vertices, when options.hulls (else empty).
  ConvexHull hull;
};

struct SolidFractureResult {
  //! In the order of their break points (ring by ring); empty cells make no piece.
  std::vector<SolidPiece> pieces;
  //! Every pair that shares cap area, sorted by (a, b).
  std::vector<SolidBond> bonds;
  //! The face the impact was located on, before the strike (it may be gone since).
  Face impact_face;
  //! The impact point moved onto the surface.
  Vec3 impact_point;
  //! The break radius used, in model units.
  double radius = 0;
  //! Wall-clock seconds per stage (steady clock), one after the other: locate; cells: the break
  //! points and cells (the region's triangles are gathered beside them);
  //! clip and cap: the cells' pieces and the remaining object's patch are clipped and capped as
  //! tasks on worker threads, and that loop's wall time is split between clip and cap as their
  //! thread times are; assemble: assembling the pieces, then the wall time of editing the
  //! remaining object (and updating the picking tree); per_piece: the rest of the wall time until
  //! every piece is measured (mass properties, hulls), on worker threads beside that edit.
  //! set_max_threads(1) (core/threads.h) keeps all of it on the calling thread, one stage after
  //! the other, and the result does not depend on it.
  struct Timings {
    double locate = 0, cells = 0, clip = 0, cap = 0, assemble = 0, per_piece = 0;
  } seconds;
};

//! Why a strike cannot be a solid fracture, as a code (solid_fracture_check()). The values are
//! the C ABI's HEDGE_SOLID_REFUSAL_* constants, in order; a value keeps its number in later
//! releases and new refusals take new values.
enum class SolidRefusal : std::int32_t {
  none,          //!< not refused
  open,          //!< the mesh is open (a boundary edge anywhere, or near the impact)
  non_manifold,  //!< a vertex near the impact joins several fans of faces
  bad_option,    //!< an illegal option or material (the message names it)
  bad_impact,    //!< the impact is not finite
  off_surface,   //!< no face lies within the tolerance of the impact
  no_face,       //!< the mesh has no face
  bad_radius,    //!< the break radius came out not positive or not finite (a mesh of zero size)
  foreign_tree,  //!< the FaceBvh passed was built over another mesh
};

//! The "auto" rule of every binding and the CLI: a strike refused for the shape of the input
//! (SolidRefusal::open or non_manifold: a mesh that does not enclose a solid where it is struck)
//! falls back to surface fracture (fracture.h), which breaks such meshes; any other refusal (a bad
//! option or impact, an empty mesh) is reported as an error, as with solid fracture alone.
bool solid_refusal_falls_back(SolidRefusal code) noexcept;

//! A refusal: its code and the message naming what and where ("the mesh is open: edge 7 (vertices
//! 3 and 4) has a face on one side only, ..."); none and "" when the strike can be made.
struct SolidFractureCheck {
  SolidRefusal code = SolidRefusal::none;
  std::string message;
};

//! Why `mesh` cannot be solid-fractured at `impact`, or none if it can: the options are illegal,
//! the impact is not finite, the mesh has no face, no face lies within the tolerance of the impact,
//! the mesh is open anywhere (only a closed mesh encloses a solid: naming a boundary edge by its
//! vertices), or it is non-manifold near the impact. Whether the mesh is closed is
//! FaceBvh::mesh_closed(): one pass over the half-edges after the tree is built or the mesh
//! changed, then kept (a solid strike keeps it closed, so repeated strikes cost the broken region
//! only); the rest checks the faces whose boxes meet the box of the broken region (as
//! fracture_solid() would with the same options). The bindings use it for "auto" (see
//! solid_refusal_falls_back()). With `bvh` (built over `mesh`, brought up to date) no tree is
//! built.
SolidFractureCheck solid_fracture_check(SurfaceMesh& mesh, const Vec3& impact,
                                        const SolidFractureOptions& options = {}, FaceBvh* bvh = nullptr);

//! solid_fracture_check()'s message: empty if the strike can be made.
std::string solid_fracture_refusal(SurfaceMesh& mesh, const Vec3& impact,
                                   const SolidFractureOptions& options = {}, FaceBvh* bvh = nullptr);

//! Breaks the closed `mesh` at `impact` (see the file comment). `mesh` becomes the remaining
//! object, closed and valid, its new caps marked in "f:inner" as well. With `bvh` (built over
//! `mesh`) the region is found through it and it is kept up to date through update(); without one
//! a temporary FaceBvh is built, O(n log n).
//! Cost: O(P^2) for the cells of P break points (pruned by distance), plus the triangles of the
//! region times the planes of their cells, plus the pieces' hulls.
//! \return the pieces and their bonds; none when no break point's cell holds part of the object
//!   (the mesh is then unchanged).
//! \throw InvalidInputError, with the mesh unchanged, for what solid_fracture_refusal() names, an
//!   illegal option (naming the field), a face property "f:submesh" that is not std::int32_t or
//!   "f:inner" that is not std::uint8_t, a bvh of another mesh, or a strike whose pieces could not
//!   be made closed (after the retries of the file comment).
SolidFractureResult fracture_solid(SurfaceMesh& mesh, const Vec3& impact,
                                   const SolidFractureOptions& options = {}, FaceBvh* bvh = nullptr);

}  // namespace hedge

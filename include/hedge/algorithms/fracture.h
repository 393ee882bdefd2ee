// Fracture: an impact breaks a surface into shards, groups of faces a physics engine can move.
//
// The steps, all local to the broken area:
//  1. locate: the face nearest to the impact, which must lie within `tolerance` of it (FaceBvh).
//  2. cut: the impact point becomes a vertex. Near a corner of its face (barycentric weight within
//     1e-3 of 1) that corner is taken as it is; near an edge of a triangle (a weight below 1e-3) the
//     edge is split there; otherwise the face is split there. No sliver face is made.
//  3. scatter: the broken area is gathered by growing over face adjacency from the impact, a face
//     keyed by the largest distance from the impact of the face centroids on its path, up to the
//     break radius (the outer ring's, plus half its spacing). Break points are placed in rings around the
//     impact, as the material says (points, spacing and jitter per ring), in the tangent plane of
//     the impact face, then carried onto the surface: each goes to the face of the area whose polar
//     coordinates around the impact (its key, in the direction its centroid lies in the tangent
//     plane) are nearest. So the rings follow a curved surface and never jump across a gap to
//     another part of the mesh; a point beyond the surface's edge goes to a face on the edge.
//  4. cut: faces of the broken area with an edge longer than the material's refine_edge are split
//     (longest edge at its midpoint, then again), so that cells are groups of faces even on a coarse
//     mesh; polygons in the area are split into triangles at their centroid. At most
//     kFractureMaxRefineSplits splits per strike.
//  5. cells: the break points' faces grow together over face adjacency, each face going to the
//     break point that reaches it first by the same key (distance to the break point's face): on a
//     plate the Voronoi cells of the break points, on any surface cells that are connected across
//     edges. Wood measures distances along its grain shortened by grain_stretch, so its cells are
//     that much longer along the grain.
//  6. detach: each cell leaves the mesh by detach_faces() (properties included) as a shard.
//  7. per shard: centroid, area, the solid (thickness > 0), mass properties and convex hull.
//
// Units: a material's break radius (the outer ring's radius) is `radius` in its `units`; the ring
// spacings only give the rings' proportions (ring i lies at radius x the spacings up to i / all the
// spacings), and refine_edge is in the same units as the spacings. The units:
//  - diagonal_fraction (the presets): a fraction of the diagonal of the mesh's bounding box, so the
//    same preset breaks the same share of an object whatever its size and resolution. The diagonal
//    is the picking tree's root box (FaceBvh::bounds()), O(1): no pass over the mesh per strike.
//  - model: model units (metres in a game), for a radius that is a physical size.
//  - edge_lengths: mean edge lengths of the impact face, so the same number of shards of the same
//    number of faces on a coarse and a fine mesh, a share of the object that shrinks as the mesh is
//    refined (the presets' former behaviour: radius = fracture_material_radius(preset)).
// A fine mesh puts more faces into the same broken area: the cost follows the area's faces. A mesh
// coarser than the cells is refined where it breaks (step 4): every edge of the broken area longer
// than refine_edge is split, so each cell is a group of faces. That takes at most
// kFractureMaxRefineSplits splits a strike; when the faces are so much larger than the cells that
// the splits run out (a break radius of 1e-3 of a large triangle), the rest of the area keeps
// larger faces, several break points fall into one face and make one shard, and the strike
// returns fewer, coarser shards than break points; the broken area still ends at the break radius
// (within one face, since faces join it by their centroid).
//
// Determinism: the library's seeded generator (SplitMix64, algorithms/geometry.h) and its
// integer-to-double conversion (no std:: distribution, whose output differs between standard
// libraries), no global state, ties broken by index and no hashed container iterated: the same
// mesh, impact, options and seed give the same shards, bit for bit, on every run.
//
// Properties: face properties (a material id) follow each face into its shard; vertex and corner
// properties (UVs, normals) are interpolated by the splits (core/operations.h) and copied by the
// detach. The remaining mesh keeps a valid, manifold boundary where the shards left.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hedge/algorithms/convex_hull.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/mass_properties.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

//! Limits of a material and of the options, so that the work of a call is bounded whatever its
//! input (checked before the mesh is touched):
//!  - at most kFractureMaxRings rings;
//!  - at most kFractureMaxPoints break points in all rings together (each one is matched against
//!    every face of the broken area, so the scattering costs points x faces of the area);
//!  - a thickness of at most kFractureMaxThicknessRatio times the diagonal of the mesh's bounding
//!    box (a thicker solid folds through itself and only inflates the volumes and masses);
//!  - a relative_thickness of at most kFractureMaxRelativeThickness: a solid at most as thick as
//!    the break radius (checked without a pass over the mesh, so a strike with a relative
//!    thickness costs the broken area only).
inline constexpr std::size_t kFractureMaxRings = 1000;
inline constexpr std::size_t kFractureMaxPoints = 10000;
inline constexpr double kFractureMaxThicknessRatio = 10;
inline constexpr double kFractureMaxRelativeThickness = 1;
//! Most faces split by the refinement (step 4) in one strike.
inline constexpr std::size_t kFractureMaxRefineSplits = 20000;
//! The thickness of the thin shell an open shard's mass properties are taken for, by default
//! (FractureOptions::shell_thickness 0): this fraction of the strike's break radius in model units.
inline constexpr double kFractureDefaultShellRatio = 0.05;

//! The units of FractureMaterial::radius (see the file comment). The values are the C ABI's.
enum class FractureUnits : std::int32_t {
  edge_lengths = 0,      //!< mean edge lengths of the impact face
  model = 1,             //!< model units
  diagonal_fraction = 2  //!< a fraction of the diagonal of the mesh's bounding box
};

//! "edge_lengths", "model", "diagonal_fraction".
const char* fracture_units_name(FractureUnits units);

//! One ring of break points around the impact.
struct FractureRing {
  //! Break points on the ring (at most 100000, and kFractureMaxPoints over all rings).
  unsigned points = 0;
  //! Distance of this ring from the previous one (from the impact for the first ring); positive.
  //! In proportion only: the spacings are scaled together so that the outer ring lies at the
  //! material's radius.
  double spacing = 1;
  //! In [0, 1]: how far points stray from even angles and from the ring's radius, as a fraction of
  //! the angle between two points and of the spacing. 0: exactly regular.
  double jitter = 0;
};

//! How a material breaks. Presets: fracture_material().
struct FractureMaterial {
  std::string name;
  std::vector<FractureRing> rings;
  //! The grain direction (wood), used when grain_stretch > 1: it must then be nonzero. Its part in
  //! the impact face's plane is the grain there; where the grain runs (nearly) along the face's
  //! normal, closer than 6 degrees, the surface is cut across the grain and the cells are round.
  Vec3 grain{};
  //! >= 1: cells are this many times longer along the grain than across it. 1: no grain.
  double grain_stretch = 1;
  //! Faces of the broken area with an edge longer than this (in the units of the spacings, so in
  //! proportion to the radius) are split until none is, so cells are made of several faces.
  //! Positive; at most kFractureMaxRefineSplits splits per strike.
  double refine_edge = 1.5;
  //! The units of `radius`.
  FractureUnits units = FractureUnits::diagonal_fraction;
  //! The break radius: the outer ring's distance from the impact, in `units`; the broken area
  //! reaches half the outer spacing farther. Finite and positive.
  double radius = 0.1;
};

//! The rings' spacings of `material` summed: the outer ring's radius in the units of the spacings
//! (which material.radius scales). For a preset, its break radius in edge lengths of the impact
//! face, as presets broke before they had units. 0 without rings.
double fracture_material_radius(const FractureMaterial& material);

//! `material` in model units, its outer ring `radius` model units from the impact: units model,
//! radius `radius`, and every spacing and refine_edge scaled by radius /
//! fracture_material_radius(material), so they read in model units too (the strike is the same as
//! with the spacings unscaled); points, jitter and grain kept. A game gives the break radius in
//! metres this way.
//! \throw InvalidInputError for a radius that is not finite and positive, or a material without
//!   rings or with a spacing that is not finite and positive (naming the ring).
FractureMaterial fracture_material_at_radius(FractureMaterial material, double radius);

//! The names fracture_material() knows: "glass", "stone", "wood", "ice".
std::vector<std::string> fracture_material_names();

//! A preset, its break radius a fraction of the object's bounding-box diagonal (units
//! diagonal_fraction; the fractions break about as much of spot, data/spot_triangulated.obj, as
//! the presets did in edge lengths at that resolution):
//!  - glass: 4 rings, 40 break points, radius 0.13: many small shards, smaller near the impact;
//!  - stone: 2 rings, 7 break points, radius 0.14: few large chunks;
//!  - wood: 3 rings, 18 break points, radius 0.11, grain along x stretched 3 times: long splinters;
//!  - ice: 3 rings, 26 break points, radius 0.11.
//! \throw InvalidInputError for another name, listing the valid ones.
FractureMaterial fracture_material(std::string_view preset);

struct FractureOptions {
  FractureMaterial material = fracture_material("glass");
  //! Seed of the break points' generator.
  std::uint64_t seed = 0;
  //! > 0: every open shard is extruded into a closed solid this thick (model units), see Shard::mesh.
  //! At most kFractureMaxThicknessRatio times the diagonal of the mesh's bounding box (the picking
  //! tree's box, FaceBvh::bounds()).
  double thickness = 0;
  //! > 0 (and thickness 0): the thickness is this fraction of the strike's break radius in model
  //! units (FractureResult::break_radius), so shards of any size get a solid of the same proportion. When
  //! what broke off is smaller than the break radius (a radius beyond the object's size), the
  //! fraction is of the diagonal of the box of all the shards instead, so a solid is never thicker
  //! than that fraction of what broke (O(k) for the k shard vertices). At most
  //! kFractureMaxRelativeThickness; no pass over the mesh checks it against the mesh's size.
  //! Both thickness and relative_thickness > 0: refused.
  double relative_thickness = 0;
  //! With a thickness, the faces the solid adds (the back copy and the side walls, the shard's new
  //! cut faces) get this value in the face property "f:submesh" (std::int32_t, the face's submesh
  //! or material), so a game can give them an inner material; the broken faces keep theirs (0 when
  //! the mesh has no "f:submesh"). -1: one more than the largest "f:submesh" of the mesh's faces
  //! (an O(F) pass), or 1 when the mesh has no such property. Otherwise >= 0.
  std::int32_t inner_submesh = -1;
  //! Mass per unit volume, for the shards' mass properties. Positive.
  double density = 1;
  //! The thickness (model units) of the thin shell whose mass properties an open shard (no
  //! thickness above) gets, so that it has a mass to give a physics engine. 0: automatic,
  //! kFractureDefaultShellRatio times the strike's break radius in model units (or times the
  //! diagonal of the box of all the shards, when that is smaller: an object smaller than the break
  //! radius). >= 0. It shapes only the mass properties, never the shard's mesh.
  double shell_thickness = 0;
  //! Largest distance (model units) from the impact to the surface. 0: 1e-3 times the longest edge
  //! of the nearest face.
  double tolerance = 0;
  //! Compute each shard's convex hull.
  bool hulls = true;
  //! Options of the hulls.
  ConvexHullOptions hull_options{};
};

struct Shard {
  //! The shard's faces with their properties. With thickness, the closed solid: the broken faces
  //! (front), a copy moved by `thickness` against the vertex normals with reversed faces (back),
  //! and two triangles per boundary edge joining them (side walls). Back vertices and corners copy
  //! the properties of the front ones they were moved from; a wall's vertices and corners copy the
  //! front vertex's properties and its faces the face properties of the front face on that edge,
  //! except "f:submesh", which is options.inner_submesh (resolved) on the back and the walls.
  SurfaceMesh mesh;
  //! Area-weighted centroid of the broken faces (the front).
  Vec3d centroid;
  //! Area of the broken faces (the front only, also with thickness).
  double area = 0;
  //! `mesh` has no boundary.
  bool closed = false;
  //! At the options' density: of the solid `mesh` bounds when it is closed (its volume:
  //! `mass.volume`); when it is open, of its surface as a thin shell shell_thickness thick
  //! (shell_mass_properties(): volume = area x shell_thickness, a positive-definite inertia). All
  //! zero only for a shard without area or whose solid folded through itself (a thickness far too
  //! large), which a physics engine must then skip.
  MassProperties mass;
  //! The thickness of the shell `mass` is taken for when the mesh is open (model units); 0 when
  //! closed.
  double shell_thickness = 0;
  //! Of `mesh`'s vertices, when options.hulls (else empty). Every vertex is checked to lie inside
  //! within hull.tolerance; should one stick out farther, hull.max_outside_distance says by how
  //! much (never seen in the test sweep since convex_hull keeps its near points).
  ConvexHull hull;
};

struct FractureResult {
  //! In the order of their break points (ring by ring, then by angle).
  std::vector<Shard> shards;
  //! The face the impact was located on, before the cut (it has broken off since).
  Face impact_face;
  //! The impact point moved onto the surface.
  Vec3 impact_point;
  //! The break radius of the strike in model units: the material's radius in its units (for
  //! diagonal_fraction, times the diagonal of the picking tree's box). 0 when the strike broke
  //! nothing (a material without break points).
  double break_radius = 0;
  //! Wall-clock seconds per stage (steady clock): locating; scattering the break points (with
  //! gathering the broken area); cutting (impact, refinement, cells); detaching; per-shard work
  //! (solid, mass properties, hulls).
  struct Timings {
    double locate = 0, scatter = 0, cut = 0, detach = 0, hulls = 0;
  } seconds;
};

//! Breaks `mesh` at `impact` (see the file comment). With `bvh` (built over `mesh`) the impact is
//! located through it and it is kept up to date through update(): the cost is then that of the
//! broken area, O(k log k) for its k faces plus the shards' hulls, whatever the size of the mesh.
//! The tree is up to date with the mesh when the call returns, ready for the next impact and for
//! queries (keep one per mesh, as the C ABI's and the wasm binding's picking trees are kept); a
//! refusal leaves the mesh as it was and the tree usable, and should the call throw after
//! editing the mesh (out of memory), the edits wait in the change log for the tree's next update().
//! Without one, a temporary FaceBvh is built first, O(n log n).
//! Faces must be convex (polygons are split at their centroid); every face of the mesh must have
//! a nonzero area near the impact.
//! \return the shards; none for a material without break points (the mesh is then unchanged).
//!   When the broken area reaches all of a small connected part, that whole part breaks off.
//! The scattering matches each break point against the faces of the broken area: O(P k) for P break
//! points (at most kFractureMaxPoints). The mesh's bounding box (for diagonal_fraction and the
//! thickness limit) is the tree's root box, FaceBvh::bounds(): no pass over the mesh. With a thickness of
//! either kind and inner_submesh -1 on a mesh with "f:submesh", one O(F) pass finds the largest submesh.
//! \throw InvalidInputError, with the mesh unchanged, for: a non-finite impact; no face within the
//!   tolerance (giving the distance to the nearest); a mesh with no face, or whose part at the
//!   impact is a single face (too small to break); an illegal material or option, naming the field
//!   (ring index included), such as more rings or break points than the limits above or a thickness
//!   beyond kFractureMaxThicknessRatio times the mesh's diagonal; a face property "f:submesh" that
//!   is not std::int32_t while there is a thickness; a bvh of another mesh.
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
FractureResult fracture(SurfaceMesh& mesh, const Vec3& impact, const FractureOptions& options = {},
                        FaceBvh* bvh = nullptr);

//! The break points of options.material in all: the most shards fracture() can return. Checks the
//! options as fracture() does, except the thickness against the mesh's size. O(rings).
//! \throw InvalidInputError for an illegal material or option, naming the field.
std::size_t fracture_break_points(const FractureOptions& options);

}  // namespace hedge

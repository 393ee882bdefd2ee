// Point location on a SurfaceMesh: the nearest face to a point, the first face a ray hits, and the
// face of a flat plate (or a height field) that contains a point. FaceBvh answers these in
// O(log n) expected time through a bounding volume hierarchy; the *_linear functions are the O(n)
// scans and serve as the reference.
//
// Faces are located through triangles: a triangle face is itself, and a polygon face is the fan of
// triangles (c0, c[i], c[i+1]) from its first corner c0 = to_vertex(halfedge(f)), or from the
// corner fan_start() names where that fan folds (a non-planar quad split along the wrong
// diagonal; core/triangulate.h): the same fan as volume(), solid fracture and
// to_indexed(..., Triangulation::fan). Every answer names the face, the fan triangle's corners
// and barycentric coordinates within that triangle. For a concave polygon the fan covers area
// outside the polygon; locating such faces is exact only for convex (and planar) polygons.
//
// Ties are broken the same way everywhere: among equally near faces (or equally far hits, or
// several faces containing a point) the smallest face index wins, and within a face the first fan
// triangle. So FaceBvh and the *_linear scans return identical answers, face included.
//
// Precision: positions are floats; distances, ray parameters and barycentric coordinates are
// computed in double from them. Queries with a NaN or infinite coordinate find nothing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "hedge/core/changes.h"
#include "hedge/core/handles.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

struct BoundingBox;  // algorithms/geometry.h

//! A point on a face: the face, the fan triangle of the face it lies in, and where.
struct SurfacePoint {
  Face face;
  //! Corners of the fan triangle (see the file comment); corners[0] is the fan's apex (the face's
  //! first corner unless that fan folds).
  std::array<Vertex, 3> corners;
  //! Weights of corners[0..2]: each in [0, 1], summing to 1 (up to rounding).
  std::array<double, 3> barycentric{};
  //! sum of barycentric[i] * position(corners[i]), rounded to float.
  Vec3 point;
};

//! The nearest point of the surface to a query point.
struct LocateResult : SurfacePoint {
  //! Squared Euclidean distance from the query point to `point` (computed in double).
  double squared_distance = 0;
};

//! Where a ray first meets the surface.
struct RayHit : SurfacePoint {
  //! Ray parameter: point = origin + t * direction, in units of the direction's length.
  double t = 0;
};

//! The closest point of triangle (a, b, c) to p, as barycentric weights of a, b, c.
struct TrianglePoint {
  double squared_distance = 0;
  std::array<double, 3> barycentric{};
};

//! Closest point of the (solid) triangle (a, b, c) to p. Degenerate triangles (collinear or
//! coincident corners) are handled: the answer is then on their edges. O(1).
TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

//! A ray-triangle intersection: parameter t and barycentric weights of a, b, c.
struct TriangleHit {
  double t = 0;
  std::array<double, 3> barycentric{};
};

//! Intersects the ray origin + t * direction, 0 <= t <= t_max, with triangle (a, b, c).
//! The test is watertight (Woop, Benthin and Wald, JCGT 2013, evaluated in double): a ray through
//! an edge or a vertex shared by several triangles of a mesh hits at least one of them, never
//! slips between them. Both sides of a triangle are hit (no back-face culling); a ray lying in the
//! triangle's plane and a degenerate triangle are missed. Returns nothing for a zero or non-finite
//! direction or origin. O(1).
std::optional<TriangleHit> intersect_ray_triangle(const Vec3& origin, const Vec3& direction, const Vec3& a,
                                                  const Vec3& b, const Vec3& c,
                                                  double t_max = std::numeric_limits<double>::infinity());

//! The coordinate plane face_containing(Vec2) projects onto; the Vec2 holds its two coordinates.
enum class ProjectionPlane { xy, xz, yz };

//! How FaceBvh splits a node while building.
enum class BvhSplit {
  //! Binned surface-area heuristic: 16 bins along the box's widest axis; nodes of fewer than 32
  //! faces are halved at the median. The default: 10-30% faster queries (bench/locate).
  sah,
  //! Median of the box centres along the widest axis: a balanced tree, a similar build time.
  median,
};

struct BvhOptions {
  BvhSplit split = BvhSplit::sah;
  //! Most faces in a leaf (1..255); a node with that many or fewer is a leaf.
  unsigned max_leaf_size = 4;
  //! update() reclaims the dead (removed or replaced) face slots when they exceed this fraction of
  //! all slots: it compacts the tree in one pass, without a build (see FaceBvh::update). Smaller
  //! keeps the tree smaller, larger makes updates cheaper.
  double rebuild_fraction = 0.25;
};

//! A bounding volume hierarchy over the live faces of one SurfaceMesh.
//!
//! Layout: a flat array of 32-byte nodes (float boxes, 32-bit indices; the two children of a node
//! are adjacent), and a flat array of 16-byte face entries in leaf order. A triangle face's entry
//! holds its three corner vertices, so a query reads positions without walking the mesh; a polygon
//! face's entry is walked through the mesh's half-edges at query time. Boxes hold faces whole.
//! About 45 bytes per face with the default options (see memory_bytes()).
//!
//! Positions are read from the mesh at query time; connectivity is read at build/update time.
//!
//! The tree is a consumer of its mesh's change log (core/changes.h): the operations of
//! core/operations.h and the algorithms mark what they change, and update() with no arguments
//! takes in exactly that. After garbage_collection() (or an assignment to the mesh), which renumbers
//! everything, queries, refit() and update(faces) throw InvalidInputError until update() or
//! rebuild() builds the tree again; they never read through stale indices.
//! \pre The mesh outlives the FaceBvh and does not move (the FaceBvh keeps its address and is
//!   attached to its change log).
//! \pre Every live face has at least 3 corners.
//! Queries are const and touch no shared mutable state: any number may run concurrently, as long as
//! nothing edits the mesh meanwhile. build(), refit() and update() need the mesh to themselves, as
//! edits do (they read and consume the change log).
class FaceBvh {
 public:
  //! Sizes and bookkeeping, for tests and tuning.
  struct Stats {
    std::size_t nodes = 0;              //!< node slots, including orphaned ones
    std::size_t orphan_nodes = 0;       //!< node slots update() left unreachable since the last build
    std::size_t leaves = 0;             //!< reachable leaves
    std::size_t live_faces = 0;         //!< faces the tree answers for
    std::size_t dead_slots = 0;         //!< face slots tombstoned by update() since the last build
    unsigned height = 0;                //!< edges on the longest root-to-leaf path
    unsigned height_at_build = 0;       //!< the same right after the last full build
    std::size_t builds = 0;             //!< full builds so far (the constructor's included)
    std::size_t compactions = 0;        //!< update() reclaiming dead slots without a build, so far
    std::size_t inserted_subtrees = 0;  //!< update() placements next to a node, since construction
    std::size_t merged_subtrees = 0;    //!< update() merges into a young subtree, since construction
  };

  //! An empty tree: every query finds nothing.
  FaceBvh() = default;
  //! Builds over the live faces of mesh. O(n log n) for n live faces. \throw as build().
  explicit FaceBvh(const SurfaceMesh& mesh, const BvhOptions& options = {});

  //! (Re)builds over the live faces of mesh, replacing the whole tree. O(n log n).
  //! \throw InvalidInputError naming the first vertex whose position is not finite,
  //!   before anything changes (require_finite_positions()).
  void build(const SurfaceMesh& mesh, const BvhOptions& options = {});
  //! Rebuilds over the same mesh with the same options. O(n log n). No-op on an empty FaceBvh.
  //! Does not throw for a position that is not finite (update() calls it, often in the middle of
  //! an edit that must not fail halfway): a face with such a corner is left out of the tree, and no
  //! query finds it. The same holds for the faces update() and refit() box.
  void rebuild();

  //! Recomputes every box bottom-up from the current positions, after vertices moved. The tree's
  //! shape is kept, so a query is as correct as after a build but may get slower when the motion was
  //! large (then rebuild()). Boxes stop covering faces tombstoned by update(). O(n).
  void refit();

  //! Takes every edit since the last build or update() into account, from the mesh's change log:
  //! faces added, removed or re-linked, and vertices moved (their faces are re-inserted; when more
  //! than an eighth of the live faces are affected, the whole tree is refitted instead). After a
  //! reset (garbage_collection()) it rebuilds. Costs as update(faces) below for the faces the log
  //! names, plus O(valence) per moved vertex; nothing when nothing changed. No-op on an empty
  //! FaceBvh that was never built.
  //! Edits made through the mesh's low-level setters count only if they are marked
  //! (SurfaceMesh::mark_changed; set_position marks itself).
  void update();
  //! True if the change log holds nothing this tree has not taken in: no edit since the last build
  //! or update(). Edits passed to update(faces) are still pending here. O(1).
  bool up_to_date() const { return changes_.pending().empty(); }

  //! Takes the given faces into account without rebuilding the whole tree, for edits the change
  //! log did not see (unmarked low-level edits); update() with no arguments finds the faces itself.
  //! \param changed_or_added faces created, or whose corners (connectivity or positions) changed.
  //!   Each one's old entry, if any, is tombstoned and a new one inserted. Deleted faces are treated
  //!   as removed; duplicates are allowed.
  //! \param removed faces deleted from the mesh (or no longer to be found). Unknown faces are ignored.
  //!
  //! Removed and replaced entries are tombstoned and the boxes of their leaves, and of the nodes
  //! above them up to where a box stops changing, are refitted at once; the new ones go into a small
  //! subtree placed near where they belong, so repeated edits in one spot stay cheap. Cost, for k
  //! faces: O(k log k + k height). When the tombstoned slots exceed options.rebuild_fraction of all
  //! slots they are reclaimed by a compaction, O(n) without sorting: the live entries close up in
  //! their leaves, and leaves left without a face are cut out of the tree. The whole tree is rebuilt,
  //! O(n log n), only when its quality has degraded: its height exceeds
  //! 2 * stats().height_at_build + 16, or the node slots cut out or orphaned since the last build
  //! outnumber the nodes in use. Batch the faces of many local operations into one call where you
  //! can.
  //! \pre Faces not listed kept their corners and positions; moved vertices need refit() (or their
  //!   faces listed here).
  //! \throw InvalidInputError for a handle that is not a face slot of the mesh, or after a reset
  //!   (garbage_collection()) that the tree has not been rebuilt since.
  void update(std::span<const Face> changed_or_added, std::span<const Face> removed = {});

  //! The nearest point of the surface to p, with its face. O(log n) expected for a point near the
  //! surface; a point far from a large mesh visits more nodes.
  //! \return nothing for an empty tree or a non-finite p.
  std::optional<LocateResult> closest_point(const Vec3& p) const;
  //! The same, restricted to points within max_distance of p (a search radius, which also makes the
  //! query cheaper). \return nothing if no face is that near, or for a negative or NaN max_distance.
  std::optional<LocateResult> closest_point(const Vec3& p, double max_distance) const;

  //! 2D plates and height fields: the face whose projection onto a coordinate plane contains p,
  //! boundary included. The projection drops one coordinate: z for ProjectionPlane::xy (the
  //! default; p = (x, y)), y for xz (p = (x, z): the ground plane of y-up engines such as Unity),
  //! x for yz (p = (y, z)). `point` is the point of the face
  //! that projects onto p (the dropped coordinate interpolated), so this also samples a height field.
  //! Faces seen edge-on (zero projected area) contain nothing. Orientation tests are exact in
  //! double for float input. O(log n) expected on a plate or a height field.
  //! \return nothing if no face contains p (outside the plate, in a hole) or p is not finite. If
  //!   several do (a point on a shared edge, a surface that folds over itself) the smallest index.
  std::optional<SurfacePoint> face_containing(const Vec2& p,
                                              ProjectionPlane plane = ProjectionPlane::xy) const;
  //! 3D plates in any orientation: the face nearest to p, if p lies within `tolerance` of it, such
  //! as an impact point a physics engine reports on a plate. Same cost as closest_point.
  //! \return nothing if no face is within tolerance, or p is not finite.
  std::optional<LocateResult> face_containing(const Vec3& p, double tolerance) const;

  //! The first face hit by origin + t * direction with 0 <= t <= t_max, for picking from a camera:
  //! watertight and two-sided, as intersect_ray_triangle. O(log n) expected.
  //! \return nothing if no face is hit, or for a zero or non-finite direction, a non-finite origin,
  //!   or a NaN or negative t_max.
  std::optional<RayHit> first_hit(const Vec3& origin, const Vec3& direction,
                                  double t_max = std::numeric_limits<double>::infinity()) const;

  //! Appends to `out` the faces whose boxes (of their corners) overlap the closed box [lo, hi],
  //! sorted by index: the faces that may meet a region inside the box. O(log n + k) expected for
  //! k faces found. Nothing for an empty tree or a box that is empty or not finite.
  void faces_in_box(const Vec3& lo, const Vec3& hi, std::vector<Face>& out) const;
  //! The same box as bounds() below, which holds every face the tree answers for (after update() it
  //! may be larger than their tight box): O(1). False, with lo and hi untouched, for an empty tree.
  bool bounds(Vec3& lo, Vec3& hi) const;
  bool empty() const { return nodes_.empty() || live_ == 0; }
  //! The root's box: it covers every face the tree answers for. After update() it may still cover
  //! faces removed since the last build, refit() or compaction (it shrinks to the faces' box then),
  //! so it never shrinks in between as pieces are taken away. Empty for a tree without faces. O(1), so a
  //! caller gets the size of the mesh without a pass over its vertices. (BoundingBox: algorithms/geometry.h.)
  BoundingBox bounds() const;
  //! Whether every edge of the mesh has a face on both sides (no boundary half-edge): a pass over
  //! the half-edges, O(H), the first time it is asked after a build or after an update() that took
  //! in changed or removed faces; kept until then, so asking again costs nothing. With `boundary`,
  //! an open mesh's first boundary half-edge is stored there. Solid fracture asks it: only a closed
  //! mesh encloses a solid, and a hole far from the impact cannot be seen from the broken region.
  bool mesh_closed(Halfedge* boundary = nullptr);
  //! Records that the mesh is (or is not) closed, for an algorithm that knows it kept a closed mesh
  //! closed: call it after the update() that took its edit in, so the next mesh_closed() makes no
  //! pass. Solid fracture does, so repeated strikes on one mesh cost the broken region only.
  void note_closed(bool closed, Halfedge boundary = Halfedge{});
  //! Heap bytes held by the tree (capacity, not size). O(1).
  std::size_t memory_bytes() const;
  const SurfaceMesh* mesh() const { return mesh_; }
  const BvhOptions& options() const { return options_; }
  //! O(#nodes): the leaves are counted.
  Stats stats() const;

 private:
  struct Node {
    float lo[3], hi[3];
    //! Leaf: first entry in entries_. Internal: first of the two adjacent children.
    Index index;
    //! Leaf: number of entries (>= 1). Internal: 0.
    Index count;
    bool is_leaf() const { return count != 0; }
  };
  //! face is kInvalidIndex for a tombstone. corner[0] is kInvalidIndex for a polygon (walked).
  struct Entry {
    Index face;
    Index corner[3];
  };
  struct Box;
  struct Builder;

  //! build() without the check of the positions (rebuild()).
  void build_tree(const SurfaceMesh& mesh, const BvhOptions& options);
  Entry make_entry(Face f) const;
  Box entry_box(const Entry& e) const;
  template <typename Fn>
  bool for_each_triangle(const Entry& e, Fn&& fn) const;
  void build_subtree(Index first_entry, Index count, Index root);
  void insert_entries(Index first_entry, Index count);
  void refit_leaf(Index node);
  void refit_internal(Index node);
  //! Refits the leaves in dirty_ and the nodes above them, up to where a box stops changing.
  void refit_dirty();
  //! Drops the tombstones, cuts leaves without a live face out of the tree, refits the internal
  //! nodes and makes bounds() tight. O(nodes + entries).
  void compact();
  //! bounds() grown to the root's box.
  void grow_bounds();
  void set_height(Index node);
  void update_slack();
  void check_fresh() const;

  const SurfaceMesh* mesh_ = nullptr;
  BvhOptions options_;
  std::vector<Node> nodes_;
  std::vector<Entry> entries_;
  //! Height of each node's subtree; update() bounds the tree's height with it.
  std::vector<std::uint32_t> height_;
  //! At the root of a subtree inserted by update(): its number of entries; 0 elsewhere.
  std::vector<Index> young_;
  //! Face index -> slot in entries_, kInvalidIndex when the face is not in the tree.
  std::vector<Index> slot_of_face_;
  //! Each node's parent (kInvalidIndex for the root; stale for orphaned nodes).
  std::vector<Index> parent_;
  //! Each entry slot's leaf (stale for slots of orphaned leaves).
  std::vector<Index> leaf_of_;
  //! Leaves update() tombstoned entries of, to refit (scratch).
  std::vector<Index> dirty_;
  //! What bounds() reports: the root's box at the last build, refit() or compaction, grown since.
  float bounds_lo_[3] = {0, 0, 0}, bounds_hi_[3] = {-1, -1, -1};
  std::size_t live_ = 0;
  std::size_t dead_ = 0;
  std::size_t orphan_nodes_ = 0;
  //! The young subtree inserted last: its entries start at tail_first_entry_ and run to the end of
  //! entries_ (before the new ones of an update), its nodes below the root from tail_first_node_ to
  //! the end of nodes_. kInvalidIndex when there is none.
  Index tail_root_ = kInvalidIndex;
  Index tail_first_entry_ = 0;
  Index tail_first_node_ = 0;
  //! This tree's place in the mesh's change log.
  ChangeConsumer changes_;
  unsigned height_at_build_ = 0;
  //! mesh_closed()'s answer: -1 until it is asked after a build or a change, then 0 or 1.
  int closed_ = -1;
  Halfedge first_boundary_{};
  std::size_t builds_ = 0;
  std::size_t compactions_ = 0;
  std::size_t inserted_ = 0;
  std::size_t merged_ = 0;
  //! Absolute slack of the distance pruning, from the root box's size.
  double slack_sq_ = 0;
};

//! Linear scans over all live faces: O(n · face degree) each, no preprocessing. Same answers as the
//! FaceBvh queries of the same name (ties included); `nothing` in the same cases.
std::optional<LocateResult> closest_point_linear(const SurfaceMesh& mesh, const Vec3& p);
std::optional<RayHit> first_hit_linear(const SurfaceMesh& mesh, const Vec3& origin, const Vec3& direction,
                                       double t_max = std::numeric_limits<double>::infinity());
std::optional<SurfacePoint> face_containing_linear(const SurfaceMesh& mesh, const Vec2& p,
                                                   ProjectionPlane plane = ProjectionPlane::xy);

}  // namespace hedge

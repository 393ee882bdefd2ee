// Internals of solid fracture (include/hedge/algorithms/fracture_solid.h), shared by
// fracture_solid.cpp (the pipeline, pieces and the remaining object), fracture_solid_cells.cpp
// (break points, planes and cells) and fracture_solid_clip.cpp (clipping and capping).
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <map>
#include <vector>

#include "hedge/algorithms/fracture_solid.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge::solid_detail {

//! A plane: value(x) = dot(n, x) + d. A point is below it when the value is negative; a point on
//! it counts as above (the tie rule: no point is ever "on" a plane).
struct Plane {
  Vec3d n;
  double d = 0;
  double value(const Vec3d& x) const { return n.x * x.x + n.y * x.y + n.z * x.z + d; }
  bool below(const Vec3d& x) const { return value(x) < 0; }
};

//! One side of a plane: inside is below it, or above it when flip.
struct HalfSpace {
  std::uint32_t plane = 0;
  bool flip = false;
};

//! The symbolic name of a point. Its position is a function of the key alone.
struct Key {
  enum Kind : std::uint32_t { vertex = 0, edge = 1, triangle = 2, corner = 3 };
  //! vertex: a = mesh vertex. edge: mesh vertices a < b (an edge or a diagonal of a polygon face),
  //! cut by plane c. triangle: soup triangle a pierced by the line of planes b < c. corner: the
  //! vertex of planes a < b < c.
  std::uint32_t kind = 0, a = 0, b = 0, c = 0;
  auto operator<=>(const Key&) const = default;
};

Key corner_key(std::uint32_t p, std::uint32_t q, std::uint32_t r);

//! The triangles of the mesh's faces in the region: each face's triangles (polygons split by
//! fan_start(), as volume() and the picking tree see them), corners counter-clockwise as the face.
struct SoupTriangle {
  std::array<Index, 3> v;          // mesh vertices
  std::array<Halfedge, 3> corner;  // the face's half-edge pointing to v[k]
  Face face;
  float lo[3], hi[3];  // box
};

//! A convex polytope: its faces (corners counter-clockwise seen from outside) on half-spaces, and
//! its corners' positions.
struct Polytope {
  struct Side {
    HalfSpace h;
    std::vector<Key> corners;
  };
  std::vector<Side> faces;
  //! The corners' positions, sorted by key, keys unique (a flat map: a cell has some tens).
  std::vector<std::pair<Key, Vec3d>> points;
  bool empty() const { return faces.empty(); }
  //! The position of corner k, which must be one of `points`.
  const Vec3d& at(const Key& k) const;
  //! Box of the corners, grown by `margin`.
  void box(double margin, float lo[3], float hi[3]) const;
};

//! Planes by id: the region's planes first, then bisectors made on demand.
struct PlaneSet {
  std::vector<Plane> planes;
  //! Bisector of break points i < j, inside for i below. Made once, so both cells use it bit for bit.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> bisector_of;
  //! plane id -> (i, j) for a bisector; (-1, -1) for a plane of the region.
  std::vector<std::pair<std::int64_t, std::int64_t>> pair_of;
  std::uint32_t bisector(std::uint32_t i, std::uint32_t j, const std::vector<Vec3d>& points);
};

//! The region P about the impact: 26 planes at distance `radius` from `centre`, each moved by up
//! to nudge / 2 (seeded) when nudge > 0.
Polytope region_polytope(const Vec3d& centre, double radius, PlaneSet& planes, std::uint64_t seed,
                         double nudge);
//! P clipped by h; false if the polytope failed to stay consistent (a degenerate clip).
bool clip_polytope(Polytope& p, HalfSpace h, const PlaneSet& planes);
//! The Voronoi cell of points[i] within P.
bool voronoi_cell(const Polytope& region, const std::vector<Vec3d>& points, std::uint32_t i, PlaneSet& planes,
                  Polytope& cell);
//! The break points of `material` (in model units) about `centre`, seeded; duplicates removed.
std::vector<Vec3d> break_points(const FractureMaterial& material, const Vec3d& centre, std::uint64_t seed,
                                double nudge);

//! Everything a key's position depends on.
struct Geometry {
  const SurfaceMesh* mesh = nullptr;
  const PlaneSet* planes = nullptr;
  const std::vector<SoupTriangle>* soup = nullptr;
  //! Positions of corner keys of the polytope at hand (triangle keys: see clip_triangle()).
  const std::map<Key, Vec3d>* corners = nullptr;
  Vec3d position(const Key& k) const;
  Vec3d vertex(Index v) const;
};

//! A convex polygon of a clipped triangle: points, and the support of each edge k (from point k to
//! k + 1): a plane id, or kNoPlane for a part of the triangle's own side.
inline constexpr std::uint32_t kNoPlane = 0xffffffffu;
struct ClipPolygon {
  std::uint32_t triangle = 0;
  std::vector<Key> keys;
  std::vector<Vec3d> pos;
  std::vector<std::uint32_t> support;
};

//! Soup triangle t clipped by every half-space of `planes` (Sutherland-Hodgman); empty keys when
//! nothing is inside. The caller may pass `first` when every corner of the triangle lies inside
//! planes[0..first) by the test clipping makes: those half-spaces leave the triangle as it is, so
//! clipping starts at planes[first], with the same result.
void clip_triangle(const Geometry& g, std::uint32_t t, const std::vector<HalfSpace>& planes, ClipPolygon& out,
                   std::size_t first = 0);

//! A directed edge of a region's boundary inside its convex outline (the region on its left).
struct ChainEdge {
  Key a, b;
  Vec3d pa, pb;
};

//! A planar region: a convex outline (corners counter-clockwise seen from `normal`) minus what the
//! chains cut off. side(key): the outline side (0..n-1) a chain end lies on, -1 for a point inside,
//! -2 for a point that lies on no side (an inconsistency). inside(): whether the outline is inside
//! the region, asked only when no chain touches it.
struct RegionInput {
  Vec3d normal;
  std::vector<Key> corners;
  std::vector<Vec3d> corner_pos;
  std::vector<ChainEdge> chain;
  std::function<int(const Key&)> side;
  std::function<bool()> inside;
};

//! Triangulates the region (several loops, holes included) in its plane. Appends triangles as
//! key triples, counter-clockwise seen from the normal, and the positions of their keys.
//! \return false on an inconsistency (then the output is partial and must be dropped).
bool fill_region(const RegionInput& in, std::vector<std::array<Key, 3>>& tris,
                 std::vector<std::pair<Key, Vec3d>>& points);

//! Triangulates one polygon with holes in 2D (points in the plane's frame, outer counter-clockwise,
//! holes clockwise): holes are bridged into the outer loop, then ears are clipped. Points are
//! named by ids; equal ids are the same point. Appends id triples. False if a hole lies in no
//! visible reach of the outer loop.
bool triangulate_with_holes(const std::vector<std::array<double, 2>>& outer_xy,
                            const std::vector<std::uint32_t>& outer_id,
                            const std::vector<std::vector<std::array<double, 2>>>& holes_xy,
                            const std::vector<std::vector<std::uint32_t>>& holes_id,
                            std::vector<std::array<std::uint32_t, 3>>& tris);

//! Two unit vectors u, v with u x v = n (n unit): u along n x the axis least aligned with n.
void plane_frame(const Vec3d& n, Vec3d& u, Vec3d& v);

}  // namespace hedge::solid_detail

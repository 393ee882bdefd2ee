// Internals of solid fracture: one strike computed without touching the mesh
// (fracture_solid_strike.cpp), then applied (fracture_solid_apply.cpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fracture_solid_internal.h"
#include "hedge/core/build.h"

namespace hedge::solid_detail {

struct StrikeInput {
  SurfaceMesh& mesh;
  const FaceBvh& tree;
  Vec3d centre;               // the impact on the surface
  double region_radius;       // of P's inscribed sphere
  FractureMaterial material;  // in model units
  const SolidFractureOptions& options;
};

//! A triangle's origin: a soup triangle, or (with kCapBit) the plane of a cap.
inline constexpr std::uint32_t kCapBit = 0x80000000u;

//! Triangles over keyed points: a piece, or the patch that replaces the region in the mesh.
struct KeyedSurface {
  std::vector<std::array<Key, 3>> tris;
  std::vector<std::uint32_t> source;
  //! Sorted by key, unique.
  std::vector<std::pair<Key, Vec3d>> points;
  void add(const std::array<Key, 3>& t, std::uint32_t from) {
    tris.push_back(t);
    source.push_back(from);
  }
  //! Sorts `points` by key and drops repeated keys; with `corner`, also sets (*corner)[3 t + k] to
  //! the index in `points` of tris[t][k] (0xffffffff if it is not there). O(n log n) in the
  //! distinct points, O(1) expected per listed point and corner.
  void finish_points(std::vector<std::uint32_t>* corner = nullptr);
  std::uint32_t index(const Key& k) const;
};

struct PieceDraft {
  std::size_t cell = 0;
  KeyedSurface surface;
  //! Built from `surface` (triangle i is face i, point i vertex i), closed; no properties yet.
  SurfaceMesh mesh;
};

struct Strike {
  PlaneSet planes;
  std::vector<SoupTriangle> soup;
  std::vector<PieceDraft> pieces;
  //! The faces of the mesh the patch replaces (sorted), and the patch: their parts outside P and
  //! P's caps, turned inwards.
  std::vector<Face> touched;
  KeyedSurface patch;
  std::vector<SolidBond> bonds;
  std::string failure;
  double seconds_cells = 0, seconds_clip = 0, seconds_cap = 0;
};

//! Finishes the points of a keyed surface and links it into `mesh` with link_closed_triangles()
//! (core_private/link_closed.h), which numbers it as build_triangles() would (point i is vertex i,
//! triangle i face i) and checks explicitly what build() would: false, with `failure` saying what,
//! unless the surface is a closed manifold, that is, no triangle repeats a point, every directed
//! edge is used once and its reverse once, the triangles around every point form one fan, and every
//! point is finite in float. Sets corner[3 t + k] to the point of s.tris[t][k]. O(corners x
//! valence) after the points' sort.
bool build_closed(KeyedSurface& s, SurfaceMesh& mesh, std::vector<std::uint32_t>& corner,
                  std::string& failure);

//! The faces whose boxes meet the box of P (sorted).
void region_faces(const StrikeInput& in, std::vector<Face>& faces);

//! Computes the strike: cells, pieces (built and checked closed), the patch (checked to fit the
//! hole it fills) and the bonds. False, with `failure` saying what, on an inconsistency.
bool compute_strike(const StrikeInput& in, const std::vector<Face>& faces, double nudge, std::uint64_t seed,
                    Strike& strike);

//! Adds to strike.patch the parts outside P of the touched soup triangles (inside_p[t]: t clipped
//! to P, touched[t] when that is not empty) and sets strike.touched; the faces around a vertex
//! that the removal would pinch are touched too. Checks that the patch fits the hole exactly.
bool patch_outside(const StrikeInput& in, const Geometry& g, const std::vector<ClipPolygon>& inside_p,
                   std::vector<char> touched, Strike& strike);

//! "f:submesh" of the caps (options.inner_submesh resolved).
std::int32_t inner_submesh_of(const SurfaceMesh& mesh, std::int32_t option);
//! The pieces with their properties (see the header).
std::vector<SolidPiece> assemble_pieces(const StrikeInput& in, Strike& strike, std::int32_t inner);
//! Replaces the touched faces of the mesh by the patch.
void apply_remaining(const StrikeInput& in, Strike& strike, std::int32_t inner);
//! Volume, mass properties and hull of every piece; `beside` (if any) runs on the workers at the
//! same time (it must not touch the pieces).
void measure_pieces(std::vector<SolidPiece>& pieces, const SolidFractureOptions& o,
                    const std::function<void()>& beside = {});

}  // namespace hedge::solid_detail

// The library's geometry toolkit: measures of a mesh's geometry (edge lengths, corner angles, face
// areas and centroids, the surface area, the bounding box and the enclosed volume), the pieces of
// the cotangent Laplacian (cotangents, cotangent weights, vertex areas), and a seeded generator.
// Every algorithm uses these rather than a copy of its own. Computed in double from the float
// positions. Vector helpers (dot, cross, norm, unit_or_zero) are in core/vec.h; the face centroid
// is core's face_centroid() (core/face_operations.h), which centroid() calls in double.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge {

// ---- Edges, corners and faces ----

//! The length of half-edge h (of its edge). O(1).
double edge_length(const SurfaceMesh& mesh, Halfedge h);

//! The longest of face f's edges. O(face degree).
double longest_edge(const SurfaceMesh& mesh, Face f);

//! The mean length of face f's edges. O(face degree).
double mean_edge_length(const SurfaceMesh& mesh, Face f);

//! The mean of f's corner positions, in double: face_centroid<double>() of core/face_operations.h
//! (face_centroid() rounds it to float). O(face degree).
Vec3d centroid(const SurfaceMesh& mesh, Face f);

//! The angle at corner `at` between the directions to a and to b, in [0, pi]; 0 if either side has
//! zero length.
double corner_angle(const Vec3d& at, const Vec3d& a, const Vec3d& b);

//! Half the length of the cross product: the area of triangle (a, b, c).
double triangle_area(const Vec3d& a, const Vec3d& b, const Vec3d& c);

//! The cotangents of the angles of triangle p at its corners 0, 1, 2; all zero for a triangle of
//! zero area (or a non-finite one).
std::array<double, 3> triangle_cotangents(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2);

// ---- The cotangent Laplacian ----
// Positions are given per vertex slot (positions.size() == mesh.vertex_slots()), so that an
// algorithm can evaluate them at positions it is still moving; the overloads without them read the
// mesh's own.

//! The cotangent weight of every edge slot: half the sum of the cotangents of the angles opposite
//! the edge in its (one or two) triangles; may be negative (an obtuse pair), 0 for deleted edges.
//! O(F).
//! \throw InvalidInputError if a face is not a triangle (the message names it) or if positions
//!   does not have one entry per vertex slot.
std::vector<double> cotangent_weights(const SurfaceMesh& mesh, std::span<const Vec3d> positions);
std::vector<double> cotangent_weights(const SurfaceMesh& mesh);

//! The barycentric area of every vertex slot: a third of the area of each fan triangle (c0, c[i],
//! c[i+1]) of the faces around it, so that they sum to the surface area; 0 for isolated and
//! deleted vertices. Any polygons. O(F).
//! \throw InvalidInputError if positions does not have one entry per vertex slot.
std::vector<double> vertex_areas(const SurfaceMesh& mesh, std::span<const Vec3d> positions);
std::vector<double> vertex_areas(const SurfaceMesh& mesh);

// ---- Areas and volumes ----

//! Newell's vector of face f: twice its area times its unit normal (for a planar polygon; the
//! best-fit plane's otherwise), oriented by its winding. O(face degree).
Vec3d area_vector(const SurfaceMesh& mesh, Face f);

//! The area of face f: half the length of its Newell vector, exact for planar polygons (a
//! non-planar polygon gets the area of its projection onto its best-fit plane). O(face degree).
double face_area(const SurfaceMesh& mesh, Face f);

//! The sum of the areas of the live faces. O(V + F).
//! \throw InvalidInputError naming the first vertex whose position is not finite.
double surface_area(const SurfaceMesh& mesh);

struct BoundingBox {
  Vec3 min{0, 0, 0}, max{0, 0, 0};
  //! True for the box of no vertex at all (min and max are then zero).
  bool empty = true;
  Vec3 size() const { return empty ? Vec3{0, 0, 0} : max - min; }
  Vec3 centre() const { return empty ? Vec3{0, 0, 0} : (min + max) * 0.5f; }
};

//! The axis-aligned box around the live vertices (isolated ones included). O(V).
//! \throw InvalidInputError naming the first vertex whose position is not finite: a box that
//!   skipped a NaN (as min and max do) would be wrong without a word.
BoundingBox bounding_box(const SurfaceMesh& mesh);

//! The signed volume the surface encloses: positive when the faces wind counter-clockwise seen from
//! outside (outward normals), negative for an inside-out surface, by the divergence theorem over the
//! faces' fan triangles (from fan_start(): the first corner unless that fan folds, the triangles
//! the picking tree and solid fracture use). For several closed pieces, the sum of theirs. O(F).
//! \throw InvalidInputError if the mesh has a boundary (an open surface encloses no volume); the
//!   message says how many boundary half-edges it has, or naming the first vertex whose position
//!   is not finite.
double volume(const SurfaceMesh& mesh);

// ---- A seeded generator ----

//! splitmix64's output function (Steele, Lea and Flood 2014): a well-mixed 64-bit value from any
//! 64-bit input, so that value i of a stream can be drawn on its own, in any order, on any thread.
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

//! A uniform double in [0, 1) from the top 53 of 64 random bits, scaled exactly.
constexpr double unit_interval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

//! splitmix64: one 64-bit state, a Weyl step of kGamma and splitmix64_mix. The same seed gives the
//! same numbers on every platform (unlike the standard distributions), so seeded algorithms
//! (fracture, distance sampling) repeat exactly.
class SplitMix64 {
 public:
  static constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15ull;
  explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}
  constexpr std::uint64_t next() { return splitmix64_mix(state_ += kGamma); }
  //! Uniform in [0, 1).
  constexpr double uniform() { return unit_interval(next()); }

 private:
  std::uint64_t state_;
};

}  // namespace hedge

// Corner texture coordinates through one collapse of decimate(): which edges are UV seams, the
// triangles around the edge's two ends before the collapse with their charts, and the corners at
// the survivor after it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge::detail::decimation {

// A seam edge: an interior edge whose two faces give one of its ends different texture coordinates.
// The corner of vertex x in face f is stored on the half-edge entering x in f.
bool is_seam(const SurfaceMesh& m, const HalfedgeProperty<Vec2>& uv, Edge e);

// One collapse's ring: the triangles around both ends before it, their corners' positions and
// texture coordinates, and which chart (faces joined across non-seam edges) each belongs to. The
// storage is kept from one collapse to the next.
class CornerRing {
 public:
  // Before collapsing h: the triangles around both ends, their corners, and their charts (faces
  // joined across spoke edges that are not seams, with union-find over the ring's slots).
  void gather(const SurfaceMesh& m, const HalfedgeProperty<Vec2>& uv, Halfedge h);
  // After the collapse: each corner at v gets the texture coordinates at p of the nearest old
  // triangle of its own chart (barycentric, clamped to the triangle).
  void interpolate(const SurfaceMesh& m, HalfedgeProperty<Vec2> uv, Vertex v, const Vec3d& p) const;

 private:
  struct RingFace {
    Face f;
    std::array<Vec3d, 3> x;
    std::array<Vec2, 3> uv;
    std::uint32_t chart;
  };
  std::vector<RingFace> ring_;
};

}  // namespace hedge::detail::decimation

// The closed spheres of BM_fracture_solid and BM_convex_hull_pieces (hedge_bench.cpp), shared with
// solid_strike_replay.cpp so that the replay strikes the very same mesh.
#pragma once

#include <cmath>
#include <cstdint>

#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"

namespace bench {

//! A closed sphere of radius 1: a cube's faces cut into n x n squares of two triangles each
//! (12 n^2 triangles), welded and pushed onto the sphere.
inline hedge::SurfaceMesh grid_sphere(int n, float radius = 1) {
  hedge::IndexedMesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = -1; side <= 1; side += 2) {
      const std::uint32_t base = static_cast<std::uint32_t>(m.positions.size());
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          float p[3];
          p[axis] = float(side);
          p[(axis + 1) % 3] = float(2 * i - n) / float(n);
          p[(axis + 2) % 3] = float(2 * j - n) / float(n);
          m.positions.push_back({p[0], p[1], p[2]});
        }
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const std::uint32_t a = base + std::uint32_t(j * (n + 1) + i), b = a + 1,
                              c = a + std::uint32_t(n + 1), d = c + 1;
          if (side > 0)
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
          else
            m.indices.insert(m.indices.end(), {a, d, b, a, c, d});
          m.face_sizes.insert(m.face_sizes.end(), {3, 3});
        }
    }
  hedge::SurfaceMesh s = hedge::build(m, {.weld = hedge::Weld::exact});
  for (hedge::Vertex v : s.vertices()) {
    const hedge::Vec3 p = s.position(v);
    const float l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z) / radius;
    s.position(v) = {p.x / l, p.y / l, p.z / l};
  }
  return s;
}

}  // namespace bench

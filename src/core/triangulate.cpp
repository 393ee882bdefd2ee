// Ear clipping in the polygon's Newell plane.
#include "hedge/core/triangulate.h"

#include <cmath>

namespace hedge {

void triangulate_polygon(std::span<const Vec3d> p, std::vector<std::array<Index, 3>>& tris) {
  const std::size_t n = p.size();
  Vec3d nrm{0, 0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3d& a = p[i];
    const Vec3d& b = p[(i + 1) % n];
    add_newell_term(nrm, a, b);
  }
  // Project onto the plane: drop the dominant normal axis, keeping orientation.
  int ax = 0;
  if (std::abs(nrm.y) > std::abs(nrm[ax])) ax = 1;
  if (std::abs(nrm.z) > std::abs(nrm[ax])) ax = 2;
  const int u = (ax + 1) % 3, v = (ax + 2) % 3;
  const double sign = nrm[ax] < 0 ? -1.0 : 1.0;
  std::vector<std::array<double, 2>> q(n);
  for (std::size_t i = 0; i < n; ++i) q[i] = {p[i][u], sign * p[i][v]};
  auto cross2 = [&](Index a, Index b, Index c) {
    return (q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[a][0]);
  };
  std::vector<Index> ring(n);
  for (std::size_t i = 0; i < n; ++i) ring[i] = static_cast<Index>(i);
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size() && !clipped; ++i) {
      const Index a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
      if (cross2(a, b, c) <= 0) continue;  // reflex or flat corner
      bool inside = false;
      for (Index r : ring) {
        if (r == a || r == b || r == c) continue;
        if (cross2(a, b, r) >= 0 && cross2(b, c, r) >= 0 && cross2(c, a, r) >= 0) {
          inside = true;
          break;
        }
      }
      if (inside) continue;
      tris.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) tris.push_back({ring[0], ring[i], ring[i + 1]});
}

}  // namespace hedge

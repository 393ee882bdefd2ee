// Corner texture coordinates through a collapse (see decimate_corners.h).
#include "decimate_corners.h"

#include <cmath>

#include "decimate_internal.h"

namespace hedge::detail::decimation {

bool is_seam(const SurfaceMesh& m, const HalfedgeProperty<Vec2>& uv, Edge e) {
  const Halfedge h = SurfaceMesh::halfedge(e, 0), t = SurfaceMesh::twin(h);
  if (m.is_boundary(h) || m.is_boundary(t)) return false;
  const Halfedge hp = m.next(m.next(h)), tp = m.next(m.next(t));
  return uv[h] != uv[tp] || uv[hp] != uv[t];
}

void CornerRing::gather(const SurfaceMesh& m, const HalfedgeProperty<Vec2>& uv, Halfedge h) {
  auto pos = [&](Vertex v) { return to_double(m.position(v)); };
  ring_.clear();
  for (const Halfedge start : {h, SurfaceMesh::twin(h)}) {
    Halfedge o = start;
    do {
      const Face f = m.face(o);
      if (f.is_valid() && (start == h || (f != m.face(h) && f != m.face(SurfaceMesh::twin(h))))) {
        const Halfedge o1 = m.next(o), o2 = m.next(o1);
        RingFace r{f,
                   {pos(m.to_vertex(o2)), pos(m.to_vertex(o)), pos(m.to_vertex(o1))},
                   {uv[o2], uv[o], uv[o1]},
                   std::uint32_t(ring_.size())};
        ring_.push_back(r);
      }
      o = m.rotate_cw(o);
    } while (o != start);
  }
  auto find = [&](std::uint32_t i) {
    while (ring_[i].chart != i) i = ring_[i].chart = ring_[ring_[i].chart].chart;
    return i;
  };
  auto slot = [&](Face f) -> std::uint32_t {
    for (std::uint32_t i = 0; i < ring_.size(); ++i)
      if (ring_[i].f == f) return i;
    return std::uint32_t(-1);
  };
  // Every spoke edge of both ends (h's edge included): join its faces unless it is a seam.
  for (const Halfedge start : {h, SurfaceMesh::twin(h)}) {
    Halfedge o = start;
    do {
      const Face f0 = m.face(o), f1 = m.face(SurfaceMesh::twin(o));
      if (f0.is_valid() && f1.is_valid() && !is_seam(m, uv, SurfaceMesh::edge(o))) {
        const std::uint32_t i = slot(f0), j = slot(f1);
        if (i != std::uint32_t(-1) && j != std::uint32_t(-1)) ring_[find(i)].chart = find(j);
      }
      o = m.rotate_cw(o);
    } while (o != start);
  }
  for (std::uint32_t i = 0; i < ring_.size(); ++i) ring_[i].chart = find(i);
}

void CornerRing::interpolate(const SurfaceMesh& m, HalfedgeProperty<Vec2> uv, Vertex v,
                             const Vec3d& p) const {
  const Halfedge start = m.halfedge(v);
  Halfedge o = start;
  do {
    const Halfedge in = SurfaceMesh::twin(o);
    const Face f = m.face(in);
    if (f.is_valid()) {
      std::uint32_t chart = std::uint32_t(-1);
      for (const RingFace& r : ring_)
        if (r.f == f) chart = r.chart;
      double best = HUGE_VAL;
      Vec2 value = uv[in];
      for (const RingFace& r : ring_) {
        if (r.chart != chart) continue;
        double b0, b1, b2;
        if (!clamped_barycentric(r.x, p, b0, b1, b2)) continue;
        const Vec3d q = r.x[0] * b0 + r.x[1] * b1 + r.x[2] * b2 - p;
        const double dist = dot(q, q);
        if (dist < best) {
          best = dist;
          value = Vec2{float(b0 * r.uv[0].x + b1 * r.uv[1].x + b2 * r.uv[2].x),
                       float(b0 * r.uv[0].y + b1 * r.uv[1].y + b2 * r.uv[2].y)};
        }
      }
      uv[in] = value;
    }
    o = m.rotate_cw(o);
  } while (o != start);
}

}  // namespace hedge::detail::decimation

// Subdivision 1-to-4 of triangle meshes: Loop's scheme and the midpoint split.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "subdivide_internal.h"

namespace hedge::detail::subdivision {

namespace {

// Loop's weight of the ring for a vertex of valence n (the vertex keeps 1 - n beta).
double loop_beta(std::size_t n) {
  const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
  return (0.625 - c * c) / double(n);
}

// Positions of the 1-to-4 schemes, from the old arrays: the old vertices (first nv entries; Loop
// moves them) and the edge vertices (then ne; Loop's masks, or midpoints).
// The three half-edges of old triangle f, from its first.
std::array<Index, 3> triangle_halfedges(const Old& o, std::size_t f) {
  const Index h0 = o.fhe[f].idx(), h1 = o.next[h0].idx();
  return {h0, h1, o.next[h1].idx()};
}

void positions_1_to_4(const SurfaceMesh& m, const Old& o, bool loop, Vec3* out) {
  const Vec3* p = m.positions().vector().data();
  for_ranges(o.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const Vec3d a = to_double(p[o.to[2 * e].idx()]), b = to_double(p[o.to[2 * e + 1].idx()]);
      Vec3d np = (a + b) * 0.5;
      if (loop && !o.sharp[e]) {
        const Vec3d c = to_double(p[o.to[o.next[2 * e].idx()].idx()]);
        const Vec3d d = to_double(p[o.to[o.next[2 * e + 1].idx()].idx()]);
        np = (a + b) * 0.375 + (c + d) * 0.125;
      }
      out[o.nv + e] = to_float(np);
    }
  });
  double betas[32];
  for (std::size_t n = 1; n < 32; ++n) betas[n] = loop_beta(n);
  for_ranges(o.nv, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const Halfedge start = o.vout[v];
      if (!loop || !start.is_valid()) {
        out[v] = p[v];
        continue;
      }
      Vec3d ring{0, 0, 0}, sharp_sum{0, 0, 0};
      std::size_t n = 0, n_sharp = 0;
      Index h = start.idx();
      do {
        const Vec3d q = to_double(p[o.to[h].idx()]);
        ring += q;
        ++n;
        if (o.sharp[h >> 1]) sharp_sum += q, ++n_sharp;
        h = o.next[h ^ 1u].idx();  // clockwise about v
      } while (h != start.idx());
      const Vec3d pv = to_double(p[v]);
      Vec3d np;
      if (n_sharp > 2) {
        np = pv;  // a corner
      } else if (n_sharp == 2) {
        np = pv * 0.75 + sharp_sum * 0.125;  // a boundary or crease curve
      } else {
        const double beta = n < 32 ? betas[n] : loop_beta(n);
        np = pv * (1 - double(n) * beta) + ring * beta;
      }
      out[v] = to_float(np);
    }
  });
}

}  // namespace

SurfaceMesh refine_1_to_4(const SurfaceMesh& src, Subdivision scheme) {
  const Old o = read_old(src);
  const std::size_t nh = 2 * (2 * o.ne + 3 * o.nf);
  SurfaceMesh m = refined_like(src, o.nv + o.ne, nh / 2, 4 * o.nf, o.nv);
  positions_1_to_4(src, o, scheme == Subdivision::loop, m.positions().vector().data());
  const Index old_base = keep_old_corners(m, src, nh);
  write_edge_halves(m, o);
  write_edge_half_properties(m, src, o, old_base);
  // Faces: three corner triangles and the middle one.
  for_ranges(o.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const std::array<Index, 3> h = triangle_halfedges(o, f);
      const Index base_edge = Index(2 * o.ne + 3 * f);
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3;
        const Halfedge s(second_half(h[k])), fi(first_half(h[k1]));
        const Halfedge in(2 * (base_edge + Index(k)));       // m_{k+1} -> m_k, in the corner face
        const Halfedge out(2 * (base_edge + Index(k)) + 1);  // m_k -> m_{k+1}, in the middle face
        const Face corner(Index(4 * f + Index(k))), middle(Index(4 * f + 3));
        m.set_vertex(in, Vertex(Index(o.nv + (h[k] >> 1))));
        m.set_vertex(out, Vertex(Index(o.nv + (h[k1] >> 1))));
        m.set_next(s, fi);
        m.set_next(fi, in);
        m.set_next(in, s);
        m.set_face(s, corner);
        m.set_face(fi, corner);
        m.set_face(in, corner);
        m.set_halfedge(corner, s);
        m.set_next(out, Halfedge(2 * (base_edge + Index(k1)) + 1));
        m.set_face(out, middle);
        if (k == 0) m.set_halfedge(middle, out);
      }
    }
  });
  PropertyContainer& hprops = m.halfedge_properties();
  if (!hprops.empty()) {
    // Corners: s enters the old corner to(h[k]); fi enters the middle of h[k1]; in enters the
    // middle of h[k]; out enters the middle of h[k1]. A middle averages the face's own corners at
    // the ends of its edge, so that values across a seam never mix.
    const float half[2] = {0.5f, 0.5f};
    for (std::size_t f = 0; f < o.nf; ++f) {
      const std::array<Index, 3> h = triangle_halfedges(o, f);
      const Index base_edge = Index(2 * o.ne + 3 * f);
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k_1 = (k + 2) % 3;
        const Index mid_k[2] = {old_base + h[k_1], old_base + h[k]};
        const Index mid_k1[2] = {old_base + h[k], old_base + h[k1]};
        hprops.copy(old_base + h[k], second_half(h[k]));
        hprops.interpolate(first_half(h[k1]), mid_k1, half, 2);
        hprops.interpolate(2 * (base_edge + Index(k)), mid_k, half, 2);
        hprops.interpolate(2 * (base_edge + Index(k)) + 1, mid_k1, half, 2);
      }
    }
    hprops.resize(nh);
  }
  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty())
    for (std::size_t f = 0; f < o.nf; ++f)
      for (std::size_t k = 0; k < 4; ++k) fprops.copy_element_from(src.face_properties(), f, 4 * f + k);
  return m;
}

}  // namespace hedge::detail::subdivision

// Catmull-Clark subdivision of polygon meshes into quads.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "subdivide_internal.h"

namespace hedge::detail::subdivision {

namespace {

// ---- Catmull-Clark ----
// Besides V + e for edge e, face f's point is vertex V + E + f. The half-edges h_0..h_{n-1} of face
// f (from halfedge(f)) get the compact numbers q = first(f) + k, first(f) being the running sum of
// the degrees of the faces before f: the quad at the corner where h_k ends is face q, and the inner
// edge from the middle of h_k to the face point is edge 2E + q, whose half-edge 2(2E + q) runs
// toward the face point and 2(2E + q) + 1 back. A face's quads and inner edges are consecutive.

void catmull_clark_positions(const SurfaceMesh& m, const Old& o, Vec3* out) {
  std::vector<Vec3d> face_point(o.nf);
  for_ranges(o.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      Vec3d c{0, 0, 0};
      std::size_t n = 0;
      for (Vertex v : m.vertices(Face(Index(f)))) c += to_double(m.position(v)), ++n;
      face_point[f] = c * (1.0 / double(n));
      out[o.nv + o.ne + f] = to_float(face_point[f]);
    }
  });
  for_ranges(o.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const Halfedge h(Index(2 * e)), t(Index(2 * e + 1));
      const Vec3d a = to_double(m.position(o.to[h.idx()])), b = to_double(m.position(o.to[t.idx()]));
      Vec3d p = (a + b) * 0.5;
      if (!o.sharp[e])
        p = (a + b + face_point[o.face[h.idx()].idx()] + face_point[o.face[t.idx()].idx()]) * 0.25;
      out[o.nv + e] = to_float(p);
    }
  });
  for_ranges(o.nv, [&](std::size_t begin, std::size_t end) {
    for (std::size_t vi = begin; vi < end; ++vi) {
      const Vertex v{Index(vi)};
      const Vec3d s = to_double(m.position(v));
      out[vi] = m.position(v);
      if (m.is_isolated(v)) continue;
      Vec3d faces{0, 0, 0}, mids{0, 0, 0}, sharp_sum{0, 0, 0};
      std::size_t n = 0, n_faces = 0, n_sharp = 0;
      for (Halfedge h : m.halfedges(v)) {
        const Vec3d w = to_double(m.position(m.to_vertex(h)));
        mids += (s + w) * 0.5;
        ++n;
        if (m.face(h).is_valid()) faces += face_point[m.face(h).idx()], ++n_faces;
        if (o.sharp[h.idx() >> 1]) sharp_sum += w, ++n_sharp;
      }
      Vec3d p = s;
      if (n_sharp == 2) {
        p = s * 0.75 + sharp_sum * 0.125;
      } else if (n_sharp < 2 && n_faces > 0) {
        const double k = double(n);
        p = (faces * (1.0 / double(n_faces)) + mids * (2.0 / k) + s * (k - 3)) * (1.0 / k);
      }
      out[vi] = to_float(p);
    }
  });
}

}  // namespace

SurfaceMesh refine_catmull_clark(const SurfaceMesh& src) {
  const Old o = read_old(src);
  // first(f): the running sum of the face degrees.
  std::vector<Index> first(o.nf + 1);
  for_ranges(o.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const Index start = o.fhe[f].idx();
      Index n = 0, h = start;
      do h = o.next[h].idx(), ++n;
      while (h != start);
      first[f + 1] = n;
    }
  });
  first[0] = 0;
  for (std::size_t f = 0; f < o.nf; ++f) first[f + 1] += first[f];
  const Index quads = first[o.nf];
  const std::size_t nv = o.nv + o.ne + o.nf, ne = 2 * o.ne + quads, nf = quads;
  SurfaceMesh m = refined_like(src, nv, ne, nf, o.nv);
  catmull_clark_positions(src, o, m.positions().vector().data());
  const Index old_base = keep_old_corners(m, src, 2 * ne);
  PropertyContainer& hprops = m.halfedge_properties();
  const bool corner_data = !hprops.empty();
  write_edge_halves(m, o);
  write_edge_half_properties(m, src, o, old_base);
  const Index inner = Index(2 * o.ne);
  auto to_centre = [&](Index q) { return Halfedge(2 * (inner + q)); };
  auto from_centre = [&](Index q) { return Halfedge(2 * (inner + q) + 1); };
  for_ranges(o.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      const Vertex centre(Index(o.nv + o.ne + f));
      const Index start = o.fhe[f].idx(), q0 = first[f], q_end = first[f + 1];
      Index hk = start;
      for (Index qk = q0; qk < q_end; ++qk) {
        const Index hn = o.next[hk].idx(), qn = qk + 1 == q_end ? q0 : qk + 1;
        const Halfedge s(second_half(hk)), fi(first_half(hn)), in = to_centre(qn), out = from_centre(qk);
        const Face quad(qk);
        m.set_vertex(in, centre);
        m.set_vertex(out, Vertex(Index(o.nv + (hk >> 1))));
        m.set_next(s, fi);
        m.set_next(fi, in);
        m.set_next(in, out);
        m.set_next(out, s);
        m.set_face(s, quad);
        m.set_face(fi, quad);
        m.set_face(in, quad);
        m.set_face(out, quad);
        m.set_halfedge(quad, s);
        hk = hn;
      }
      m.set_halfedge(centre, from_centre(q0));
    }
  });
  // The face point's vertex properties, and the corners: at old vertices copied, at edge middles
  // the average of the face's own corners at the edge's ends, at the face point the average of the
  // face's corners.
  std::vector<Index> ring, corners, old_corners;  // per face, reused
  std::vector<float> weights;
  const bool vertex_data = m.vertex_properties().array_count() > 1;
  for (std::size_t f = 0; f < o.nf && (vertex_data || corner_data); ++f) {
    const Vertex centre(Index(o.nv + o.ne + f));
    ring.clear();
    Index h = o.fhe[f].idx();
    do {
      ring.push_back(h);
      h = o.next[h].idx();
    } while (h != o.fhe[f].idx());
    const std::size_t n = ring.size();
    weights.assign(n, 1.f / float(n));
    corners.resize(n);
    for (std::size_t k = 0; k < n; ++k) corners[k] = o.to[ring[k]].idx();
    if (vertex_data)
      m.vertex_properties().interpolate(centre.idx(), corners.data(), weights.data(), n,
                                        m.positions().array());
    if (!corner_data) continue;
    const float half[2] = {0.5f, 0.5f};
    for (std::size_t k = 0; k < n; ++k) {
      const Index hk = ring[k], hn = ring[(k + 1) % n], hp = ring[(k + n - 1) % n];
      const Index mid_k[2] = {old_base + hp, old_base + hk};
      const Index mid_n[2] = {old_base + hk, old_base + hn};
      hprops.copy(old_base + hk, second_half(hk));
      hprops.interpolate(first_half(hn), mid_n, half, 2);
      hprops.interpolate(from_centre(first[f] + Index(k)).idx(), mid_k, half, 2);
    }
    old_corners.resize(n);
    for (std::size_t k = 0; k < n; ++k) old_corners[k] = old_base + ring[k];
    for (std::size_t k = 0; k < n; ++k)
      hprops.interpolate(to_centre(first[f] + Index(k)).idx(), old_corners.data(), weights.data(), n);
  }
  if (corner_data) hprops.resize(2 * ne);
  // Face properties: face f's quads take f's.
  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty())
    for (std::size_t f = 0; f < o.nf; ++f)
      for (Index q = first[f]; q < first[f + 1]; ++q) fprops.copy_element_from(src.face_properties(), f, q);
  return m;
}

}  // namespace hedge::detail::subdivision

// Subdivision at face centres: the split of every face about its centroid, and Kobbelt's sqrt(3).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "hedge/core/face_operations.h"
#include "subdivide_internal.h"

namespace hedge::detail::subdivision {

namespace {

// ---- Splitting at face centres, and Kobbelt's sqrt(3) ----
// Old vertices, edges and half-edges keep their index; face f's centre is vertex V + f. Face f's
// half-edges h_0..h_{n-1} (from halfedge(f)) get the compact numbers q = first[f] + k, the running
// sum of the face degrees, so for triangles q = 3f + k. The spoke from the centre to to(h_k) is edge
// E + q, whose half-edge in(q) = 2(E + q) runs to the centre and out(q) = 2(E + q) + 1 away from it.
// Face q is the triangle at h_k: h_k, in(q), out(q - 1) when split. sqrt(3) then flips every edge it
// may: the triangle at h_k becomes in(q(twin h_k)), h_k, out(q - 1), h_k now running from the far
// face's centre to its own face's centre.

struct Split {
  std::size_t nv = 0, ne = 0, nf = 0;
  std::vector<Index> first;  // per face, and the total at the end
  std::vector<Index> ring;   // face half-edges in face order: ring[first[f] + k] = h_k
};

Split face_rings(const SurfaceMesh& m) {
  Split s;
  s.nv = m.vertex_slots();
  s.ne = m.edge_slots();
  s.nf = m.face_slots();
  const std::vector<Halfedge>& next = m.halfedge_next_array();
  auto degree = [&](std::size_t f) {
    const Halfedge start = m.halfedge(Face(Index(f)));
    Index n = 0;
    Halfedge h = start;
    do h = next[h.idx()], ++n;
    while (h != start);
    return n;
  };
  s.first.resize(s.nf + 1);
  for_ranges(s.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) s.first[f + 1] = degree(f);
  });
  s.first[0] = 0;
  for (std::size_t f = 0; f < s.nf; ++f) s.first[f + 1] += s.first[f];
  s.ring.resize(s.first[s.nf]);
  for_ranges(s.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      Halfedge h = m.halfedge(Face(Index(f)));
      for (Index c = s.first[f]; c < s.first[f + 1]; ++c, h = next[h.idx()]) s.ring[c] = h.idx();
    }
  });
  return s;
}

// Kobbelt's smoothing of the old vertices: (1 - a) p + a * (mean of the ring), a = (4 - 2 cos(2 pi / n)) / 9.
// A vertex on two or more sharp edges (boundary or "e:crease") stays: those edges are not refined.
std::vector<Vec3> sqrt3_positions(const SurfaceMesh& m, const std::vector<std::uint8_t>& keep) {
  std::vector<Vec3> out(m.vertex_slots());
  const Vec3* p = m.positions().vector().data();
  const std::vector<Vertex>& to = m.halfedge_vertex_array();
  const std::vector<Halfedge>& next = m.halfedge_next_array();
  double alphas[32];
  for (std::size_t n = 1; n < 32; ++n) alphas[n] = (4 - 2 * std::cos(2 * std::numbers::pi / double(n))) / 9;
  for_ranges(out.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      out[v] = p[v];
      const Halfedge start = m.halfedge(Vertex(Index(v)));
      if (!start.is_valid()) continue;
      Vec3d ring{0, 0, 0};
      std::size_t n = 0, n_sharp = 0;
      Index h = start.idx();
      do {
        ring += to_double(p[to[h].idx()]);
        ++n;
        n_sharp += keep[h >> 1];
        h = next[h ^ 1u].idx();  // clockwise about v
      } while (h != start.idx());
      if (n_sharp >= 2) continue;
      const double a = n < 32 ? alphas[n] : (4 - 2 * std::cos(2 * std::numbers::pi / double(n))) / 9;
      out[v] = to_float(to_double(p[v]) * (1 - a) + ring * (a / double(n)));
    }
  });
  return out;
}

}  // namespace

SurfaceMesh refine_at_centres(const SurfaceMesh& src, bool sqrt3) {
  const Split s = face_rings(src);
  const std::size_t nc = s.ring.size();
  const Index E = Index(s.ne), V = Index(s.nv);
  // Which edges sqrt(3) leaves unflipped (boundary and crease edges), and each half-edge's q.
  std::vector<std::uint8_t> keep;
  std::vector<Index> q;
  std::vector<Vec3> smoothed;
  if (sqrt3) {
    keep.resize(s.ne);
    const auto crease = src.get_edge_property<std::uint8_t>("e:crease");
    for_ranges(s.ne, [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e)
        keep[e] = src.is_boundary(Edge(Index(e))) || (crease && crease[Edge(Index(e))] != 0);
    });
    q.resize(2 * s.ne);  // boundary half-edges' entries are never read
    for_ranges(nc, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) q[s.ring[i]] = Index(i);
    });
    smoothed = sqrt3_positions(src, keep);
  }
  // Face centroids, summed in double as face_centroid() does.
  std::vector<Vec3> centres(s.nf);
  for_ranges(s.nf, [&](std::size_t begin, std::size_t end) {
    const Vec3* p = src.positions().vector().data();
    const std::vector<Vertex>& to = src.halfedge_vertex_array();
    for (std::size_t f = begin; f < end; ++f) {
      Vec3d c{0, 0, 0};
      for (Index i = s.first[f]; i < s.first[f + 1]; ++i) c += to_double(p[to[s.ring[i]].idx()]);
      centres[f] = to_float(c / double(s.first[f + 1] - s.first[f]));
    }
  });

  // Old vertices, edges and half-edges keep their index, links and properties; the links of the
  // old half-edges of faces and the old vertices' outgoing half-edges are rewritten below.
  SurfaceMesh m = refined_like(src, s.nv + s.nf, s.ne + nc, nc, s.nv);
  for_ranges(2 * s.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t h = begin; h < end; ++h) {
      m.set_vertex(Halfedge(Index(h)), src.to_vertex(Halfedge(Index(h))));
      m.set_next(Halfedge(Index(h)), src.next(Halfedge(Index(h))));
      m.set_face(Halfedge(Index(h)), src.face(Halfedge(Index(h))));
    }
  });
  for_ranges(s.nv, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      m.set_halfedge(Vertex(Index(v)), src.halfedge(Vertex(Index(v))));
  });
  {
    const PropertyContainer& hfrom = src.halfedge_properties();
    PropertyContainer& hto = m.halfedge_properties();
    if (!hto.empty())
      for (std::size_t h = 0; h < 2 * s.ne; ++h) hto.copy_element_from(hfrom, h, h);
    const PropertyContainer& efrom = src.edge_properties();
    PropertyContainer& eto = m.edge_properties();
    if (!eto.empty())
      for (std::size_t e = 0; e < s.ne; ++e) eto.copy_element_from(efrom, e, e);
  }
  auto in = [&](Index c) { return Halfedge(2 * (E + c)); };
  auto out = [&](Index c) { return Halfedge(2 * (E + c) + 1); };
  for_ranges(s.nf, [&](std::size_t f_begin, std::size_t f_end) {
    for (std::size_t f = f_begin; f < f_end; ++f) {
      const Index b = s.first[f], n = s.first[f + 1] - b;
      const Vertex centre(V + Index(f));
      // The corners first: sqrt(3) turns to(h_k) toward the centre below.
      for (Index k = 0; k < n; ++k) {
        const Halfedge h(s.ring[b + k]);
        m.set_vertex(in(b + k), centre);
        m.set_vertex(out(b + k), m.to_vertex(h));
      }
      for (Index k = 0; k < n; ++k) {
        const Index c = b + k, cp = b + (k + n - 1) % n;
        const Halfedge h(s.ring[c]);
        const Face child(c);
        Halfedge lead = in(c);  // the half-edge before h's successor: in(c) when split
        if (sqrt3 && !keep[h.idx() >> 1]) {
          lead = in(q[h.idx() ^ 1u]);
          m.set_vertex(h, centre);
          m.set_next(lead, h);
          m.set_next(h, out(cp));
        } else {
          m.set_next(h, lead);
          m.set_next(lead, out(cp));
        }
        m.set_next(out(cp), sqrt3 && !keep[h.idx() >> 1] ? lead : h);
        m.set_face(h, child);
        m.set_face(lead, child);
        m.set_face(out(cp), child);
        m.set_halfedge(child, h);
      }
      m.set_halfedge(centre, out(b));
    }
  });
  // An interior old vertex whose outgoing half-edge was flipped leaves by the spoke of that edge's twin.
  if (sqrt3)
    for_ranges(s.nv, [&](std::size_t begin, std::size_t end) {
      for (std::size_t v = begin; v < end; ++v) {
        const Halfedge o = m.halfedge(Vertex(Index(v)));
        if (o.is_valid() && !m.is_boundary(o) && !keep[o.idx() >> 1])
          m.set_halfedge(Vertex(Index(v)), in(q[o.idx() ^ 1u]));
      }
    });

  // Properties. Vertex: the centre averages its face's corners. Corner: in(q) enters the centre and
  // averages the face's own corners; out(q - 1) enters from(h_k) and takes the corner before h_k;
  // a flipped h_k enters its face's centre. Edge: old edges keep theirs (a flipped edge too), spokes
  // get the default. Face: the children of f take f's.
  std::vector<float> weights;
  std::vector<Index> corners;
  PropertyContainer& hprops = m.halfedge_properties();
  const bool vertex_data = m.vertex_properties().array_count() > 1;
  for (std::size_t f = 0; f < s.nf && (vertex_data || !hprops.empty()); ++f) {
    const Index b = s.first[f], n = s.first[f + 1] - b;
    weights.assign(n, 1.f / float(n));
    corners.resize(n);
    for (Index k = 0; k < n; ++k) corners[k] = m.to_vertex(out(b + k)).idx();
    if (vertex_data)
      m.vertex_properties().interpolate(V + f, corners.data(), weights.data(), n, m.positions().array());
    if (hprops.empty()) continue;
    hprops.interpolate(in(b).idx(), &s.ring[b], weights.data(), n);
    for (Index k = 0; k < n; ++k) {
      if (k > 0) hprops.copy(in(b).idx(), in(b + k).idx());
      hprops.copy(s.ring[b + (k + n - 1) % n], out(b + (k + n - 1) % n).idx());
    }
  }
  if (sqrt3 && !hprops.empty())
    for (std::size_t c = 0; c < nc; ++c)
      if (!keep[s.ring[c] >> 1]) hprops.copy(in(Index(c)).idx(), s.ring[c]);
  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty())
    for (std::size_t f = 0; f < s.nf; ++f)
      for (Index c = s.first[f]; c < s.first[f + 1]; ++c)
        fprops.copy_element_from(src.face_properties(), f, c);
  for (std::size_t f = 0; f < s.nf; ++f) m.position(Vertex(V + Index(f))) = centres[f];
  for (std::size_t v = 0; v < s.nv; ++v)
    m.position(Vertex(Index(v))) = sqrt3 ? smoothed[v] : src.position(Vertex(Index(v)));
  return m;
}

}  // namespace hedge::detail::subdivision

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
  std::vector<Index> first;    // per face, and the total at the end
  std::vector<Index> ring;     // face half-edges in face order: ring[first[f] + k] = h_k
  std::vector<Vertex> corner;  // corner[c] = to(ring[c]), gathered with ring
  std::vector<Index> q;        // per half-edge: its c (filled for sqrt(3) only)
};

// The rings of m's faces. With `triangles` (the caller checked that every face is one), first[f]
// is 3f without walking the faces; with `with_q`, q[ring[c]] = c (boundary half-edges' entries
// stay unset and are never read). One walk of each face gathers its half-edges and their targets,
// so that the passes after it read them in order rather than through the half-edge arrays.
Split face_rings(const SurfaceMesh& m, bool triangles, bool with_q) {
  Split s;
  s.nv = m.vertex_slots();
  s.ne = m.edge_slots();
  s.nf = m.face_slots();
  const Halfedge* next = m.halfedge_next_array().data();
  const Vertex* to = m.halfedge_vertex_array().data();
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
    for (std::size_t f = begin; f < end; ++f) s.first[f + 1] = triangles ? 3 : degree(f);
  });
  s.first[0] = 0;
  for (std::size_t f = 0; f < s.nf; ++f) s.first[f + 1] += s.first[f];
  s.ring.resize(s.first[s.nf]);
  s.corner.resize(s.ring.size());
  if (with_q) s.q.resize(2 * s.ne);
  for_ranges(s.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      Halfedge h = m.halfedge(Face(Index(f)));
      for (Index c = s.first[f]; c < s.first[f + 1]; ++c, h = next[h.idx()]) {
        s.ring[c] = h.idx();
        s.corner[c] = to[h.idx()];
        if (with_q) s.q[h.idx()] = c;
      }
    }
  });
  return s;
}

// Kobbelt's smoothing of the old vertices: (1 - a) p + a * (mean of the ring), a = (4 - 2 cos(2 pi / n)) / 9.
// A vertex on two or more sharp edges (boundary or "e:crease") stays, but for a boundary vertex
// whose two boundary edges are both split in this step (`split`): it moves by the ternary cubic
// B-spline rule (4 prev + 19 p + 4 next) / 27 along its boundary.
// Writes out[v] for every vertex slot v of m (out is the refined mesh's positions, not m's).
void sqrt3_positions(const SurfaceMesh& m, const std::vector<std::uint8_t>& sharp,
                     const std::vector<std::uint8_t>& split, Vec3* out) {
  const Vec3* p = m.positions().vector().data();
  const std::vector<Vertex>& to = m.halfedge_vertex_array();
  const std::vector<Halfedge>& next = m.halfedge_next_array();
  double alphas[32];
  for (std::size_t n = 1; n < 32; ++n) alphas[n] = (4 - 2 * std::cos(2 * std::numbers::pi / double(n))) / 9;
  for_ranges(m.vertex_slots(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      out[v] = p[v];
      const Halfedge start = m.halfedge(Vertex(Index(v)));
      if (!start.is_valid()) continue;
      Vec3d ring{0, 0, 0}, ends{0, 0, 0};
      std::size_t n = 0, n_sharp = 0, n_split = 0;
      Index h = start.idx();
      do {
        const Vec3d q = to_double(p[to[h].idx()]);
        ring += q;
        ++n;
        n_sharp += sharp[h >> 1];
        if (!split.empty() && split[h >> 1]) ends += q, ++n_split;
        h = next[h ^ 1u].idx();  // clockwise about v
      } while (h != start.idx());
      if (n_sharp == 2 && n_split == 2) {
        out[v] = to_float((to_double(p[v]) * 19 + ends * 4) * (1.0 / 27));
        continue;
      }
      if (n_sharp >= 2) continue;
      const double a = n < 32 ? alphas[n] : (4 - 2 * std::cos(2 * std::numbers::pi / double(n))) / 9;
      out[v] = to_float(to_double(p[v]) * (1 - a) + ring * (a / double(n)));
    }
  });
}

// The boundary split of an even sqrt(3) step (Kobbelt's boundary rule). After an odd step every
// boundary face is (A, B, M): a boundary edge A -> B and an interior vertex M. The even step puts
// two points on the edge, P = (Z + 16 A + 10 B) / 27 and Q = (10 A + 16 B + W) / 27 (Z before A
// and W after B along the boundary), and makes the face the fan (A, P, M), (P, Q, M), (Q, B, M),
// whose edges A-M and B-M are flipped like any interior edge; so two steps split every boundary
// edge in three, as they do every interior one. P takes the face's centre index V + f, Q the
// index V + F + j and the new edge Q-B the index E + C + j (C the corners, j counting the split
// faces in face order); old edge A-B becomes P-Q and the spoke to A becomes A-P.
struct BoundarySplit {
  std::vector<std::uint8_t> split;  // per edge: a boundary edge split in this step
  std::vector<Index> faces;         // the split faces, in face order
  std::vector<Index> of_face;       // per face: j, or kNone
  std::vector<Index> side;          // per split face: k of its boundary half-edge h_k
  static constexpr Index kNone = ~Index(0);
};

BoundarySplit find_boundary_split(const SurfaceMesh& m, const Split& s,
                                  const std::vector<std::uint8_t>& sharp) {
  BoundarySplit b;
  b.split.assign(s.ne, 0);
  b.of_face.assign(s.nf, BoundarySplit::kNone);
  const auto crease = m.get_edge_property<std::uint8_t>("e:crease");
  for (std::size_t f = 0; f < s.nf; ++f) {
    Index side = BoundarySplit::kNone, count = 0;
    for (Index c = s.first[f]; c < s.first[f + 1]; ++c) {
      const Index h = s.ring[c];
      if (sharp[h >> 1] && m.is_boundary(Halfedge(h ^ 1u)) && !(crease && crease[Edge(h >> 1)] != 0))
        side = c - s.first[f], ++count;
    }
    if (count != 1) continue;  // after an odd step every boundary face has exactly one
    b.split[s.ring[s.first[f] + side] >> 1] = 1;
    b.of_face[f] = Index(b.faces.size());
    b.faces.push_back(Index(f));
    b.side.push_back(side);
  }
  return b;
}

// Rewrites what the pass of refine_at_centres made of each split face (A, B, M) and its flipped
// neighbours (see BoundarySplit): positions, links and properties of P, Q and the new edge. `sharp`:
// the edges the pass left unflipped.
void apply_boundary_split(SurfaceMesh& m, const SurfaceMesh& src, const Split& s, const BoundarySplit& b,
                          const std::vector<std::uint8_t>& sharp) {
  if (b.faces.empty()) return;
  const Index E = Index(s.ne), V = Index(s.nv), C = Index(s.ring.size()), F = Index(s.nf);
  auto in = [&](Index c) { return Halfedge(2 * (E + c)); };
  auto out = [&](Index c) { return Halfedge(2 * (E + c) + 1); };
  // The boundary half-edge before each one (src's loops), and where a boundary half-edge's chain of
  // new boundary half-edges starts: B -> Q of its face when split (B its start), else itself.
  std::vector<Index> prev(2 * s.ne, 0);
  for (std::size_t h = 0; h < 2 * s.ne; ++h)
    if (src.is_boundary(Halfedge(Index(h)))) prev[src.next(Halfedge(Index(h))).idx()] = Index(h);
  auto extra = [&](std::size_t j) { return Halfedge(2 * (E + C + Index(j))); };  // Q -> B; twin B -> Q
  auto chain = [&](Halfedge t) {
    return b.split[t.idx() >> 1] ? SurfaceMesh::twin(extra(b.of_face[src.face(SurfaceMesh::twin(t)).idx()]))
                                 : t;
  };
  const Vec3* p = src.positions().vector().data();
  PropertyContainer& vprops = m.vertex_properties();
  PropertyContainer& hprops = m.halfedge_properties();
  PropertyContainer& eprops = m.edge_properties();
  const bool vertex_data = vprops.array_count() > 1;
  for (std::size_t j = 0; j < b.faces.size(); ++j) {
    const Index f = b.faces[j], base = s.first[f];
    const Index q0 = base + b.side[j], q1 = base + (b.side[j] + 1) % 3, q2 = base + (b.side[j] + 2) % 3;
    const Halfedge h0(s.ring[q0]), h1(s.ring[q1]), h2(s.ring[q2]), t0 = SurfaceMesh::twin(h0);
    const Halfedge x0 = extra(j), x1 = SurfaceMesh::twin(x0);
    const Vertex a = src.from_vertex(h0), bv = src.to_vertex(h0), mv = src.to_vertex(h1);
    const Vertex P(V + f), Q(V + F + Index(j));
    const Halfedge lead1 = m.next(out(q0));  // B -> C_R if h1 was flipped, else h1 itself
    // Face q0 becomes (P, Q, M): h0 P -> Q, out(q0) Q -> M, in(q1) M -> P.
    m.set_vertex(h0, Q);
    m.set_vertex(out(q0), mv);
    m.set_next(h0, out(q0));
    m.set_next(out(q0), in(q1));
    m.set_next(in(q1), h0);
    m.set_face(out(q0), Face(q0));
    m.set_face(in(q1), Face(q0));
    // in(q0) now runs M -> Q, and x0 (Q -> B) takes out(q0)'s place in face q1.
    m.set_vertex(in(q0), Q);
    m.set_vertex(x0, bv);
    m.set_face(x0, Face(q1));
    m.set_next(x0, lead1);
    if (!sharp[h1.idx() >> 1]) {
      // q1 = (Q, B, C_R): x0, B -> C_R, h1 C_R -> Q. The neighbour's (M, Q, C_R) takes in(q0).
      const Halfedge to_cr = SurfaceMesh::twin(h1), back = m.next(to_cr);
      m.set_vertex(h1, Q);
      m.set_next(h1, x0);
      m.set_next(back, in(q0));
      m.set_next(in(q0), to_cr);
      m.set_face(in(q0), m.face(to_cr));
    } else {
      // q1 = (Q, B, M): x0, h1 B -> M, in(q0) M -> Q.
      m.set_next(h1, in(q0));
      m.set_next(in(q0), x0);
      m.set_face(in(q0), Face(q1));
    }
    m.set_halfedge(Face(q1), x0);
    // The boundary: B -> Q -> P -> A, then the chain of the half-edge after t0.
    m.set_vertex(x1, Q);
    m.set_face(x1, Face());
    m.set_next(x1, t0);
    m.set_vertex(t0, P);
    m.set_next(t0, out(q2));
    m.set_face(out(q2), Face());
    m.set_next(out(q2), chain(src.next(t0)));
    m.set_halfedge(P, out(q2));
    m.set_halfedge(Q, t0);
    if (m.halfedge(bv) == t0) m.set_halfedge(bv, x1);
    if (m.halfedge(a) == h0) m.set_halfedge(a, in(q2));
    // Positions by the ternary cubic B-spline rule along the boundary.
    const Vec3d pa = to_double(p[a.idx()]), pb = to_double(p[bv.idx()]);
    const Vec3d pz = to_double(p[src.to_vertex(src.next(t0)).idx()]);
    const Vec3d pw = to_double(p[src.from_vertex(Halfedge(prev[t0.idx()])).idx()]);
    m.position(P) = to_float((pz + pa * 16 + pb * 10) * (1.0 / 27));
    m.position(Q) = to_float((pa * 10 + pb * 16 + pw) * (1.0 / 27));
    // Properties: P and Q divide A-B in thirds (vertex and corner data alike); both new boundary
    // edges A-P and Q-B take A-B's edge properties.
    const float thirds[2][2] = {{2.f / 3, 1.f / 3}, {1.f / 3, 2.f / 3}};
    if (vertex_data) {
      const Index ends[2] = {a.idx(), bv.idx()};
      vprops.interpolate(P.idx(), ends, thirds[0], 2, m.positions().array());
      vprops.interpolate(Q.idx(), ends, thirds[1], 2, m.positions().array());
    }
    if (!eprops.empty()) {
      eprops.copy_element_from(src.edge_properties(), h0.idx() >> 1, E + C + Index(j));
      eprops.copy_element_from(src.edge_properties(), h0.idx() >> 1, E + q2);
    }
    if (hprops.empty()) continue;
    // h_k's value is the corner of f at to(h_k): B for h0, M for h1, A for h2.
    const PropertyContainer& old = src.halfedge_properties();
    hprops.copy_element_from(old, h0.idx(), x0.idx());               // Q -> B enters B
    hprops.copy_element_from(old, h1.idx(), out(q0).idx());          // Q -> M enters M
    hprops.copy_element_from(old, h2.idx(), in(q2).idx());           // A's value, for now
    const Index corners[2] = {in(q2).idx(), x0.idx()};               // A, B
    hprops.interpolate(in(q1).idx(), corners, thirds[0], 2);         // M -> P enters P
    hprops.interpolate(h0.idx(), corners, thirds[1], 2);             // P -> Q enters Q
    hprops.copy(in(q1).idx(), in(q2).idx());                         // A -> P
    hprops.copy(h0.idx(), in(q0).idx());                             // M -> Q
    if (!sharp[h1.idx() >> 1]) hprops.copy(h0.idx(), h1.idx());      // C_R -> Q
    if (!sharp[h2.idx() >> 1]) hprops.copy(in(q1).idx(), h2.idx());  // C_L -> P
    hprops.copy(t0.idx(), x1.idx());
  }
  // Boundary half-edges of edges not split run on to the chain of the old next.
  for (std::size_t h = 0; h < 2 * s.ne; ++h) {
    const Halfedge t{Index(h)};
    if (src.is_boundary(t) && !b.split[h >> 1]) m.set_next(t, chain(src.next(t)));
  }
}

}  // namespace

SurfaceMesh refine_at_centres(const SurfaceMesh& src, bool sqrt3, bool split_boundary) {
  // sqrt(3) is only called on triangle meshes (subdivide() checks).
  const Split s = face_rings(src, sqrt3, sqrt3);
  const std::size_t nc = s.ring.size();
  const Index E = Index(s.ne), V = Index(s.nv);
  // Which edges are sharp and stay unflipped (boundary and crease edges), which boundary edges an
  // even sqrt(3) step splits.
  std::vector<std::uint8_t> sharp;
  BoundarySplit bsplit;
  const std::vector<Index>& q = s.q;
  if (sqrt3) {
    sharp.resize(s.ne);
    const auto crease = src.get_edge_property<std::uint8_t>("e:crease");
    for_ranges(s.ne, [&](std::size_t begin, std::size_t end) {
      for (std::size_t e = begin; e < end; ++e)
        sharp[e] = src.is_boundary(Edge(Index(e))) || (crease && crease[Edge(Index(e))] != 0);
    });
    if (split_boundary) bsplit = find_boundary_split(src, s, sharp);
  }

  // Old vertices, edges and half-edges keep their index, links and properties; the links of the
  // old half-edges of faces are rewritten below. Positions go straight into the result: the old
  // vertices' (smoothed by sqrt(3)), then the face centroids, summed in double as face_centroid()
  // does.
  const std::size_t nb = bsplit.faces.size();
  SurfaceMesh m = refined_like(src, s.nv + s.nf + nb, s.ne + nc + nb, nc, s.nv);
  Vec3* pos = m.positions().vector().data();
  const Vec3* old_pos = src.positions().vector().data();
  if (sqrt3)
    sqrt3_positions(src, sharp, bsplit.split, pos);
  else
    std::copy(old_pos, old_pos + s.nv, pos);
  const Vertex* old_to = src.halfedge_vertex_array().data();
  const Halfedge* old_next = src.halfedge_next_array().data();
  const Face* old_face = src.halfedge_face_array().data();
  const Halfedge* old_out = src.vertex_halfedge_array().data();
  for_ranges(s.nf, [&](std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) {
      Vec3d c{0, 0, 0};
      for (Index i = s.first[f]; i < s.first[f + 1]; ++i) c += to_double(old_pos[s.corner[i].idx()]);
      pos[s.nv + f] = to_float(c / double(s.first[f + 1] - s.first[f]));
    }
  });
  // By value: a store through the mesh's arrays could otherwise make E be read again each time.
  auto in = [E](Index c) { return Halfedge(2 * (E + c)); };
  auto out = [E](Index c) { return Halfedge(2 * (E + c) + 1); };
  // Every old half-edge keeps its target unless sqrt(3) flips it below; the face loop links the
  // half-edges of faces, so only boundary half-edges keep their old next here (and their face,
  // invalid as the resize left it).
  for_ranges(2 * s.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t h = begin; h < end; ++h) {
      m.set_vertex(Halfedge(Index(h)), old_to[h]);
      if (!old_face[h].is_valid()) m.set_next(Halfedge(Index(h)), old_next[h]);
    }
  });
  // An old vertex leaves by its old half-edge, or, if sqrt(3) flips that (an interior edge), by
  // the spoke of the edge's twin.
  for_ranges(s.nv, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v) {
      const Halfedge o = old_out[v];
      const bool flipped = sqrt3 && o.is_valid() && old_face[o.idx()].is_valid() && !sharp[o.idx() >> 1];
      m.set_halfedge(Vertex(Index(v)), flipped ? in(q[o.idx() ^ 1u]) : o);
    }
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
  for_ranges(s.nf, [&](std::size_t f_begin, std::size_t f_end) {
    for (std::size_t f = f_begin; f < f_end; ++f) {
      const Index b = s.first[f], n = s.first[f + 1] - b;
      const Vertex centre(V + Index(f));
      for (Index k = 0; k < n; ++k) {
        const Index c = b + k, cp = k == 0 ? b + n - 1 : c - 1;
        const Index h = s.ring[c];
        const Face child(c);
        m.set_vertex(in(c), centre);
        m.set_vertex(out(c), s.corner[c]);
        if (sqrt3 && !sharp[h >> 1]) {
          // Flipped: h now runs from the far face's centre to this one's, after that face's spoke
          // in(q(twin h)).
          const Halfedge lead = in(q[h ^ 1u]);
          m.set_vertex(Halfedge(h), centre);
          m.set_next(lead, Halfedge(h));
          m.set_next(Halfedge(h), out(cp));
          m.set_next(out(cp), lead);
          m.set_face(lead, child);
        } else {
          m.set_next(Halfedge(h), in(c));
          m.set_next(in(c), out(cp));
          m.set_next(out(cp), Halfedge(h));
          m.set_face(in(c), child);
        }
        m.set_face(Halfedge(h), child);
        m.set_face(out(cp), child);
        m.set_halfedge(child, Halfedge(h));
      }
      m.set_halfedge(centre, out(b));
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
      if (!sharp[s.ring[c] >> 1]) hprops.copy(in(Index(c)).idx(), s.ring[c]);
  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty())
    for (std::size_t f = 0; f < s.nf; ++f)
      for (Index c = s.first[f]; c < s.first[f + 1]; ++c)
        fprops.copy_element_from(src.face_properties(), f, c);
  apply_boundary_split(m, src, s, bsplit, sharp);
  return m;
}

}  // namespace hedge::detail::subdivision

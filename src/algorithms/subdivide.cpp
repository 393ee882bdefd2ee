#include "hedge/algorithms/subdivide.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "hedge/error.h"

namespace hedge {

namespace {

// The halves of old half-edge h = 2e + s, as new half-edges: first(h) runs from h's start to the
// edge's new vertex, second(h) from there to h's end (see the header for the numbering).
inline Index first_half(Index h) { return 4 * (h >> 1) + 3 * (h & 1); }
inline Index second_half(Index h) { return 4 * (h >> 1) + 2 - (h & 1); }

struct Old {
  std::size_t nv = 0, ne = 0, nf = 0;
  std::vector<Vertex> to;       // per half-edge
  std::vector<Halfedge> next;   // per half-edge
  std::vector<Face> face;       // per half-edge
  std::vector<Halfedge> vout;   // per vertex
  std::vector<Halfedge> fhe;    // per face
};

// Loop's positions for the old vertices (first nv entries) and the edge vertices (then ne).
std::vector<Vec3> loop_positions(const SurfaceMesh& m, const Old& o) {
  std::vector<Vec3> out(o.nv + o.ne);
  const auto crease = m.get_edge_property<std::uint8_t>("e:crease");
  auto sharp = [&](Edge e) { return m.is_boundary(e) || (crease && crease[e] != 0); };
  for (Vertex v : m.vertices()) {
    const Vec3d p = to_double(m.position(v));
    if (m.is_isolated(v)) {
      out[v.idx()] = m.position(v);
      continue;
    }
    Vec3d ring{0, 0, 0}, sharp_sum{0, 0, 0};
    std::size_t n = 0, n_sharp = 0;
    for (Halfedge h : m.halfedges(v)) {
      const Vec3d q = to_double(m.position(m.to_vertex(h)));
      ring += q;
      ++n;
      if (sharp(SurfaceMesh::edge(h))) {
        sharp_sum += q;
        ++n_sharp;
      }
    }
    Vec3d np;
    if (n_sharp > 2) {
      np = p;  // a corner
    } else if (n_sharp == 2) {
      np = p * 0.75 + sharp_sum * 0.125;  // a boundary or crease curve
    } else {
      const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
      const double beta = (0.625 - c * c) / double(n);
      np = p * (1 - double(n) * beta) + ring * beta;
    }
    out[v.idx()] = to_float(np);
  }
  for (Edge e : m.edges()) {
    const Halfedge h = SurfaceMesh::halfedge(e, 0), t = SurfaceMesh::twin(h);
    const Vec3d a = to_double(m.position(m.to_vertex(h))), b = to_double(m.position(m.to_vertex(t)));
    Vec3d np = (a + b) * 0.5;
    if (!sharp(e)) {
      const Vec3d c = to_double(m.position(m.to_vertex(m.next(h))));
      const Vec3d d = to_double(m.position(m.to_vertex(m.next(t))));
      np = (a + b) * 0.375 + (c + d) * 0.125;
    }
    out[o.nv + e.idx()] = to_float(np);
  }
  return out;
}

void check(const SurfaceMesh& m, Subdivision scheme, int steps) {
  if (steps < 0) throw InvalidInputError("subdivide: steps must be 0 or more, got " + std::to_string(steps));
  if (scheme != Subdivision::catmull_clark)
    for (Face f : m.faces())
    if (m.valence(f) != 3)
      throw InvalidInputError("subdivide: the 1-to-4 schemes need triangles, and face " + std::to_string(f.idx()) +
                              " has " + std::to_string(m.valence(f)) + " corners (triangulate first)");
  // Each step multiplies the half-edges by about 4; refuse what would not fit 32-bit indices.
  // (Catmull-Clark: each step makes 2E + H/2 edges, at most 4x the half-edges.)
  double halfedges = double(m.n_halfedges()), faces = double(m.n_faces());
  for (int s = 0; s < steps; ++s) {
    halfedges = scheme == Subdivision::catmull_clark ? 4 * halfedges : 2 * halfedges + 6 * faces;
    faces *= 4;
    if (halfedges > double(1u << 31))
      throw InvalidInputError("subdivide: " + std::to_string(steps) + " steps would exceed 2^31 half-edges");
  }
}

Old read_old(SurfaceMesh& m) {
  if (m.has_garbage()) m.garbage_collection();
  Old o;
  o.nv = m.vertex_slots();
  o.ne = m.edge_slots();
  o.nf = m.face_slots();
  o.to.resize(2 * o.ne);
  o.next.resize(2 * o.ne);
  o.face.resize(2 * o.ne);
  for (std::size_t h = 0; h < 2 * o.ne; ++h) {
    o.to[h] = m.to_vertex(Halfedge(Index(h)));
    o.next[h] = m.next(Halfedge(Index(h)));
    o.face[h] = m.face(Halfedge(Index(h)));
  }
  o.vout.resize(o.nv);
  for (std::size_t v = 0; v < o.nv; ++v) o.vout[v] = m.halfedge(Vertex(Index(v)));
  o.fhe.resize(o.nf);
  for (std::size_t f = 0; f < o.nf; ++f) o.fhe[f] = m.halfedge(Face(Index(f)));
  return o;
}

// Resizes the mesh for the refined one (nv, ne, nf) and, when there is corner data, keeps a copy
// of the old half-edges' values past the end of the new ones, where no write reaches them.
// Returns the index of that copy's first element.
Index resize_keeping_corners(SurfaceMesh& m, const Old& o, std::size_t nv, std::size_t ne, std::size_t nf) {
  PropertyContainer& hprops = m.halfedge_properties();
  const std::size_t nh = 2 * ne;
  m.resize(nv, ne, nf);
  if (!hprops.empty()) {
    hprops.resize(nh + 2 * o.ne);
    for (std::size_t h = 0; h < 2 * o.ne; ++h) hprops.copy(h, nh + h);
  }
  return Index(nh);
}

// The halves of every old edge (with the boundary half-edges' links), the outgoing half-edges of
// the old vertices and of the edge vertices V + e, and the halves' edge properties.
void write_edge_halves(SurfaceMesh& m, const Old& o, Index old_base) {
  PropertyContainer& hprops = m.halfedge_properties();
  const bool corner_data = !hprops.empty();
  for (std::size_t e = 0; e < o.ne; ++e) {
    const Index h0 = Index(2 * e), h1 = h0 + 1;
    const Vertex a = o.to[h1], b = o.to[h0], mid(Index(o.nv + e));
    m.set_vertex(Halfedge(first_half(h0)), mid);   // a -> mid
    m.set_vertex(Halfedge(second_half(h1)), a);    // mid -> a
    m.set_vertex(Halfedge(second_half(h0)), b);    // mid -> b
    m.set_vertex(Halfedge(first_half(h1)), mid);   // b -> mid
    for (const Index h : {h0, h1}) {
      if (o.face[h].is_valid()) continue;
      // A boundary half-edge: both halves are boundary, linked along the loop.
      m.set_face(Halfedge(first_half(h)), Face());
      m.set_face(Halfedge(second_half(h)), Face());
      m.set_next(Halfedge(first_half(h)), Halfedge(second_half(h)));
      m.set_next(Halfedge(second_half(h)), Halfedge(first_half(o.next[h].idx())));
      if (corner_data) {
        hprops.copy(old_base + h, first_half(h));
        hprops.copy(old_base + h, second_half(h));
      }
    }
    // The edge vertex's outgoing half-edge: a boundary one if the edge is on the boundary.
    m.set_halfedge(mid, Halfedge(!o.face[h0].is_valid() ? second_half(h0)
                                 : !o.face[h1].is_valid() ? second_half(h1)
                                                          : second_half(h0)));
  }
  // Old vertices: the first half of their old outgoing half-edge (boundary stays boundary).
  for (std::size_t v = 0; v < o.nv; ++v)
    m.set_halfedge(Vertex(Index(v)), o.vout[v].is_valid() ? Halfedge(first_half(o.vout[v].idx())) : Halfedge());
  // Edge properties: both halves; going from the last edge down never overwrites one still to read.
  PropertyContainer& eprops = m.edge_properties();
  if (!eprops.empty())
    for (std::size_t e = o.ne; e-- > 0;) {
      eprops.copy(e, 2 * e + 1);
      eprops.copy(e, 2 * e);
    }
  // Vertex properties of the edge vertices: the average of the ends (positions too, for now).
  const float half[2] = {0.5f, 0.5f};
  for (std::size_t e = 0; e < o.ne; ++e) {
    const Index ends[2] = {o.to[2 * e].idx(), o.to[2 * e + 1].idx()};
    m.vertex_properties().interpolate(o.nv + e, ends, half, 2);
  }
}

void refine_1_to_4(SurfaceMesh& m, Subdivision scheme) {
  Old o = read_old(m);
  const std::vector<Vec3> positions = scheme == Subdivision::loop ? loop_positions(m, o) : std::vector<Vec3>{};
  const std::size_t nv = o.nv + o.ne, ne = 2 * o.ne + 3 * o.nf, nf = 4 * o.nf, nh = 2 * ne;
  const Index old_base = resize_keeping_corners(m, o, nv, ne, nf);
  PropertyContainer& hprops = m.halfedge_properties();
  const bool corner_data = !hprops.empty();
  write_edge_halves(m, o, old_base);
  // Faces: three corner triangles and the middle one.
  for (std::size_t f = 0; f < o.nf; ++f) {
    Index h[3];
    h[0] = o.fhe[f].idx();
    h[1] = o.next[h[0]].idx();
    h[2] = o.next[h[1]].idx();
    const Index base_edge = Index(2 * o.ne + 3 * f);
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3;
      const Halfedge s(second_half(h[k])), fi(first_half(h[k1]));
      const Halfedge in(2 * (base_edge + Index(k)));     // m_{k+1} -> m_k, in the corner face
      const Halfedge out(2 * (base_edge + Index(k)) + 1);  // m_k -> m_{k+1}, in the middle face
      const Face corner(Index(4 * f + Index(k))), middle(Index(4 * f + 3));
      const Vertex mk(Index(o.nv + (h[k] >> 1))), mk1(Index(o.nv + (h[k1] >> 1)));
      m.set_vertex(in, mk);
      m.set_vertex(out, mk1);
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
      if (corner_data) {
        // Corners: s enters the old corner to(h[k]); fi enters the middle of h[k1]; in enters the
        // middle of h[k]; out enters the middle of h[k1]. A middle averages the face's own corners
        // at the ends of its edge, so that values across a seam never mix.
        const Index k_1 = Index((k + 2) % 3);
        const float half[2] = {0.5f, 0.5f};
        const Index mid_k[2] = {old_base + h[k_1], old_base + h[k]};
        const Index mid_k1[2] = {old_base + h[k], old_base + h[k1]};
        hprops.copy(old_base + h[k], s.idx());
        hprops.interpolate(fi.idx(), mid_k1, half, 2);
        hprops.interpolate(in.idx(), mid_k, half, 2);
        hprops.interpolate(out.idx(), mid_k1, half, 2);
      }
    }
  }
  if (corner_data) hprops.resize(nh);

  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty())
    for (std::size_t f = o.nf; f-- > 0;)
      for (std::size_t k = 4; k-- > 0;) fprops.copy(f, 4 * f + k);
  if (scheme == Subdivision::loop)
    for (std::size_t v = 0; v < nv; ++v) m.position(Vertex(Index(v))) = positions[v];
}


// ---- Catmull-Clark ----
// Besides V + e for edge e, face f's point is vertex V + E + f. Every half-edge h of a face gets a
// compact number q(h) (the faces' half-edges in half-edge order): the quad at the corner where h
// ends is face q(h), and the inner edge from the middle of h to its face's point is edge 2E + q(h),
// whose half-edge 2(2E + q(h)) runs toward the face point and 2(2E + q(h)) + 1 back.

std::vector<Vec3> catmull_clark_positions(const SurfaceMesh& m, const Old& o) {
  std::vector<Vec3> out(o.nv + o.ne + o.nf);
  std::vector<Vec3d> face_point(o.nf, Vec3d{0, 0, 0});
  for (Face f : m.faces()) {
    Vec3d c{0, 0, 0};
    std::size_t n = 0;
    for (Vertex v : m.vertices(f)) c += to_double(m.position(v)), ++n;
    face_point[f.idx()] = c * (1.0 / double(n));
    out[o.nv + o.ne + f.idx()] = to_float(face_point[f.idx()]);
  }
  const auto crease = m.get_edge_property<std::uint8_t>("e:crease");
  auto sharp = [&](Edge e) { return m.is_boundary(e) || (crease && crease[e] != 0); };
  for (Edge e : m.edges()) {
    const Halfedge h = SurfaceMesh::halfedge(e, 0), t = SurfaceMesh::twin(h);
    const Vec3d a = to_double(m.position(m.to_vertex(h))), b = to_double(m.position(m.to_vertex(t)));
    Vec3d p = (a + b) * 0.5;
    if (!sharp(e)) p = (a + b + face_point[m.face(h).idx()] + face_point[m.face(t).idx()]) * 0.25;
    out[o.nv + e.idx()] = to_float(p);
  }
  for (Vertex v : m.vertices()) {
    const Vec3d s = to_double(m.position(v));
    out[v.idx()] = m.position(v);
    if (m.is_isolated(v)) continue;
    Vec3d faces{0, 0, 0}, mids{0, 0, 0}, sharp_sum{0, 0, 0};
    std::size_t n = 0, n_faces = 0, n_sharp = 0;
    for (Halfedge h : m.halfedges(v)) {
      const Vec3d w = to_double(m.position(m.to_vertex(h)));
      mids += (s + w) * 0.5;
      ++n;
      if (m.face(h).is_valid()) faces += face_point[m.face(h).idx()], ++n_faces;
      if (sharp(SurfaceMesh::edge(h))) sharp_sum += w, ++n_sharp;
    }
    Vec3d p = s;
    if (n_sharp == 2) {
      p = s * 0.75 + sharp_sum * 0.125;
    } else if (n_sharp < 2 && n_faces > 0) {
      const double k = double(n);
      p = (faces * (1.0 / double(n_faces)) + mids * (2.0 / k) + s * (k - 3)) * (1.0 / k);
    }
    out[v.idx()] = to_float(p);
  }
  return out;
}

void refine_catmull_clark(SurfaceMesh& m) {
  Old o = read_old(m);
  const std::vector<Vec3> positions = catmull_clark_positions(m, o);
  // q(h) for the half-edges of faces.
  std::vector<Index> q(2 * o.ne, kInvalidIndex);
  Index quads = 0;
  for (std::size_t h = 0; h < 2 * o.ne; ++h)
    if (o.face[h].is_valid()) q[h] = quads++;
  const std::size_t nv = o.nv + o.ne + o.nf, ne = 2 * o.ne + quads, nf = quads;
  const Index old_base = resize_keeping_corners(m, o, nv, ne, nf);
  PropertyContainer& hprops = m.halfedge_properties();
  const bool corner_data = !hprops.empty();
  write_edge_halves(m, o, old_base);
  const Index inner = Index(2 * o.ne);
  auto to_centre = [&](Index h) { return Halfedge(2 * (inner + q[h])); };
  auto from_centre = [&](Index h) { return Halfedge(2 * (inner + q[h]) + 1); };
  std::vector<Index> ring, corners, old_corners;  // per face, reused
  std::vector<float> weights;
  for (std::size_t f = 0; f < o.nf; ++f) {
    const Vertex centre(Index(o.nv + o.ne + f));
    ring.clear();
    Index h = o.fhe[f].idx();
    do {
      ring.push_back(h);
      h = o.next[h].idx();
    } while (h != o.fhe[f].idx());
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Index hk = ring[k], hn = ring[(k + 1) % n], hp = ring[(k + n - 1) % n];
      const Halfedge s(second_half(hk)), fi(first_half(hn)), in = to_centre(hn), out = from_centre(hk);
      const Face quad(q[hk]);
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
      if (corner_data) {
        const float half[2] = {0.5f, 0.5f};
        const Index mid_k[2] = {old_base + hp, old_base + hk};
        const Index mid_n[2] = {old_base + hk, old_base + hn};
        hprops.copy(old_base + hk, s.idx());
        hprops.interpolate(fi.idx(), mid_n, half, 2);
        hprops.interpolate(out.idx(), mid_k, half, 2);
      }
    }
    m.set_halfedge(centre, from_centre(ring[0]));
    // The face point's vertex properties, and the corners at it: the average of the face's corners.
    weights.assign(n, 1.f / float(n));
    corners.resize(n);
    for (std::size_t k = 0; k < n; ++k) corners[k] = o.to[ring[k]].idx();
    m.vertex_properties().interpolate(centre.idx(), corners.data(), weights.data(), n);
    if (corner_data) {
      old_corners.resize(n);
      for (std::size_t k = 0; k < n; ++k) old_corners[k] = old_base + ring[k];
      for (std::size_t k = 0; k < n; ++k) hprops.interpolate(to_centre(ring[k]).idx(), old_corners.data(), weights.data(), n);
    }
  }
  if (corner_data) hprops.resize(2 * ne);
  // Face properties: quad q(h) takes face(h). Quads are numbered by half-edge, not by face, so a
  // quad may land on a parent still to be read: copy from a snapshot of the parents.
  PropertyContainer& fprops = m.face_properties();
  if (!fprops.empty()) {
    PropertyContainer parents = fprops;
    parents.resize(o.nf);
    for (std::size_t f = 0; f < o.nf; ++f) {
      Index h = o.fhe[f].idx();
      do {
        fprops.copy_element_from(parents, f, q[h]);
        h = o.next[h].idx();
      } while (h != o.fhe[f].idx());
    }
  }
  for (std::size_t v = 0; v < nv; ++v) m.position(Vertex(Index(v))) = positions[v];
}

}  // namespace

void subdivide(SurfaceMesh& mesh, Subdivision scheme, int steps) {
  check(mesh, scheme, steps);
  for (int s = 0; s < steps; ++s) {
    if (scheme == Subdivision::catmull_clark) {
      refine_catmull_clark(mesh);
    } else {
      refine_1_to_4(mesh, scheme);
    }
  }
  if (steps > 0) mesh.changes().notify();
}

}  // namespace hedge

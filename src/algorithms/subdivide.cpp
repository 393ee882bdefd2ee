#include "hedge/algorithms/subdivide.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "hedge/core/operations.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge {

namespace {

// The halves of old half-edge h = 2e + s, as new half-edges: first(h) runs from h's start to the
// edge's new vertex, second(h) from there to h's end (see the header for the numbering).
inline Index first_half(Index h) { return 4 * (h >> 1) + 3 * (h & 1); }
inline Index second_half(Index h) { return 4 * (h >> 1) + 2 - (h & 1); }

// Every pass writes each new element from a formula of the old ones, so a pass splits between
// threads (include/hedge/core/threads.h) without changing the result; at most 8 of them, as a pass
// streams memory and more threads only queue for it.
constexpr std::size_t kMaxThreads = 8;
template <typename Body>
void for_ranges(std::size_t n, Body&& body) {
  detail::parallel_ranges(n, body, std::size_t(1) << 15, kMaxThreads);
}

// The mesh being refined, read-only: the refined one is built in a mesh of its own, so that the
// input stays as it was until the result is complete.
struct Old {
  std::size_t nv = 0, ne = 0, nf = 0;
  const Vertex* to = nullptr;       // per half-edge
  const Halfedge* next = nullptr;   // per half-edge
  const Face* face = nullptr;       // per half-edge
  const Halfedge* vout = nullptr;   // per vertex
  const Halfedge* fhe = nullptr;    // per face
  std::vector<std::uint8_t> sharp;  // per edge: boundary or "e:crease"
};

// Loop's weight of the ring for a vertex of valence n (the vertex keeps 1 - n beta).
double loop_beta(std::size_t n) {
  const double c = 0.375 + 0.25 * std::cos(2 * std::numbers::pi / double(n));
  return (0.625 - c * c) / double(n);
}

// Positions of the 1-to-4 schemes, from the old arrays: the old vertices (first nv entries; Loop
// moves them) and the edge vertices (then ne; Loop's masks, or midpoints).
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

void check(const SurfaceMesh& m, Subdivision scheme, int steps) {
  if (steps < 0) throw InvalidInputError("subdivide: steps must be 0 or more, got " + std::to_string(steps));
  const bool any_polygon = scheme == Subdivision::catmull_clark || scheme == Subdivision::split_faces;
  // The corners of all faces, and the first face that is not a triangle (one pass, on all cores).
  const std::size_t nf = m.face_slots();
  const std::vector<Halfedge>& next = m.halfedge_next_array();
  const std::vector<Halfedge>& fhe = m.face_halfedge_array();
  std::atomic<std::size_t> all_corners{0}, not_triangle{nf};
  for_ranges(nf, [&](std::size_t begin, std::size_t end) {
    std::size_t sum = 0, first = nf;
    for (std::size_t f = begin; f < end; ++f) {
      if (m.is_deleted(Face(Index(f)))) continue;
      const Index h0 = fhe[f].idx(), h2 = next[next[h0].idx()].idx();
      if (next[h2].idx() == h0) {
        sum += 3;
        continue;
      }
      if (first == nf) first = f;
      sum += m.valence(Face(Index(f)));
    }
    all_corners += sum;
    std::size_t seen = not_triangle.load();
    while (first < seen && !not_triangle.compare_exchange_weak(seen, first)) {
    }
  });
  double corners = double(all_corners.load());
  if (!any_polygon && not_triangle.load() < nf) {
    const Face f(Index(not_triangle.load()));
    throw InvalidInputError(std::string("subdivide: the ") +
                            (scheme == Subdivision::sqrt3 ? "sqrt3" : "1-to-4") +
                            " scheme needs triangles, and face " + std::to_string(f.idx()) + " has " +
                            std::to_string(m.valence(f)) + " corners (triangulate first)");
  }
  // Refuse what would not fit 32-bit indices. With H half-edges, F faces and C face corners, a step
  // makes: Loop, midpoint 2H + 6F half-edges, 4F faces; Catmull-Clark at most 4H; split-faces and
  // sqrt3 H + 2C half-edges and C faces of three corners.
  double halfedges = double(m.n_halfedges()), faces = double(m.n_faces());
  for (int s = 0; s < steps; ++s) {
    if (scheme == Subdivision::catmull_clark) {
      halfedges *= 4;
    } else if (any_polygon || scheme == Subdivision::sqrt3) {
      halfedges += 2 * corners;
      faces = corners;
      corners = 3 * faces;
    } else {
      halfedges = 2 * halfedges + 6 * faces;
      faces *= 4;
    }
    if (halfedges > double(1u << 31))
      throw InvalidInputError("subdivide: " + std::to_string(steps) + " steps would exceed 2^31 half-edges");
  }
}

// ---- the memory estimate ----

// Live element counts of a mesh (c: face corners), as doubles so that no step overflows.
struct Counts {
  double v = 0, e = 0, f = 0, c = 0;
};

Counts counts_after(const Counts& n, Subdivision scheme) {
  switch (scheme) {
    case Subdivision::catmull_clark:
      return {n.v + n.e + n.f, 2 * n.e + n.c, n.c, 4 * n.c};
    case Subdivision::sqrt3:
    case Subdivision::split_faces:
      return {n.v + n.f, n.e + n.c, n.c, 3 * n.c};
    default:
      return {n.v + n.e, 2 * n.e + 3 * n.f, 4 * n.f, 12 * n.f};
  }
}

// Bytes per element of a mesh like `m` (connectivity, deletion bits, every property).
struct ElementBytes {
  double v, h, e, f, corner;
  explicit ElementBytes(const SurfaceMesh& m)
      : v(sizeof(Halfedge) + 0.125 + double(m.vertex_properties().element_bytes())),
        h(sizeof(Vertex) + sizeof(Halfedge) + sizeof(Face) + double(m.halfedge_properties().element_bytes())),
        e(0.125 + double(m.edge_properties().element_bytes())),
        f(sizeof(Halfedge) + 0.125 + double(m.face_properties().element_bytes())),
        corner(double(m.halfedge_properties().element_bytes())) {}
  double of(const Counts& n) const { return n.v * v + 2 * n.e * h + n.e * e + n.f * f; }
};

// The working arrays of one step reading a mesh of counts n (sharp flags, face points, corner
// offsets, smoothed positions), in bytes per element of the mesh read, and the slack of the arrays
// the steps grow (capacity beyond size): calibrated against the peak resident memory of steps of
// each scheme on meshes with and without corner texture coordinates.
double work_bytes_per_element(Subdivision scheme) {
  switch (scheme) {
    case Subdivision::catmull_clark:
      return 48;
    case Subdivision::sqrt3:
    case Subdivision::split_faces:
      return 24;
    default:
      return 8;
  }
}
constexpr double kSlack = 1.25;

double estimate(const SurfaceMesh& m, Subdivision scheme, int steps) {
  const ElementBytes bytes(m);
  Counts n{double(m.n_vertices()), double(m.n_edges()), double(m.n_faces()), 0};
  for (Face f : m.faces()) n.c += double(m.valence(f));
  const double compact = m.has_garbage() ? bytes.of(n) : 0;
  double peak = 0, previous = 0;
  for (int s = 0; s < steps; ++s) {
    const Counts next = counts_after(n, scheme);
    // Corner properties (texture coordinates) are gathered per new half-edge before they are set.
    const double work = work_bytes_per_element(scheme) * (n.v + n.e + n.f) + 2 * next.e * bytes.corner;
    const double made = kSlack * bytes.of(next);
    // Step s reads the mesh before it (the input, or the result of step s - 1, still held) and
    // builds the next one.
    peak = std::max(peak, compact + (s > 0 ? previous : 0) + made + work);
    previous = made;
    n = next;
  }
  return peak;
}

std::size_t saturate(double bytes) {
  bytes = std::ceil(bytes);
  return bytes >= double(std::numeric_limits<std::size_t>::max()) ? std::numeric_limits<std::size_t>::max()
                                                                  : std::size_t(bytes);
}

void check_memory(const SurfaceMesh& m, Subdivision scheme, int steps, std::size_t max_memory) {
  if (max_memory == 0 || steps == 0) return;
  const double need = estimate(m, scheme, steps);
  if (saturate(need) <= max_memory) return;
  int fit = 0;
  while (fit + 1 < steps && saturate(estimate(m, scheme, fit + 1)) <= max_memory) ++fit;
  throw InvalidInputError(
      "subdivide: " + std::to_string(steps) + (steps == 1 ? " step" : " steps") + " would need about " +
      bytes_text(need) + " (estimated) for " + std::to_string(m.n_faces()) +
      " faces, more than the memory budget of " + bytes_text(double(max_memory)) + "; " +
      (fit == 0 ? std::string("not even one step fits")
                : "at most " + std::to_string(fit) + (fit == 1 ? " step fits" : " steps fit")) +
      " (subdivide_memory() gives the estimate)");
}

Old read_old(const SurfaceMesh& m) {
  Old o;
  o.nv = m.vertex_slots();
  o.ne = m.edge_slots();
  o.nf = m.face_slots();
  o.to = m.halfedge_vertex_array().data();
  o.next = m.halfedge_next_array().data();
  o.face = m.halfedge_face_array().data();
  o.vout = m.vertex_halfedge_array().data();
  o.fhe = m.face_halfedge_array().data();
  o.sharp.resize(o.ne);
  const auto crease = m.get_edge_property<std::uint8_t>("e:crease");
  for_ranges(o.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e)
      o.sharp[e] = !o.face[2 * e].is_valid() || !o.face[2 * e + 1].is_valid() ||
                   (crease && crease[Edge(Index(e))] != 0);
  });
  return o;
}

// An empty mesh of nv vertices, ne edges and nf faces (links invalid) with the properties of
// `src`, whose first `keep_vertices` vertices carry src's vertex properties (positions aside: the
// caller writes them all).
SurfaceMesh refined_like(const SurfaceMesh& src, std::size_t nv, std::size_t ne, std::size_t nf,
                         std::size_t keep_vertices) {
  SurfaceMesh out;
  out.vertex_properties().add_missing_from(src.vertex_properties());
  out.halfedge_properties().add_missing_from(src.halfedge_properties());
  out.edge_properties().add_missing_from(src.edge_properties());
  out.face_properties().add_missing_from(src.face_properties());
  out.resize(nv, ne, nf);
  const PropertyContainer& from = src.vertex_properties();
  if (from.array_count() > 1)
    for (std::size_t v = 0; v < keep_vertices; ++v) out.vertex_properties().copy_element_from(from, v, v);
  return out;
}

// When there is corner data, makes room in out past its nh half-edges for a copy of the old
// half-edges' values, where no write reaches them, and copies them there. Returns the index of
// that copy's first element.
Index keep_old_corners(SurfaceMesh& out, const SurfaceMesh& src, std::size_t nh) {
  PropertyContainer& hprops = out.halfedge_properties();
  if (!hprops.empty()) {
    const std::size_t old_nh = src.halfedge_slots();
    hprops.resize(nh + old_nh);
    for (std::size_t h = 0; h < old_nh; ++h) hprops.copy_element_from(src.halfedge_properties(), h, nh + h);
  }
  return Index(nh);
}

// The halves of every old edge (with the boundary half-edges' links), the outgoing half-edges of
// the old vertices and of the edge vertices V + e.
void write_edge_halves(SurfaceMesh& m, const Old& o) {
  for_ranges(o.ne, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const Index h0 = Index(2 * e), h1 = h0 + 1;
      const Vertex a = o.to[h1], b = o.to[h0], mid(Index(o.nv + e));
      m.set_vertex(Halfedge(first_half(h0)), mid);  // a -> mid
      m.set_vertex(Halfedge(second_half(h1)), a);   // mid -> a
      m.set_vertex(Halfedge(second_half(h0)), b);   // mid -> b
      m.set_vertex(Halfedge(first_half(h1)), mid);  // b -> mid
      for (const Index h : {h0, h1}) {
        if (o.face[h].is_valid()) continue;
        // A boundary half-edge: both halves are boundary, linked along the loop.
        m.set_face(Halfedge(first_half(h)), Face());
        m.set_face(Halfedge(second_half(h)), Face());
        m.set_next(Halfedge(first_half(h)), Halfedge(second_half(h)));
        m.set_next(Halfedge(second_half(h)), Halfedge(first_half(o.next[h].idx())));
      }
      // The edge vertex's outgoing half-edge: a boundary one if the edge is on the boundary.
      m.set_halfedge(mid, Halfedge(!o.face[h0].is_valid()   ? second_half(h0)
                                   : !o.face[h1].is_valid() ? second_half(h1)
                                                            : second_half(h0)));
    }
  });
  // Old vertices: the first half of their old outgoing half-edge (boundary stays boundary).
  for_ranges(o.nv, [&](std::size_t begin, std::size_t end) {
    for (std::size_t v = begin; v < end; ++v)
      m.set_halfedge(Vertex(Index(v)),
                     o.vout[v].is_valid() ? Halfedge(first_half(o.vout[v].idx())) : Halfedge());
  });
}

// The properties of the edge halves: boundary halves' corners (the old corner values sit at
// old_base + h), edge properties of both halves, and the edge vertices' vertex properties (the
// average of the ends; positions are the caller's).
void write_edge_half_properties(SurfaceMesh& m, const SurfaceMesh& src, const Old& o, Index old_base) {
  PropertyContainer& hprops = m.halfedge_properties();
  if (!hprops.empty())
    for (Index h = 0; h < 2 * o.ne; ++h)
      if (!o.face[h].is_valid()) {
        hprops.copy(old_base + h, first_half(h));
        hprops.copy(old_base + h, second_half(h));
      }
  // Edge properties: both halves.
  PropertyContainer& eprops = m.edge_properties();
  if (!eprops.empty())
    for (std::size_t e = 0; e < o.ne; ++e) {
      eprops.copy_element_from(src.edge_properties(), e, 2 * e);
      eprops.copy_element_from(src.edge_properties(), e, 2 * e + 1);
    }
  PropertyContainer& vprops = m.vertex_properties();
  if (vprops.array_count() > 1) {
    const float half[2] = {0.5f, 0.5f};
    for (std::size_t e = 0; e < o.ne; ++e) {
      const Index ends[2] = {o.to[2 * e].idx(), o.to[2 * e + 1].idx()};
      vprops.interpolate(o.nv + e, ends, half, 2, m.positions().array());
    }
  }
}

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
      Index h[3];
      h[0] = o.fhe[f].idx();
      h[1] = o.next[h[0]].idx();
      h[2] = o.next[h[1]].idx();
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
      Index h[3];
      h[0] = o.fhe[f].idx();
      h[1] = o.next[h[0]].idx();
      h[2] = o.next[h[1]].idx();
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

// One step from src, into a mesh of its own.
SurfaceMesh refine(const SurfaceMesh& src, Subdivision scheme) {
  switch (scheme) {
    case Subdivision::catmull_clark:
      return refine_catmull_clark(src);
    case Subdivision::sqrt3:
      return refine_at_centres(src, true);
    case Subdivision::split_faces:
      return refine_at_centres(src, false);
    default:
      return refine_1_to_4(src, scheme);
  }
}

}  // namespace

std::size_t subdivide_memory(const SurfaceMesh& mesh, Subdivision scheme, int steps) {
  if (steps < 0)
    throw InvalidInputError("subdivide_memory: steps must be 0 or more, got " + std::to_string(steps));
  return saturate(estimate(mesh, scheme, steps));
}

void subdivide(SurfaceMesh& mesh, Subdivision scheme, int steps, const Progress& progress,
               std::size_t max_memory) {
  check(mesh, scheme, steps);
  check_memory(mesh, scheme, steps, max_memory);
  report_progress(progress, 0);
  if (steps == 0) return;
  // Every step reads the mesh before it and writes a new one; `mesh` takes the last one only
  // (swap_elements cannot fail), so that a failure on the way (std::bad_alloc) leaves it as it was.
  SurfaceMesh compact, result;
  const SurfaceMesh* from = &mesh;
  if (mesh.has_garbage()) {
    compact = mesh;
    compact.garbage_collection();
    from = &compact;
  }
  for (int s = 0; s < steps; ++s) {
    SurfaceMesh next = refine(*from, scheme);
    result = std::move(next);
    from = &result;
    if (s + 1 == steps) break;
    // Each step costs about as much as all the steps before it together times the growth (4 or 3).
    const double growth = scheme == Subdivision::sqrt3 || scheme == Subdivision::split_faces ? 3 : 4;
    try {
      report_progress(progress, (std::pow(growth, s + 1) - 1) / (std::pow(growth, steps) - 1));
    } catch (...) {
      mesh.swap_elements(result);  // the steps done stay done
      mesh.changes().notify();
      throw;
    }
  }
  mesh.swap_elements(result);
  mesh.changes().notify();
  report_progress(progress, 1);
}

}  // namespace hedge

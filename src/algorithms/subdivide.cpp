#include "hedge/algorithms/subdivide.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "hedge/error.h"
#include "subdivide_internal.h"

// The checks, the memory estimate, the builders every scheme shares and the loop over the steps.
// The schemes' steps are in subdivide_one_to_four.cpp, subdivide_catmull_clark.cpp and
// subdivide_face_centres.cpp.

namespace hedge {

namespace detail::subdivision {

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

}  // namespace detail::subdivision

namespace {

using namespace detail::subdivision;

double boundary_edges(const SurfaceMesh& m) {
  double n = 0;
  for (Edge e : m.edges()) n += m.is_boundary(e);
  return n;
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
  // sqrt3 H + 2C half-edges and C faces of three corners, and in its even steps 2 more half-edges
  // per boundary edge.
  double halfedges = double(m.n_halfedges()), faces = double(m.n_faces());
  double boundary = scheme == Subdivision::sqrt3 && steps > 1 ? boundary_edges(m) : 0;
  for (int s = 0; s < steps; ++s) {
    if (scheme == Subdivision::catmull_clark) {
      halfedges *= 4;
    } else if (any_polygon || scheme == Subdivision::sqrt3) {
      halfedges += 2 * corners;
      if (s % 2 == 1) halfedges += 2 * boundary, boundary *= 3;
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

// Live element counts of a mesh (c: face corners, b: boundary edges), as doubles so that no step
// overflows.
struct Counts {
  double v = 0, e = 0, f = 0, c = 0, b = 0;
};

// The counts after step `step` (from 0) of a call. An odd-numbered sqrt(3) step splits each
// boundary edge in three: its face's centroid gives way to the two points, so one more vertex and
// one more edge each.
Counts counts_after(const Counts& n, Subdivision scheme, int step) {
  switch (scheme) {
    case Subdivision::catmull_clark:
      return {n.v + n.e + n.f, 2 * n.e + n.c, n.c, 4 * n.c, 2 * n.b};
    case Subdivision::sqrt3:
      if (step % 2 == 1) return {n.v + n.f + n.b, n.e + n.c + n.b, n.c, 3 * n.c, 3 * n.b};
      return {n.v + n.f, n.e + n.c, n.c, 3 * n.c, n.b};
    case Subdivision::split_faces:
      return {n.v + n.f, n.e + n.c, n.c, 3 * n.c, n.b};
    default:
      return {n.v + n.e, 2 * n.e + 3 * n.f, 4 * n.f, 12 * n.f, 2 * n.b};
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
  Counts n{double(m.n_vertices()), double(m.n_edges()), double(m.n_faces()), 0, boundary_edges(m)};
  for (Face f : m.faces()) n.c += double(m.valence(f));
  const double compact = m.has_garbage() ? bytes.of(n) : 0;
  double peak = 0, previous = 0;
  for (int s = 0; s < steps; ++s) {
    const Counts next = counts_after(n, scheme, s);
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

// One step from src, into a mesh of its own. `step` counts from 0 within the call: sqrt(3) splits
// the boundary in its odd-numbered (second, fourth, ...) steps.
SurfaceMesh refine(const SurfaceMesh& src, Subdivision scheme, int step) {
  switch (scheme) {
    case Subdivision::catmull_clark:
      return refine_catmull_clark(src);
    case Subdivision::sqrt3:
      return refine_at_centres(src, true, step % 2 == 1);
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
  require_finite_positions(mesh, "subdivide");
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
    SurfaceMesh next = refine(*from, scheme, s);
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

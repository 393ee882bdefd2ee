#include "hedge/algorithms/normals.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#endif

#include "hedge/algorithms/geometry.h"
#include "hedge/error.h"

namespace hedge {

namespace {

// The mesh's arrays, read in place: every pass below is a loop over them, with no handle checks,
// no circulators and no property lookups inside it.
struct Arrays {
  const Vec3* p;
  const Vertex* to;
  const Halfedge* next;
  const Halfedge* fhe;
  std::size_t n_faces;  // face slots
  bool garbage;
  const SurfaceMesh& m;
  explicit Arrays(const SurfaceMesh& mesh)
      : p(mesh.positions().vector().data()),
        to(mesh.halfedge_vertex_array().data()),
        next(mesh.halfedge_next_array().data()),
        fhe(mesh.face_halfedge_array().data()),
        n_faces(mesh.face_slots()),
        garbage(mesh.has_garbage()),
        m(mesh) {}
  bool live(std::size_t f) const { return !garbage || !m.is_deleted(Face(Index(f))); }
};

// (p1 - p0) x (p2 - p0), component by component from the corners in place: copying a corner into
// a local Vec3 made the compiler reload it across two stores, a stalled store forward per face.
inline Vec3 triangle_cross(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  const float ax = p1.x - p0.x, ay = p1.y - p0.y, az = p1.z - p0.z;
  const float bx = p2.x - p0.x, by = p2.y - p0.y, bz = p2.z - p0.z;
  return {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
}

// Newell's vector of a polygon of four or more corners whose first half-edge is h0.
[[gnu::noinline]] Vec3 polygon_area_vector(const Arrays& a, Index h0) {
  Vec3 n{0, 0, 0};
  Index h = h0;
  do {
    const Vec3 u = a.p[a.to[h].idx()], v = a.p[a.to[a.next[h].idx()].idx()];
    n += Vec3{(u.y - v.y) * (u.z + v.z), (u.z - v.z) * (u.x + v.x), (u.x - v.x) * (u.y + v.y)};
    h = a.next[h].idx();
  } while (h != h0);
  return n;
}

// Newell's vector of the face whose first half-edge is h0 (twice its area times its unit normal),
// in float: for a triangle the cross product of two edges, which for floats that are close is
// exact up to one rounding of each product.
inline Vec3 area_vector_float(const Arrays& a, Index h0) {
  const Index h1 = a.next[h0].idx(), h2 = a.next[h1].idx();
  if (a.next[h2].idx() != h0) return polygon_area_vector(a, h0);
  return triangle_cross(a.p[a.to[h0].idx()], a.p[a.to[h1].idx()], a.p[a.to[h2].idx()]);
}

// n divided by its length; zero if that is zero or not finite (one range test on the squared length).
inline Vec3 unit_or_zero_float(const Vec3& n) {
  const float s = n.x * n.x + n.y * n.y + n.z * n.z;
  return s > 0 && s <= std::numeric_limits<float>::max() ? n * (1.f / std::sqrt(s)) : Vec3{0, 0, 0};
}

// The angle at corner v between the edges to a and to b (zero if either is degenerate), in double.
float corner_angle(const Vec3& v, const Vec3& a, const Vec3& b) {
  const Vec3d o = to_double(v);
  const Vec3d x = to_double(a) - o, y = to_double(b) - o;
  const double s = norm(cross(x, y)), c = dot(x, y);
  return float((s > 0 || c != 0) ? std::atan2(s, c) : 0.0);
}

// The angle of the face at the corner where half-edge `in` ends, between the edges back to
// from(in) and on to to(next(in)).
float corner_angle_at(const Arrays& a, Index in) {
  return corner_angle(a.p[a.to[in].idx()], a.p[a.to[in ^ 1u].idx()], a.p[a.to[a.next[in].idx()].idx()]);
}

// Adds to sum[to(h)], for every corner of every live face (h entering the corner), the face's
// contribution: its Newell vector (area), its unit normal (uniform) or its unit normal times the
// corner's angle (angle). One pass over the faces, in face order, so the sums are the same on
// every run; triangles take a path of their own, which adds the same values as the general loop.
// `unit`, if given, holds the faces' unit normals (unit_face_normals), which are then not computed
// again.
void scatter_face_normals(const Arrays& a, NormalWeighting w, Vec3* sum, const Vec3* unit = nullptr) {
  for (std::size_t f = 0; f < a.n_faces; ++f) {
    if (!a.live(f)) continue;
    const Index h0 = a.fhe[f].idx(), h1 = a.next[h0].idx(), h2 = a.next[h1].idx();
    if (a.next[h2].idx() == h0) {
      const Index i0 = a.to[h0].idx(), i1 = a.to[h1].idx(), i2 = a.to[h2].idx();
      const Vec3 &p0 = a.p[i0], &p1 = a.p[i1], &p2 = a.p[i2];
      Vec3 n = unit && w != NormalWeighting::area ? unit[f] : triangle_cross(p0, p1, p2);
      if (!unit && w != NormalWeighting::area) n = unit_or_zero_float(n);
      if (w == NormalWeighting::angle) {
        // The corner entered by h0 lies between from(h0) = to(h2) and to(next(h0)) = to(h1).
        sum[i0] += n * corner_angle(p0, p2, p1);
        sum[i1] += n * corner_angle(p1, p0, p2);
        sum[i2] += n * corner_angle(p2, p1, p0);
        continue;
      }
      sum[i0] += n;
      sum[i1] += n;
      sum[i2] += n;
      continue;
    }
    Vec3 n = unit && w != NormalWeighting::area ? unit[f] : area_vector_float(a, h0);
    if (!unit && w != NormalWeighting::area) n = unit_or_zero_float(n);
    Index h = h0;
    do {
      sum[a.to[h].idx()] += w == NormalWeighting::angle ? n * corner_angle_at(a, h) : n;
      h = a.next[h].idx();
    } while (h != h0);
  }
}

// How many faces write_unit_normals reads, and then normalises, at a time.
constexpr std::size_t kBlock = 64;

// n[k] = unit_or_zero_float(n[k]) for k < count, n given as three arrays of coordinates padded to
// a multiple of 4 and aligned to 16 bytes (the aligned loads need both). With SSE2, four at a time: the same
// IEEE operations in the same order (x * x + y * y, then + z * z; 1 / sqrt(s); each coordinate times that),
// so the same bits; a face's own square root and division no longer wait for its loads, and four share one
// instruction.
void normalise_block(float* x, float* y, float* z, std::size_t count) {
#if defined(__SSE2__) || defined(_M_X64)
  const __m128 one = _mm_set1_ps(1.f), zero = _mm_setzero_ps();
  const __m128 top = _mm_set1_ps(std::numeric_limits<float>::max());
  for (std::size_t k = 0; k < count; k += 4) {
    const __m128 a = _mm_load_ps(x + k), b = _mm_load_ps(y + k), c = _mm_load_ps(z + k);
    const __m128 s = _mm_add_ps(_mm_add_ps(_mm_mul_ps(a, a), _mm_mul_ps(b, b)), _mm_mul_ps(c, c));
    // s > 0 and s <= max, false for NaN: zero otherwise, as unit_or_zero_float.
    const __m128 ok = _mm_and_ps(_mm_cmpgt_ps(s, zero), _mm_cmple_ps(s, top));
    const __m128 inv = _mm_div_ps(one, _mm_sqrt_ps(s));
    _mm_store_ps(x + k, _mm_and_ps(_mm_mul_ps(a, inv), ok));
    _mm_store_ps(y + k, _mm_and_ps(_mm_mul_ps(b, inv), ok));
    _mm_store_ps(z + k, _mm_and_ps(_mm_mul_ps(c, inv), ok));
  }
#else
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 n = unit_or_zero_float(Vec3{x[k], y[k], z[k]});
    x[k] = n.x, y[k] = n.y, z[k] = n.z;
  }
#endif
}

// out[f] = the unit normal of every live face f, in float (zero if degenerate); deleted faces'
// slots are left as they are. A block of faces at a time, in three passes: the first walks each
// face's half-edges to its corners and asks for their positions, so that the loads of many faces
// are under way at once rather than each face's chain of loads (face, next, next, next, target,
// position) waiting on the one before; the second takes the cross products of the corners, by
// then arrived; the third normalises the block (normalise_block) and writes it out.
void write_unit_normals(const Arrays& a, Vec3* out) {
  const std::size_t n = a.n_faces;
  const Vec3* p = a.p;
  const Vertex* to = a.to;
  const Halfedge* next = a.next;
  const Halfedge* fhe = a.fhe;
  enum : std::uint8_t { kDeleted, kTriangle, kPolygon };
  std::uint8_t kind[kBlock];
  Index corner[3 * kBlock];
  alignas(16) float x[kBlock], y[kBlock], z[kBlock];
  for (std::size_t b = 0; b < n; b += kBlock) {
    const std::size_t m = std::min(kBlock, n - b);
    for (std::size_t k = 0; k < m; ++k) {
      if (!a.live(b + k)) {
        kind[k] = kDeleted;
        continue;
      }
      const Index h0 = fhe[b + k].idx(), h1 = next[h0].idx(), h2 = next[h1].idx();
      kind[k] = next[h2].idx() == h0 ? kTriangle : kPolygon;
      const Index i0 = to[h0].idx(), i1 = to[h1].idx(), i2 = to[h2].idx();
      corner[3 * k] = i0, corner[3 * k + 1] = i1, corner[3 * k + 2] = i2;
      __builtin_prefetch(p + i0);
      __builtin_prefetch(p + i1);
      __builtin_prefetch(p + i2);
    }
    const std::size_t padded = (m + 3) & ~std::size_t(3);
    for (std::size_t k = 0; k < padded; ++k) {
      Vec3 v{0, 0, 0};
      if (k < m && kind[k] == kTriangle)
        v = triangle_cross(p[corner[3 * k]], p[corner[3 * k + 1]], p[corner[3 * k + 2]]);
      else if (k < m && kind[k] == kPolygon)
        v = polygon_area_vector(a, fhe[b + k].idx());
      x[k] = v.x, y[k] = v.y, z[k] = v.z;
    }
    normalise_block(x, y, z, padded);
    for (std::size_t k = 0; k < m; ++k)
      if (kind[k] != kDeleted) out[b + k] = Vec3{x[k], y[k], z[k]};
  }
}

// Unit normals of every face slot, in float (zero for deleted and degenerate faces).
std::vector<Vec3> unit_face_normals(const Arrays& a) {
  std::vector<Vec3> n(a.n_faces, Vec3{0, 0, 0});
  write_unit_normals(a, n.data());
  return n;
}

void mark_all_faces(SurfaceMesh& mesh) {
  if (mesh.changes().active())
    for (Face f : mesh.faces()) mesh.mark_changed(f, ChangeEvent::faces_changed);
  mesh.changes().notify();
}

}  // namespace

Vec3 face_normal(const SurfaceMesh& mesh, Face f) { return to_float(unit_or_zero(area_vector(mesh, f))); }

FaceProperty<Vec3> compute_face_normals(SurfaceMesh& mesh, std::string_view name) {
  require_finite_positions(mesh, "compute_face_normals");
  FaceProperty<Vec3> prop = mesh.face_property<Vec3>(name);
  write_unit_normals(Arrays(mesh), prop.vector().data());
  mark_all_faces(mesh);
  return prop;
}

VertexProperty<Vec3> compute_vertex_normals(SurfaceMesh& mesh, NormalWeighting weighting,
                                            std::string_view name) {
  require_finite_positions(mesh, "compute_vertex_normals");
  VertexProperty<Vec3> prop = mesh.vertex_property<Vec3>(name);
  Vec3* out = prop.vector().data();
  // Deleted vertices keep their value; the live ones are summed from zero.
  const std::size_t nv = mesh.vertex_slots();
  const bool garbage = mesh.has_garbage();
  for (std::size_t v = 0; v < nv; ++v)
    if (!garbage || !mesh.is_deleted(Vertex(Index(v)))) out[v] = Vec3{0, 0, 0};
  scatter_face_normals(Arrays(mesh), weighting, out);
  for (std::size_t v = 0; v < nv; ++v)
    if (!garbage || !mesh.is_deleted(Vertex(Index(v)))) out[v] = unit_or_zero_float(out[v]);
  if (mesh.changes().active())
    for (Vertex v : mesh.vertices()) mesh.mark_changed(v, ChangeEvent::vertex_data_changed);
  mesh.changes().notify();
  return prop;
}

HalfedgeProperty<Vec3> compute_corner_normals(SurfaceMesh& mesh, double crease_degrees,
                                              NormalWeighting weighting, std::string_view name) {
  if (!(crease_degrees >= 0 && crease_degrees <= 180))
    throw InvalidInputError("compute_corner_normals: the crease angle must be in [0, 180] degrees, got " +
                            std::to_string(crease_degrees));
  require_finite_positions(mesh, "compute_corner_normals");
  const Arrays a(mesh);
  const std::vector<Vec3> unit = unit_face_normals(a);
  const std::size_t nv = mesh.vertex_slots(), nh = mesh.halfedge_slots();
  const Face* face = mesh.halfedge_face_array().data();
  const float cos_crease = float(std::cos(crease_degrees * std::numbers::pi / 180));
  // A vertex whose faces form one wedge all round (no boundary or crease edge at it), the common
  // case, gets the normal compute_vertex_normals gives it: the sum over its faces in face order.
  std::vector<Vec3> smooth(nv, Vec3{0, 0, 0});
  scatter_face_normals(a, weighting, smooth.data(), unit.data());
  for (Vec3& n : smooth) n = unit_or_zero_float(n);
  // The other vertices: an end of a boundary edge, or of a crease edge, where the two faces'
  // normals differ by more than the crease angle (180 degrees keeps every edge smooth, even
  // between faces of opposite normals).
  std::vector<char> split(nv, 0);
  for (std::size_t h = 0; h < nh; h += 2) {
    if (a.garbage && mesh.is_deleted(Halfedge(Index(h)))) continue;
    const Face fa = face[h], fb = face[h + 1];
    if (!fa.is_valid() || !fb.is_valid() ||
        (crease_degrees < 180 && dot(unit[fa.idx()], unit[fb.idx()]) < cos_crease))
      split[a.to[h].idx()] = split[a.to[h + 1].idx()] = 1;
  }
  HalfedgeProperty<Vec3> prop = mesh.halfedge_property<Vec3>(name);
  Vec3* out = prop.vector().data();
  for (std::size_t h = 0; h < nh; ++h) {
    if (a.garbage && mesh.is_deleted(Halfedge(Index(h)))) continue;
    const Index v = a.to[h].idx();
    // Boundary half-edges (no face) get zero; the corners of split vertices are written below.
    out[h] = face[h].is_valid() && !split[v] ? smooth[v] : Vec3{0, 0, 0};
  }
  // What face(in) adds at the corner where `in` ends.
  auto contribution = [&](Index in) {
    const Index f = face[in].idx();
    switch (weighting) {
      case NormalWeighting::area:
        return area_vector_float(a, a.fhe[f].idx());
      case NormalWeighting::uniform:
        return unit[f];
      case NormalWeighting::angle:
        break;
    }
    return unit[f] * corner_angle_at(a, in);
  };
  const Halfedge* vertex_halfedge = mesh.vertex_halfedge_array().data();
  std::vector<Index> outs;  // the half-edges leaving v, in rotation order
  std::vector<Index> ins;   // ins[i]: the half-edge entering v in face(outs[i]) (or its gap)
  std::vector<char> cut;    // cut[i]: a wedge ends between face(ins[i - 1]) and face(ins[i])
  for (std::size_t v = 0; v < nv; ++v) {
    if (!split[v]) continue;  // isolated and deleted vertices are never split
    outs.clear();
    const Index o0 = vertex_halfedge[v].idx();
    Index o = o0;
    do {
      outs.push_back(o);
      o = a.next[o ^ 1u].idx();  // rotate clockwise: next(twin(o))
    } while (o != o0);
    // next(twin(outs[i - 1])) is outs[i]: twin(outs[i - 1]) enters v in face(outs[i]).
    const std::size_t k = outs.size();
    ins.resize(k);
    ins[0] = outs[k - 1] ^ 1u;
    for (std::size_t i = 1; i < k; ++i) ins[i] = outs[i - 1] ^ 1u;
    cut.assign(k, 0);
    std::size_t start = k;  // the first cut; split vertices have one
    for (std::size_t i = 0; i < k; ++i) {
      const Face fa = face[ins[i == 0 ? k - 1 : i - 1]], fb = face[ins[i]];
      cut[i] = !fa.is_valid() || !fb.is_valid() ||
               (crease_degrees < 180 && dot(unit[fa.idx()], unit[fb.idx()]) < cos_crease);
      if (cut[i] && start == k) start = i;
    }
    // Walk the ring once from the first cut, closing a wedge at each cut.
    auto at = [&](std::size_t s) { return start + s < k ? start + s : start + s - k; };  // s steps on
    std::size_t wedge_begin = 0;  // in steps from start
    Vec3 sum{0, 0, 0};
    auto close_wedge = [&](std::size_t end) {
      const Vec3 normal = unit_or_zero_float(sum);
      for (std::size_t s = wedge_begin; s < end; ++s) {
        const Index in = ins[at(s)];
        if (face[in].is_valid()) out[in] = normal;
      }
      sum = Vec3{0, 0, 0};
      wedge_begin = end;
    };
    for (std::size_t s = 0; s < k; ++s) {
      const std::size_t i = at(s);
      if (s > 0 && cut[i]) close_wedge(s);
      if (face[ins[i]].is_valid()) sum += contribution(ins[i]);
    }
    close_wedge(k);
  }
  mark_all_faces(mesh);
  return prop;
}

}  // namespace hedge

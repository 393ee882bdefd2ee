#include "hedge/algorithms/normals.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

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

Vec3 cross3(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
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
  const Vec3 p0 = a.p[a.to[h0].idx()];
  return cross3(a.p[a.to[h1].idx()] - p0, a.p[a.to[h2].idx()] - p0);
}

inline Vec3 unit_or_zero_float(const Vec3& n) {
  const float l = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return l > 0 && std::isfinite(l) ? n * (1.f / l) : Vec3{0, 0, 0};
}

// The angle of the face at the corner where half-edge `in` ends, between the edges back to
// from(in) and on to to(next(in)).
float corner_angle_at(const Arrays& a, Index in) {
  const Vec3d v = to_double(a.p[a.to[in].idx()]);
  const Vec3d x = to_double(a.p[a.m.from_vertex(Halfedge(in)).idx()]) - v;
  const Vec3d y = to_double(a.p[a.to[a.next[in].idx()].idx()]) - v;
  const double s = norm(cross(x, y)), c = dot(x, y);
  return float((s > 0 || c != 0) ? std::atan2(s, c) : 0.0);
}

// Adds to sum[to(h)], for every corner of every live face (h entering the corner), the face's
// contribution: its Newell vector (area), its unit normal (uniform) or its unit normal times the
// corner's angle (angle). One pass over the faces, in face order, so the sums are the same on
// every run; triangles weighted by area, the common case, take a path of their own.
void scatter_face_normals(const Arrays& a, NormalWeighting w, Vec3* sum) {
  for (std::size_t f = 0; f < a.n_faces; ++f) {
    if (!a.live(f)) continue;
    const Index h0 = a.fhe[f].idx(), h1 = a.next[h0].idx(), h2 = a.next[h1].idx();
    if (w == NormalWeighting::area && a.next[h2].idx() == h0) {
      const Index i0 = a.to[h0].idx(), i1 = a.to[h1].idx(), i2 = a.to[h2].idx();
      const Vec3 p0 = a.p[i0], n = cross3(a.p[i1] - p0, a.p[i2] - p0);
      sum[i0] += n;
      sum[i1] += n;
      sum[i2] += n;
      continue;
    }
    Vec3 n = area_vector_float(a, h0);
    if (w != NormalWeighting::area) n = unit_or_zero_float(n);
    Index h = h0;
    do {
      sum[a.to[h].idx()] += w == NormalWeighting::angle ? n * corner_angle_at(a, h) : n;
      h = a.next[h].idx();
    } while (h != h0);
  }
}

// Unit normals of every face slot, in float (zero for deleted and degenerate faces).
std::vector<Vec3> unit_face_normals(const Arrays& a) {
  std::vector<Vec3> n(a.n_faces, Vec3{0, 0, 0});
  for (std::size_t f = 0; f < a.n_faces; ++f)
    if (a.live(f)) n[f] = unit_or_zero_float(area_vector_float(a, a.fhe[f].idx()));
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
  const Arrays a(mesh);
  Vec3* out = prop.vector().data();
  for (std::size_t f = 0; f < a.n_faces; ++f)
    if (a.live(f)) out[f] = unit_or_zero_float(area_vector_float(a, a.fhe[f].idx()));
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
  std::vector<Vec3> area;
  if (weighting == NormalWeighting::area) {
    area.assign(a.n_faces, Vec3{0, 0, 0});
    for (std::size_t f = 0; f < a.n_faces; ++f)
      if (a.live(f)) area[f] = area_vector_float(a, a.fhe[f].idx());
  }
  const float cos_crease = float(std::cos(crease_degrees * std::numbers::pi / 180));
  HalfedgeProperty<Vec3> prop = mesh.halfedge_property<Vec3>(name);
  Vec3* out = prop.vector().data();
  const Face* face = mesh.halfedge_face_array().data();
  // What face(in) adds at the corner where `in` ends.
  auto contribution = [&](Index in) {
    const Index f = face[in].idx();
    switch (weighting) {
      case NormalWeighting::area:
        return area[f];
      case NormalWeighting::uniform:
        return unit[f];
      case NormalWeighting::angle:
        break;
    }
    return unit[f] * corner_angle_at(a, in);
  };
  std::vector<Index> ins;  // the half-edges entering v, in rotation order
  std::vector<char> cut;   // cut[i]: a wedge ends between face(ins[i - 1]) and face(ins[i])
  for (Vertex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    ins.clear();
    for (Halfedge o : mesh.halfedges(v)) ins.push_back(SurfaceMesh::twin(o).idx());
    // With o_i the outgoing half-edges in rotation order, face(o_i) is entered by twin(o_{i-1}):
    // rotated by one, ins[i] is the corner of face(o_i).
    const std::size_t k = ins.size();
    std::rotate(ins.begin(), ins.end() - 1, ins.end());
    cut.assign(k, 0);
    bool any_cut = false;
    for (std::size_t i = 0; i < k; ++i) {
      const Face fa = face[ins[(i + k - 1) % k]], fb = face[ins[i]];
      // 180 degrees keeps every edge smooth, even between faces of opposite normals.
      cut[i] = !fa.is_valid() || !fb.is_valid() ||
               (crease_degrees < 180 && dot(unit[fa.idx()], unit[fb.idx()]) < cos_crease);
      any_cut = any_cut || cut[i];
    }
    // Walk the ring once from a cut (or anywhere, for a single wedge), closing a wedge at each cut.
    std::size_t start = 0;
    if (any_cut)
      while (!cut[start]) ++start;
    std::size_t wedge_begin = 0;  // in steps from start
    Vec3 sum{0, 0, 0};
    auto close_wedge = [&](std::size_t end) {
      const Vec3 normal = unit_or_zero_float(sum);
      for (std::size_t s = wedge_begin; s < end; ++s) {
        const Index in = ins[(start + s) % k];
        if (face[in].is_valid()) out[in] = normal;
      }
      sum = Vec3{0, 0, 0};
      wedge_begin = end;
    };
    for (std::size_t s = 0; s < k; ++s) {
      const std::size_t i = (start + s) % k;
      if (s > 0 && cut[i]) close_wedge(s);
      if (face[ins[i]].is_valid()) sum += contribution(ins[i]);
    }
    close_wedge(k);
  }
  for (Halfedge h : mesh.halfedges())
    if (mesh.is_boundary(h)) out[h.idx()] = Vec3{0, 0, 0};
  mark_all_faces(mesh);
  return prop;
}

}  // namespace hedge

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

// Unit and area normals of every face slot.
struct FaceNormals {
  std::vector<Vec3d> unit, area;
};
FaceNormals all_face_normals(const SurfaceMesh& m) {
  FaceNormals n;
  n.unit.assign(m.face_slots(), Vec3d{0, 0, 0});
  n.area.assign(m.face_slots(), Vec3d{0, 0, 0});
  for (Face f : m.faces()) {
    n.area[f.idx()] = area_vector(m, f);
    n.unit[f.idx()] = unit_or_zero(n.area[f.idx()]);
  }
  return n;
}

// What face F adds to the normal at its corner where `out` (leaving v, in F) starts and `in`
// (entering v, in F) ends.
Vec3d weighted(const SurfaceMesh& m, const FaceNormals& n, Face f, Halfedge out, Halfedge in,
               NormalWeighting w) {
  switch (w) {
    case NormalWeighting::area:
      return n.area[f.idx()];
    case NormalWeighting::uniform:
      return n.unit[f.idx()];
    case NormalWeighting::angle:
      break;
  }
  const Vec3d v = to_double(m.position(m.from_vertex(out)));
  const double a =
      corner_angle(v, to_double(m.position(m.to_vertex(out))), to_double(m.position(m.from_vertex(in))));
  return n.unit[f.idx()] * a;
}

}  // namespace

Vec3 face_normal(const SurfaceMesh& mesh, Face f) { return to_float(unit_or_zero(area_vector(mesh, f))); }

FaceProperty<Vec3> compute_face_normals(SurfaceMesh& mesh, std::string_view name) {
  require_finite_positions(mesh, "compute_face_normals");
  FaceProperty<Vec3> prop = mesh.face_property<Vec3>(name);
  for (Face f : mesh.faces()) {
    prop[f] = face_normal(mesh, f);
    mesh.mark_changed(f, ChangeEvent::faces_changed);
  }
  mesh.changes().notify();
  return prop;
}

VertexProperty<Vec3> compute_vertex_normals(SurfaceMesh& mesh, NormalWeighting weighting,
                                            std::string_view name) {
  require_finite_positions(mesh, "compute_vertex_normals");
  const FaceNormals n = all_face_normals(mesh);
  VertexProperty<Vec3> prop = mesh.vertex_property<Vec3>(name);
  for (Vertex v : mesh.vertices()) {
    Vec3d sum{0, 0, 0};
    if (!mesh.is_isolated(v)) {
      // Outgoing half-edges o_i in rotation order: face(o_i) holds o_i and, entering v, twin(o_{i-1}).
      Halfedge prev_out;
      Halfedge first;
      for (Halfedge o : mesh.halfedges(v)) {
        if (!first.is_valid()) first = o;
        if (prev_out.is_valid() && mesh.face(o).is_valid())
          sum += weighted(mesh, n, mesh.face(o), o, SurfaceMesh::twin(prev_out), weighting);
        prev_out = o;
      }
      if (mesh.face(first).is_valid())
        sum += weighted(mesh, n, mesh.face(first), first, SurfaceMesh::twin(prev_out), weighting);
    }
    prop[v] = to_float(unit_or_zero(sum));
    mesh.mark_changed(v, ChangeEvent::vertex_data_changed);
  }
  mesh.changes().notify();
  return prop;
}

HalfedgeProperty<Vec3> compute_corner_normals(SurfaceMesh& mesh, double crease_degrees,
                                              NormalWeighting weighting, std::string_view name) {
  if (!(crease_degrees >= 0 && crease_degrees <= 180))
    throw InvalidInputError("compute_corner_normals: the crease angle must be in [0, 180] degrees, got " +
                            std::to_string(crease_degrees));
  require_finite_positions(mesh, "compute_corner_normals");
  const FaceNormals n = all_face_normals(mesh);
  const double cos_crease = std::cos(crease_degrees * std::numbers::pi / 180);
  HalfedgeProperty<Vec3> prop = mesh.halfedge_property<Vec3>(name);
  std::vector<Halfedge> outs;
  std::vector<char> cut;  // cut[i]: a wedge ends between face(outs[i - 1]) and face(outs[i])
  for (Vertex v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    outs.clear();
    for (Halfedge o : mesh.halfedges(v)) outs.push_back(o);
    const std::size_t k = outs.size();
    cut.assign(k, 0);
    bool any_cut = false;
    for (std::size_t i = 0; i < k; ++i) {
      const Face a = mesh.face(outs[(i + k - 1) % k]), b = mesh.face(outs[i]);
      // 180 degrees keeps every edge smooth, even between faces of opposite normals.
      cut[i] = !a.is_valid() || !b.is_valid() ||
               (crease_degrees < 180 && dot(n.unit[a.idx()], n.unit[b.idx()]) < cos_crease);
      any_cut = any_cut || cut[i];
    }
    // Walk the ring once from a cut (or anywhere, for a single wedge), closing a wedge at each cut.
    std::size_t start = 0;
    if (any_cut)
      while (!cut[start]) ++start;
    std::size_t wedge_begin = 0;  // in steps from start
    Vec3d sum{0, 0, 0};
    auto close_wedge = [&](std::size_t end) {
      const Vec3 normal = to_float(unit_or_zero(sum));
      for (std::size_t s = wedge_begin; s < end; ++s) {
        const std::size_t i = (start + s) % k;
        if (mesh.face(outs[i]).is_valid()) prop[SurfaceMesh::twin(outs[(i + k - 1) % k])] = normal;
      }
      sum = Vec3d{0, 0, 0};
      wedge_begin = end;
    };
    for (std::size_t s = 0; s < k; ++s) {
      const std::size_t i = (start + s) % k;
      if (s > 0 && cut[i]) close_wedge(s);
      const Face f = mesh.face(outs[i]);
      if (f.is_valid())
        sum += weighted(mesh, n, f, outs[i], SurfaceMesh::twin(outs[(i + k - 1) % k]), weighting);
    }
    close_wedge(k);
  }
  for (Halfedge h : mesh.halfedges())
    if (mesh.is_boundary(h)) prop[h] = Vec3{0, 0, 0};
  for (Face f : mesh.faces()) mesh.mark_changed(f, ChangeEvent::faces_changed);
  mesh.changes().notify();
  return prop;
}

}  // namespace hedge

// hedge backend: build_triangles with default options (strict policy, no welding), then the same
// operations as the peers through hedge's idiomatic circulators.
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bench_common.h"
#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/operations.h"
#include "hedge/core/surface_mesh.h"

namespace bench {
namespace {

static_assert(sizeof(hedge::Vec3) == 3 * sizeof(float), "Vec3 must be three packed floats");

struct HBox final : MeshBox {
  explicit HBox(hedge::SurfaceMesh&& mesh) : m(std::move(mesh)) {}
  hedge::SurfaceMesh m;
  std::size_t n_vertices() const override { return m.n_vertices(); }
  std::size_t n_faces() const override { return m.n_faces(); }
  std::size_t own_memory_bytes() const override { return m.memory_bytes(); }
};

const hedge::SurfaceMesh& mesh_of(Context& c) { return static_cast<HBox*>(c.mesh)->m; }
F3 f3(const hedge::Vec3& p) { return {p.x, p.y, p.z}; }

std::unique_ptr<MeshBox> build(const Input& in) {
  // The float x3 array is viewed as Vec3 (same layout): no conversion.
  std::span<const hedge::Vec3> positions(reinterpret_cast<const hedge::Vec3*>(in.xyz.data()),
                                         in.n_vertices());
  return std::make_unique<HBox>(hedge::build_triangles(positions, in.tri));
}

double build_op(Context& c) {
  c.out = build(c.input);
  return static_cast<double>(c.out->n_vertices() + c.out->n_faces());
}

double one_ring(Context& c) {
  const hedge::SurfaceMesh& m = mesh_of(c);
  double sum = 0;
  for (hedge::Vertex v : m.vertices()) {
    RingSum r;
    for (hedge::Vertex u : m.vertices(v)) {
      const hedge::Vec3& p = m.position(u);
      r.add(p.x, p.y, p.z);
    }
    sum += r.total();
  }
  return sum;
}

double vertex_normals(Context& c) {
  const hedge::SurfaceMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  float* vn = c.scratch.vertex_normal.data();
  for (hedge::Face f : m.faces()) {
    auto it = m.vertices(f).begin();
    F3 p0 = f3(m.position(*it));
    ++it;
    F3 p1 = f3(m.position(*it));
    ++it;
    F3 p2 = f3(m.position(*it));
    store(fn, f.idx(), area_normal(p0, p1, p2));
  }
  double sum = 0;
  for (hedge::Vertex v : m.vertices()) {
    F3 n{0, 0, 0};
    for (hedge::Face f : m.faces(v)) n += load(fn, f.idx());
    n = normalized(n);
    store(vn, v.idx(), n);
    sum += abs_sum(n);
  }
  return sum;
}

// ---- Random local edits: the same draws as the peers (EditRng), on a private copy. ----
// (copy_mesh below also serves the subdivision, which refines a private copy.)

std::unique_ptr<MeshBox> copy_mesh(const MeshBox& reference) {
  return std::make_unique<HBox>(hedge::SurfaceMesh(static_cast<const HBox&>(reference).m));
}
hedge::SurfaceMesh& edit_mesh(Context& c) { return static_cast<HBox*>(c.mesh)->m; }

//! The library's own call, compute_vertex_normals(area), into "v:normal" of a private copy that
//! already has the property (as the peers' normals are requested before the timer).
std::unique_ptr<MeshBox> copy_with_normals(const MeshBox& reference) {
  auto box = std::make_unique<HBox>(hedge::SurfaceMesh(static_cast<const HBox&>(reference).m));
  hedge::compute_vertex_normals(box->m);
  return box;
}
double builtin_vertex_normals(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  const hedge::VertexProperty<hedge::Vec3> n = hedge::compute_vertex_normals(m, hedge::NormalWeighting::area);
  float* vn = c.scratch.vertex_normal.data();
  double sum = 0;
  for (hedge::Vertex v : m.vertices()) {
    store(vn, v.idx(), f3(n[v]));
    sum += abs_sum(f3(n[v]));
  }
  return sum;
}

//! Face normals over the public API: Newell's vector of a triangle, normalised, into the scratch
//! array. Returns the sum of |x| + |y| + |z| of the unit normals.
double face_normals(Context& c) {
  const hedge::SurfaceMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  double sum = 0;
  for (hedge::Face f : m.faces()) {
    const hedge::Halfedge h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const F3 n = normalized(area_normal(f3(m.position(m.to_vertex(h0))), f3(m.position(m.to_vertex(h1))),
                                        f3(m.position(m.to_vertex(h2)))));
    store(fn, f.idx(), n);
    sum += abs_sum(n);
  }
  return sum;
}

//! The library's own compute_face_normals into "f:normal" of a private copy that already has it.
std::unique_ptr<MeshBox> copy_with_face_normals(const MeshBox& reference) {
  auto box = std::make_unique<HBox>(hedge::SurfaceMesh(static_cast<const HBox&>(reference).m));
  hedge::compute_face_normals(box->m);
  return box;
}
double builtin_face_normals(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  const hedge::FaceProperty<hedge::Vec3> n = hedge::compute_face_normals(m);
  double sum = 0;
  for (hedge::Face f : m.faces()) sum += abs_sum(f3(n[f]));
  return sum;
}

//! Corner normals over the public API, as OpenMesh's update_halfedge_normals computes them: per
//! corner, the sum of the unit normals of the faces of its wedge (the faces around the vertex
//! between crease or boundary edges), normalised, stored per half-edge; the face normals are
//! computed first. Returns the sum of |x| + |y| + |z| over the corners.
double corner_normals(Context& c) {
  const hedge::SurfaceMesh& m = mesh_of(c);
  face_normals(c);
  const float* fn = c.scratch.face_normal.data();
  float* out = c.scratch.corner_normal.data();
  const float cos_crease = static_cast<float>(std::cos(kCornerCreaseDegrees * 3.14159265358979323846 / 180));
  auto crease = [&](hedge::Halfedge h) {  // between face(h) and face(twin(h))
    const hedge::Face a = m.face(h), b = m.face(hedge::SurfaceMesh::twin(h));
    if (!a.is_valid() || !b.is_valid()) return true;
    const F3 p = load(fn, a.idx()), q = load(fn, b.idx());
    return p.x * q.x + p.y * q.y + p.z * q.z < cos_crease;
  };
  double sum = 0;
  std::vector<hedge::Halfedge> ring;  // the corners at v: prev(o) for each outgoing o, clockwise
  for (hedge::Vertex v : m.vertices()) {
    ring.clear();
    for (hedge::Halfedge o : m.halfedges(v)) ring.push_back(m.prev(o));
    const std::size_t k = ring.size();
    // ring[i] is twin(o_{i-1}): its edge lies between face(ring[i - 1]) and face(ring[i]).
    std::size_t start = 0;
    for (std::size_t i = 0; i < k; ++i)
      if (crease(ring[i])) {
        start = i;
        break;
      }
    for (std::size_t s = 0; s < k;) {
      std::size_t e = s;
      F3 n{0, 0, 0};
      do {
        const hedge::Face f = m.face(ring[(start + e) % k]);
        if (f.is_valid()) n += load(fn, f.idx());
        ++e;
      } while (e < k && !crease(ring[(start + e) % k]));
      n = normalized(n);
      for (std::size_t t = s; t < e; ++t) {
        const hedge::Halfedge h = ring[(start + t) % k];
        if (!m.face(h).is_valid()) continue;
        store(out, h.idx(), n);
        sum += abs_sum(n);
      }
      s = e;
    }
  }
  return sum;
}

//! The library's own compute_corner_normals (uniform weighting, as OpenMesh's) into "h:normal" of a
//! private copy that already has it.
std::unique_ptr<MeshBox> copy_with_corner_normals(const MeshBox& reference) {
  auto box = std::make_unique<HBox>(hedge::SurfaceMesh(static_cast<const HBox&>(reference).m));
  hedge::compute_corner_normals(box->m, kCornerCreaseDegrees, hedge::NormalWeighting::uniform);
  return box;
}
double builtin_corner_normals(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  const hedge::HalfedgeProperty<hedge::Vec3> n =
      hedge::compute_corner_normals(m, kCornerCreaseDegrees, hedge::NormalWeighting::uniform);
  double sum = 0;
  for (hedge::Halfedge h : m.halfedges())
    if (!m.is_boundary(h)) sum += abs_sum(f3(n[h]));
  return sum;
}

//! Ten smoothing iterations (lambda 0.5, boundary fixed) of the private copy. Returns the sum of
//! |x| + |y| + |z| over the vertices after.
template <hedge::SmoothMethod method>
double smooth_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  hedge::SmoothOptions o;
  o.method = method;
  o.iterations = 10;
  hedge::smooth(m, o);
  double sum = 0;
  for (hedge::Vertex v : m.vertices())
    sum += std::abs(m.position(v).x) + std::abs(m.position(v).y) + std::abs(m.position(v).z);
  return sum;
}

//! One step of Catmull-Clark on the private copy (of a triangle mesh: 3 quads a triangle).
double catmull_clark_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  hedge::subdivide(m, hedge::Subdivision::catmull_clark, 1);
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! A private copy made all quads by one untimed Catmull-Clark step: the input of catmull_clark_quads.
std::unique_ptr<MeshBox> quad_copy(const MeshBox& reference) {
  auto box = std::make_unique<HBox>(hedge::SurfaceMesh(static_cast<const HBox&>(reference).m));
  hedge::subdivide(box->m, hedge::Subdivision::catmull_clark, 1);
  return box;
}

//! `steps` steps of Kobbelt's sqrt(3) scheme in one call on the private copy. Returns #V + #F after.
template <int steps>
double sqrt3_op(Context& c) {
  hedge::SurfaceMesh& m = static_cast<HBox*>(c.mesh)->m;
  hedge::subdivide(m, hedge::Subdivision::sqrt3, steps);
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! One step of Loop's subdivision of the private copy. Returns #V + #F after.
double loop_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  hedge::subdivide(m, hedge::Subdivision::loop, 1);
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! Random half-edge (deleted ones redrawn), can_collapse, then collapse: from_vertex(h) merges into
//! to_vertex(h), which keeps its position. Returns the number of collapses done.
hedge::Halfedge halfedge_at(std::size_t i) { return hedge::Halfedge(static_cast<hedge::Index>(i)); }
hedge::Edge edge_at(std::size_t i) { return hedge::Edge(static_cast<hedge::Index>(i)); }

double collapse_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  return static_cast<double>(edit_sequence(
      [&] { return m.halfedge_slots(); }, [&](std::size_t j) { return m.is_deleted(halfedge_at(j)); },
      [&](std::size_t i) {
        const hedge::Halfedge h = halfedge_at(i);
        return hedge::can_collapse(m, h) && hedge::collapse(m, h).is_valid();
      }));
}

//! Random edge (among the current ones: the count grows), split at its midpoint: the triangle on
//! each side becomes two. Returns #V + #F after the sequence.
double split_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  edit_sequence([&] { return m.edge_slots(); }, [&](std::size_t j) { return m.is_deleted(edge_at(j)); },
                [&](std::size_t i) {
                  const hedge::Edge e = edge_at(i);
                  const hedge::Halfedge h = hedge::SurfaceMesh::halfedge(e, 0);
                  const hedge::Vec3& a = m.position(m.from_vertex(h));
                  const hedge::Vec3& b = m.position(m.to_vertex(h));
                  const hedge::Vec3 mid{0.5f * (a.x + b.x), 0.5f * (a.y + b.y), 0.5f * (a.z + b.z)};
                  hedge::split_edge(m, e, mid);
                  return true;
                });
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! Random edge, can_flip, then flip. Returns the number of flips done.
double flip_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  return static_cast<double>(
      edit_sequence([&] { return m.edge_slots(); }, [&](std::size_t j) { return m.is_deleted(edge_at(j)); },
                    [&](std::size_t i) {
                      return hedge::can_flip(m, edge_at(i)) && hedge::flip(m, edge_at(i)).is_valid();
                    }));
}

//! decimate() with its default options down to the common target vertex count
//! (decimate_target_vertices). Returns the vertices left.
double decimate_op(Context& c) {
  hedge::SurfaceMesh& m = edit_mesh(c);
  hedge::DecimateOptions o;
  o.target_vertices = decimate_target_vertices(c.input);
  return static_cast<double>(hedge::decimate(m, o).vertices);
}

//! Live vertices and faces, renumbered in order.
Input decimate_result(const MeshBox& edited) {
  const hedge::SurfaceMesh& m = static_cast<const HBox&>(edited).m;
  Input out;
  std::vector<std::uint32_t> index(m.vertex_slots(), UINT32_MAX);
  for (hedge::Vertex v : m.vertices()) {
    index[v.idx()] = static_cast<std::uint32_t>(out.n_vertices());
    const hedge::Vec3& p = m.position(v);
    out.xyz.insert(out.xyz.end(), {p.x, p.y, p.z});
  }
  for (hedge::Face f : m.faces())
    for (hedge::Vertex v : m.vertices(f)) out.tri.push_back(index[v.idx()]);
  return out;
}

std::string check_decimate(const MeshBox&, const MeshBox& edited, double) {
  const std::vector<std::string> problems = static_cast<const HBox&>(edited).m.validate();
  return problems.empty()
             ? ""
             : "validate(): " + std::to_string(problems.size()) + " problem(s), first: " + problems.front();
}

Counts counts(const hedge::SurfaceMesh& m) { return {m.n_vertices(), m.n_edges(), m.n_faces()}; }

template <EditKind kind>
std::string check_edit(const MeshBox& reference, const MeshBox& edited, double checksum) {
  const hedge::SurfaceMesh& before = static_cast<const HBox&>(reference).m;
  const hedge::SurfaceMesh& after = static_cast<const HBox&>(edited).m;
  std::string err;
  const std::vector<std::string> problems = after.validate();
  if (!problems.empty())
    err = "validate(): " + std::to_string(problems.size()) + " problem(s), first: " + problems.front() + "; ";
  return err + check_edit_counts(kind, counts(before), counts(after), checksum);
}

}  // namespace

Backend hedge_backend() {
  Backend b;
  b.label = "hedge";
  b.key = "hedge";
  b.notes =
      "hedge: build_triangles, default options (strict, no weld), float positions; decimation: decimate() "
      "with its default options and target_vertices";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  b.ops["vertex_normals_builtin"] = {copy_with_normals, builtin_vertex_normals};
  b.ops["face_normals"] = {copy_mesh, face_normals};
  b.ops["face_normals_builtin"] = {copy_with_face_normals, builtin_face_normals};
  b.ops["corner_normals"] = {copy_mesh, corner_normals};
  b.ops["corner_normals_builtin"] = {copy_with_corner_normals, builtin_corner_normals};
  b.ops["collapse"] = {copy_mesh, collapse_op, check_edit<EditKind::collapse>};
  b.ops["split"] = {copy_mesh, split_op, check_edit<EditKind::split>};
  b.ops["flip"] = {copy_mesh, flip_op, check_edit<EditKind::flip>};
  b.ops["loop"] = {copy_mesh, loop_op};
  b.ops["catmull_clark"] = {copy_mesh, catmull_clark_op};
  b.ops["catmull_clark_quads"] = {quad_copy, catmull_clark_op};
  b.ops["sqrt3"] = {copy_mesh, sqrt3_op<1>, nullptr, decimate_result};
  b.ops["sqrt3_two"] = {copy_mesh, sqrt3_op<2>, nullptr, decimate_result};
  b.ops["smooth_uniform"] = {copy_mesh, smooth_op<hedge::SmoothMethod::uniform>};
  b.ops["smooth_cotan"] = {copy_mesh, smooth_op<hedge::SmoothMethod::cotangent>};
  b.ops["decimate"] = {copy_mesh, decimate_op, check_decimate, decimate_result};
  return b;
}

}  // namespace bench

// OpenMesh backend: TriMesh_ArrayKernelT with default traits (float Vec3f points), used through its
// public API only. Built the standard way: reserve, add_vertex for every vertex, add_face for
// every triangle.
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>
#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_common.h"

namespace bench {
namespace {

using OMesh = OpenMesh::TriMesh_ArrayKernelT<>;

struct OMBox final : MeshBox {
  OMesh m;
  std::size_t n_vertices() const override { return m.n_vertices(); }
  std::size_t n_faces() const override { return m.n_faces(); }
};

OMesh& mesh_of(Context& c) { return static_cast<OMBox*>(c.mesh)->m; }

// Catmull-Clark needs OpenMesh's polygon mesh type.
using OPolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;
struct OPolyBox final : MeshBox {
  OPolyMesh m;
  std::size_t n_vertices() const override { return m.n_vertices(); }
  std::size_t n_faces() const override { return m.n_faces(); }
};

void catmull_clark_step(OPolyMesh& m) {
  OpenMesh::Subdivider::Uniform::CatmullClarkT<OPolyMesh> cc;
  cc.attach(m);
  cc(1);
  cc.detach();
}

//! The reference triangle mesh as a polygon mesh, made all quads by one untimed Catmull-Clark
//! step: the input of catmull_clark_quads.
std::unique_ptr<MeshBox> quad_copy(const MeshBox& reference) {
  const OMesh& t = static_cast<const OMBox&>(reference).m;
  auto box = std::make_unique<OPolyBox>();
  OPolyMesh& m = box->m;
  m.reserve(t.n_vertices(), t.n_edges(), t.n_faces());
  for (OMesh::VertexHandle v : t.vertices()) m.add_vertex(t.point(v));
  std::vector<OPolyMesh::VertexHandle> corners;
  for (OMesh::FaceHandle f : t.faces()) {
    corners.clear();
    for (OMesh::VertexHandle v : t.fv_range(f)) corners.push_back(OPolyMesh::VertexHandle(v.idx()));
    m.add_face(corners);
  }
  catmull_clark_step(m);
  return box;
}

//! One Catmull-Clark step of the quad mesh. Returns #V + #F after.
double catmull_clark_quads_op(Context& c) {
  OPolyMesh& m = static_cast<OPolyBox*>(c.mesh)->m;
  catmull_clark_step(m);
  return static_cast<double>(m.n_vertices() + m.n_faces());
}
F3 f3(const OMesh::Point& p) { return {p[0], p[1], p[2]}; }

std::unique_ptr<MeshBox> build(const Input& in) {
  auto box = std::make_unique<OMBox>();
  OMesh& m = box->m;
  const std::size_t nv = in.n_vertices(), nf = in.n_faces();
  m.reserve(nv, (3 * nf + 1) / 2, nf);  // exact for a closed triangle mesh
  for (std::size_t i = 0; i < nv; ++i)
    m.add_vertex(OMesh::Point(in.xyz[3 * i], in.xyz[3 * i + 1], in.xyz[3 * i + 2]));
  for (std::size_t f = 0; f < nf; ++f)
    m.add_face(OMesh::VertexHandle(static_cast<int>(in.tri[3 * f])),
               OMesh::VertexHandle(static_cast<int>(in.tri[3 * f + 1])),
               OMesh::VertexHandle(static_cast<int>(in.tri[3 * f + 2])));
  return box;
}

double build_op(Context& c) {
  c.out = build(c.input);
  return static_cast<double>(c.out->n_vertices() + c.out->n_faces());
}

double one_ring(Context& c) {
  const OMesh& m = mesh_of(c);
  double sum = 0;
  for (OMesh::VertexHandle v : m.vertices()) {
    RingSum r;
    for (OMesh::VertexHandle u : m.vv_range(v)) {
      const OMesh::Point& p = m.point(u);
      r.add(p[0], p[1], p[2]);
    }
    sum += r.total();
  }
  return sum;
}

double vertex_normals(Context& c) {
  const OMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  float* vn = c.scratch.vertex_normal.data();
  for (OMesh::FaceHandle f : m.faces()) {
    auto it = m.cfv_iter(f);
    F3 p0 = f3(m.point(*it));
    ++it;
    F3 p1 = f3(m.point(*it));
    ++it;
    F3 p2 = f3(m.point(*it));
    store(fn, f.idx(), area_normal(p0, p1, p2));
  }
  double sum = 0;
  for (OMesh::VertexHandle v : m.vertices()) {
    F3 n{0, 0, 0};
    for (OMesh::FaceHandle f : m.vf_range(v)) n += load(fn, f.idx());
    n = normalized(n);
    store(vn, v.idx(), n);
    sum += abs_sum(n);
  }
  return sum;
}

// ---- Random local edits: the same draws as hedge (EditRng), on a private copy. ----

//! A copy with the status attributes that collapse, is_collapse_ok and deleted-element tests need
//! (requested before the timer starts).
std::unique_ptr<MeshBox> copy_mesh(const MeshBox& reference) {
  auto box = std::make_unique<OMBox>();
  box->m = static_cast<const OMBox&>(reference).m;
  box->m.request_vertex_status();
  box->m.request_edge_status();
  box->m.request_halfedge_status();
  box->m.request_face_status();
  return box;
}

//! Random half-edge (deleted ones redrawn), is_collapse_ok, then collapse: from_vertex_handle(h)
//! merges into to_vertex_handle(h), which keeps its position. Returns the number of collapses done.
OMesh::HalfedgeHandle halfedge_at(std::size_t i) { return OMesh::HalfedgeHandle(static_cast<int>(i)); }
OMesh::EdgeHandle edge_at(std::size_t i) { return OMesh::EdgeHandle(static_cast<int>(i)); }

double collapse_op(Context& c) {
  OMesh& m = mesh_of(c);
  // n_halfedges() includes deleted ones until garbage_collection.
  return static_cast<double>(edit_sequence([&] { return m.n_halfedges(); },
                                           [&](std::size_t j) { return m.status(halfedge_at(j)).deleted(); },
                                           [&](std::size_t i) {
                                             if (!m.is_collapse_ok(halfedge_at(i))) return false;
                                             m.collapse(halfedge_at(i));
                                             return true;
                                           }));
}

//! Random edge (among the current ones), TriMesh split(eh, point) = add_vertex + the 2-to-4 split
//! (TriConnectivity::split, what TriMesh split_edge(eh, vh) calls): the triangle on each side
//! becomes two, as in hedge. Returns #V + #F after the sequence.
double split_op(Context& c) {
  OMesh& m = mesh_of(c);
  edit_sequence([&] { return m.n_edges(); }, [&](std::size_t j) { return m.status(edge_at(j)).deleted(); },
                [&](std::size_t i) {
                  const OMesh::EdgeHandle e = edge_at(i);
                  const OMesh::HalfedgeHandle h = m.halfedge_handle(e, 0);
                  const OMesh::Point& a = m.point(m.from_vertex_handle(h));
                  const OMesh::Point& b = m.point(m.to_vertex_handle(h));
                  const OMesh::Point mid(0.5f * (a[0] + b[0]), 0.5f * (a[1] + b[1]), 0.5f * (a[2] + b[2]));
                  m.split(e, mid);
                  return true;
                });
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! Ten iterations of OpenMesh's JacobiLaplaceSmootherT, C0: with uniform weights (Tangential_and_Normal)
//! or with cotangent weights (Normal), the two weightings OpenMesh offers; both move vertices along
//! the whole Laplacian vector (only Tangential projects it). Returns the sum of |x| + |y| + |z| over the
//! vertices after.
template <bool uniform>
double smooth_op(Context& c) {
  OMesh& m = mesh_of(c);
  using Smoother = OpenMesh::Smoother::JacobiLaplaceSmootherT<OMesh>;
  Smoother s(m);
  s.initialize(uniform ? Smoother::Tangential_and_Normal : Smoother::Normal, Smoother::C0);
  s.smooth(10);
  double sum = 0;
  for (auto v : m.vertices())
    sum += std::abs(m.point(v)[0]) + std::abs(m.point(v)[1]) + std::abs(m.point(v)[2]);
  return sum;
}

//! One step of OpenMesh's Subdivider::Uniform::LoopT on the private copy. Returns #V + #F after.
double loop_op(Context& c) {
  OMesh& m = mesh_of(c);
  OpenMesh::Subdivider::Uniform::LoopT<OMesh> loop;
  loop.attach(m);
  loop(1);
  loop.detach();
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! OpenMesh's own update_normals() (face normals, then vertex normals from them) on a private copy
//! whose normals were requested before the timer.
std::unique_ptr<MeshBox> copy_with_normals(const MeshBox& reference) {
  auto box = copy_mesh(reference);
  OMesh& m = static_cast<OMBox*>(box.get())->m;
  m.request_face_normals();
  m.request_vertex_normals();
  return box;
}
double builtin_vertex_normals(Context& c) {
  OMesh& m = mesh_of(c);
  m.update_normals();
  float* vn = c.scratch.vertex_normal.data();
  double sum = 0;
  for (OMesh::VertexHandle v : m.vertices()) {
    const OMesh::Normal& n = m.normal(v);
    store(vn, static_cast<std::size_t>(v.idx()), F3{n[0], n[1], n[2]});
    sum += abs_sum(F3{n[0], n[1], n[2]});
  }
  return sum;
}

//! Face normals over OpenMesh's API (as hedge's face_normals): into the scratch array.
double face_normals(Context& c) {
  const OMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  double sum = 0;
  for (OMesh::FaceHandle f : m.faces()) {
    auto it = m.cfv_iter(f);
    F3 p0 = f3(m.point(*it));
    ++it;
    F3 p1 = f3(m.point(*it));
    ++it;
    F3 p2 = f3(m.point(*it));
    const F3 n = normalized(area_normal(p0, p1, p2));
    store(fn, static_cast<std::size_t>(f.idx()), n);
    sum += abs_sum(n);
  }
  return sum;
}

//! OpenMesh's own update_face_normals() on a private copy whose face normals were requested
//! before the timer.
std::unique_ptr<MeshBox> copy_with_face_normals(const MeshBox& reference) {
  auto box = copy_mesh(reference);
  static_cast<OMBox*>(box.get())->m.request_face_normals();
  return box;
}
double builtin_face_normals(Context& c) {
  OMesh& m = mesh_of(c);
  m.update_face_normals();
  double sum = 0;
  for (OMesh::FaceHandle f : m.faces()) {
    const OMesh::Normal& n = m.normal(f);
    sum += abs_sum(F3{n[0], n[1], n[2]});
  }
  return sum;
}

//! OpenMesh's own corner normals: update_face_normals(), which they are computed from, then
//! update_halfedge_normals(the crease angle in radians), on a private copy whose face and
//! half-edge normals were requested before the timer.
std::unique_ptr<MeshBox> copy_with_corner_normals(const MeshBox& reference) {
  auto box = copy_mesh(reference);
  OMesh& m = static_cast<OMBox*>(box.get())->m;
  m.request_face_normals();
  m.request_halfedge_normals();
  return box;
}
double builtin_corner_normals(Context& c) {
  OMesh& m = mesh_of(c);
  m.update_face_normals();
  m.update_halfedge_normals(kCornerCreaseDegrees * M_PI / 180);
  double sum = 0;
  for (OMesh::HalfedgeHandle h : m.halfedges()) {
    if (m.is_boundary(h)) continue;
    const OMesh::Normal& n = m.normal(h);
    sum += abs_sum(F3{n[0], n[1], n[2]});
  }
  return sum;
}

//! `steps` steps of OpenMesh's Subdivider::Uniform::Sqrt3T in one call on the private copy.
//! Returns #V + #F after.
template <int steps>
double sqrt3_op(Context& c) {
  OMesh& m = mesh_of(c);
  OpenMesh::Subdivider::Uniform::Sqrt3T<OMesh> sqrt3;
  sqrt3.attach(m);
  sqrt3(steps);
  sqrt3.detach();
  return static_cast<double>(m.n_vertices() + m.n_faces());
}

//! Random edge, is_flip_ok, then flip. Returns the number of flips done.
double flip_op(Context& c) {
  OMesh& m = mesh_of(c);
  return static_cast<double>(edit_sequence([&] { return m.n_edges(); },
                                           [&](std::size_t j) { return m.status(edge_at(j)).deleted(); },
                                           [&](std::size_t i) {
                                             if (!m.is_flip_ok(edge_at(i))) return false;
                                             m.flip(edge_at(i));
                                             return true;
                                           }));
}

//! Live element counts (n_vertices() etc. include deleted elements until garbage_collection).
Counts counts(const OMesh& m) {
  Counts n;
  for (auto v : m.vertices()) (void)v, ++n.v;  // the ranges skip deleted elements
  for (auto e : m.edges()) (void)e, ++n.e;
  for (auto f : m.faces()) (void)f, ++n.f;
  return n;
}

//! The first line of what OpenMesh's MeshCheckerT finds wrong with `m`, or "" when nothing.
std::string mesh_checker_problem(const OMesh& m) {
  std::ostringstream log;
  if (OpenMesh::Utils::MeshCheckerT<OMesh>(m).check(OpenMesh::Utils::MeshCheckerT<OMesh>::CHECK_ALL, log))
    return "";
  const std::string first = log.str();
  return "MeshCheckerT::check failed: " + first.substr(0, first.find('\n')) + "; ";
}

template <EditKind kind>
std::string check_edit(const MeshBox& reference, const MeshBox& edited, double checksum) {
  const OMesh& before = static_cast<const OMBox&>(reference).m;
  const OMesh& after = static_cast<const OMBox&>(edited).m;
  std::string err = mesh_checker_problem(after);
  for (auto f : after.faces())
    if (after.valence(f) != 3) {
      err += "a face of " + std::to_string(after.valence(f)) + " vertices; ";
      break;
    }
  return err + check_edit_counts(kind, counts(before), counts(after), checksum);
}

//! DecimaterT with ModQuadricT as its only module, no error limit, down to the common target vertex
//! count (decimate_target_vertices). Returns the vertices left.
double decimate_op(Context& c) {
  OMesh& m = mesh_of(c);
  OpenMesh::Decimater::DecimaterT<OMesh> decimater(m);
  OpenMesh::Decimater::ModQuadricT<OMesh>::Handle quadric;
  decimater.add(quadric);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  const std::size_t collapses = decimater.decimate_to(decimate_target_vertices(c.input));
  return static_cast<double>(m.n_vertices() - collapses);
}

//! Live vertices and faces, renumbered in order.
Input decimate_result(const MeshBox& edited) {
  const OMesh& m = static_cast<const OMBox&>(edited).m;
  Input out;
  std::vector<std::uint32_t> index(m.n_vertices(), UINT32_MAX);
  for (auto v : m.vertices()) {
    index[static_cast<std::size_t>(v.idx())] = static_cast<std::uint32_t>(out.n_vertices());
    for (int d = 0; d < 3; ++d) out.xyz.push_back(m.point(v)[d]);
  }
  for (auto f : m.faces())
    for (auto v : m.fv_range(f)) out.tri.push_back(index[static_cast<std::size_t>(v.idx())]);
  return out;
}

std::string check_decimate(const MeshBox&, const MeshBox& edited, double) {
  return mesh_checker_problem(static_cast<const OMBox&>(edited).m);
}

}  // namespace

Backend openmesh_backend() {
  Backend b;
  b.label = "OpenMesh";
  b.key = "openmesh";
  b.notes = "OpenMesh " + std::to_string(OM_GET_VER) + "." + std::to_string(OM_GET_MAJ) +
            ": TriMesh_ArrayKernelT<> default traits (float), reserve + add_vertex + add_face; decimation: "
            "DecimaterT with ModQuadricT alone (no error limit), decimate_to(the target vertex count)";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  b.ops["vertex_normals_builtin"] = {copy_with_normals, builtin_vertex_normals};
  b.ops["face_normals"] = {copy_mesh, face_normals};
  b.ops["face_normals_builtin"] = {copy_with_face_normals, builtin_face_normals};
  b.ops["corner_normals_builtin"] = {copy_with_corner_normals, builtin_corner_normals};
  b.ops["collapse"] = {copy_mesh, collapse_op, check_edit<EditKind::collapse>};
  b.ops["split"] = {copy_mesh, split_op, check_edit<EditKind::split>};
  b.ops["flip"] = {copy_mesh, flip_op, check_edit<EditKind::flip>};
  b.ops["loop"] = {copy_mesh, loop_op};
  b.ops["sqrt3"] = {copy_mesh, sqrt3_op<1>, nullptr, decimate_result};
  b.ops["sqrt3_two"] = {copy_mesh, sqrt3_op<2>, nullptr, decimate_result};
  b.ops["catmull_clark_quads"] = {quad_copy, catmull_clark_quads_op};
  b.ops["smooth_uniform"] = {copy_mesh, smooth_op<true>};
  b.ops["smooth_cotan"] = {copy_mesh, smooth_op<false>};
  b.ops["decimate"] = {copy_mesh, decimate_op, check_decimate, decimate_result};
  return b;
}

}  // namespace bench

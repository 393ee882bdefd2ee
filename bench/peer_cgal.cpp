// CGAL backend: Surface_mesh<Simple_cartesian<float>::Point_3> (float coordinates, like hedge),
// used through its public API only. Built with reserve + add_vertex + add_face(v0, v1, v2), which
// measured faster than Polygon_mesh_processing::polygon_soup_to_polygon_mesh (that one goes through
// the same Euler::add_face and allocates a vector per face besides).
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/version.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

// Garland-Heckbert policies (new in CGAL 5.5) need Eigen; without it, the default Lindstrom-Turk.
#if defined(CGAL_EIGEN3_ENABLED)
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#define HEDGE_BENCH_CGAL_GARLAND_HECKBERT 1
#else
#define HEDGE_BENCH_CGAL_GARLAND_HECKBERT 0
#endif

#include "bench_common.h"

namespace bench {
namespace {

using Kernel = CGAL::Simple_cartesian<float>;
using SMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VI = SMesh::Vertex_index;
using FI = SMesh::Face_index;
using HI = SMesh::Halfedge_index;
using EI = SMesh::Edge_index;

struct SMBox final : MeshBox {
  SMesh m;
  std::size_t n_vertices() const override { return m.number_of_vertices(); }
  std::size_t n_faces() const override { return m.number_of_faces(); }
};

const SMesh& mesh_of(Context& c) { return static_cast<SMBox*>(c.mesh)->m; }
F3 f3(const Kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

std::unique_ptr<MeshBox> build(const Input& in) {
  auto box = std::make_unique<SMBox>();
  SMesh& m = box->m;
  const std::size_t nv = in.n_vertices(), nf = in.n_faces();
  m.reserve(static_cast<SMesh::size_type>(nv), static_cast<SMesh::size_type>((3 * nf + 1) / 2),
            static_cast<SMesh::size_type>(nf));
  for (std::size_t i = 0; i < nv; ++i)
    m.add_vertex(Kernel::Point_3(in.xyz[3 * i], in.xyz[3 * i + 1], in.xyz[3 * i + 2]));
  for (std::size_t f = 0; f < nf; ++f)
    m.add_face(VI(in.tri[3 * f]), VI(in.tri[3 * f + 1]), VI(in.tri[3 * f + 2]));
  return box;
}

double build_op(Context& c) {
  c.out = build(c.input);
  return static_cast<double>(c.out->n_vertices() + c.out->n_faces());
}

double one_ring(Context& c) {
  const SMesh& m = mesh_of(c);
  double sum = 0;
  for (VI v : m.vertices()) {
    SMesh::Halfedge_index h = m.halfedge(v);
    if (h == SMesh::null_halfedge()) continue;  // isolated
    RingSum r;
    for (VI u : CGAL::vertices_around_target(h, m)) {
      const Kernel::Point_3& p = m.point(u);
      r.add(p.x(), p.y(), p.z());
    }
    sum += r.total();
  }
  return sum;
}

double vertex_normals(Context& c) {
  const SMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  float* vn = c.scratch.vertex_normal.data();
  for (FI f : m.faces()) {
    auto range = CGAL::vertices_around_face(m.halfedge(f), m);
    auto it = range.begin();
    F3 p0 = f3(m.point(*it));
    ++it;
    F3 p1 = f3(m.point(*it));
    ++it;
    F3 p2 = f3(m.point(*it));
    store(fn, static_cast<std::size_t>(f), area_normal(p0, p1, p2));
  }
  double sum = 0;
  for (VI v : m.vertices()) {
    F3 n{0, 0, 0};
    SMesh::Halfedge_index h = m.halfedge(v);
    if (h != SMesh::null_halfedge())
      for (FI f : CGAL::faces_around_target(h, m))
        if (f != SMesh::null_face()) n += load(fn, static_cast<std::size_t>(f));
    n = normalized(n);
    store(vn, static_cast<std::size_t>(v), n);
    sum += abs_sum(n);
  }
  return sum;
}

// ---- Random local edits: the same draws as hedge (EditRng), on a private copy. ----

std::unique_ptr<MeshBox> copy_mesh(const MeshBox& reference) {
  auto box = std::make_unique<SMBox>();
  box->m = static_cast<const SMBox&>(reference).m;
  return box;
}
SMesh& edit_mesh(Context& c) { return static_cast<SMBox*>(c.mesh)->m; }

//! One step of CGAL's Subdivision_method_3::CatmullClark_subdivision on the private copy.
double catmull_clark_op(Context& c) {
  SMesh& m = edit_mesh(c);
  CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(1));
  return static_cast<double>(m.number_of_vertices() + m.number_of_faces());
}

//! A private copy made all quads by one untimed Catmull-Clark step: the input of catmull_clark_quads.
std::unique_ptr<MeshBox> quad_copy(const MeshBox& reference) {
  auto box = std::make_unique<SMBox>();
  box->m = static_cast<const SMBox&>(reference).m;
  CGAL::Subdivision_method_3::CatmullClark_subdivision(box->m, CGAL::parameters::number_of_iterations(1));
  return box;
}

//! CGAL's own Polygon_mesh_processing::compute_vertex_normals into a vertex property map of a private
//! copy, added before the timer.
std::unique_ptr<MeshBox> copy_with_normals(const MeshBox& reference) {
  auto box = std::make_unique<SMBox>();
  box->m = static_cast<const SMBox&>(reference).m;
  box->m.add_property_map<VI, Kernel::Vector_3>("v:normal", Kernel::Vector_3(0, 0, 0));
  return box;
}
double builtin_vertex_normals(Context& c) {
  SMesh& m = edit_mesh(c);
  auto normals = m.property_map<VI, Kernel::Vector_3>("v:normal").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(m, normals);
  float* vn = c.scratch.vertex_normal.data();
  double sum = 0;
  for (VI v : m.vertices()) {
    const Kernel::Vector_3& n = normals[v];
    store(vn, static_cast<std::size_t>(v), F3{n.x(), n.y(), n.z()});
    sum += abs_sum(F3{n.x(), n.y(), n.z()});
  }
  return sum;
}

//! Face normals over CGAL's API (as hedge's face_normals): into the scratch array.
double face_normals(Context& c) {
  const SMesh& m = mesh_of(c);
  float* fn = c.scratch.face_normal.data();
  double sum = 0;
  for (FI f : m.faces()) {
    auto range = CGAL::vertices_around_face(m.halfedge(f), m);
    auto it = range.begin();
    F3 p0 = f3(m.point(*it));
    ++it;
    F3 p1 = f3(m.point(*it));
    ++it;
    F3 p2 = f3(m.point(*it));
    const F3 n = normalized(area_normal(p0, p1, p2));
    store(fn, static_cast<std::size_t>(f), n);
    sum += abs_sum(n);
  }
  return sum;
}

//! CGAL's own Polygon_mesh_processing::compute_face_normals into a face property map of a private
//! copy, added before the timer.
std::unique_ptr<MeshBox> copy_with_face_normals(const MeshBox& reference) {
  auto box = std::make_unique<SMBox>();
  box->m = static_cast<const SMBox&>(reference).m;
  box->m.add_property_map<FI, Kernel::Vector_3>("f:normal", Kernel::Vector_3(0, 0, 0));
  return box;
}
double builtin_face_normals(Context& c) {
  SMesh& m = edit_mesh(c);
  auto normals = m.property_map<FI, Kernel::Vector_3>("f:normal").first;
  CGAL::Polygon_mesh_processing::compute_face_normals(m, normals);
  double sum = 0;
  for (FI f : m.faces()) {
    const Kernel::Vector_3& n = normals[f];
    sum += abs_sum(F3{n.x(), n.y(), n.z()});
  }
  return sum;
}

//! `steps` steps of CGAL's Subdivision_method_3::Sqrt3_subdivision in one call on the private copy.
//! Returns #V + #F.
template <int steps>
double sqrt3_op(Context& c) {
  SMesh& m = edit_mesh(c);
  CGAL::Subdivision_method_3::Sqrt3_subdivision(m, CGAL::parameters::number_of_iterations(steps));
  return static_cast<double>(m.number_of_vertices() + m.number_of_faces());
}

//! Live vertices and faces of a float mesh, renumbered in order.
Input float_result(const MeshBox& edited) {
  const SMesh& m = static_cast<const SMBox&>(edited).m;
  Input out;
  std::vector<std::uint32_t> index(m.num_vertices(), UINT32_MAX);
  for (VI v : m.vertices()) {
    index[static_cast<std::size_t>(v)] = static_cast<std::uint32_t>(out.n_vertices());
    const Kernel::Point_3& p = m.point(v);
    out.xyz.insert(out.xyz.end(), {p.x(), p.y(), p.z()});
  }
  for (FI f : m.faces())
    for (VI v : CGAL::vertices_around_face(m.halfedge(f), m))
      out.tri.push_back(index[static_cast<std::size_t>(v)]);
  return out;
}

//! One step of CGAL's Subdivision_method_3::Loop_subdivision on the private copy. Returns #V + #F.
double loop_op(Context& c) {
  SMesh& m = edit_mesh(c);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  return static_cast<double>(m.number_of_vertices() + m.number_of_faces());
}

//! Random half-edge h (removed ones redrawn), Euler::does_satisfy_link_condition(edge(h)) (the
//! documented precondition of Euler::collapse_edge on a triangle mesh besides triangulation), then
//! Euler::collapse_edge. That collapses halfedge(edge(h)), which is h or its opposite; the
//! connectivity is the same either way, and the survivor gets target(h)'s position, so the result
//! matches hedge's from_vertex(h)-into-to_vertex(h). Returns the number of collapses done.
HI halfedge_at(std::size_t i) { return HI(static_cast<SMesh::size_type>(i)); }
EI edge_at(std::size_t i) { return EI(static_cast<SMesh::size_type>(i)); }

double collapse_op(Context& c) {
  SMesh& m = edit_mesh(c);
  // num_halfedges() includes removed ones (kept until collect_garbage).
  return static_cast<double>(edit_sequence([&] { return m.num_halfedges(); },
                                           [&](std::size_t j) { return m.is_removed(halfedge_at(j)); },
                                           [&](std::size_t i) {
                                             const HI h = halfedge_at(i);
                                             const EI e = m.edge(h);
                                             if (!CGAL::Euler::does_satisfy_link_condition(e, m))
                                               return false;
                                             const Kernel::Point_3 keep = m.point(m.target(h));
                                             const VI v = CGAL::Euler::collapse_edge(e, m);
                                             m.point(v) = keep;
                                             return true;
                                           }));
}

//! Random edge (among the current ones), split at its midpoint so that the result matches hedge's
//! split_edge: Euler::split_edge inserts the vertex (each incident triangle becomes a quad), then
//! Euler::split_face on each non-border side joins the new vertex to that side's tip. Returns
//! #V + #F after the sequence.
double split_op(Context& c) {
  SMesh& m = edit_mesh(c);
  edit_sequence([&] { return m.num_edges(); }, [&](std::size_t j) { return m.is_removed(edge_at(j)); },
                [&](std::size_t i) {
                  const HI h = m.halfedge(edge_at(i));  // a -> b
                  const Kernel::Point_3& a = m.point(m.source(h));
                  const Kernel::Point_3& b = m.point(m.target(h));
                  const Kernel::Point_3 mid(0.5f * (a.x() + b.x()), 0.5f * (a.y() + b.y()),
                                            0.5f * (a.z() + b.z()));
                  const HI hnew = CGAL::Euler::split_edge(h, m);  // a -> v, then h: v -> b
                  m.point(m.target(hnew)) = mid;
                  if (!m.is_border(h))
                    CGAL::Euler::split_face(hnew, m.next(h), m);  // v -> tip of (a, v, b, c)
                  const HI o = m.opposite(h);                     // b -> v, v -> a, a -> d, d -> b
                  if (!m.is_border(o)) CGAL::Euler::split_face(o, m.next(m.next(o)), m);
                  return true;
                });
  return static_cast<double>(m.number_of_vertices() + m.number_of_faces());
}

//! The conditions hedge's can_flip checks, written with Surface_mesh's API (CGAL has no flip
//! predicate; Euler::flip_edge only requires two triangles): e interior, both faces triangles,
//! distinct tips not joined by an edge yet, neither end an interior vertex of valence 3.
bool can_flip(const SMesh& m, EI e) {
  if (m.is_border(e)) return false;
  const HI h = m.halfedge(e), o = m.opposite(h);
  if (m.next(m.next(m.next(h))) != h || m.next(m.next(m.next(o))) != o) return false;
  const VI c = m.target(m.next(h)), d = m.target(m.next(o));
  if (c == d || m.halfedge(c, d) != SMesh::null_halfedge()) return false;
  for (VI v : {m.source(h), m.target(h)})
    if (m.degree(v) == 3 && !m.is_border(v)) return false;
  return true;
}

//! Random edge, the check above, then Euler::flip_edge. Returns the number of flips done.
double flip_op(Context& c) {
  SMesh& m = edit_mesh(c);
  return static_cast<double>(edit_sequence([&] { return m.num_edges(); },
                                           [&](std::size_t j) { return m.is_removed(edge_at(j)); },
                                           [&](std::size_t i) {
                                             if (!can_flip(m, edge_at(i))) return false;
                                             CGAL::Euler::flip_edge(m.halfedge(edge_at(i)), m);
                                             return true;
                                           }));
}

Counts counts(const SMesh& m) { return {m.number_of_vertices(), m.number_of_edges(), m.number_of_faces()}; }

template <EditKind kind>
std::string check_edit(const MeshBox& reference, const MeshBox& edited, double checksum) {
  const SMesh& before = static_cast<const SMBox&>(reference).m;
  const SMesh& after = static_cast<const SMBox&>(edited).m;
  std::string err;
  if (!after.is_valid(false)) err += "Surface_mesh::is_valid failed; ";
  if (!CGAL::is_valid_polygon_mesh(after)) err += "is_valid_polygon_mesh failed; ";
  if (!CGAL::is_triangle_mesh(after)) err += "is_triangle_mesh failed; ";
  return err + check_edit_counts(kind, counts(before), counts(after), checksum);
}

// ---- Decimation, on a copy in double coordinates (the quadrics lose too much in float). ----

using DKernel = CGAL::Simple_cartesian<double>;
using DMesh = CGAL::Surface_mesh<DKernel::Point_3>;

struct DMBox final : MeshBox {
  DMesh m;
  std::size_t n_vertices() const override { return m.number_of_vertices(); }
  std::size_t n_faces() const override { return m.number_of_faces(); }
};

std::unique_ptr<MeshBox> copy_to_double(const MeshBox& reference) {
  const SMesh& from = static_cast<const SMBox&>(reference).m;
  auto box = std::make_unique<DMBox>();
  DMesh& m = box->m;
  m.reserve(from.number_of_vertices(), from.number_of_edges(), from.number_of_faces());
  for (VI v : from.vertices())
    m.add_vertex(DKernel::Point_3(from.point(v).x(), from.point(v).y(), from.point(v).z()));
  for (FI f : from.faces()) {
    const HI h = from.halfedge(f);
    m.add_face(DMesh::Vertex_index(from.target(h)), DMesh::Vertex_index(from.target(from.next(h))),
               DMesh::Vertex_index(from.target(from.next(from.next(h)))));
  }
  return box;
}

//! Stops the edge collapses when the mesh is down to a vertex count (CGAL's own count predicates
//! count edges).
struct StopAtVertexCount {
  const DMesh* mesh;
  std::size_t target;
  template <class FT, class Profile>
  bool operator()(const FT&, const Profile&, std::size_t, std::size_t) const {
    return mesh->number_of_vertices() <= target;
  }
};

//! Surface_mesh_simplification::edge_collapse with the Garland-Heckbert plane policies (cost and
//! placement) when available, down to the common target vertex count. Returns the vertices left.
double decimate_op(Context& c) {
  DMesh& m = static_cast<DMBox*>(c.mesh)->m;
  namespace SMS = CGAL::Surface_mesh_simplification;
  const StopAtVertexCount stop{&m, decimate_target_vertices(c.input)};
#if HEDGE_BENCH_CGAL_GARLAND_HECKBERT
  SMS::GarlandHeckbert_plane_policies<DMesh, DKernel> policies(m);
  SMS::edge_collapse(m, stop,
                     CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
#else
  SMS::edge_collapse(m, stop);
#endif
  return static_cast<double>(m.number_of_vertices());
}

//! Live vertices and faces, renumbered in order.
Input decimate_result(const MeshBox& edited) {
  const DMesh& m = static_cast<const DMBox&>(edited).m;
  Input out;
  std::vector<std::uint32_t> index(m.num_vertices(), UINT32_MAX);
  for (auto v : m.vertices()) {
    index[static_cast<std::size_t>(v)] = static_cast<std::uint32_t>(out.n_vertices());
    const DKernel::Point_3& p = m.point(v);
    out.xyz.insert(out.xyz.end(),
                   {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())});
  }
  for (auto f : m.faces())
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      out.tri.push_back(index[static_cast<std::size_t>(v)]);
  return out;
}

std::string check_decimate(const MeshBox&, const MeshBox& edited, double) {
  const DMesh& m = static_cast<const DMBox&>(edited).m;
  std::string err;
  if (!m.is_valid(false)) err += "Surface_mesh::is_valid failed; ";
  if (!CGAL::is_triangle_mesh(m)) err += "is_triangle_mesh failed; ";
  return err;
}

}  // namespace

Backend cgal_backend() {
  Backend b;
  b.label = "CGAL";
  b.key = "cgal";
  b.notes = "CGAL " + std::to_string(CGAL_VERSION_NR / 10000000 % 100) + "." +
            std::to_string(CGAL_VERSION_NR / 100000 % 100) + "." +
            std::to_string(CGAL_VERSION_NR / 10000 % 10) +
            ": Surface_mesh<Simple_cartesian<float>::Point_3>, reserve + add_vertex + add_face; decimation: "
            "edge_collapse on a Simple_cartesian<double> copy, " +
            (HEDGE_BENCH_CGAL_GARLAND_HECKBERT ? "GarlandHeckbert_plane_policies"
                                               : "default Lindstrom-Turk policies") +
            ", stopped at the target vertex count";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  b.ops["vertex_normals_builtin"] = {copy_with_normals, builtin_vertex_normals};
  b.ops["face_normals"] = {copy_mesh, face_normals};
  b.ops["face_normals_builtin"] = {copy_with_face_normals, builtin_face_normals};
  b.ops["collapse"] = {copy_mesh, collapse_op, check_edit<EditKind::collapse>};
  b.ops["split"] = {copy_mesh, split_op, check_edit<EditKind::split>};
  b.ops["flip"] = {copy_mesh, flip_op, check_edit<EditKind::flip>};
  b.ops["loop"] = {copy_mesh, loop_op};
  b.ops["catmull_clark"] = {copy_mesh, catmull_clark_op};
  b.ops["catmull_clark_quads"] = {quad_copy, catmull_clark_op};
  b.ops["decimate"] = {copy_to_double, decimate_op, check_decimate, decimate_result};
  b.ops["sqrt3"] = {copy_mesh, sqrt3_op<1>, nullptr, float_result};
  b.ops["sqrt3_two"] = {copy_mesh, sqrt3_op<2>, nullptr, float_result};
  return b;
}

}  // namespace bench

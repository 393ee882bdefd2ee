// CGAL backend: Surface_mesh<Simple_cartesian<float>::Point_3> (float coordinates, like hedge),
// used through its public API only. Built with reserve + add_vertex + add_face(v0, v1, v2), which
// measured faster than Polygon_mesh_processing::polygon_soup_to_polygon_mesh (that one goes through
// the same Euler::add_face and allocates a vector per face besides).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/version.h>

#include <memory>

#include "bench_common.h"

namespace bench {
namespace {

using Kernel = CGAL::Simple_cartesian<float>;
using SMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VI = SMesh::Vertex_index;
using FI = SMesh::Face_index;

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
  for (std::size_t i = 0; i < nv; ++i) m.add_vertex(Kernel::Point_3(in.xyz[3 * i], in.xyz[3 * i + 1], in.xyz[3 * i + 2]));
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

}  // namespace

Backend cgal_backend() {
  Backend b;
  b.label = "CGAL";
  b.key = "cgal";
  b.notes = "CGAL " + std::to_string(CGAL_VERSION_NR / 10000000 % 100) + "." +
            std::to_string(CGAL_VERSION_NR / 100000 % 100) + "." + std::to_string(CGAL_VERSION_NR / 10000 % 10) +
            ": Surface_mesh<Simple_cartesian<float>::Point_3>, reserve + add_vertex + add_face";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  return b;
}

}  // namespace bench

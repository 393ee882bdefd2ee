// OpenMesh backend: TriMesh_ArrayKernelT with default traits (float Vec3f points), used through its
// public API only. Built the standard way: reserve, add_vertex for every vertex, add_face for
// every triangle.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cmath>
#include <memory>

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
F3 f3(const OMesh::Point& p) { return {p[0], p[1], p[2]}; }

std::unique_ptr<MeshBox> build(const Input& in) {
  auto box = std::make_unique<OMBox>();
  OMesh& m = box->m;
  const std::size_t nv = in.n_vertices(), nf = in.n_faces();
  m.reserve(nv, (3 * nf + 1) / 2, nf);  // exact for a closed triangle mesh
  for (std::size_t i = 0; i < nv; ++i) m.add_vertex(OMesh::Point(in.xyz[3 * i], in.xyz[3 * i + 1], in.xyz[3 * i + 2]));
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

}  // namespace

Backend openmesh_backend() {
  Backend b;
  b.label = "OpenMesh";
  b.key = "openmesh";
  b.notes = "OpenMesh " + std::to_string(OM_GET_VER) + "." + std::to_string(OM_GET_MAJ) +
            ": TriMesh_ArrayKernelT<> default traits (float), reserve + add_vertex + add_face";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  return b;
}

}  // namespace bench

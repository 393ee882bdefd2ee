// hedge backend: build_triangles with default options (strict policy, no welding), then the same
// operations as the peers through hedge's idiomatic circulators.
#include <memory>
#include <span>

#include "bench_common.h"
#include "hedge/core/build.h"
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
  std::span<const hedge::Vec3> positions(reinterpret_cast<const hedge::Vec3*>(in.xyz.data()), in.n_vertices());
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

}  // namespace

Backend hedge_backend() {
  Backend b;
  b.label = "hedge";
  b.key = "hedge";
  b.notes = "hedge: build_triangles, default options (strict, no weld), float positions";
  b.build = build;
  b.ops["build"] = {nullptr, build_op};
  b.ops["one_ring"] = {nullptr, one_ring};
  b.ops["vertex_normals"] = {nullptr, vertex_normals};
  return b;
}

}  // namespace bench

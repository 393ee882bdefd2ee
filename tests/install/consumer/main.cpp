// Uses an installed hedge: builds a tetrahedron and checks its counts and validity, then sends it
// through the glTF writer and reader, which link without any glTF library of the consumer's.
#include <hedge/core/build.h>
#include <hedge/core/export.h>
#include <hedge/core/surface_mesh.h>
#include <hedge/io/io.h>

#include <cstdint>
#include <cstdio>
#include <vector>

int main() {
  const std::vector<hedge::Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<std::uint32_t> triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  const hedge::SurfaceMesh mesh = hedge::build_triangles(positions, triangles);

  std::printf("tetrahedron: %zu vertices, %zu edges, %zu faces\n", mesh.n_vertices(), mesh.n_edges(),
              mesh.n_faces());
  const bool ok = mesh.n_vertices() == 4 && mesh.n_edges() == 6 && mesh.n_faces() == 4 &&
                  mesh.n_halfedges() == 12 && mesh.boundary_loops().empty() && mesh.validate().empty();
  if (!ok) {
    std::fprintf(stderr, "unexpected counts or an invalid mesh\n");
    return 1;
  }
  const hedge::IndexedMesh back =
      hedge::read_gltf(hedge::write_glb(hedge::to_indexed(mesh)), "tetrahedron.glb");
  if (back.positions != positions || back.indices.size() != triangles.size()) {
    std::fprintf(stderr, "the glTF round trip changed the tetrahedron\n");
    return 1;
  }
  std::printf("ok\n");
  return 0;
}

#include "subdivide.h"

#include "edge_table.h"

namespace hedge::structures {

TriangleArrays subdivide_midpoint(const TriangleArrays& mesh) {
  const EdgeTable table = match_edges(mesh.triangles, mesh.n_vertices());
  const Index n_v = static_cast<Index>(mesh.n_vertices());
  TriangleArrays out;
  out.positions.reserve(n_v + table.n_edges());
  out.positions.assign(mesh.positions.begin(), mesh.positions.end());
  for (Index c : table.corner_of_edge) {
    const Vec3& p = mesh.positions[mesh.triangles[c]];
    const Vec3& q = mesh.positions[mesh.triangles[corner_next(c)]];
    out.positions.push_back((p + q) * 0.5f);
  }
  out.triangles.reserve(4 * mesh.triangles.size());
  for (Index t = 0; t < mesh.n_faces(); ++t) {
    const Index a = mesh.triangles[3 * t], b = mesh.triangles[3 * t + 1], c = mesh.triangles[3 * t + 2];
    // Midpoints of a->b, b->c, c->a.
    const Index ab = n_v + table.edge_of[3 * t], bc = n_v + table.edge_of[3 * t + 1],
                ca = n_v + table.edge_of[3 * t + 2];
    for (Index i : {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca}) out.triangles.push_back(i);
  }
  return out;
}

}  // namespace hedge::structures

// What the subdivision tests share (subdivide_test.cpp, subdivide_one_to_four_test.cpp,
// subdivide_catmull_clark_test.cpp, subdivide_face_centres_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include "hedge/core/surface_mesh.h"

namespace hedge::test {

struct Counts {
  std::size_t v, e, f, loops;
};
inline Counts counts(const SurfaceMesh& m) {
  return {m.n_vertices(), m.n_edges(), m.n_faces(), m.boundary_loops().size()};
}

// Seam edges: the two faces of an edge disagree on the texcoords at one of its ends.
inline std::size_t seam_edges(const SurfaceMesh& s) {
  const auto t = s.get_halfedge_property<Vec2>("h:texcoord");
  std::size_t n = 0;
  for (Edge e : s.edges()) {
    const Halfedge h = SurfaceMesh::halfedge(e, 0), g = SurfaceMesh::twin(h);
    if (s.is_boundary(h) || s.is_boundary(g)) continue;
    // h enters to(h); in g's face the corner at to(h) is entered by the half-edge before g.
    Halfedge before_g = g;
    while (s.next(before_g) != g) before_g = s.next(before_g);
    Halfedge before_h = h;
    while (s.next(before_h) != h) before_h = s.next(before_h);
    n += !(t[h] == t[before_g]) || !(t[g] == t[before_h]);
  }
  return n;
}

// Boundary vertices of `before` moved by the cubic B-spline curve rule: 3/4 of themselves and 1/8 of
// each boundary neighbour (old vertices keep their index).
inline void expect_boundary_curve_rule(const SurfaceMesh& before, const SurfaceMesh& after) {
  for (Vertex v : before.vertices()) {
    if (!before.is_boundary(v)) continue;
    Vec3d ends{0, 0, 0};
    for (Halfedge h : before.halfedges(v))
      if (before.is_boundary(SurfaceMesh::edge(h))) ends += to_double(before.position(before.to_vertex(h)));
    const Vec3d want = to_double(before.position(v)) * 0.75 + ends * 0.125;
    EXPECT_NEAR(after.position(v).x, want.x, 1e-6);
    EXPECT_NEAR(after.position(v).y, want.y, 1e-6);
    EXPECT_NEAR(after.position(v).z, want.z, 1e-6);
  }
}

}  // namespace hedge::test

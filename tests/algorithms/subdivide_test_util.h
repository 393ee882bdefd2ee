// What the subdivision tests share (subdivide_test.cpp, subdivide_one_to_four_test.cpp,
// subdivide_catmull_clark_test.cpp, subdivide_face_centres_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string_view>

#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/error.h"
#include "test_meshes.h"

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

// `got` is within `tolerance` of `want` in each coordinate.
inline ::testing::AssertionResult near(const Vec3& got, const Vec3d& want, double tolerance) {
  const Vec3d d = to_double(got) - want;
  if (std::abs(d.x) <= tolerance && std::abs(d.y) <= tolerance && std::abs(d.z) <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << got.x << ", " << got.y << ", " << got.z << ") is not within " << tolerance << " of ("
         << want.x << ", " << want.y << ", " << want.z << ")";
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
    EXPECT_TRUE(near(after.position(v), want, 1e-6)) << "boundary vertex " << v.idx();
  }
}

// A lattice of 10 x 10 squares cut into triangles, each vertex lifted to a random height in
// [-0.5, 0.5] drawn from `seed`.
inline SurfaceMesh bumpy_lattice(unsigned seed) {
  IndexedMesh in = triangle_lattice(10);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  for (Vec3& p : in.positions) p.z = u(rng);
  return build(in);
}

// The vertex in the middle of bumpy_lattice(), far from its boundary.
inline Vertex lattice_centre() { return Vertex(Index(5 * 11 + 5)); }

// The sum of the positions of v's neighbours.
inline Vec3d neighbour_sum(const SurfaceMesh& m, Vertex v) {
  Vec3d sum{0, 0, 0};
  for (Vertex w : m.vertices(v)) sum += to_double(m.position(w));
  return sum;
}

// subdivide(m, scheme, steps) is refused with an InvalidInputError whose message contains `says`,
// and leaves the counts of m as they were.
inline ::testing::AssertionResult refused_unchanged(SurfaceMesh& m, Subdivision scheme, int steps,
                                                    std::string_view says) {
  const Counts before = counts(m);
  try {
    subdivide(m, scheme, steps);
    return ::testing::AssertionFailure() << "the mesh was subdivided";
  } catch (const InvalidInputError& e) {
    if (std::string_view(e.what()).find(says) == std::string_view::npos)
      return ::testing::AssertionFailure()
             << "the error \"" << e.what() << "\" does not say \"" << says << "\"";
  }
  const Counts after = counts(m);
  if (after.v != before.v || after.e != before.e || after.f != before.f || after.loops != before.loops)
    return ::testing::AssertionFailure() << "the refused subdivision changed the counts";
  return ::testing::AssertionSuccess();
}

}  // namespace hedge::test

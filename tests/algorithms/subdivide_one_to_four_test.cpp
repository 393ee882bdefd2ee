// Loop's scheme and the midpoint split (src/algorithms/subdivide_one_to_four.cpp).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <stdexcept>
#include <string>

#include "heap_hooks.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "subdivide_test_util.h"
#include "test_meshes.h"

namespace hedge {
namespace {

TEST(Subdivide, MidpointKeepsTheShape) {
  SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  const SurfaceMesh before = m;
  const double v0 = volume(m), a0 = surface_area(m);
  subdivide(m, Subdivision::midpoint, 2);
  EXPECT_NEAR(volume(m), v0, 1e-6 * std::abs(v0));
  EXPECT_NEAR(surface_area(m), a0, 1e-6 * a0);
  for (Vertex v : before.vertices())
    EXPECT_EQ(m.position(v), before.position(v));  // old vertices keep index and place
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, LoopReproducesLinearFunctionsInTheInterior) {
  IndexedMesh in = test::triangle_lattice(10);
  for (Vec3& p : in.positions) p.z = 0.3f * p.x + 0.2f * p.y + 1;
  SurfaceMesh m = build(in);
  subdivide(m, Subdivision::loop, 2);
  int checked = 0;
  for (Vertex v : m.vertices()) {
    const Vec3 p = m.position(v);
    if (p.x < 2.5f || p.x > 7.5f || p.y < 2.5f || p.y > 6.0f) continue;  // away from the boundary rules
    EXPECT_NEAR(p.z, 0.3f * p.x + 0.2f * p.y + 1, 1e-5);
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, LoopConvergesToTheLimitPositionOfARegularVertex) {
  // A regular vertex's limit under Loop's scheme is p/2 + (sum of its 6 neighbours)/12.
  SurfaceMesh m = test::bumpy_lattice(7);
  const Vertex centre = test::lattice_centre();
  ASSERT_EQ(m.valence(centre), 6u);
  const Vec3d limit = to_double(m.position(centre)) * 0.5 + test::neighbour_sum(m, centre) * (1.0 / 12);
  subdivide(m, Subdivision::loop, 6);  // old vertices keep their index
  EXPECT_TRUE(test::near(m.position(centre), limit, 2e-3));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, LoopBoundaryFollowsTheCurveRules) {
  IndexedMesh in = test::grid(4, true);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-0.3f, 0.3f);
  for (Vec3& p : in.positions) p.z = u(rng);
  SurfaceMesh m = build(in);
  const SurfaceMesh before = m;
  subdivide(m, Subdivision::loop, 1);
  test::expect_boundary_curve_rule(before, m);
  for (Edge e : before.edges()) {
    if (!before.is_boundary(e)) continue;
    const Vertex mid(Index(before.vertex_slots() + e.idx()));
    const Vec3 a = before.position(before.vertex(e, 0)), b = before.position(before.vertex(e, 1));
    EXPECT_NEAR(m.position(mid).z, 0.5f * (a.z + b.z), 1e-6);
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, CreaseEdgesStaySharp) {
  // The triangulated cube with its 12 cube edges marked: they stay straight and the corners stay.
  SurfaceMesh m = build(test::cube());
  {
    IndexedMesh tri;
    tri.positions = test::cube().positions;
    tri.indices = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                   1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    m = build(tri);
  }
  auto crease = m.add_edge_property<std::uint8_t>("e:crease", 0);
  for (Edge e : m.edges()) {
    const Vec3 d = m.position(m.vertex(e, 0)) - m.position(m.vertex(e, 1));
    const int axes = (d.x != 0) + (d.y != 0) + (d.z != 0);
    crease[e] = axes == 1;  // a cube edge, not a face diagonal
  }
  subdivide(m, Subdivision::loop, 2);
  const BoundingBox box = bounding_box(m);
  EXPECT_EQ(box.min, (Vec3{0, 0, 0}));
  EXPECT_EQ(box.max, (Vec3{1, 1, 1}));
  for (Index corner = 0; corner < 8; ++corner)
    EXPECT_EQ(m.position(Vertex(corner)), test::cube().positions[corner]);
  // Every vertex on a crease edge lies on a cube edge: two of its coordinates are 0 or 1.
  const auto c = m.get_edge_property<std::uint8_t>("e:crease");
  for (Edge e : m.edges()) {
    if (!c[e]) continue;
    for (int i = 0; i < 2; ++i) {
      const Vec3 p = m.position(m.vertex(e, i));
      const int on = (p.x == 0 || p.x == 1) + (p.y == 0 || p.y == 1) + (p.z == 0 || p.z == 1);
      EXPECT_GE(on, 2);
    }
  }
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

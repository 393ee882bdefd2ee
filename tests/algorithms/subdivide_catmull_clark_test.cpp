// Catmull-Clark (src/algorithms/subdivide_catmull_clark.cpp).
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

TEST(CatmullClark, ACubeBecomesQuadsTendingToARoundBody) {
  SurfaceMesh m = build(test::cube());
  subdivide(m, Subdivision::catmull_clark, 1);
  EXPECT_EQ(m.n_vertices(), 26u);
  EXPECT_EQ(m.n_edges(), 48u);
  EXPECT_EQ(m.n_faces(), 24u);
  for (Face f : m.faces()) EXPECT_EQ(m.valence(f), 4u);
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
  double last_volume = 1;
  auto roundness = [](const SurfaceMesh& s) {
    double lo = 1e9, hi = 0;
    for (Vertex v : s.vertices()) {
      const double d = norm(to_double(s.position(v)) - Vec3d{0.5, 0.5, 0.5});
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
    return hi / lo;
  };
  for (int step = 0; step < 3; ++step) {
    const double v = volume(m);
    EXPECT_LT(v, last_volume);
    last_volume = v;
    subdivide(m, Subdivision::catmull_clark, 1);
  }
  EXPECT_LT(roundness(m), 1.1);  // the cube's own ratio is sqrt(3)
  EXPECT_EQ(long(m.n_vertices()) - long(m.n_edges()) + long(m.n_faces()), 2);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CatmullClark, AnyPolygonsBecomeOneQuadPerCorner) {
  SurfaceMesh m =
      read_mesh(test::data_path("spot_control_mesh.obj"));  // 4 triangles, 160 quads, 16 pentagons
  const test::Counts c = test::counts(m);
  subdivide(m, Subdivision::catmull_clark, 1);
  EXPECT_EQ(m.n_faces(), 4u * 3 + 160 * 4 + 16 * 5);
  EXPECT_EQ(m.n_vertices(), c.v + c.e + c.f);
  for (Face f : m.faces()) EXPECT_EQ(m.valence(f), 4u);
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
}

TEST(CatmullClark, ReproducesALinearHeightFieldAndKeepsTheBoundaryRules) {
  IndexedMesh in = test::grid(8, false);
  for (Vec3& p : in.positions) p.z = 0.25f * p.x - 0.5f * p.y + 2;
  SurfaceMesh m = build(in);
  const SurfaceMesh before = m;
  subdivide(m, Subdivision::catmull_clark, 2);
  for (Vertex v : m.vertices()) {
    const Vec3 p = m.position(v);
    EXPECT_NEAR(p.z, 0.25f * p.x - 0.5f * p.y + 2, 1e-5);  // boundary curves are linear too
  }
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  // One step: a boundary vertex moves by the curve rule, 3/4 itself and 1/8 of each boundary neighbour.
  SurfaceMesh one = before;
  subdivide(one, Subdivision::catmull_clark, 1);
  test::expect_boundary_curve_rule(before, one);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CatmullClark, TexcoordSeamsAndFacePropertiesFollow) {
  SurfaceMesh m = read_mesh(test::data_path("spot_control_mesh.obj"));
  ASSERT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord"));
  auto id = m.add_face_property<int>("f:id", -1);
  for (Face f : m.faces()) id[f] = int(f.idx());
  std::vector<int> corners_of(m.face_slots());
  for (Face f : m.faces()) corners_of[f.idx()] = int(m.valence(f));
  const std::size_t seams_before = test::seam_edges(m);
  ASSERT_GT(seams_before, 0u);
  subdivide(m, Subdivision::catmull_clark, 1);
  EXPECT_EQ(test::seam_edges(m), 2 * seams_before);
  // Each face's quads carry its id, as many as it had corners.
  std::vector<int> quads_of(corners_of.size(), 0);
  const auto after = m.get_face_property<int>("f:id");
  for (Face f : m.faces()) ++quads_of[std::size_t(after[f])];
  EXPECT_EQ(quads_of, corners_of);
  EXPECT_TRUE(m.validate().empty());
}

// ---- sqrt(3) and split-faces ----

// Every corner's texcoord as a function of where it sits: the xy of `before`'s position for an old
// vertex (it keeps its index), of the current position for a new one.

}  // namespace
}  // namespace hedge

// Splitting at face centres and sqrt(3) (src/algorithms/subdivide_face_centres.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "heap_hooks.h"
#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "subdivide_test_util.h"
#include "test_meshes.h"

namespace hedge {
namespace {

std::size_t boundary_edges(const SurfaceMesh& m) {
  std::size_t n = 0;
  for (Edge e : m.edges()) n += m.is_boundary(e);
  return n;
}

void expect_texcoords_follow_positions(const SurfaceMesh& before, const SurfaceMesh& after) {
  const auto uv = after.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(uv);
  for (Halfedge h : after.halfedges()) {
    if (after.is_boundary(h)) continue;
    const Vertex v = after.to_vertex(h);
    const Vec3 p = v.idx() < before.vertex_slots() ? before.position(v) : after.position(v);
    EXPECT_NEAR(uv[h].x, p.x, 1e-5);
    EXPECT_NEAR(uv[h].y, p.y, 1e-5);
  }
}

SurfaceMesh with_planar_texcoords(IndexedMesh in) {
  SurfaceMesh m = build(in);
  auto uv = m.add_halfedge_property<Vec2>("h:texcoord");
  for (Halfedge h : m.halfedges())
    if (!m.is_boundary(h)) uv[h] = Vec2{m.position(m.to_vertex(h)).x, m.position(m.to_vertex(h)).y};
  return m;
}

TEST(Sqrt3, CountsAfterStepsOnClosedAndOpenMeshes) {
  SurfaceMesh tet = build(test::tetrahedron());  // 4 V, 6 E, 4 F
  subdivide(tet, Subdivision::sqrt3, 1);
  EXPECT_EQ(tet.n_vertices(), 8u);  // V + F
  EXPECT_EQ(tet.n_edges(), 18u);    // E + 3F
  EXPECT_EQ(tet.n_faces(), 12u);    // 3F
  EXPECT_TRUE(tet.is_triangle_mesh());
  subdivide(tet, Subdivision::sqrt3, 2);
  EXPECT_EQ(tet.n_faces(), 108u);
  EXPECT_EQ(tet.n_vertices(), 8u + 12 + 36);
  EXPECT_EQ(long(tet.n_vertices()) - long(tet.n_edges()) + long(tet.n_faces()), 2);
  // A centre joins its 3 corners and, by the flips, the 3 neighbouring centres; old vertices keep
  // their valence (their edges now run to the centres of their faces).
  for (Vertex v : tet.vertices()) EXPECT_EQ(tet.valence(v), v.idx() < 4 ? 3u : 6u);
  EXPECT_TRUE(tet.validate().empty()) << tet.validate().front();

  SurfaceMesh grid = build(test::grid(3, true));  // 16 V, 33 E, 18 F, one loop of 12 edges
  const SurfaceMesh before = grid;
  const test::Counts c = test::counts(grid);
  subdivide(grid, Subdivision::sqrt3, 1);
  // The first step neither splits nor flips boundary edges, and boundary vertices stay.
  for (Edge e : before.edges()) {
    EXPECT_EQ(grid.is_boundary(e), before.is_boundary(e));
    if (before.is_boundary(e)) EXPECT_EQ(grid.vertices(e), before.vertices(e));
  }
  for (Vertex v : before.vertices())
    if (before.is_boundary(v)) EXPECT_EQ(grid.position(v), before.position(v));
  // The second splits each of the 12 boundary edges in three: its face gets the two points instead
  // of a centroid, so one more vertex and one more edge each.
  grid = before;
  subdivide(grid, Subdivision::sqrt3, 2);
  EXPECT_EQ(grid.n_vertices(), c.v + c.f + 3 * c.f + 12);
  EXPECT_EQ(grid.n_edges(), c.e + 3 * c.f + 3 * (3 * c.f) + 12);
  EXPECT_EQ(grid.n_faces(), 9 * c.f);
  ASSERT_EQ(grid.boundary_loops().size(), 1u);
  EXPECT_EQ(boundary_edges(grid), 36u);
  EXPECT_TRUE(grid.validate().empty()) << grid.validate().front();
}

// Two triangles, (0, 0, 0), (3, 0, 0), (3, 3, 1), (0, 3, 0), split along 0-2: two steps, every
// position worked out by hand from Kobbelt's stencils.
//  Step 1: boundary vertices stay; centres c0 = (2, 1, 1/3), c1 = (1, 2, 1/3); edge 0-2 flips to
//   c0-c1. Each of the four boundary faces (v_i, v_i+1, c) has one boundary edge.
//  Step 2: boundary vertices move by (4 prev + 19 p + 4 next) / 27: v0 -> (4/9, 4/9, 0),
//   v1 -> (23/9, 4/9, 4/27), v2 -> (23/9, 23/9, 19/27), v3 -> (4/9, 23/9, 4/27). Each boundary
//   edge a -> b (z before a, w after b) gets (z + 16 a + 10 b) / 27 and (10 a + 16 b + w) / 27:
//   v0 v1: (10/9, 1/9, 0), (17/9, 1/9, 1/27); v1 v2: (26/9, 10/9, 10/27), (26/9, 17/9, 16/27);
//   v2 v3: (17/9, 26/9, 16/27), (10/9, 26/9, 10/27); v3 v0: (1/9, 17/9, 1/27), (1/9, 10/9, 0).
//   c0 and c1 have valence 4 (a = 4/9): c0 -> 5/9 c0 + 1/9 (v0 + v1 + v2 + c1) = (17/9, 10/9, 1/3),
//   c1 -> (10/9, 17/9, 1/3). The two interior faces (v0, c0, c1) and (v2, c1, c0) get their
//   centroids (1, 1, 2/9) and (2, 2, 5/9).
TEST(Sqrt3, TwoStepsOnAnOpenMeshMatchTheStencilsWorkedByHand) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {3, 0, 0}, {3, 3, 1}, {0, 3, 0}};
  in.indices = {0, 1, 2, 0, 2, 3};
  SurfaceMesh m = build(in);
  subdivide(m, Subdivision::sqrt3, 2);
  const double n = 1.0 / 9, t = 1.0 / 27;
  const std::vector<Vec3d> want = {{4 * n, 4 * n, 0},
                                   {23 * n, 4 * n, 4 * t},
                                   {23 * n, 23 * n, 19 * t},
                                   {4 * n, 23 * n, 4 * t},
                                   {10 * n, n, 0},
                                   {17 * n, n, t},
                                   {26 * n, 10 * n, 10 * t},
                                   {26 * n, 17 * n, 16 * t},
                                   {17 * n, 26 * n, 16 * t},
                                   {10 * n, 26 * n, 10 * t},
                                   {n, 17 * n, t},
                                   {n, 10 * n, 0},
                                   {17 * n, 10 * n, 1.0 / 3},
                                   {10 * n, 17 * n, 1.0 / 3},
                                   {1, 1, 2 * n},
                                   {2, 2, 5 * n}};
  ASSERT_EQ(m.n_vertices(), want.size());
  EXPECT_EQ(m.n_faces(), 18u);
  std::vector<int> used(want.size(), 0);
  for (Vertex v : m.vertices()) {
    std::size_t hit = want.size();
    for (std::size_t i = 0; i < want.size(); ++i)
      if (test::near(m.position(v), want[i], 1e-6)) hit = i;
    ASSERT_LT(hit, want.size()) << "vertex " << v.idx() << " at " << m.position(v).x << ", "
                                << m.position(v).y << ", " << m.position(v).z << " is none of the expected";
    ++used[hit];
  }
  for (int u : used) EXPECT_EQ(u, 1);
  // v1 and v3 were on one face each: after step 1 the edge v1-c0 lies between two split faces, and
  // flips like any interior edge, joining the points beside v1; so v1 keeps one triangle.
  EXPECT_EQ(m.valence(Vertex(1)), 2u);
  EXPECT_EQ(m.valence(Vertex(3)), 2u);
  ASSERT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(boundary_edges(m), 12u);
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
}

// The smallest angle of each face on the boundary, after 4 steps of a grid: Kobbelt's rule keeps
// them near the interior's; never splitting the boundary made needles (median 0.5 degrees).
TEST(Sqrt3, BoundaryFacesStayWellShaped) {
  SurfaceMesh m = build(test::grid(4, true));
  subdivide(m, Subdivision::sqrt3, 4);
  std::vector<double> smallest;
  for (Face f : m.faces()) {
    bool on_boundary = false;
    for (Halfedge h : m.halfedges(f)) on_boundary = on_boundary || m.is_boundary(SurfaceMesh::twin(h));
    if (!on_boundary) continue;
    double a = 1e9;
    for (Halfedge h : m.halfedges(f))
      a = std::min(
          a, corner_angle(to_double(m.position(m.to_vertex(h))), to_double(m.position(m.from_vertex(h))),
                          to_double(m.position(m.to_vertex(m.next(h))))));
    smallest.push_back(a * 180 / 3.14159265358979);
  }
  ASSERT_FALSE(smallest.empty());
  std::nth_element(smallest.begin(), smallest.begin() + smallest.size() / 2, smallest.end());
  EXPECT_GT(smallest[smallest.size() / 2], 15.0);
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
}

// Boundary edges marked "e:crease" keep the rule of crease edges: never split, their vertices stay,
// so the boundary polygon is kept exactly (to patch a hole in a mesh that is not refined).
TEST(Sqrt3, BoundaryEdgesMarkedAsCreasesAreKept) {
  SurfaceMesh m = build(test::grid(3, true));
  auto crease = m.add_edge_property<std::uint8_t>("e:crease", 0);
  for (Edge e : m.edges()) crease[e] = m.is_boundary(e);
  const SurfaceMesh before = m;
  subdivide(m, Subdivision::sqrt3, 2);
  for (Edge e : before.edges())
    if (before.is_boundary(e)) EXPECT_EQ(m.vertices(e), before.vertices(e));
  for (Vertex v : before.vertices())
    if (before.is_boundary(v)) EXPECT_EQ(m.position(v), before.position(v));
  EXPECT_EQ(boundary_edges(m), 12u);
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
}

TEST(Sqrt3, ARegularVertexMovesByKobbeltsRuleAndTendsToItsLimit) {
  SurfaceMesh m = test::bumpy_lattice(11);
  const Vertex centre = test::lattice_centre();
  ASSERT_EQ(m.valence(centre), 6u);
  const Vec3d mean = test::neighbour_sum(m, centre) * (1.0 / 6);
  const Vec3d p = to_double(m.position(centre));
  // Valence 6: a = (4 - 2 cos 60deg) / 9 = 1/3. The limit of (p, mean) under one step's matrix
  // [[1 - a, a], [1/3, 2/3]] is p / (1 + 3a) + mean * 3a / (1 + 3a) = (p + mean) / 2.
  const Vec3d one = p * (2.0 / 3) + mean * (1.0 / 3), limit = (p + mean) * 0.5;
  subdivide(m, Subdivision::sqrt3, 1);
  EXPECT_TRUE(test::near(m.position(centre), one, 1e-5));
  subdivide(m, Subdivision::sqrt3, 6);  // the other eigenvalue is 1/3: 3^-7 of the start is left
  EXPECT_TRUE(test::near(m.position(centre), limit, 1e-3));
  EXPECT_TRUE(m.validate().empty());
}

// The icosahedron on the unit sphere: its faces are the vertex triples at mutual distance 2 (before
// scaling), turned to face outward.
IndexedMesh icosahedron() {
  IndexedMesh m;
  const float g = 1.6180340f;
  for (float a : {-1.f, 1.f})
    for (float b : {-g, g}) m.positions.insert(m.positions.end(), {{0, a, b}, {a, b, 0}, {b, 0, a}});
  for (Index i = 0; i < 12; ++i)
    for (Index j = i + 1; j < 12; ++j)
      for (Index k = j + 1; k < 12; ++k) {
        const Vec3 a = m.positions[i], b = m.positions[j], c = m.positions[k];
        if (std::abs(norm(to_double(a - b)) - 2) > 1e-3 || std::abs(norm(to_double(b - c)) - 2) > 1e-3 ||
            std::abs(norm(to_double(c - a)) - 2) > 1e-3)
          continue;
        const Vec3d n = cross(to_double(b - a), to_double(c - a));
        if (dot(n, to_double(a)) > 0)
          m.indices.insert(m.indices.end(), {i, j, k});
        else
          m.indices.insert(m.indices.end(), {i, k, j});
      }
  for (Vec3& p : m.positions) p = to_float(to_double(p) * (1.0 / norm(to_double(p))));
  return m;
}

TEST(Sqrt3, ASphereStaysRound) {
  SurfaceMesh m = build(icosahedron());
  ASSERT_EQ(m.n_faces(), 20u);
  ASSERT_TRUE(m.validate().empty());
  subdivide(m, Subdivision::midpoint, 2);
  for (Vertex v : m.vertices())
    m.position(v) = to_float(to_double(m.position(v)) * (1.0 / norm(to_double(m.position(v)))));
  subdivide(m, Subdivision::sqrt3, 3);
  double lo = 1e9, hi = 0;
  for (Vertex v : m.vertices()) {
    const double r = norm(to_double(m.position(v)));
    lo = std::min(lo, r), hi = std::max(hi, r);
  }
  EXPECT_LE(hi, 1.0 + 1e-6);  // smoothing only averages points of the ball
  EXPECT_GT(lo, 0.97);        // it shrinks a little, as an approximating scheme does
  EXPECT_LT(hi / lo, 1.01);   // and stays round
  EXPECT_EQ(m.n_faces(), 320u * 27);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Sqrt3, CreaseEdgesAreKeptAndTheirCornersStay) {
  IndexedMesh tri;
  tri.positions = test::cube().positions;
  tri.indices = {0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  SurfaceMesh m = build(tri);
  auto crease = m.add_edge_property<std::uint8_t>("e:crease", 0);
  for (Edge e : m.edges()) {
    const Vec3 d = m.position(m.vertex(e, 0)) - m.position(m.vertex(e, 1));
    crease[e] = (d.x != 0) + (d.y != 0) + (d.z != 0) == 1;  // a cube edge, not a face diagonal
  }
  const SurfaceMesh before = m;
  subdivide(m, Subdivision::sqrt3, 2);
  for (Edge e : before.edges())
    if (crease[e]) {
      EXPECT_EQ(m.vertices(e), before.vertices(e));
      EXPECT_TRUE(m.get_edge_property<std::uint8_t>("e:crease")[e]);
    }
  for (Index corner = 0; corner < 8; ++corner)
    EXPECT_EQ(m.position(Vertex(corner)), before.position(Vertex(corner)));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Sqrt3, PropertiesFollowAndTheLogResets) {
  SurfaceMesh m = with_planar_texcoords(test::triangle_lattice(4));
  auto id = m.add_face_property<int>("f:id", -1);
  for (Face f : m.faces()) id[f] = int(f.idx()) * 10;
  auto weight = m.add_vertex_property<float>("v:weight", 0);
  for (Vertex v : m.vertices()) weight[v] = float(v.idx());
  const SurfaceMesh before = m;
  const ChangeConsumer watch(m.watch_changes());
  subdivide(m, Subdivision::sqrt3);
  EXPECT_TRUE(watch.pending().reset);
  expect_texcoords_follow_positions(before, m);
  const auto after = m.get_face_property<int>("f:id");
  for (Face f : m.faces()) EXPECT_EQ(after[f], int(f.idx() / 3) * 10);
  const auto w = m.get_vertex_property<float>("v:weight");
  for (Face f : before.faces()) {
    float sum = 0;
    for (Vertex v : before.vertices(f)) sum += float(v.idx());
    EXPECT_FLOAT_EQ(w[Vertex(Index(before.vertex_slots() + f.idx()))], sum / 3);
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Sqrt3, PolygonsAreRefusedUnchanged) {
  SurfaceMesh quads = build(test::grid(2, false));
  EXPECT_TRUE(test::refused_unchanged(quads, Subdivision::sqrt3, 1,
                                      "sqrt3 scheme needs triangles, and face 0 has 4 corners"));
  EXPECT_TRUE(quads.validate().empty());
}

TEST(SplitFaces, PolygonsFanAboutTheirCentroidsAndNothingMoves) {
  SurfaceMesh m =
      read_mesh(test::data_path("spot_control_mesh.obj"));  // 4 triangles, 160 quads, 16 pentagons
  const SurfaceMesh before = m;
  const test::Counts c = test::counts(m);
  const std::size_t seams_before = test::seam_edges(m);
  subdivide(m, Subdivision::split_faces, 1);
  const std::size_t corners = 4 * 3 + 160 * 4 + 16 * 5;
  EXPECT_EQ(m.n_faces(), corners);
  EXPECT_EQ(m.n_vertices(), c.v + c.f);
  EXPECT_EQ(m.n_edges(), c.e + corners);
  EXPECT_TRUE(m.is_triangle_mesh());
  for (Vertex v : before.vertices()) EXPECT_EQ(m.position(v), before.position(v));
  for (Face f : before.faces()) EXPECT_EQ(m.position(Vertex(Index(c.v + f.idx()))), face_centroid(before, f));
  EXPECT_EQ(test::seam_edges(m), seams_before);  // spokes run inside faces: no seam crosses them
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();

  SurfaceMesh tet = build(test::tetrahedron());  // planar faces: the volume stays
  const double v0 = volume(tet);
  subdivide(tet, Subdivision::split_faces, 2);
  EXPECT_NEAR(volume(tet), v0, 1e-6);

  SurfaceMesh grid = with_planar_texcoords(test::grid(3, false));
  const SurfaceMesh flat = grid;
  subdivide(grid, Subdivision::split_faces, 2);
  EXPECT_EQ(grid.n_faces(), 9u * 4 * 3);
  EXPECT_EQ(grid.boundary_loops().size(), 1u);
  for (Edge e : flat.edges()) EXPECT_EQ(grid.vertices(e), flat.vertices(e));  // old edges keep their index
  EXPECT_TRUE(grid.validate().empty());
}

TEST(SplitFaces, ProgressRisesToOnePerStep) {
  SurfaceMesh m = build(test::tetrahedron());
  std::vector<double> seen;
  subdivide(m, Subdivision::split_faces, 3, [&](double f) { seen.push_back(f); });
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(seen.front(), 0.0);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_GT(seen[i], seen[i - 1]);
  EXPECT_EQ(m.n_faces(), 4u * 27);
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

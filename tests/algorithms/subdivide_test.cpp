#include "hedge/algorithms/subdivide.h"

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
#include "hedge/core/build.h"
#include "hedge/core/changes.h"
#include "hedge/core/operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "test_meshes.h"

namespace hedge {
namespace {

struct Counts {
  std::size_t v, e, f, loops;
};
Counts counts(const SurfaceMesh& m) {
  return {m.n_vertices(), m.n_edges(), m.n_faces(), m.boundary_loops().size()};
}

// Seam edges: the two faces of an edge disagree on the texcoords at one of its ends.
std::size_t seam_edges(const SurfaceMesh& s) {
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
void expect_boundary_curve_rule(const SurfaceMesh& before, const SurfaceMesh& after) {
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

TEST(Subdivide, CountsAfterStepsOnClosedAndOpenMeshes) {
  for (Subdivision scheme : {Subdivision::loop, Subdivision::midpoint}) {
    SurfaceMesh tet = build(test::tetrahedron());
    subdivide(tet, scheme, 1);
    EXPECT_EQ(tet.n_vertices(), 10u);
    EXPECT_EQ(tet.n_edges(), 24u);
    EXPECT_EQ(tet.n_faces(), 16u);
    subdivide(tet, scheme, 2);
    EXPECT_EQ(tet.n_faces(), 256u);
    EXPECT_EQ(long(tet.n_vertices()) - long(tet.n_edges()) + long(tet.n_faces()), 2);
    EXPECT_TRUE(tet.validate().empty()) << tet.validate().front();

    SurfaceMesh grid = build(test::grid(3, true));  // 16 V, 33 E, 18 F, one loop of 12 edges
    const Counts c = counts(grid);
    subdivide(grid, scheme, 1);
    EXPECT_EQ(grid.n_vertices(), c.v + c.e);
    EXPECT_EQ(grid.n_edges(), 2 * c.e + 3 * c.f);
    EXPECT_EQ(grid.n_faces(), 4 * c.f);
    EXPECT_EQ(grid.boundary_loops().size(), 1u);
    std::size_t boundary_edges = 0;
    for (Edge e : grid.edges()) boundary_edges += grid.is_boundary(e);
    EXPECT_EQ(boundary_edges, 24u);
    EXPECT_TRUE(grid.validate().empty()) << grid.validate().front();
  }
}

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
  IndexedMesh in = test::triangle_lattice(10);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  for (Vec3& p : in.positions) p.z = u(rng);
  SurfaceMesh m = build(in);
  const Vertex centre(Index(5 * 11 + 5));
  ASSERT_EQ(m.valence(centre), 6u);
  Vec3d sum{0, 0, 0};
  for (Vertex w : m.vertices(centre)) sum += to_double(m.position(w));
  const Vec3d limit = to_double(m.position(centre)) * 0.5 + sum * (1.0 / 12);
  subdivide(m, Subdivision::loop, 6);  // old vertices keep their index
  EXPECT_NEAR(m.position(centre).x, limit.x, 2e-3);
  EXPECT_NEAR(m.position(centre).y, limit.y, 2e-3);
  EXPECT_NEAR(m.position(centre).z, limit.z, 2e-3);
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
  expect_boundary_curve_rule(before, m);
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

TEST(Subdivide, CornerTexcoordsKeepTheirSeams) {
  SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  const auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(uv);
  const std::size_t seams_before = seam_edges(m);
  ASSERT_GT(seams_before, 10u);
  subdivide(m, Subdivision::loop, 1);
  EXPECT_EQ(seam_edges(m), 2 * seams_before);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, FacePropertiesGoToTheChildrenAndTheLogResets) {
  SurfaceMesh m = build(test::grid(2, true));
  auto id = m.add_face_property<int>("f:id", -1);
  for (Face f : m.faces()) id[f] = int(f.idx()) * 10;
  const ChangeConsumer watch(m.watch_changes());
  subdivide(m, Subdivision::loop);
  EXPECT_TRUE(watch.pending().reset);
  const auto after = m.get_face_property<int>("f:id");
  for (Face f : m.faces()) EXPECT_EQ(after[f], int(f.idx() / 4) * 10);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, DeletedElementsAreCollectedFirst) {
  SurfaceMesh m = build(test::grid(3, true));
  ASSERT_TRUE(remove_face(m, Face(4)));
  const std::size_t faces = m.n_faces();
  subdivide(m, Subdivision::loop);
  EXPECT_EQ(m.n_faces(), 4 * faces);
  EXPECT_FALSE(m.has_garbage());
  EXPECT_TRUE(m.validate().empty());
}

TEST(Subdivide, PolygonsAndBadStepsAreRefusedUnchanged) {
  SurfaceMesh quads = build(test::grid(2, false));
  try {
    subdivide(quads, Subdivision::loop);
    FAIL() << "quads were subdivided";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("face 0 has 4 corners"), std::string::npos) << e.what();
  }
  EXPECT_EQ(quads.n_faces(), 4u);
  SurfaceMesh tet = build(test::tetrahedron());
  EXPECT_THROW(subdivide(tet, Subdivision::loop, -1), InvalidInputError);
  EXPECT_THROW(subdivide(tet, Subdivision::loop, 20), InvalidInputError);
  EXPECT_EQ(tet.n_faces(), 4u);
  subdivide(tet, Subdivision::midpoint, 0);
  EXPECT_EQ(tet.n_faces(), 4u);
  SurfaceMesh empty;
  subdivide(empty, Subdivision::loop, 3);
  EXPECT_EQ(empty.n_faces(), 0u);
  EXPECT_TRUE(tet.validate().empty());
}

TEST(Subdivide, TheMemoryEstimateBoundsTheResultAndABudgetRefusesBeforeAllocating) {
  SurfaceMesh tet = build(test::tetrahedron());
  const std::size_t plain = subdivide_memory(tet, Subdivision::loop, 3);
  tet.add_vertex_property<double>("v:weight", 0);  // properties count in the estimate
  EXPECT_GT(subdivide_memory(tet, Subdivision::loop, 3), plain);
  EXPECT_EQ(subdivide_memory(tet, Subdivision::loop, 0), 0u);
  EXPECT_THROW((void)subdivide_memory(tet, Subdivision::loop, -1), InvalidInputError);
  // Each step of the 1-to-4 schemes makes about four times the memory.
  const std::size_t five = subdivide_memory(tet, Subdivision::loop, 5),
                    six = subdivide_memory(tet, Subdivision::loop, 6);
  EXPECT_GT(six, 3 * five);
  EXPECT_LT(six, 5 * five);
  // Astronomically many steps saturate instead of overflowing.
  EXPECT_EQ(subdivide_memory(tet, Subdivision::loop, 100), std::numeric_limits<std::size_t>::max());
  for (Subdivision scheme :
       {Subdivision::loop, Subdivision::catmull_clark, Subdivision::sqrt3, Subdivision::split_faces}) {
    SurfaceMesh m = tet;
    const std::size_t estimate = subdivide_memory(m, scheme, 4);
    subdivide(m, scheme, 4, {}, estimate);  // the estimate is a budget that suffices
    // It covers the result (the last mesh made) and is not far above the two last meshes.
    EXPECT_GE(estimate, m.memory_bytes()) << int(scheme);
    EXPECT_LT(estimate, 4 * m.memory_bytes()) << int(scheme);
  }

  // A budget one byte short: refused, the mesh untouched, and almost nothing allocated.
  const std::size_t need = subdivide_memory(tet, Subdivision::loop, 6);
  const long before = test::heap_allocations();
  try {
    subdivide(tet, Subdivision::loop, 6, {}, need - 1);
    FAIL() << "no error past the budget";
  } catch (const InvalidInputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("6 steps would need about"), std::string::npos) << what;
    EXPECT_NE(what.find("at most 5 steps fit"), std::string::npos) << what;
  }
  EXPECT_LT(test::heap_allocations() - before, 200);  // the message and the checks' threads, no mesh
  EXPECT_EQ(tet.n_faces(), 4u);
  EXPECT_TRUE(tet.validate().empty());
  // 0: no budget.
  subdivide(tet, Subdivision::loop, 2, {}, 0);
  EXPECT_EQ(tet.n_faces(), 64u);
}

// ---- The strong guarantee: an allocation that fails anywhere in a step leaves the mesh as it was ----

// A triangle mesh with garbage, a boundary, a crease, and a property of every kind (one of them a
// std::string, whose copies allocate).
SurfaceMesh mesh_with_everything(bool triangles) {
  SurfaceMesh m = build(test::grid(3, triangles));
  auto name = m.add_vertex_property<std::string>("v:name", "");
  auto weight = m.add_vertex_property<float>("v:weight", 0.f);
  for (Vertex v : m.vertices())
    name[v] = "vertex number " + std::to_string(v.idx()), weight[v] = float(v.idx());
  auto uv = m.add_halfedge_property<Vec2>("h:texcoord", Vec2{0, 0});
  for (Halfedge h : m.halfedges()) uv[h] = Vec2{float(h.idx()), 1.f};
  auto crease = m.add_edge_property<std::uint8_t>("e:crease", 0);
  crease[Edge(5)] = 1;
  auto tag = m.add_face_property<std::string>("f:tag", "none");
  for (Face f : m.faces()) tag[f] = "the tag of face number " + std::to_string(f.idx());
  EXPECT_TRUE(remove_face(m, Face(1)));
  return m;
}

// Every count, link, deletion flag, position and property value of a equals b's.
void expect_identical(const SurfaceMesh& a, const SurfaceMesh& b) {
  ASSERT_EQ(a.vertex_slots(), b.vertex_slots());
  ASSERT_EQ(a.edge_slots(), b.edge_slots());
  ASSERT_EQ(a.face_slots(), b.face_slots());
  EXPECT_EQ(a.n_vertices(), b.n_vertices());
  EXPECT_EQ(a.n_edges(), b.n_edges());
  EXPECT_EQ(a.n_faces(), b.n_faces());
  EXPECT_TRUE(a.halfedge_vertex_array() == b.halfedge_vertex_array());
  EXPECT_TRUE(a.halfedge_next_array() == b.halfedge_next_array());
  EXPECT_TRUE(a.halfedge_face_array() == b.halfedge_face_array());
  EXPECT_TRUE(a.vertex_halfedge_array() == b.vertex_halfedge_array());
  EXPECT_TRUE(a.face_halfedge_array() == b.face_halfedge_array());
  for (Vertex v : a.vertices()) EXPECT_EQ(a.is_deleted(v), b.is_deleted(v));
  for (Edge e : a.edges()) EXPECT_EQ(a.is_deleted(e), b.is_deleted(e));
  for (Face f : a.faces()) EXPECT_EQ(a.is_deleted(f), b.is_deleted(f));
  EXPECT_EQ(a.vertex_properties().names(), b.vertex_properties().names());
  EXPECT_EQ(a.halfedge_properties().names(), b.halfedge_properties().names());
  EXPECT_EQ(a.edge_properties().names(), b.edge_properties().names());
  EXPECT_EQ(a.face_properties().names(), b.face_properties().names());
  EXPECT_TRUE(a.positions().vector() == b.positions().vector());
  EXPECT_TRUE(a.get_vertex_property<std::string>("v:name").vector() ==
              b.get_vertex_property<std::string>("v:name").vector());
  EXPECT_TRUE(a.get_vertex_property<float>("v:weight").vector() ==
              b.get_vertex_property<float>("v:weight").vector());
  EXPECT_TRUE(a.get_halfedge_property<Vec2>("h:texcoord").vector() ==
              b.get_halfedge_property<Vec2>("h:texcoord").vector());
  EXPECT_TRUE(a.get_edge_property<std::uint8_t>("e:crease").vector() ==
              b.get_edge_property<std::uint8_t>("e:crease").vector());
  EXPECT_TRUE(a.get_face_property<std::string>("f:tag").vector() ==
              b.get_face_property<std::string>("f:tag").vector());
}

// Fails the k-th allocation of subdivide(m, scheme, steps) for k = 0, 1, ... until a call gets
// through: each failed call must leave m identical to the input and valid; the call that gets
// through must give what a call without failures gives.
void expect_strong_guarantee(Subdivision scheme, bool triangles, int steps) {
  const SurfaceMesh input = mesh_with_everything(triangles);
  SurfaceMesh reference = input;
  subdivide(reference, scheme, steps);
  int failures = 0;
  for (long k = 0;; ++k) {
    SurfaceMesh m = input;
    const auto name = m.get_vertex_property<std::string>("v:name");  // a handle held across the call
    bool threw = false;
    test::fail_allocation_after(k);  // tests/heap_hooks.h
    try {
      subdivide(m, scheme, steps);
    } catch (const std::bad_alloc&) {
      threw = true;
    }
    test::disarm_allocation_failure();
    if (!threw) {
      expect_identical(m, reference);
      EXPECT_EQ(name.vector().size(), m.vertex_slots());  // the handle sees the refined mesh
      EXPECT_TRUE(m.validate().empty());
      break;
    }
    ++failures;
    SCOPED_TRACE("allocation " + std::to_string(k) + " failed");
    EXPECT_TRUE(m.validate().empty());
    expect_identical(m, input);
    ASSERT_LT(k, 100000) << "subdivide never got through";
    if (::testing::Test::HasFailure()) break;
  }
  // Every step allocates its arrays, properties and threads: many points were tried.
  EXPECT_GT(failures, 100 * steps);
}

TEST(Subdivide, AnAllocationFailureAnywhereLeavesTheMeshAsItWas) {
  for (Subdivision scheme : {Subdivision::loop, Subdivision::midpoint, Subdivision::sqrt3,
                             Subdivision::split_faces, Subdivision::catmull_clark})
    for (int steps : {1, 2}) {
      SCOPED_TRACE("scheme " + std::to_string(int(scheme)) + ", steps " + std::to_string(steps));
      expect_strong_guarantee(scheme, true, steps);
    }
  SCOPED_TRACE("Catmull-Clark of quads");
  expect_strong_guarantee(Subdivision::catmull_clark, false, 2);
}

TEST(Subdivide, PropertyHandlesStayValidAndAProgressThatThrowsKeepsTheStepsDone) {
  SurfaceMesh m = build(test::grid(2, true));
  auto weight = m.add_vertex_property<float>("v:weight", 0.f);
  for (Vertex v : m.vertices()) weight[v] = 1.f;
  const std::size_t faces = m.n_faces();
  int calls = 0;
  const Progress stop_after_first = [&](double f) {
    if (f > 0 && ++calls == 1) throw std::runtime_error("cancelled");
  };
  EXPECT_THROW(subdivide(m, Subdivision::loop, 3, stop_after_first), std::runtime_error);
  EXPECT_EQ(m.n_faces(), 4 * faces);  // the first step stays done
  ASSERT_EQ(weight.vector().size(), m.vertex_slots());
  for (Vertex v : m.vertices()) EXPECT_EQ(weight[v], 1.f);  // new vertices average their edge's ends
  EXPECT_TRUE(m.validate().empty());
}

// ---- Catmull-Clark ----

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
  const Counts c = counts(m);
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
  expect_boundary_curve_rule(before, one);
  EXPECT_TRUE(m.validate().empty());
}

TEST(CatmullClark, TexcoordSeamsAndFacePropertiesFollow) {
  SurfaceMesh m = read_mesh(test::data_path("spot_control_mesh.obj"));
  ASSERT_TRUE(m.get_halfedge_property<Vec2>("h:texcoord"));
  auto id = m.add_face_property<int>("f:id", -1);
  for (Face f : m.faces()) id[f] = int(f.idx());
  std::vector<int> corners_of(m.face_slots());
  for (Face f : m.faces()) corners_of[f.idx()] = int(m.valence(f));
  const std::size_t seams_before = seam_edges(m);
  ASSERT_GT(seams_before, 0u);
  subdivide(m, Subdivision::catmull_clark, 1);
  EXPECT_EQ(seam_edges(m), 2 * seams_before);
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
  const Counts c = counts(grid);
  subdivide(grid, Subdivision::sqrt3, 2);
  EXPECT_EQ(grid.n_vertices(), c.v + c.f + 3 * c.f);
  EXPECT_EQ(grid.n_edges(), c.e + 3 * c.f + 3 * (3 * c.f));
  EXPECT_EQ(grid.n_faces(), 9 * c.f);
  EXPECT_EQ(grid.boundary_loops().size(), 1u);
  // Boundary edges are neither split nor flipped, and boundary vertices stay.
  for (Edge e : before.edges()) {
    EXPECT_EQ(grid.is_boundary(e), before.is_boundary(e));
    if (before.is_boundary(e)) EXPECT_EQ(grid.vertices(e), before.vertices(e));
  }
  for (Vertex v : before.vertices())
    if (before.is_boundary(v)) EXPECT_EQ(grid.position(v), before.position(v));
  EXPECT_TRUE(grid.validate().empty()) << grid.validate().front();
}

TEST(Sqrt3, ARegularVertexMovesByKobbeltsRuleAndTendsToItsLimit) {
  IndexedMesh in = test::triangle_lattice(10);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f);
  for (Vec3& p : in.positions) p.z = u(rng);
  SurfaceMesh m = build(in);
  const Vertex centre(Index(5 * 11 + 5));
  ASSERT_EQ(m.valence(centre), 6u);
  Vec3d mean{0, 0, 0};
  for (Vertex w : m.vertices(centre)) mean += to_double(m.position(w)) * (1.0 / 6);
  const Vec3d p = to_double(m.position(centre));
  // Valence 6: a = (4 - 2 cos 60deg) / 9 = 1/3. The limit of (p, mean) under one step's matrix
  // [[1 - a, a], [1/3, 2/3]] is p / (1 + 3a) + mean * 3a / (1 + 3a) = (p + mean) / 2.
  const Vec3d one = p * (2.0 / 3) + mean * (1.0 / 3), limit = (p + mean) * 0.5;
  subdivide(m, Subdivision::sqrt3, 1);
  EXPECT_NEAR(m.position(centre).x, one.x, 1e-5);
  EXPECT_NEAR(m.position(centre).y, one.y, 1e-5);
  EXPECT_NEAR(m.position(centre).z, one.z, 1e-5);
  subdivide(m, Subdivision::sqrt3, 6);  // the other eigenvalue is 1/3: 3^-7 of the start is left
  EXPECT_NEAR(m.position(centre).x, limit.x, 1e-3);
  EXPECT_NEAR(m.position(centre).y, limit.y, 1e-3);
  EXPECT_NEAR(m.position(centre).z, limit.z, 1e-3);
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
  try {
    subdivide(quads, Subdivision::sqrt3);
    FAIL() << "quads were subdivided";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("sqrt3 scheme needs triangles, and face 0 has 4 corners"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(quads.n_faces(), 4u);
  EXPECT_TRUE(quads.validate().empty());
}

TEST(SplitFaces, PolygonsFanAboutTheirCentroidsAndNothingMoves) {
  SurfaceMesh m =
      read_mesh(test::data_path("spot_control_mesh.obj"));  // 4 triangles, 160 quads, 16 pentagons
  const SurfaceMesh before = m;
  const Counts c = counts(m);
  const std::size_t seams_before = seam_edges(m);
  subdivide(m, Subdivision::split_faces, 1);
  const std::size_t corners = 4 * 3 + 160 * 4 + 16 * 5;
  EXPECT_EQ(m.n_faces(), corners);
  EXPECT_EQ(m.n_vertices(), c.v + c.f);
  EXPECT_EQ(m.n_edges(), c.e + corners);
  EXPECT_TRUE(m.is_triangle_mesh());
  for (Vertex v : before.vertices()) EXPECT_EQ(m.position(v), before.position(v));
  for (Face f : before.faces()) EXPECT_EQ(m.position(Vertex(Index(c.v + f.idx()))), face_centroid(before, f));
  EXPECT_EQ(seam_edges(m), seams_before);  // spokes run inside faces: no seam crosses them
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

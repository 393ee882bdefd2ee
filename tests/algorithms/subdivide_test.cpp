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
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "subdivide_test_util.h"
#include "test_meshes.h"

namespace hedge {
namespace {

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
    const test::Counts c = test::counts(grid);
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

TEST(Subdivide, CornerTexcoordsKeepTheirSeams) {
  SurfaceMesh m = read_mesh(test::data_path("spot_triangulated.obj"));
  const auto uv = m.get_halfedge_property<Vec2>("h:texcoord");
  ASSERT_TRUE(uv);
  const std::size_t seams_before = test::seam_edges(m);
  ASSERT_GT(seams_before, 10u);
  subdivide(m, Subdivision::loop, 1);
  EXPECT_EQ(test::seam_edges(m), 2 * seams_before);
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
  EXPECT_TRUE(test::refused_unchanged(quads, Subdivision::loop, 1, "face 0 has 4 corners"));
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

TEST(Subdivide, RefusesANonFinitePositionBeforeRefining) {
  SurfaceMesh m = build(test::cube());
  for (Subdivision s : {Subdivision::catmull_clark, Subdivision::split_faces})
    test::expect_refuses_non_finite(m, Vertex(3), "subdivide", [&] { subdivide(m, s, 1); });
  SurfaceMesh t = build(test::tetrahedron());
  for (Subdivision s : {Subdivision::loop, Subdivision::midpoint, Subdivision::sqrt3})
    test::expect_refuses_non_finite(t, Vertex(1), "subdivide", [&] { subdivide(t, s, 1); });
}

}  // namespace
}  // namespace hedge

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
  for (const auto& p : problems)
    if (p.find(what) != std::string::npos) return true;
  return false;
}

TEST(Validate, BuiltMeshesAreValid) {
  EXPECT_TRUE(build(test::tetrahedron()).validate().empty());
  EXPECT_TRUE(build(test::cube()).validate().empty());
  EXPECT_TRUE(build(test::grid(5, true)).validate().empty());
  EXPECT_TRUE(SurfaceMesh().validate().empty());
}

TEST(Validate, BrokenNextIsReported) {
  SurfaceMesh m = build(test::tetrahedron());
  Halfedge h(0);
  m.set_next(h, m.next(m.next(h)));  // skip one: a face cycle of two, and a half-edge with no predecessor
  auto p = m.validate();
  EXPECT_FALSE(p.empty());
  EXPECT_TRUE(mentions(p, "next/prev not inverse")) << p.front();
}

TEST(Validate, WrongVertexAtNextIsReported) {
  SurfaceMesh m = build(test::tetrahedron());
  Halfedge h(0);
  m.set_vertex(h, m.to_vertex(m.next(h)));
  EXPECT_TRUE(mentions(m.validate(), "but its next"));
}

TEST(Validate, BoundaryVertexMustHoldBoundaryHalfedge) {
  SurfaceMesh m = build(test::grid(2, false));
  Vertex corner(0);
  Halfedge interior;
  for (Halfedge h : m.halfedges(corner))
    if (!m.is_boundary(h)) interior = h;
  ASSERT_TRUE(interior.is_valid());
  m.set_halfedge(corner, interior);
  EXPECT_TRUE(mentions(m.validate(), "is on a boundary but its half-edge"));
}

TEST(Validate, ReferencesToDeletedElementsAreReported) {
  SurfaceMesh m = build(test::tetrahedron());
  m.mark_deleted(Vertex(2));
  EXPECT_TRUE(mentions(m.validate(), "dead or invalid vertex 2"));
  SurfaceMesh m2 = build(test::tetrahedron());
  m2.mark_deleted(Face(1));
  EXPECT_TRUE(mentions(m2.validate(), "dead or invalid face 1"));
}

TEST(Validate, FaceHalfedgeOfAnotherFaceIsReported) {
  SurfaceMesh m = build(test::tetrahedron());
  m.set_halfedge(Face(0), m.halfedge(Face(1)));
  auto p = m.validate();
  EXPECT_TRUE(mentions(p, "face 0: its halfedge")) << (p.empty() ? "" : p.front());
}

TEST(Validate, DanglingEdgeAndLoopAreReported) {
  SurfaceMesh m;
  Vertex a = m.add_vertex({0, 0, 0});
  Vertex b = m.add_vertex({1, 0, 0});
  Halfedge h = m.new_edge(a, b);
  m.set_next(h, m.twin(h));
  m.set_next(m.twin(h), h);
  m.set_halfedge(a, h);
  m.set_halfedge(b, m.twin(h));
  EXPECT_TRUE(mentions(m.validate(), "dangling edge"));
  Halfedge l = m.new_edge(a, a);
  m.set_next(l, m.twin(l));
  m.set_next(m.twin(l), l);
  EXPECT_TRUE(mentions(m.validate(), "is a loop"));
}

TEST(Validate, PinchedVertexIsReported) {
  // Two triangles glued by hand at a vertex, with the boundary loops closed through it in two
  // separate cycles: every local link is right, but rotation about the vertex sees only one fan.
  SurfaceMesh a = build(test::grid(1, true));  // a square of two triangles
  EXPECT_TRUE(a.validate().empty());
  IndexedMesh bowtie;
  bowtie.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bowtie.indices = {0, 1, 2, 0, 3, 4};
  BuildOptions o;
  o.policy = TopologyPolicy::repair;
  SurfaceMesh m = build(bowtie, o);
  ASSERT_EQ(m.n_vertices(), 6u);
  // Undo the split: point every half-edge entering vertex 5 back to vertex 0.
  for (Halfedge h : m.halfedges())
    if (m.to_vertex(h) == Vertex(5)) m.set_vertex(h, Vertex(0));
  m.set_halfedge(Vertex(5), Halfedge());
  auto p = m.validate();
  EXPECT_TRUE(mentions(p, "vertex 0 is non-manifold")) << (p.empty() ? "" : p.front());
}

TEST(Validate, NonFinitePositionsAreNamedBesideTheConnectivity) {
  SurfaceMesh m = build(test::cube());
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  m.position(Vertex(2)) = {nan, 0, 1};
  m.position(Vertex(5)) = {0, -inf, 0};
  EXPECT_EQ(m.validate(), (std::vector<std::string>{"vertex 2 has a non-finite position (nan, 0, 1)",
                                                    "vertex 5 has a non-finite position (0, -inf, 0)"}));
  // A bad position does not hide a broken link.
  m.set_next(Halfedge(0), m.next(m.next(Halfedge(0))));
  const auto p = m.validate();
  EXPECT_TRUE(mentions(p, "vertex 2 has a non-finite position"));
  EXPECT_TRUE(mentions(p, "next/prev not inverse"));
  // A deleted vertex's position is not looked at.
  SurfaceMesh g = build(test::grid(2, true));
  test::poison(g, Vertex(4));
  ASSERT_TRUE(remove_vertex(g, Vertex(4)));
  EXPECT_EQ(g.validate(), std::vector<std::string>{});
}

TEST(Validate, NonFinitePositionsAreCappedLikeOtherProblems) {
  SurfaceMesh m = build(test::grid(40, true));  // 41 x 41 vertices
  for (Vertex v : m.vertices()) test::poison(m, v);
  const auto p = m.validate();
  ASSERT_EQ(p.size(), 1001u);
  EXPECT_EQ(p.back(), "... and 681 more problems");
}

TEST(RequireFinitePositions, NamesTheFirstBadVertex) {
  SurfaceMesh m = build(test::grid(3, true));
  require_finite_positions(m, "check");
  test::expect_refuses_non_finite(m, Vertex(5), "check", [&] { require_finite_positions(m, "check"); });
  // An infinity is refused as a NaN is.
  m.position(Vertex(3)).z = -std::numeric_limits<float>::infinity();
  EXPECT_THROW(require_finite_positions(m, "check"), InvalidInputError);
  m.position(Vertex(3)).z = 0;
  // A deleted vertex's position is not looked at.
  test::poison(m, Vertex(5));
  ASSERT_TRUE(remove_vertex(m, Vertex(5)));
  require_finite_positions(m, "check");
  EXPECT_EQ(m.validate(), std::vector<std::string>{});
}

}  // namespace
}  // namespace hedge

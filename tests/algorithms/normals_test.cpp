#include "hedge/algorithms/normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "non_finite.h"
#include "test_meshes.h"

namespace hedge {
namespace {

void expect_near(const Vec3& a, const Vec3& b, double eps = 1e-6) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// The outward diagonal direction at a corner of the unit cube.
Vec3 diagonal(const Vec3& p) {
  const float s = 1 / std::sqrt(3.f);
  return {p.x > 0.5f ? s : -s, p.y > 0.5f ? s : -s, p.z > 0.5f ? s : -s};
}

TEST(Normals, FaceNormalFollowsTheWinding) {
  const SurfaceMesh m = build(test::cube());
  for (Face f : m.faces()) {
    const Vec3 n = face_normal(m, f);
    // Outward: the face's centre minus the cube's centre points the same way.
    Vec3 c{0, 0, 0};
    for (Vertex v : m.vertices(f)) c += m.position(v) * 0.25f;
    const Vec3 out = c - Vec3{0.5f, 0.5f, 0.5f};
    expect_near(n, out * 2.f);
  }
  // A face whose corners lie on a line: zero.
  SurfaceMesh flat = build(test::tetrahedron());
  for (Vertex v : flat.vertices()) flat.set_position(v, Vec3{float(v.idx()), 0, 0});
  for (Face f : flat.faces()) EXPECT_EQ(face_normal(flat, f), (Vec3{0, 0, 0}));
}

TEST(Normals, AngleWeightingIsIndependentOfTheTriangulation) {
  // The triangulated cube: a corner has one or two triangles of each of its three sides.
  SurfaceMesh m = build(to_indexed(build(test::cube()), {.triangulation = Triangulation::fan}));
  const auto angle = compute_vertex_normals(m, NormalWeighting::angle);
  for (Vertex v : m.vertices()) expect_near(angle[v], diagonal(m.position(v)));
  // Area and uniform weighting see the extra triangles: at some corner they lean off the diagonal.
  const auto area = compute_vertex_normals(m, NormalWeighting::area, "v:area_normal");
  const auto uniform = compute_vertex_normals(m, NormalWeighting::uniform, "v:uniform_normal");
  double off_area = 0, off_uniform = 0;
  for (Vertex v : m.vertices()) {
    EXPECT_NEAR(norm(area[v]), 1, 1e-6);
    const Vec3 d = diagonal(m.position(v));
    off_area = std::max(off_area, double(norm(area[v] - d)));
    off_uniform = std::max(off_uniform, double(norm(uniform[v] - d)));
  }
  EXPECT_GT(off_area, 0.05);
  EXPECT_GT(off_uniform, 0.05);
  EXPECT_TRUE(m.validate().empty());
}

// A 2 x 1 quad in z = 0 (area 2, normal +z) and a triangle of area 1/2 in x = 0 (normal +x) share
// the edge from (0, 0, 0) to (0, 1, 0). Worked by hand: at (0, 0, 0) area weighting gives
// (1/2, 0, 2) / sqrt(17/4), uniform weighting (1, 0, 1) / sqrt(2); with the triangle removed (its
// slot left as garbage) the quad's +z alone.
TEST(Normals, PolygonsWeighByAreaAndRemovedFacesAddNothing) {
  IndexedMesh in;
  in.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  in.indices = {0, 1, 2, 3, 0, 3, 4};
  in.face_sizes = {4, 3};
  SurfaceMesh m = build(in);
  const float r = 1 / std::sqrt(4.25f), s = 1 / std::sqrt(2.f);
  expect_near(compute_vertex_normals(m, NormalWeighting::area)[Vertex(0)], Vec3{0.5f * r, 0, 2 * r});
  expect_near(compute_vertex_normals(m, NormalWeighting::uniform, "v:u")[Vertex(0)], Vec3{s, 0, s});
  expect_near(compute_face_normals(m)[Face(0)], Vec3{0, 0, 1});
  expect_near(compute_face_normals(m)[Face(1)], Vec3{1, 0, 0});
  remove_face(m, Face(1));
  ASSERT_TRUE(m.has_garbage());
  expect_near(compute_vertex_normals(m, NormalWeighting::area)[Vertex(0)], Vec3{0, 0, 1});
  expect_near(compute_vertex_normals(m, NormalWeighting::angle, "v:a")[Vertex(3)], Vec3{0, 0, 1});
  EXPECT_TRUE(m.validate().empty());
}

// More faces than the loop reads ahead, some removed: every live face gets face_normal's value
// (the grid is bent over a paraboloid, so that the faces' normals differ), and the removed faces'
// slots keep what they held.
TEST(Normals, FaceNormalsOfAManyFacedMeshSkipRemovedFaces) {
  IndexedMesh in = test::grid(8, true);
  for (Vec3& p : in.positions) p.z = 0.05f * (p.x * p.x + 2 * p.y * p.y);
  SurfaceMesh m = build(in);
  ASSERT_EQ(m.n_faces(), 128u);
  FaceProperty<Vec3> n = compute_face_normals(m);
  const Vec3 mark{7, 7, 7};
  int removed = 0;
  for (Index f = 20; f < 128 && removed < 4; f += 17) {
    if (!can_remove_face(m, Face(f))) continue;
    remove_face(m, Face(f));
    n[Face(f)] = mark;
    ++removed;
  }
  ASSERT_EQ(removed, 4);
  ASSERT_TRUE(m.has_garbage());
  compute_face_normals(m);
  for (std::size_t f = 0; f < m.face_slots(); ++f) {
    if (m.is_deleted(Face(Index(f)))) {
      EXPECT_EQ(n[Face(Index(f))], mark) << "face " << f;
      continue;
    }
    expect_near(n[Face(Index(f))], face_normal(m, Face(Index(f))));
    EXPECT_NEAR(double(norm(to_double(n[Face(Index(f))]))), 1.0, 1e-6);
  }
  EXPECT_TRUE(m.validate().empty());
}

// compute_face_normals takes its faces in blocks and normalises four at a time; each triangle's
// normal is still, bit for bit, its two edges' cross product in float times 1 / sqrt of its
// squared length, or zero for a degenerate triangle. On a bent grid of more faces than a block,
// with faces removed and faces made degenerate.
TEST(Normals, FaceNormalsAreTheFloatCrossProductNormalisedBitForBit) {
  IndexedMesh in = test::grid(12, true);
  for (Vec3& p : in.positions) p.z = 0.37f * std::sin(3 * p.x) + 0.11f * p.x * p.y;
  in.positions[1] = in.positions[0];  // the faces at the edge 0-1 are degenerate
  SurfaceMesh m = build(in);
  ASSERT_GT(m.n_faces(), 200u);
  for (Index f = 30; f < 200; f += 41)
    if (can_remove_face(m, Face(f))) remove_face(m, Face(f));
  ASSERT_TRUE(m.has_garbage());
  const FaceProperty<Vec3> n = compute_face_normals(m);
  int zero = 0;
  for (Face f : m.faces()) {
    const Halfedge h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const Vec3 &p0 = m.position(m.to_vertex(h0)), &p1 = m.position(m.to_vertex(h1)),
               &p2 = m.position(m.to_vertex(h2));
    const float ax = p1.x - p0.x, ay = p1.y - p0.y, az = p1.z - p0.z;
    const float bx = p2.x - p0.x, by = p2.y - p0.y, bz = p2.z - p0.z;
    const Vec3 c{ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
    const float s = c.x * c.x + c.y * c.y + c.z * c.z;
    const float inv = s > 0 ? 1.f / std::sqrt(s) : 0.f;
    const Vec3 want = s > 0 ? Vec3{c.x * inv, c.y * inv, c.z * inv} : Vec3{0, 0, 0};
    zero += s == 0;
    EXPECT_EQ(n[f].x, want.x) << "face " << f.idx();
    EXPECT_EQ(n[f].y, want.y) << "face " << f.idx();
    EXPECT_EQ(n[f].z, want.z) << "face " << f.idx();
  }
  EXPECT_GT(zero, 0);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Normals, CornerNormalsSplitAtCreases) {
  SurfaceMesh m = build(to_indexed(build(test::cube()), {.triangulation = Triangulation::fan}));
  // 30 degrees: every edge of the cube is a crease, so every corner gets its face's normal.
  auto hard = compute_corner_normals(m, 30);
  for (Halfedge h : m.halfedges()) {
    if (m.is_boundary(h)) continue;
    expect_near(hard[h], face_normal(m, m.face(h)));
  }
  // 180 degrees: nothing is a crease; every corner gets its vertex's (angle-weighted) normal.
  auto smooth = compute_corner_normals(m, 180, NormalWeighting::angle, "h:smooth");
  for (Halfedge h : m.halfedges()) expect_near(smooth[h], diagonal(m.position(m.to_vertex(h))));
  // 0 degrees: flat shading even across the coplanar diagonals.
  auto flat = compute_corner_normals(m, 0, NormalWeighting::angle, "h:flat");
  for (Halfedge h : m.halfedges()) expect_near(flat[h], face_normal(m, m.face(h)));
  EXPECT_TRUE(m.validate().empty());
}

TEST(Normals, ARidgeIsAWedgeBoundaryOnlyBelowItsAngle) {
  // Two strips meeting at a ridge along x at 90 degrees (a roof), each two triangles deep, plus
  // their boundary: the ridge vertices have two wedges under a 45-degree crease, one under 100.
  IndexedMesh in;
  for (int i = 0; i < 3; ++i) {
    in.positions.push_back({float(i), 0, -1});  // 3i: left eave
    in.positions.push_back({float(i), 1, 0});   // 3i + 1: ridge
    in.positions.push_back({float(i), 0, 1});   // 3i + 2: right eave
  }
  for (Index i = 0; i < 2; ++i) {
    const Index a = 3 * i, b = 3 * i + 1, c = 3 * i + 2, d = 3 * i + 3, e = 3 * i + 4, f = 3 * i + 5;
    in.indices.insert(in.indices.end(), {a, b, e, a, e, d, b, c, f, b, f, e});
  }
  SurfaceMesh m = build(in);
  ASSERT_TRUE(m.validate().empty());
  auto sharp = compute_corner_normals(m, 45);
  auto soft = compute_corner_normals(m, 100, NormalWeighting::angle, "h:soft");
  const Vertex ridge(4);  // the middle of the ridge
  ASSERT_EQ(m.position(ridge), (Vec3{1, 1, 0}));
  for (Halfedge h : m.halfedges()) {
    if (m.is_boundary(h) || m.to_vertex(h) != ridge) continue;
    const Vec3 fn = face_normal(m, m.face(h));
    expect_near(sharp[h], fn);            // one side of the ridge or the other
    expect_near(soft[h], Vec3{0, 1, 0});  // the two sides blended: straight up
  }
  for (Halfedge h : m.halfedges())
    if (m.is_boundary(h)) EXPECT_EQ(sharp[h], (Vec3{0, 0, 0}));
}

TEST(Normals, CornersOfASmoothVertexGetItsVertexNormalBitForBit) {
  // An open scan: boundary vertices, and many creases under 20 degrees.
  SurfaceMesh m = read_mesh(test::data_path("elephant-with-holes.off"));
  ASSERT_GT(m.n_faces(), 1000u);
  for (NormalWeighting w : {NormalWeighting::area, NormalWeighting::angle, NormalWeighting::uniform}) {
    const auto vn = compute_vertex_normals(m, w);
    const auto smooth = compute_corner_normals(m, 180, w);
    const auto creased = compute_corner_normals(m, 20, w, "h:creased");
    // A vertex with no boundary edge and no crease edge is one wedge: its corners get the vertex
    // normal exactly, as if computed by compute_vertex_normals. (Edges within 1e-4 of the crease
    // angle's cosine are left out: the call rounds its face normals to float.)
    const float cos20 = float(std::cos(20 * std::numbers::pi / 180));
    auto one_wedge = [&](Vertex v) {
      for (Halfedge o : m.halfedges(v)) {
        if (m.is_boundary(SurfaceMesh::edge(o))) return false;
        const Vec3 a = face_normal(m, m.face(o)), b = face_normal(m, m.face(SurfaceMesh::twin(o)));
        if (dot(a, b) < cos20 + 1e-4f) return false;
      }
      return true;
    };
    std::size_t exact = 0, wedges = 0;
    for (Halfedge h : m.halfedges()) {
      if (m.is_boundary(h)) continue;
      const Vertex v = m.to_vertex(h);
      if (!m.is_boundary(v)) {
        EXPECT_EQ(smooth[h], vn[v]) << "corner " << h.idx();
        ++exact;
      } else {
        expect_near(smooth[h], vn[v]);  // one wedge too, summed around from the boundary
      }
      if (one_wedge(v)) {
        EXPECT_EQ(creased[h], vn[v]) << "corner " << h.idx();
        ++wedges;
      }
    }
    EXPECT_GT(exact, 1000u);
    EXPECT_GT(wedges, 1000u);
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Normals, WritesAreMarkedForTheChangeLog) {
  SurfaceMesh m = build(test::grid(3, true));
  const ChangeConsumer watch(m.watch_changes());
  compute_vertex_normals(m);
  EXPECT_EQ(watch.pending().vertices.size(), m.n_vertices());
  EXPECT_TRUE(any(watch.pending().events & ChangeEvent::vertex_data_changed));
  watch.consume();
  compute_corner_normals(m, 40);
  EXPECT_EQ(watch.pending().faces.size(), m.n_faces());
  // A flat grid: every normal is +z.
  const auto n = m.get_halfedge_property<Vec3>("h:normal");
  ASSERT_TRUE(n);
  for (Halfedge h : m.halfedges())
    if (!m.is_boundary(h)) expect_near(n[h], Vec3{0, 0, 1});
  EXPECT_TRUE(m.validate().empty());
}

TEST(Normals, BadCreaseAnglesAreRefused) {
  SurfaceMesh m = build(test::tetrahedron());
  EXPECT_THROW(compute_corner_normals(m, -1), InvalidInputError);
  EXPECT_THROW(compute_corner_normals(m, 181), InvalidInputError);
  EXPECT_THROW(compute_corner_normals(m, std::nan("")), InvalidInputError);
  EXPECT_FALSE(m.get_halfedge_property<Vec3>("h:normal"));  // nothing was added
}

TEST(Normals, RefuseANonFinitePosition) {
  SurfaceMesh m = build(test::cube());
  test::expect_refuses_non_finite(m, Vertex(6), "compute_face_normals", [&] { compute_face_normals(m); });
  test::expect_refuses_non_finite(m, Vertex(6), "compute_vertex_normals", [&] { compute_vertex_normals(m); });
  test::expect_refuses_non_finite(m, Vertex(6), "compute_corner_normals",
                                  [&] { compute_corner_normals(m, 30); });
  EXPECT_FALSE(m.get_face_property<Vec3>("f:normal"));
}

}  // namespace
}  // namespace hedge

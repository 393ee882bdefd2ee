#include "hedge/core/export.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hedge/core/build.h"
#include "test_meshes.h"

namespace hedge {
namespace {

double area(const IndexedMesh& m) {
  double a = 0;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    Vec3d p = to_double(m.positions[m.indices[t]]), q = to_double(m.positions[m.indices[t + 1]]),
          r = to_double(m.positions[m.indices[t + 2]]);
    a += 0.5 * norm(cross(q - p, r - p));
  }
  return a;
}

TEST(Export, RoundTripKeepsTrianglesAndPolygons) {
  for (const IndexedMesh& in :
       {test::tetrahedron(), test::article_example(), test::cube(), test::grid(3, false)}) {
    SurfaceMesh m = build(in);
    IndexedMesh out = to_indexed(m);
    EXPECT_EQ(out.positions, in.positions);
    EXPECT_EQ(out.indices, in.indices);
    EXPECT_EQ(out.face_sizes, in.face_sizes);
    EXPECT_TRUE(m.validate().empty());
  }
}

// "f:submesh" follows each face into face_submeshes, one per output face also when the faces are
// triangulated; a mesh without it has none.
TEST(Export, FaceSubmeshesFollowTheFaces) {
  SurfaceMesh m = build(test::cube());
  EXPECT_TRUE(to_indexed(m).face_submeshes.empty());
  auto submesh = m.add_face_property<std::int32_t>(kSubmeshProperty, 0);
  submesh[Face(2)] = 7;
  const IndexedMesh quads = to_indexed(m);
  ASSERT_EQ(quads.face_submeshes.size(), m.n_faces());
  for (std::size_t f = 0; f < m.n_faces(); ++f) EXPECT_EQ(quads.face_submeshes[f], f == 2 ? 7 : 0) << f;
  for (Triangulation t : {Triangulation::fan, Triangulation::ear}) {
    ExportOptions o;
    o.triangulation = t;
    const IndexedMesh tris = to_indexed(m, o);
    ASSERT_EQ(tris.face_submeshes.size(), tris.face_count());
    for (std::size_t i = 0; i < tris.face_count(); ++i)
      EXPECT_EQ(tris.face_submeshes[i], i / 2 == 2 ? 7 : 0) << i;  // two triangles per quad
  }
  EXPECT_TRUE(m.validate().empty());
}

TEST(Export, ClockwiseReversesEveryFaceKeepingItsFirstCorner) {
  SurfaceMesh m = build(test::tetrahedron());
  ExportOptions o;
  o.winding = Winding::cw;
  IndexedMesh out = to_indexed(m, o);
  IndexedMesh in = test::tetrahedron();
  for (std::size_t t = 0; t < in.indices.size(); t += 3) {
    EXPECT_EQ(out.indices[t], in.indices[t]);
    EXPECT_EQ(out.indices[t + 1], in.indices[t + 2]);
    EXPECT_EQ(out.indices[t + 2], in.indices[t + 1]);
  }
  // Importing the clockwise buffers reversed again gives the same mesh.
  BuildOptions bo;
  IndexedMesh back = out;
  for (std::size_t t = 0; t < back.indices.size(); t += 3)
    std::swap(back.indices[t + 1], back.indices[t + 2]);
  EXPECT_EQ(to_indexed(build(back, bo)).indices, in.indices);
}

TEST(Export, FanAndEarTriangulation) {
  SurfaceMesh cube = build(test::cube());
  ExportOptions o;
  o.triangulation = Triangulation::fan;
  IndexedMesh fan = to_indexed(cube, o);
  EXPECT_TRUE(fan.face_sizes.empty());
  EXPECT_EQ(fan.indices.size(), 36u);
  EXPECT_NEAR(area(fan), 6.0, 1e-9);

  // A concave "L" hexagon: a fan from corner 0 would leave the polygon, ear clipping does not.
  IndexedMesh l;
  l.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  l.indices = {1, 2, 3, 4, 5, 0};  // a fan from (2,0) crosses the notch
  l.face_sizes = {6};
  SurfaceMesh lm = build(l);
  o.triangulation = Triangulation::ear;
  IndexedMesh ear = to_indexed(lm, o);
  EXPECT_EQ(ear.indices.size(), 12u);
  EXPECT_NEAR(area(ear), 3.0, 1e-9);
  // Every ear keeps the polygon's orientation (+z).
  for (std::size_t t = 0; t < ear.indices.size(); t += 3) {
    Vec3 p = ear.positions[ear.indices[t]], q = ear.positions[ear.indices[t + 1]],
         r = ear.positions[ear.indices[t + 2]];
    EXPECT_GT(cross(q - p, r - p).z, 0.0f);
  }
  // The fan from corner 0, (2,0), would fold over the notch; the fan starts at the notch's
  // corner (1,1) instead (fan_start()), and tiles the polygon.
  o.triangulation = Triangulation::fan;
  const IndexedMesh fan_l = to_indexed(lm, o);
  EXPECT_NEAR(area(fan_l), 3.0, 1e-9);
  EXPECT_EQ(fan_l.positions[fan_l.indices[0]], (Vec3{1, 1, 0}));
}

TEST(Export, DeletedVerticesAreSkippedAndMapped) {
  IndexedMesh in = test::tetrahedron();
  in.positions.insert(in.positions.begin(), Vec3{9, 9, 9});  // isolated vertex 0
  for (auto& i : in.indices) ++i;
  SurfaceMesh m = build(in);
  m.mark_deleted(Vertex(0));
  std::vector<Index> map;
  IndexedMesh out = to_indexed(m, {}, &map);
  EXPECT_EQ(out.positions.size(), 4u);
  EXPECT_EQ(map[0], kInvalidIndex);
  EXPECT_EQ(map[1], 0u);
  EXPECT_EQ(out.indices, test::tetrahedron().indices);
  EXPECT_TRUE(m.validate().empty());
}

TEST(Export, CornerAttributesAreDeduplicated) {
  IndexedMesh in = test::cube();
  in.texcoords = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (std::size_t c = 0; c < in.indices.size(); ++c)
    in.texcoord_indices.push_back(static_cast<Index>(c % 4));
  SurfaceMesh m = build(in);
  IndexedMesh out = to_indexed(m);
  EXPECT_EQ(out.texcoords.size(), 4u);
  ASSERT_EQ(out.texcoord_indices.size(), 24u);
  for (std::size_t c = 0; c < 24; ++c) EXPECT_EQ(out.texcoords[out.texcoord_indices[c]], in.texcoords[c % 4]);
  ExportOptions o;
  o.corner_attributes = false;
  EXPECT_TRUE(to_indexed(m, o).texcoord_indices.empty());
  EXPECT_TRUE(m.validate().empty());
}

TEST(Export, ColoursGoThroughBuildAndExportPerCorner) {
  // Each side of the cube its own colour: every vertex has three, one per side around it.
  IndexedMesh in = test::cube();
  ASSERT_EQ(in.face_sizes.size(), 6u);
  for (std::size_t f = 0; f < 6; ++f)
    in.colors.push_back({0.125f * float(f), 1.0f - 0.1f * float(f), 0.5f, f % 2 ? 0.25f : 1.0f});
  for (std::size_t f = 0; f < 6; ++f)
    for (std::uint32_t k = 0; k < in.face_sizes[f]; ++k) in.color_indices.push_back(static_cast<Index>(f));
  SurfaceMesh m = build(in);
  const auto col = m.get_halfedge_property<Color>("h:color");
  ASSERT_TRUE(col);
  for (Face f : m.faces())
    for (Halfedge h : m.halfedges(f)) EXPECT_EQ(col[h], in.colors[f.idx()]);
  const IndexedMesh out = to_indexed(m);
  EXPECT_EQ(out.colors.size(), 6u);  // deduplicated
  ASSERT_EQ(out.color_indices.size(), in.indices.size());
  EXPECT_EQ(out.indices, in.indices);
  for (std::size_t c = 0; c < in.indices.size(); ++c)
    EXPECT_EQ(out.colors[out.color_indices[c]], in.colors[in.color_indices[c]]) << c;
  ExportOptions o;
  o.corner_attributes = false;
  EXPECT_TRUE(to_indexed(m, o).color_indices.empty());
  EXPECT_TRUE(m.validate().empty());
}

}  // namespace
}  // namespace hedge

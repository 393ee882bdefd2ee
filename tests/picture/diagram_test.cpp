#include "picture/diagram.h"

#include <gtest/gtest.h>

#include <string>

#include "hedge/error.h"
#include "hedge/io/io.h"
#include "picture/picture_test_util.h"

namespace hedge::picture {
namespace {

using test::count;

// Two quads and two triangles in the plane z = 0: 11 edges, 8 of them on the boundary.
SurfaceMesh patch() {
  return test::mesh_of(
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1.2f, 0}, {0, 2, 0}, {1, 2, 0}},
      {0, 1, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 6}, {4, 3, 3, 4});
}

TEST(Diagram, EveryHalfEdgeIsOneArrowAndBoundaryOnesAreMarked) {
  const SurfaceMesh m = patch();
  SvgCanvas svg(700, 560);
  draw_halfedge_diagram(m, diagram_camera(m, 700.0 / 560), svg);
  const std::string out = svg.svg();
  std::size_t boundary = 0;
  for (Halfedge h : m.halfedges()) boundary += m.is_boundary(h);
  EXPECT_EQ(boundary, 8u);
  EXPECT_EQ(count(out, "<g class=\"halfedge\">") + count(out, "<g class=\"halfedge boundary\">"),
            m.n_halfedges());
  EXPECT_EQ(count(out, "<g class=\"halfedge boundary\">"), boundary);
  for (Halfedge h : m.halfedges())
    EXPECT_NE(out.find(">h" + std::to_string(h.idx()) + "<"), std::string::npos);
  for (Vertex v : m.vertices()) EXPECT_NE(out.find(">v" + std::to_string(v.idx()) + "<"), std::string::npos);
  for (Face f : m.faces()) EXPECT_NE(out.find(">f" + std::to_string(f.idx()) + "<"), std::string::npos);
}

TEST(Diagram, TwinsRunSideBySideInOppositeDirections) {
  // Two triangles sharing the edge 1-2: the two arrows along it point opposite ways.
  const SurfaceMesh m = test::mesh_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2, 2, 1, 3});
  Image img(400, 400);
  ImageCanvas canvas(img);
  DiagramOptions o;
  o.labels = false;
  o.legend = false;
  SvgCanvas svg(400, 400);
  draw_halfedge_diagram(m, diagram_camera(m, 1), svg, o);
  draw_halfedge_diagram(m, diagram_camera(m, 1), canvas, o);
  const std::string out = svg.svg();
  EXPECT_EQ(count(out, "<g class=\"halfedge"), 10u);
  int ink = 0;
  for (int y = 0; y < 400; ++y)
    for (int x = 0; x < 400; ++x) ink += img.at(x, y) != Rgb{255, 255, 255};
  EXPECT_GT(ink, 20000);  // the two faces are filled
}

TEST(Diagram, FlatMeshesAreSeenStraightOn) {
  const SurfaceMesh m = patch();
  const Camera c = diagram_camera(m, 1);
  EXPECT_EQ(c.fov_degrees, 0);
  EXPECT_NEAR(std::abs(c.eye.z - c.target.z), std::sqrt(dot(c.eye - c.target, c.eye - c.target)), 1e-9);
  const SurfaceMesh tet = read_mesh(std::string(HEDGE_DATA_DIR) + "/tet.obj");
  EXPECT_GT(diagram_camera(tet, 1).fov_degrees, 0);
}

TEST(Diagram, LargeOrEmptyMeshesAreRefused) {
  const SurfaceMesh spot = read_mesh(std::string(HEDGE_DATA_DIR) + "/spot_triangulated.obj");
  SvgCanvas svg(300, 300);
  try {
    draw_halfedge_diagram(spot, diagram_camera(spot, 1), svg);
    FAIL() << "a mesh of " << spot.n_faces() << " faces was drawn";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(spot.n_faces())), std::string::npos) << e.what();
  }
  EXPECT_THROW(draw_halfedge_diagram(SurfaceMesh(), test::ortho_camera(), svg), InvalidInputError);
  DiagramOptions many;
  many.max_faces = spot.n_faces();
  SvgCanvas tiny(300, 20);
  EXPECT_THROW(draw_halfedge_diagram(patch(), test::ortho_camera(), tiny), InvalidInputError);
}

}  // namespace
}  // namespace hedge::picture

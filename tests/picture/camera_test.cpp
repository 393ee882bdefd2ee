#include "picture/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "hedge/error.h"
#include "hedge/io/io.h"
#include "picture/picture_test_util.h"

namespace hedge::picture {
namespace {

TEST(Camera, ViewNames) {
  EXPECT_EQ(parse_view("front"), View::front);
  EXPECT_EQ(parse_view("iso"), View::iso);
  EXPECT_EQ(parse_view("top"), View::top);
  EXPECT_FALSE(parse_view("sideways"));
  EXPECT_FALSE(parse_view(""));
}

TEST(Camera, OrthographicProjectionMapsTheSquareOntoThePicture) {
  const Projection p(test::ortho_camera(), 200, 100);
  const auto a = p({-1, 1, 0});
  EXPECT_NEAR(a.x, 50, 1e-9);  // height 2 fills 100 pixels: 50 per unit, about the centre (100, 50)
  EXPECT_NEAR(a.y, 0, 1e-9);
  const auto c = p({0, 0, 3});
  EXPECT_NEAR(c.x, 100, 1e-9);
  EXPECT_NEAR(c.y, 50, 1e-9);
  EXPECT_NEAR(c.depth, 7, 1e-9);
}

TEST(Camera, FrameKeepsEveryVertexInsideThePicture) {
  const SurfaceMesh m = read_mesh(std::string(HEDGE_DATA_DIR) + "/spot_control_mesh.obj");
  for (View v : {View::front, View::back, View::left, View::right, View::top, View::bottom, View::iso})
    for (double aspect : {0.5, 1.0, 2.0}) {
      const int w = int(200 * aspect), h = 200;
      const Camera c = frame(m, v, aspect);
      const Projection p(c, w, h);
      double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
      for (Vertex u : m.vertices()) {
        const auto q = p(to_double(m.position(u)));
        EXPECT_GT(q.depth, 0);
        x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
      }
      EXPECT_GE(x0, 0);
      EXPECT_LE(x1, w);
      EXPECT_GE(y0, 0);
      EXPECT_LE(y1, h);
      // and fills it along one axis at least (not a speck in the middle)
      EXPECT_GT(std::max((x1 - x0) / w, (y1 - y0) / h), 0.6) << int(v) << " " << aspect;
    }
}

TEST(Camera, DegenerateCamerasAreRefused) {
  Camera c = test::ortho_camera();
  c.target = c.eye;
  EXPECT_THROW(Projection(c, 10, 10), InvalidInputError);
  c = test::ortho_camera();
  c.up = {0, 0, 1};  // along the view direction
  EXPECT_THROW(Projection(c, 10, 10), InvalidInputError);
  c = test::ortho_camera();
  c.fov_degrees = 200;
  EXPECT_THROW(Projection(c, 10, 10), InvalidInputError);
  c.fov_degrees = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Projection(c, 10, 10), InvalidInputError);
  EXPECT_THROW(frame(SurfaceMesh(), View::iso, 1), InvalidInputError);
}

}  // namespace
}  // namespace hedge::picture

#include "picture/raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "picture/picture_test_util.h"

namespace hedge::picture {
namespace {

using test::mesh_of;
using test::ortho_camera;

const Rgb kRed{255, 0, 0}, kGreen{0, 200, 0}, kWhite{255, 255, 255}, kBlack{0, 0, 0};

RenderOptions flat_colour(Rgb base, int size = 100) {
  RenderOptions o;
  o.width = o.height = size;
  o.shading = Shading::unlit;
  o.base = base;
  o.boundary = false;
  o.background = kWhite;
  return o;
}

// Signed distance in pixels from p to the edges of triangle abc (positive inside).
double inside_distance(double px, double py, const double (&t)[3][2]) {
  double d = std::numeric_limits<double>::infinity();
  double area2 = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
  for (int i = 0; i < 3; ++i) {
    const double* a = t[i];
    const double* b = t[(i + 1) % 3];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double cross = ex * (py - a[1]) - ey * (px - a[0]);
    d = std::min(d, (area2 > 0 ? cross : -cross) / std::hypot(ex, ey));
  }
  return d;
}

TEST(Render, ASingleRedTriangleCoversItsPixelsWithinOnePixel) {
  const SurfaceMesh m = mesh_of({{-0.6f, -0.6f, 0}, {0.6f, -0.6f, 0}, {-0.6f, 0.6f, 0}}, {0, 1, 2});
  const Image img = render(m, ortho_camera(), flat_colour(kRed));
  ASSERT_EQ(img.width(), 100);
  ASSERT_EQ(img.height(), 100);
  // World (x, y) -> pixel (50 + 50 x, 50 - 50 y).
  const double tri[3][2] = {{20, 80}, {80, 80}, {20, 20}};
  int red = 0;
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 100; ++x) {
      const double d = inside_distance(x + 0.5, y + 0.5, tri);
      if (d >= 1) {
        EXPECT_EQ(img.at(x, y), kRed) << x << "," << y;
        ++red;
      } else if (d <= -1) {
        EXPECT_EQ(img.at(x, y), kWhite) << x << "," << y;
      }
    }
  EXPECT_GT(red, 1500);  // about half of 60 x 60
}

TEST(Render, EdgesAreAntiAliasedBySupersampling) {
  const SurfaceMesh m = mesh_of({{-0.6f, -0.6f, 0}, {0.6f, -0.6f, 0}, {-0.6f, 0.55f, 0}}, {0, 1, 2});
  auto blended = [&](int supersample) {
    RenderOptions o = flat_colour(kRed);
    o.supersample = supersample;
    const Image img = render(m, ortho_camera(), o);
    int n = 0;
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x) {
        const Rgb c = img.at(x, y);
        n += c != kRed && c != kWhite;
      }
    return n;
  };
  EXPECT_EQ(blended(1), 0);
  EXPECT_GT(blended(2), 40);  // along the slanted side
}

TEST(Render, ANearFaceHidesAFarOneWhateverTheirOrder) {
  // A square at z = 1 in front of one at z = -1, overlapping on [-0.2, 0.5]^2 (pixels 40..75 across,
  // 25..60 down). Each face has its own colour (ColorBy::face); in the overlap the picture must
  // equal the picture of the near square alone.
  const std::vector<Vec3> near = {{-0.5f, -0.5f, 1}, {0.5f, -0.5f, 1}, {0.5f, 0.5f, 1}, {-0.5f, 0.5f, 1}};
  const std::vector<Vec3> far = {{-0.2f, -0.2f, -1}, {0.8f, -0.2f, -1}, {0.8f, 0.8f, -1}, {-0.2f, 0.8f, -1}};
  for (bool near_first : {true, false})
    for (double fov : {0.0, 11.42}) {  // 11.42 degrees: about the same framing at distance 10
      std::vector<Vec3> pos = near_first ? near : far;
      const std::vector<Vec3>& second = near_first ? far : near;
      pos.insert(pos.end(), second.begin(), second.end());
      const SurfaceMesh m = mesh_of(pos, {0, 1, 2, 3, 4, 5, 6, 7}, {4, 4});
      const Face far_face = near_first ? Face(1) : Face(0);
      RenderOptions o = flat_colour(kRed);
      o.color_by = ColorBy::face;
      Camera c = ortho_camera();
      c.fov_degrees = fov;
      const Image both = render(m, c, o);
      SurfaceMesh near_alone = m;
      remove_faces(near_alone, std::vector<Face>{far_face});
      ASSERT_TRUE(near_alone.validate().empty());
      const Image expected = render(near_alone, c, o);
      const Rgb near_colour = expected.at(50, 50);
      EXPECT_NE(near_colour, kWhite);
      for (int y = 30; y <= 55; ++y)
        for (int x = 45; x <= 70; ++x)
          ASSERT_EQ(both.at(x, y), near_colour)
              << x << "," << y << ", near first " << near_first << ", fov " << fov;
      // Outside the near square, the far one shows.
      EXPECT_NE(both.at(85, 20), kWhite) << "fov " << fov;
      EXPECT_NE(both.at(85, 20), near_colour);
      EXPECT_TRUE(m.validate().empty());
    }
}

TEST(Render, WireframeColourOnEdgesNotInFaceInteriors) {
  // Two triangles of a square: its sides and its diagonal are edges.
  const SurfaceMesh tris =
      mesh_of({{-0.8f, -0.8f, 0}, {0.8f, -0.8f, 0}, {0.8f, 0.8f, 0}, {-0.8f, 0.8f, 0}}, {0, 1, 2, 0, 2, 3});
  RenderOptions o = flat_colour({200, 200, 200});
  o.wireframe = true;
  o.wire = kBlack;
  const Image img = render(tris, ortho_camera(), o);
  // The diagonal runs from pixel (10, 90) to (90, 10): x + y = 100.
  int on_diagonal = 0;
  for (int x = 20; x < 80; ++x) on_diagonal += img.at(x, 99 - x).r < 150 || img.at(x, 100 - x).r < 150;
  EXPECT_GE(on_diagonal, 58);
  // The sides: x = 10 and y = 10 (within a pixel).
  for (int t = 20; t < 80; t += 7) {
    EXPECT_LT(std::min(img.at(10, t).r, img.at(9, t).r), 150) << t;
    EXPECT_LT(std::min(img.at(t, 10).r, img.at(t, 9).r), 150) << t;
  }
  // Interiors, farther than 3 pixels from every edge, keep the face colour.
  for (int y = 14; y < 86; ++y)
    for (int x = 14; x < 86; ++x)
      if (std::abs(x + 0.5 + y + 0.5 - 100) / std::sqrt(2.0) > 3)
        EXPECT_EQ(img.at(x, y), (Rgb{200, 200, 200}));

  // One quad face: its fan diagonal is not an edge and is not drawn.
  const SurfaceMesh quad =
      mesh_of({{-0.8f, -0.8f, 0}, {0.8f, -0.8f, 0}, {0.8f, 0.8f, 0}, {-0.8f, 0.8f, 0}}, {0, 1, 2, 3}, {4});
  const Image q = render(quad, ortho_camera(), o);
  for (int y = 14; y < 86; ++y)
    for (int x = 14; x < 86; ++x) EXPECT_EQ(q.at(x, y), (Rgb{200, 200, 200})) << x << "," << y;
}

TEST(Render, HiddenEdgesDoNotShowThroughAFaceInFront) {
  // A wireframe square at z = -1 behind an opaque one at z = 1 of the same size.
  const SurfaceMesh m = mesh_of({{-0.8f, -0.8f, -1},
                                 {0.8f, -0.8f, -1},
                                 {0.8f, 0.8f, -1},
                                 {-0.8f, 0.8f, -1},
                                 {-0.9f, -0.9f, 1},
                                 {0.9f, -0.9f, 1},
                                 {0.9f, 0.9f, 1},
                                 {-0.9f, 0.9f, 1}},
                                {0, 1, 2, 0, 2, 3, 4, 5, 6, 7}, {3, 3, 4});
  RenderOptions o = flat_colour({200, 200, 200});
  o.wireframe = true;
  o.wire = kBlack;
  const Image img = render(m, ortho_camera(), o);
  // The far diagonal would cross the middle; the near quad has no diagonal.
  for (int y = 10; y < 90; ++y)
    for (int x = 10; x < 90; ++x) EXPECT_EQ(img.at(x, y), (Rgb{200, 200, 200})) << x << "," << y;
}

TEST(Render, BoundaryEdgesAreHighlightedWithoutTheWireframe) {
  const SurfaceMesh m =
      mesh_of({{-0.8f, -0.8f, 0}, {0.8f, -0.8f, 0}, {0.8f, 0.8f, 0}, {-0.8f, 0.8f, 0}}, {0, 1, 2, 0, 2, 3});
  RenderOptions o = flat_colour({200, 200, 200});
  o.boundary = true;
  o.boundary_color = kRed;
  const Image img = render(m, ortho_camera(), o);
  int red_on_sides = 0;
  for (int t = 15; t < 85; ++t) red_on_sides += img.at(10, t) == kRed || img.at(t, 89) == kRed;
  EXPECT_GT(red_on_sides, 60);
  for (int x = 20; x < 80; ++x)
    EXPECT_EQ(img.at(x, 100 - x), (Rgb{200, 200, 200})) << "the diagonal is interior";
}

TEST(Render, ColourByShardGivesEachPieceItsOwnColour) {
  const SurfaceMesh m = mesh_of({{-0.9f, -0.9f, 0},
                                 {-0.1f, -0.9f, 0},
                                 {-0.9f, -0.1f, 0},
                                 {0.1f, 0.1f, 0},
                                 {0.9f, 0.1f, 0},
                                 {0.1f, 0.9f, 0}},
                                {0, 1, 2, 3, 4, 5});
  RenderOptions o = flat_colour(kRed);
  o.color_by = ColorBy::shard;
  const Image img = render(m, ortho_camera(), o);
  const Rgb a = img.at(15, 85), b = img.at(60, 40);  // inside the first and the second triangle
  EXPECT_NE(a, b);
  EXPECT_NE(a, kWhite);
  EXPECT_NE(b, kWhite);
}

// The cut faces of a solid fracture (face property "f:inner") take the inner colour.
TEST(Render, ColourByShardDrawsInnerFacesInTheInnerColour) {
  SurfaceMesh m = mesh_of({{-0.9f, -0.9f, 0},
                           {-0.1f, -0.9f, 0},
                           {-0.9f, -0.1f, 0},
                           {0.1f, 0.1f, 0},
                           {0.9f, 0.1f, 0},
                           {0.1f, 0.9f, 0}},
                          {0, 1, 2, 3, 4, 5});
  auto inner = m.add_face_property<std::uint8_t>("f:inner", 0);
  inner[Face(1)] = 1;
  RenderOptions o = flat_colour(kRed);
  o.color_by = ColorBy::shard;
  o.inner_color = kGreen;
  const Image img = render(m, ortho_camera(), o);
  EXPECT_EQ(img.at(60, 40), kGreen);  // inside the second triangle
  EXPECT_NE(img.at(15, 85), kGreen);
  EXPECT_NE(img.at(15, 85), kWhite);
}

TEST(Render, CurvatureOfAConvexSolidIsPositiveEverywhere) {
  const SurfaceMesh m = read_mesh(std::string(HEDGE_DATA_DIR) + "/hourglass_ico.obj");
  RenderOptions o;
  o.width = o.height = 120;
  o.shading = Shading::unlit;
  o.color_by = ColorBy::curvature;
  o.boundary = false;
  const Image img = render(m, frame(m, View::front, 1), o);
  int warm = 0, cold = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 120; ++x) {
      const Rgb c = img.at(x, y);
      if (c == o.background) continue;
      warm += c.r > c.b + 20;
      cold += c.b > c.r + 20;
    }
  // Two icospheres (repair splits the vertex they share): convex all over, so red, never blue.
  EXPECT_GT(warm, 1000);
  EXPECT_EQ(cold, 0);
}

TEST(Render, MarkedVerticesAreDrawnAsDots) {
  SurfaceMesh m = mesh_of({{-0.8f, -0.8f, 0}, {0.8f, -0.8f, 0}, {0.8f, 0.8f, 0}, {-0.8f, 0.8f, 0}, {0, 0, 0}},
                          {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
  RenderOptions o = flat_colour({200, 200, 200});
  o.marked = {Vertex(4)};
  o.marked_color = kGreen;
  const Image img = render(m, ortho_camera(), o);
  EXPECT_EQ(img.at(50, 50), kGreen);
  EXPECT_EQ(img.at(30, 50), (Rgb{200, 200, 200}));
}

TEST(Render, ThreadsDoNotChangeThePicture) {
  const SurfaceMesh m = read_mesh(std::string(HEDGE_DATA_DIR) + "/spot_triangulated.obj");
  RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.wireframe = true;
  o.feature_angle = 40;
  o.threads = 1;
  const Camera c = frame(m, View::iso, 160.0 / 120);
  const Image one = render(m, c, o);
  o.threads = 3;
  const Image three = render(m, c, o);
  EXPECT_EQ(one.pixels(), three.pixels());
  int drawn = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) drawn += one.at(x, y) != o.background;
  EXPECT_GT(drawn, 2000);
}

TEST(Render, BadInputIsRefusedWithAClearError) {
  SurfaceMesh m = mesh_of({{-0.6f, -0.6f, 0}, {0.6f, -0.6f, 0}, {-0.6f, 0.6f, 0}}, {0, 1, 2});
  RenderOptions o = flat_colour(kRed);
  o.width = o.height = 0;
  EXPECT_THROW(render(m, ortho_camera(), o), InvalidInputError);
  o.width = o.height = 100000;
  EXPECT_THROW(render(m, ortho_camera(), o), InvalidInputError);
  o = flat_colour(kRed);
  o.width = o.height = 8192;  // a valid picture, but 16 samples per pixel would need 7.5 GB
  o.supersample = 4;
  EXPECT_THROW(render(m, ortho_camera(), o), InvalidInputError);
  o = flat_colour(kRed);
  o.supersample = 5;
  EXPECT_THROW(render(m, ortho_camera(), o), InvalidInputError);
  o = flat_colour(kRed);
  Camera bad = ortho_camera();
  bad.target = bad.eye;
  EXPECT_THROW(render(m, bad, o), InvalidInputError);
  EXPECT_THROW(render(SurfaceMesh(), ortho_camera(), o), InvalidInputError);
  m.set_position(Vertex(1), {std::numeric_limits<float>::quiet_NaN(), 0, 0});
  try {
    render(m, ortho_camera(), o);
    FAIL() << "a NaN position was drawn";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hedge::picture

#include "picture/canvas.h"

#include <gtest/gtest.h>

#include <string>

#include "picture/picture_test_util.h"

namespace hedge::picture {
namespace {

using test::count;

TEST(ImageCanvas, PolygonsFillTheirInsideAndBlendTheirRim) {
  Image img(40, 40, {255, 255, 255});
  ImageCanvas canvas(img);
  const Point2 square[] = {{10, 10}, {30, 10}, {30, 30}, {10, 30}};
  canvas.polygon(square, {0, 0, 255});
  EXPECT_EQ(img.at(20, 20), (Rgb{0, 0, 255}));
  EXPECT_EQ(img.at(5, 5), (Rgb{255, 255, 255}));
  const Point2 half_pixel[] = {{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}};
  canvas.polygon(half_pixel, {0, 0, 0});
  EXPECT_EQ(img.at(0, 0), (Rgb{128, 128, 128}));  // half covered
  canvas.disc({20, 20}, 3, {255, 0, 0});
  EXPECT_EQ(img.at(20, 20), (Rgb{255, 0, 0}));
  canvas.line({0, 35}, {40, 35}, 2, {0, 255, 0});
  EXPECT_EQ(img.at(20, 35), (Rgb{0, 255, 0}));
  EXPECT_EQ(img.at(20, 38), (Rgb{255, 255, 255}));
}

TEST(ImageCanvas, TextLeavesInk) {
  Image img(120, 30, {255, 255, 255});
  ImageCanvas canvas(img);
  canvas.text({60, 15}, 16, "h12 f3", {0, 0, 0});
  int ink = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 120; ++x) ink += img.at(x, y).r < 128;
  EXPECT_GT(ink, 30);
}

TEST(SvgCanvas, WritesOneElementPerShapeAndEscapesText) {
  SvgCanvas svg(100, 50);
  const Point2 tri[] = {{0, 0}, {10, 0}, {0, 10}};
  svg.polygon(tri, {1, 2, 3}, 0.5);
  svg.arrow({0, 0}, {50, 0}, 1, 5, {255, 0, 0}, "halfedge boundary");
  svg.arrow({0, 0}, {0, 0}, 1, 5, {255, 0, 0}, "halfedge");  // zero length: nothing
  svg.text({5, 5}, 10, "a<b & \"c\"", {0, 0, 0});
  const std::string out = svg.svg();
  EXPECT_EQ(out.rfind("<?xml", 0), 0u);
  EXPECT_NE(out.find("width=\"100\" height=\"50\""), std::string::npos);
  EXPECT_EQ(count(out, "<g class=\"halfedge boundary\">"), 1u);
  EXPECT_EQ(count(out, "class=\"halfedge\""), 0u);
  EXPECT_NE(out.find("#010203"), std::string::npos);
  EXPECT_NE(out.find("a&lt;b &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(out.find("</svg>"), std::string::npos);
}

}  // namespace
}  // namespace hedge::picture

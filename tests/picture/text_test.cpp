#include "picture/text.h"

#include <gtest/gtest.h>

#include "hedge/error.h"

namespace hedge::picture {
namespace {

TEST(Font, WidthGrowsWithTheTextAndTheSize) {
  const Font& font = Font::standard();
  EXPECT_EQ(font.width("", 12), 0);
  EXPECT_GT(font.width("ab", 12), font.width("a", 12));
  EXPECT_NEAR(font.width("hedge", 24), 2 * font.width("hedge", 12), 0.5);
}

TEST(Font, DrawsInkWhereItSays) {
  Image img(200, 40, {255, 255, 255});
  Font::standard().draw(img, 100, 10, 20, "Wide", {0, 0, 0});
  int left = 0, right = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 200; ++x)
      if (img.at(x, y).r < 128) (x < 100 ? left : right)++;
  EXPECT_EQ(left, 0);
  EXPECT_GT(right, 40);
}

TEST(Font, AMissingOrBrokenFontFileIsAnIoError) {
  EXPECT_THROW(Font("/nonexistent/font.ttf"), IoError);
  EXPECT_THROW(Font(std::string(HEDGE_DATA_DIR) + "/tet.obj"), IoError);
}

}  // namespace
}  // namespace hedge::picture

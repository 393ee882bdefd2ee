#include "picture/image.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <filesystem>
#include <fstream>

#include "hedge/error.h"

namespace hedge::picture {
namespace {

TEST(Image, SizesAreChecked) {
  EXPECT_NO_THROW(check_size(1, 1, "x"));
  EXPECT_NO_THROW(check_size(8192, 8192, "x"));
  EXPECT_THROW(check_size(0, 0, "x"), InvalidInputError);
  EXPECT_THROW(check_size(-5, 10, "x"), InvalidInputError);
  EXPECT_THROW(check_size(100000, 100000, "x"), InvalidInputError);
  EXPECT_THROW(check_size(16384, 16384, "x"), InvalidInputError);  // too many pixels
  EXPECT_THROW(Image(0, 10), InvalidInputError);
}

TEST(Image, PasteClipsAndBlendMixes) {
  Image a(4, 3, {0, 0, 0});
  Image b(2, 2, {255, 255, 255});
  a.paste(b, 3, 2);  // only (3, 2) lands inside
  EXPECT_EQ(a.at(3, 2), (Rgb{255, 255, 255}));
  EXPECT_EQ(a.at(2, 2), (Rgb{0, 0, 0}));
  a.paste(b, -1, -1);
  EXPECT_EQ(a.at(0, 0), (Rgb{255, 255, 255}));
  EXPECT_EQ(a.at(1, 0), (Rgb{0, 0, 0}));
  a.blend(1, 1, {200, 100, 0}, 0.5f);
  EXPECT_EQ(a.at(1, 1), (Rgb{100, 50, 0}));
  a.blend(10, 10, {1, 2, 3}, 1);  // outside: ignored
}

TEST(Image, PngRoundTripKeepsSizeAndPixels) {
  Image img(320, 240, {10, 20, 30});
  for (int x = 0; x < 320; ++x) img.set(x, x % 240, {250, 128, 7});
  const std::string png = encode_png(img);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                              int(png.size()), &w, &h, &channels, 3);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(w, 320);
  EXPECT_EQ(h, 240);
  EXPECT_TRUE(std::equal(img.pixels().begin(), img.pixels().end(), data));
  stbi_image_free(data);
}

TEST(Image, WritePngReplacesAtomicallyAndFailsCleanly) {
  const auto dir = std::filesystem::temp_directory_path() / "hedge_picture_image_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "a.png").string();
  write_png(Image(3, 2), path);
  EXPECT_EQ(std::filesystem::file_size(path), encode_png(Image(3, 2)).size());
  EXPECT_THROW(write_png(Image(3, 2), (dir / "missing" / "b.png").string()), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
  // Only the finished file is there: no temporary left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()),
            1);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace hedge::picture

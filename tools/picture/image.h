// Images for the pictures the hedge tool makes: 8-bit RGB pixels in rows, PNG encoding through
// stb_image_write (Debian's libstb), and the size limits every picture is checked against.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hedge::picture {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

//! Largest width or height of a picture, and largest number of pixels (a 8192 x 8192 picture).
inline constexpr int kMaxSide = 16384;
inline constexpr std::int64_t kMaxPixels = std::int64_t(8192) * 8192;

//! \throw InvalidInputError unless 1 <= width, height <= kMaxSide and width * height <= kMaxPixels;
//!   `what` names the picture in the message.
void check_size(int width, int height, const char* what);

//! An RGB picture, row by row from the top.
class Image {
 public:
  Image() = default;
  //! \throw InvalidInputError for a size check_size refuses.
  Image(int width, int height, Rgb fill = {255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0; }
  Rgb at(int x, int y) const {
    const std::uint8_t* p = &pixels_[3 * (std::size_t(y) * width_ + x)];
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, Rgb c) {
    std::uint8_t* p = &pixels_[3 * (std::size_t(y) * width_ + x)];
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
  //! Mixes c into pixel (x, y) with weight alpha in [0, 1]; pixels outside the image are ignored.
  void blend(int x, int y, Rgb c, float alpha);
  //! Copies `src` with its top-left corner at (x, y), clipped to this image.
  void paste(const Image& src, int x, int y);
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }
  std::vector<std::uint8_t>& pixels() { return pixels_; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> pixels_;
};

//! The image as PNG file bytes.
std::string encode_png(const Image& image);
//! Writes the image as a PNG file; the file is replaced atomically, so a failure leaves no
//! half-written file. \throw IoError naming the path.
void write_png(const Image& image, const std::string& path);

}  // namespace hedge::picture

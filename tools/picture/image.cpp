#include "image.h"

#include <stb_image_write.h>

#include <algorithm>

#include "hedge/error.h"
#include "hedge/io/io.h"

namespace hedge::picture {

void check_size(int width, int height, const char* what) {
  const auto describe = [&] {
    return std::string(what) + " of " + std::to_string(width) + "x" + std::to_string(height);
  };
  if (width < 1 || height < 1) throw InvalidInputError(describe() + ": width and height must be at least 1");
  if (width > kMaxSide || height > kMaxSide)
    throw InvalidInputError(describe() + ": width and height must be at most " + std::to_string(kMaxSide));
  if (std::int64_t(width) * height > kMaxPixels)
    throw InvalidInputError(describe() + ": more than " + std::to_string(kMaxPixels) + " pixels");
}

Image::Image(int width, int height, Rgb fill) : width_(width), height_(height) {
  check_size(width, height, "a picture");
  pixels_.resize(3 * std::size_t(width) * height);
  for (std::size_t i = 0; i < pixels_.size(); i += 3) {
    pixels_[i] = fill.r;
    pixels_[i + 1] = fill.g;
    pixels_[i + 2] = fill.b;
  }
}

void Image::blend(int x, int y, Rgb c, float alpha) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || !(alpha > 0)) return;
  alpha = std::min(alpha, 1.f);
  std::uint8_t* p = &pixels_[3 * (std::size_t(y) * width_ + x)];
  const std::uint8_t in[3] = {c.r, c.g, c.b};
  for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(p[k] + (float(in[k]) - p[k]) * alpha + 0.5f);
}

void Image::paste(const Image& src, int x0, int y0) {
  for (int y = std::max(0, -y0); y < src.height() && y0 + y < height_; ++y) {
    const int xs = std::max(0, -x0), xe = std::min(src.width(), width_ - x0);
    if (xs >= xe) continue;
    std::copy_n(&src.pixels_[3 * (std::size_t(y) * src.width() + xs)], 3 * (xe - xs),
                &pixels_[3 * (std::size_t(y0 + y) * width_ + x0 + xs)]);
  }
}

std::string encode_png(const Image& image) {
  std::string out;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (image.empty() || stbi_write_png_to_func(append, &out, image.width(), image.height(), 3,
                                              image.pixels().data(), 3 * image.width()) == 0)
    throw InvalidInputError("PNG encoding failed for a picture of " + std::to_string(image.width()) + "x" +
                            std::to_string(image.height()));
  return out;
}

void write_png(const Image& image, const std::string& path) { write_file_atomic(path, encode_png(image)); }

}  // namespace hedge::picture

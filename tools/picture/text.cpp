#include "text.h"

#include <stb_truetype.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "hedge/error.h"
#include "hedge/io/io.h"

namespace hedge::picture {

struct Font::Impl {
  std::string data;
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0, line_gap = 0;
};

namespace {
constexpr const char* kStandardFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

int glyph_of(char c) { return (c >= 32 && c < 127) ? c : '?'; }
}  // namespace

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->data = read_file(path);
  const auto* bytes = reinterpret_cast<const unsigned char*>(impl_->data.data());
  const int offset = impl_->data.size() >= 12 ? stbtt_GetFontOffsetForIndex(bytes, 0) : -1;
  if (offset < 0 || stbtt_InitFont(&impl_->info, bytes, offset) == 0)
    throw IoError(path, 0, -1, "not a TrueType font");
  stbtt_GetFontVMetrics(&impl_->info, &impl_->ascent, &impl_->descent, &impl_->line_gap);
}

Font::~Font() = default;

const Font& Font::standard() {
  static const Font font = [] {
    const char* env = std::getenv("HEDGE_FONT");
    const std::string path = env != nullptr && *env != '\0' ? env : kStandardFont;
    try {
      return Font(path);
    } catch (const IoError& e) {
      throw IoError(path, 0, -1,
                    std::string("no font for the text of pictures (") + e.what() +
                        "); install Debian's fonts-dejavu-core or set HEDGE_FONT to a .ttf file");
    }
  }();
  return font;
}

double Font::width(std::string_view text, double px) const {
  const float scale = stbtt_ScaleForPixelHeight(&impl_->info, float(px));
  double w = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, glyph_of(text[i]), &advance, &lsb);
    w += advance * scale;
    if (i + 1 < text.size())
      w += scale * stbtt_GetCodepointKernAdvance(&impl_->info, glyph_of(text[i]), glyph_of(text[i + 1]));
  }
  return w;
}

void Font::draw(Image& image, double x, double y, double px, std::string_view text, Rgb color) const {
  if (!(px > 0) || !(px < 1000) || !std::isfinite(x) || !std::isfinite(y)) return;
  const float scale = stbtt_ScaleForPixelHeight(&impl_->info, float(px));
  const double baseline = y + impl_->ascent * scale;
  const int base_y = int(std::floor(baseline));
  double pen = x;
  std::vector<unsigned char> bitmap;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int g = glyph_of(text[i]);
    const int pen_x = int(std::floor(pen));
    const float shift_x = float(pen - pen_x), shift_y = float(baseline - base_y);
    int x0, y0, x1, y1;
    stbtt_GetCodepointBitmapBoxSubpixel(&impl_->info, g, scale, scale, shift_x, shift_y, &x0, &y0, &x1, &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      bitmap.assign(std::size_t(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&impl_->info, bitmap.data(), w, h, w, scale, scale, shift_x, shift_y,
                                        g);
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c)
          if (const unsigned char a = bitmap[std::size_t(r) * w + c])
            image.blend(pen_x + x0 + c, base_y + y0 + r, color, a / 255.f);
    }
    int advance = 0, lsb = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, g, &advance, &lsb);
    pen += advance * scale;
    if (i + 1 < text.size())
      pen += scale * stbtt_GetCodepointKernAdvance(&impl_->info, g, glyph_of(text[i + 1]));
  }
}

}  // namespace hedge::picture

// Text in pictures: captions and labels, drawn anti-aliased from a TrueType font through
// stb_truetype (Debian's libstb). The font is DejaVu Sans from Debian's fonts-dejavu-core unless
// the environment variable HEDGE_FONT names another .ttf file.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "image.h"

namespace hedge::picture {

class Font {
 public:
  //! Reads a TrueType font file. \throw IoError if it cannot be read or is not a TrueType font.
  explicit Font(const std::string& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  //! The font of every picture: $HEDGE_FONT, else DejaVu Sans where Debian installs it. Loaded once.
  //! \throw IoError naming what was tried when no font is found.
  static const Font& standard();

  //! Width in pixels of `text` at pixel height px.
  double width(std::string_view text, double px) const;
  //! Draws `text` with the top of its line at y and its left end at x, at pixel height px (the
  //! distance from the highest ascender to the lowest descender). Only ASCII is drawn; other bytes
  //! become '?'.
  void draw(Image& image, double x, double y, double px, std::string_view text, Rgb color) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hedge::picture

// Two-dimensional drawing for diagrams: one interface, drawn either into an Image (anti-aliased by
// 4x4 coverage samples per pixel) or written as SVG. Coordinates are pixels, x right and y down.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "image.h"

namespace hedge::picture {

struct Point2 {
  double x = 0, y = 0;
};

enum class Anchor { start, middle, end };

class Canvas {
 public:
  virtual ~Canvas() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  //! A filled polygon (even-odd rule), with `opacity` in [0, 1].
  virtual void polygon(std::span<const Point2> points, Rgb fill, double opacity = 1) = 0;
  //! A straight line of the given width, with flat ends.
  virtual void line(Point2 a, Point2 b, double width, Rgb color) = 0;
  //! A line from a to b with a filled arrowhead at b. `kind` names what the arrow shows (SVG class).
  virtual void arrow(Point2 a, Point2 b, double width, double head, Rgb color, std::string_view kind) = 0;
  virtual void disc(Point2 centre, double radius, Rgb fill) = 0;
  //! Text of pixel height px, its line's vertical middle at `at.y`.
  virtual void text(Point2 at, double px, std::string_view text, Rgb color,
                    Anchor anchor = Anchor::middle) = 0;
};

//! Draws onto an image (which it does not own); text through Font::standard().
class ImageCanvas : public Canvas {
 public:
  explicit ImageCanvas(Image& image) : image_(&image) {}
  int width() const override { return image_->width(); }
  int height() const override { return image_->height(); }
  void polygon(std::span<const Point2> points, Rgb fill, double opacity = 1) override;
  void line(Point2 a, Point2 b, double width, Rgb color) override;
  void arrow(Point2 a, Point2 b, double width, double head, Rgb color, std::string_view kind) override;
  void disc(Point2 centre, double radius, Rgb fill) override;
  void text(Point2 at, double px, std::string_view text, Rgb color, Anchor anchor = Anchor::middle) override;

 private:
  Image* image_;
};

//! Collects SVG elements; svg() gives the whole document.
class SvgCanvas : public Canvas {
 public:
  //! \throw InvalidInputError for a size check_size refuses.
  SvgCanvas(int width, int height, Rgb background = {255, 255, 255});
  int width() const override { return width_; }
  int height() const override { return height_; }
  void polygon(std::span<const Point2> points, Rgb fill, double opacity = 1) override;
  void line(Point2 a, Point2 b, double width, Rgb color) override;
  void arrow(Point2 a, Point2 b, double width, double head, Rgb color, std::string_view kind) override;
  void disc(Point2 centre, double radius, Rgb fill) override;
  void text(Point2 at, double px, std::string_view text, Rgb color, Anchor anchor = Anchor::middle) override;
  std::string svg() const;

 private:
  int width_, height_;
  std::string body_;
};

}  // namespace hedge::picture

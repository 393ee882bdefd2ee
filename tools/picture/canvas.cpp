#include "canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "text.h"

namespace hedge::picture {

namespace {

bool finite(Point2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The quad of a line of width w from a to b; empty for a zero-length line.
std::vector<Point2> line_quad(Point2 a, Point2 b, double w) {
  const double dx = b.x - a.x, dy = b.y - a.y, l = std::hypot(dx, dy);
  if (!(l > 0)) return {};
  const double nx = -dy / l * w / 2, ny = dx / l * w / 2;
  return {{a.x + nx, a.y + ny}, {b.x + nx, b.y + ny}, {b.x - nx, b.y - ny}, {a.x - nx, a.y - ny}};
}

// The shaft's end and the arrowhead's corners for an arrow from a to b.
struct ArrowShape {
  Point2 shaft_end;
  Point2 head[3];
  bool ok = false;
};
ArrowShape arrow_shape(Point2 a, Point2 b, double head) {
  ArrowShape s;
  const double dx = b.x - a.x, dy = b.y - a.y, l = std::hypot(dx, dy);
  if (!(l > 0)) return s;
  const double ux = dx / l, uy = dy / l, h = std::min(head, 0.6 * l);
  const Point2 base{b.x - ux * h, b.y - uy * h};
  s.shaft_end = base;
  s.head[0] = b;
  s.head[1] = {base.x - uy * h * 0.45, base.y + ux * h * 0.45};
  s.head[2] = {base.x + uy * h * 0.45, base.y - ux * h * 0.45};
  s.ok = true;
  return s;
}

std::string hex(Rgb c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string escape(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += (c >= 32 && c < 127) ? c : '?';
    }
  }
  return out;
}

}  // namespace

// ---- ImageCanvas ----

void ImageCanvas::polygon(std::span<const Point2> pts, Rgb fill, double opacity) {
  if (pts.size() < 3 || !(opacity > 0)) return;
  for (const Point2& p : pts)
    if (!finite(p)) return;
  double x0 = pts[0].x, x1 = x0, y0 = pts[0].y, y1 = y0;
  for (const Point2& p : pts) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  const int ix0 = std::max(0, int(std::floor(x0))), ix1 = std::min(width() - 1, int(std::floor(x1)));
  const int iy0 = std::max(0, int(std::floor(y0))), iy1 = std::min(height() - 1, int(std::floor(y1)));
  constexpr int kSub = 4;
  for (int y = iy0; y <= iy1; ++y)
    for (int x = ix0; x <= ix1; ++x) {
      int inside = 0;
      for (int sy = 0; sy < kSub; ++sy)
        for (int sx = 0; sx < kSub; ++sx) {
          const double px = x + (sx + 0.5) / kSub, py = y + (sy + 0.5) / kSub;
          bool in = false;  // even-odd crossing test
          for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
            const Point2 &a = pts[i], &b = pts[j];
            if ((a.y > py) != (b.y > py) && px < a.x + (py - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
          }
          inside += in;
        }
      if (inside > 0) image_->blend(x, y, fill, float(opacity * inside / (kSub * kSub)));
    }
}

void ImageCanvas::line(Point2 a, Point2 b, double width, Rgb color) {
  const std::vector<Point2> q = line_quad(a, b, width);
  polygon(q, color);
}

void ImageCanvas::arrow(Point2 a, Point2 b, double width, double head, Rgb color, std::string_view) {
  const ArrowShape s = arrow_shape(a, b, head);
  if (!s.ok) return;
  line(a, s.shaft_end, width, color);
  polygon(s.head, color);
}

void ImageCanvas::disc(Point2 c, double r, Rgb fill) {
  std::vector<Point2> pts;
  const int n = std::clamp(int(r * 2), 12, 64);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * 3.141592653589793 * i / n;
    pts.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
  }
  polygon(pts, fill);
}

void ImageCanvas::text(Point2 at, double px, std::string_view text, Rgb color, Anchor anchor) {
  const Font& font = Font::standard();
  double x = at.x;
  if (anchor != Anchor::start) {
    const double w = font.width(text, px);
    x -= anchor == Anchor::middle ? w / 2 : w;
  }
  font.draw(*image_, x, at.y - px / 2, px, text, color);
}

// ---- SvgCanvas ----

SvgCanvas::SvgCanvas(int width, int height, Rgb background) : width_(width), height_(height) {
  check_size(width, height, "a diagram");
  body_ += "<rect width=\"100%\" height=\"100%\" fill=\"" + hex(background) + "\"/>\n";
}

void SvgCanvas::polygon(std::span<const Point2> pts, Rgb fill, double opacity) {
  if (pts.size() < 3) return;
  std::string p;
  for (const Point2& q : pts) {
    if (!finite(q)) return;
    p += num(q.x) + "," + num(q.y) + " ";
  }
  p.pop_back();
  body_ += "<polygon points=\"" + p + "\" fill=\"" + hex(fill) + "\"";
  if (opacity < 1) body_ += " fill-opacity=\"" + num(opacity) + "\"";
  body_ += "/>\n";
}

void SvgCanvas::line(Point2 a, Point2 b, double width, Rgb color) {
  if (!finite(a) || !finite(b)) return;
  body_ += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(b.x) + "\" y2=\"" + num(b.y) +
           "\" stroke=\"" + hex(color) + "\" stroke-width=\"" + num(width) + "\"/>\n";
}

void SvgCanvas::arrow(Point2 a, Point2 b, double width, double head, Rgb color, std::string_view kind) {
  const ArrowShape s = arrow_shape(a, b, head);
  if (!s.ok || !finite(a) || !finite(b)) return;
  body_ += "<g class=\"" + escape(kind) + "\">";
  body_ += "<line x1=\"" + num(a.x) + "\" y1=\"" + num(a.y) + "\" x2=\"" + num(s.shaft_end.x) + "\" y2=\"" +
           num(s.shaft_end.y) + "\" stroke=\"" + hex(color) + "\" stroke-width=\"" + num(width) + "\"/>";
  body_ += "<polygon points=\"";
  for (const Point2& q : s.head) body_ += num(q.x) + "," + num(q.y) + " ";
  body_.pop_back();
  body_ += "\" fill=\"" + hex(color) + "\"/></g>\n";
}

void SvgCanvas::disc(Point2 c, double r, Rgb fill) {
  if (!finite(c)) return;
  body_ += "<circle cx=\"" + num(c.x) + "\" cy=\"" + num(c.y) + "\" r=\"" + num(r) + "\" fill=\"" +
           hex(fill) + "\"/>\n";
}

void SvgCanvas::text(Point2 at, double px, std::string_view text, Rgb color, Anchor anchor) {
  if (!finite(at)) return;
  const char* a = anchor == Anchor::start ? "start" : anchor == Anchor::middle ? "middle" : "end";
  body_ += "<text x=\"" + num(at.x) + "\" y=\"" + num(at.y) + "\" font-size=\"" + num(px) +
           "\" text-anchor=\"" + a + "\" dominant-baseline=\"central\" fill=\"" + hex(color) + "\">" +
           escape(text) + "</text>\n";
}

std::string SvgCanvas::svg() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
         std::to_string(width_) + "\" height=\"" + std::to_string(height_) + "\" viewBox=\"0 0 " +
         std::to_string(width_) + " " + std::to_string(height_) +
         "\" font-family=\"DejaVu Sans, sans-serif\">\n" + body_ + "</svg>\n";
}

}  // namespace hedge::picture

// Colour helpers of the pictures: blends and a categorical palette.
#pragma once

#include <cmath>
#include <cstdint>

#include "image.h"

namespace hedge::picture {

inline std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::fmin(255.f, std::fmax(0.f, v + 0.5f)));
}

//! a + (b - a) * t.
inline Rgb mix(Rgb a, Rgb b, double t) {
  const float u = float(t);
  return {to_byte(a.r + (b.r - a.r) * u), to_byte(a.g + (b.g - a.g) * u), to_byte(a.b + (b.b - a.b) * u)};
}

//! Weights wa + wb + wc = 1.
inline Rgb mix3(Rgb a, Rgb b, Rgb c, float wa, float wb, float wc) {
  return {to_byte(a.r * wa + b.r * wb + c.r * wc), to_byte(a.g * wa + b.g * wb + c.g * wc),
          to_byte(a.b * wa + b.b * wb + c.b * wc)};
}

inline Rgb scale(Rgb c, float k) { return {to_byte(c.r * k), to_byte(c.g * k), to_byte(c.b * k)}; }

//! A light, saturated colour for category i; neighbouring categories get distant hues (golden-ratio
//! steps around the hue circle).
inline Rgb categorical(std::uint32_t i) {
  const double hue = std::fmod(0.13 + 0.6180339887498949 * double(i), 1.0) * 6;
  const double sat = 0.55, val = 0.95;
  const int sector = int(hue) % 6;
  const double f = hue - std::floor(hue);
  const double p = val * (1 - sat), q = val * (1 - sat * f), t = val * (1 - sat * (1 - f));
  // Each sector of the hue circle takes red, green and blue from these four levels.
  const double level[4] = {val, p, q, t};
  constexpr int kRgbLevel[6][3] = {{0, 3, 1}, {2, 0, 1}, {1, 0, 3}, {1, 2, 0}, {3, 1, 0}, {0, 1, 2}};
  const int* pick = kRgbLevel[sector];
  const double r = level[pick[0]], g = level[pick[1]], b = level[pick[2]];
  return {to_byte(float(r * 255)), to_byte(float(g * 255)), to_byte(float(b * 255))};
}

}  // namespace hedge::picture

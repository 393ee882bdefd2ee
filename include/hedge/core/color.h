// The colour type of the "h:color" and "v:color" properties and of IndexedMesh::colors.
#pragma once

namespace hedge {

//! RGBA colour, as engines store vertex colours in float.
struct Color {
  float r = 1, g = 1, b = 1, a = 1;
  friend bool operator==(const Color&, const Color&) = default;
  // Blending, so that colours are interpolated on split edges and faces like other attributes.
  friend Color operator+(const Color& x, const Color& y) {
    return {x.r + y.r, x.g + y.g, x.b + y.b, x.a + y.a};
  }
  friend Color operator*(const Color& x, float s) { return {x.r * s, x.g * s, x.b * s, x.a * s}; }
};

}  // namespace hedge

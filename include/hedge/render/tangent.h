// Tangents for render buffers: a Vec4 per corner ("h:tangent"), xyz the tangent direction and w the
// handedness (+1 or -1) of the bitangent, cross(normal, tangent) * w, as engines (Unity, glTF)
// store them. Vec4 is the four-float member of VecN, with the component-wise arithmetic of
// core/vec.h, so that the edits interpolate "h:tangent" like any corner property.
#pragma once

#include <cmath>

#include "hedge/core/vec.h"

namespace hedge {

template <typename T>
struct VecN<T, 4> {
  T x{}, y{}, z{}, w{};
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
  constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : (i == 2 ? z : w)); }
  friend constexpr bool operator==(const VecN&, const VecN&) = default;
};

using Vec4 = VecN<float, 4>;

//! t made perpendicular to the unit normal n (Gram-Schmidt) and of unit length, its handedness w
//! kept as +1 or -1 (an interpolated w in between takes its sign; 0 counts as +1). A tangent along
//! n (nothing perpendicular is left) keeps its direction, normalised if it can be.
inline Vec4 orthogonal_tangent(const Vec4& t, const Vec3& n) {
  const Vec3d td{t.x, t.y, t.z}, nd{n.x, n.y, n.z};
  Vec3d p = td - nd * dot(nd, td);
  const double len = norm(p);
  const double tlen = norm(td);
  if (len > 1e-6 * (tlen > 0 ? tlen : 1))
    p = p / len;
  else
    p = tlen > 0 ? td / tlen : td;
  return {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z), t.w < 0 ? -1.f : 1.f};
}

}  // namespace hedge

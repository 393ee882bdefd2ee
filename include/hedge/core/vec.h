// Small fixed-size vectors used for positions and attributes. Float storage, as engines use;
// algorithms that need precision convert to double where they accumulate.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace hedge {

template <typename T, int N>
struct VecN;

template <typename T>
struct VecN<T, 2> {
  T x{}, y{};
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : y; }
  constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : y; }
  friend constexpr bool operator==(const VecN&, const VecN&) = default;
};

template <typename T>
struct VecN<T, 3> {
  T x{}, y{}, z{};
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr const T& operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend constexpr bool operator==(const VecN&, const VecN&) = default;
};

// Component-wise arithmetic, written once for every size. The second operand and the scalar are
// not deduced, so they convert as a plain parameter would (a braced list, an int scalar).
template <typename T, int N>
constexpr VecN<T, N>& operator+=(VecN<T, N>& a, const std::type_identity_t<VecN<T, N>>& b) {
  for (std::size_t i = 0; i < N; ++i) a[i] += b[i];
  return a;
}
template <typename T, int N>
constexpr VecN<T, N>& operator-=(VecN<T, N>& a, const std::type_identity_t<VecN<T, N>>& b) {
  for (std::size_t i = 0; i < N; ++i) a[i] -= b[i];
  return a;
}
template <typename T, int N>
constexpr VecN<T, N>& operator*=(VecN<T, N>& a, std::type_identity_t<T> s) {
  for (std::size_t i = 0; i < N; ++i) a[i] *= s;
  return a;
}
template <typename T, int N>
constexpr VecN<T, N> operator+(VecN<T, N> a, const std::type_identity_t<VecN<T, N>>& b) {
  return a += b;
}
template <typename T, int N>
constexpr VecN<T, N> operator-(VecN<T, N> a, const std::type_identity_t<VecN<T, N>>& b) {
  return a -= b;
}
template <typename T, int N>
constexpr VecN<T, N> operator*(VecN<T, N> a, std::type_identity_t<T> s) {
  return a *= s;
}
template <typename T, int N>
constexpr VecN<T, N> operator*(std::type_identity_t<T> s, VecN<T, N> a) {
  return a *= s;
}
template <typename T, int N>
constexpr VecN<T, N> operator/(VecN<T, N> a, std::type_identity_t<T> s) {
  return a *= T(1) / s;
}
template <typename T, int N>
constexpr VecN<T, N> operator-(VecN<T, N> a) {
  return a *= T(-1);
}

using Vec2 = VecN<float, 2>;
using Vec3 = VecN<float, 3>;
using Vec3d = VecN<double, 3>;

template <typename T>
constexpr T dot(const VecN<T, 3>& a, const VecN<T, 3>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr VecN<T, 3> cross(const VecN<T, 3>& a, const VecN<T, 3>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
inline T norm(const VecN<T, 3>& a) {
  return std::sqrt(dot(a, a));
}
template <typename T>
inline VecN<T, 3> normalize(const VecN<T, 3>& a) {
  T n = norm(a);
  return n > T(0) ? a / n : a;
}
//! a scaled to length 1, or zero when its length is zero or not finite (a degenerate normal).
template <typename T>
inline VecN<T, 3> unit_or_zero(const VecN<T, 3>& a) {
  const T n = norm(a);
  return n > T(0) && std::isfinite(n) ? a * (T(1) / n) : VecN<T, 3>{0, 0, 0};
}
inline Vec3d to_double(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 to_float(const Vec3d& v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
}
//! v with each coordinate rounded to float and back: the point as a float position stores it.
//! Use this rather than to_double(to_float(v)), from which GCC 12's vectoriser (-O2 and above)
//! drops the rounding of x and y; the empty asm makes each float a value it cannot see through.
inline Vec3d rounded_to_float(const Vec3d& v) {
  const auto round = [](double d) {
    float f = static_cast<float>(d);
#if defined(__GNUC__) && !defined(__clang__)
    asm("" : "+m"(f));
#endif
    return static_cast<double>(f);
  };
  return {round(v.x), round(v.y), round(v.z)};
}
//! The bits of a float (memcpy rather than std::bit_cast, which older standard libraries such as
//! emscripten's libc++ lack). For non-negative floats they order as the values do; -0 and +0
//! differ.
inline std::uint32_t float_bits(float f) {
  std::uint32_t out;
  std::memcpy(&out, &f, sizeof(out));
  return out;
}
template <typename T, int N>
inline bool is_finite(const VecN<T, N>& v) {
  for (std::size_t i = 0; i < N; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace hedge

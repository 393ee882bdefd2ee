// What decimate.cpp keeps apart: the quadric (a sum of weighted squared distances to planes, its
// evaluation and its scale-free minimiser, a truncated pseudo-inverse), the radix sort of the
// candidates' keys, and the clamped barycentric coordinates of corner interpolation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "hedge/algorithms/geometry.h"

namespace hedge::detail::decimation {

// Directions of a quadric whose eigenvalue is below this fraction of the largest are left
// undetermined by the placement (see Quadric::minimiser).
constexpr double kRankTolerance = 1e-3;

// Sum of weighted squared distances to planes n.x + d = 0: x'Ax + 2b'x + c, with A symmetric
// (a00 a01 a02 a11 a12 a22) and w the total weight of the geometric planes.
struct Quadric {
  double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0, b0 = 0, b1 = 0, b2 = 0, c = 0, w = 0;

  void add(const Quadric& q) {
    a00 += q.a00, a01 += q.a01, a02 += q.a02, a11 += q.a11, a12 += q.a12, a22 += q.a22;
    b0 += q.b0, b1 += q.b1, b2 += q.b2, c += q.c, w += q.w;
  }
  // Adds weight x (n.x + d)^2; n need not be unit length (its length scales the term).
  void add_plane(const Vec3d& n, double d, double weight) {
    a00 += weight * n.x * n.x, a01 += weight * n.x * n.y, a02 += weight * n.x * n.z;
    a11 += weight * n.y * n.y, a12 += weight * n.y * n.z, a22 += weight * n.z * n.z;
    b0 += weight * d * n.x, b1 += weight * d * n.y, b2 += weight * d * n.z;
    c += weight * d * d;
  }
  double eval(const Vec3d& p) const {
    const double x = p.x, y = p.y, z = p.z;
    return x * (a00 * x + 2 * (a01 * y + a02 * z + b0)) + y * (a11 * y + 2 * (a12 * z + b1)) +
           z * (a22 * z + 2 * b2) + c;
  }
  // (A + c u u^T)^-1 v, for a unit u (c = 0: A^-1 v); false if singular.
  bool solve(const Vec3d& u, double c, const Vec3d& v, Vec3d& x) const {
    const double m00 = a00 + c * u.x * u.x, m01 = a01 + c * u.x * u.y, m02 = a02 + c * u.x * u.z;
    const double m11 = a11 + c * u.y * u.y, m12 = a12 + c * u.y * u.z, m22 = a22 + c * u.z * u.z;
    const double c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
    const double det = m00 * c00 + m01 * c01 + m02 * c02;
    if (!(std::abs(det) > 0)) return false;
    const double c11 = m00 * m22 - m02 * m02, c12 = m01 * m02 - m00 * m12, c22 = m00 * m11 - m01 * m01;
    const double inv = 1 / det;
    x = {inv * (c00 * v.x + c01 * v.y + c02 * v.z), inv * (c01 * v.x + c11 * v.y + c12 * v.z),
         inv * (c02 * v.x + c12 * v.y + c22 * v.z)};
    return true;
  }

  // The eigenvalues of A, largest first (the closed form for symmetric 3x3 matrices).
  std::array<double, 3> eigenvalues() const {
    const double q = (a00 + a11 + a22) / 3;
    const double off = a01 * a01 + a02 * a02 + a12 * a12;
    const double p2 = (a00 - q) * (a00 - q) + (a11 - q) * (a11 - q) + (a22 - q) * (a22 - q) + 2 * off;
    const double p = std::sqrt(p2 / 6);
    if (!(p > 0)) return {q, q, q};
    // B = (A - q I) / p; its eigenvalues are 2 cos(phi + 2 pi k / 3), with cos(3 phi) = det(B) / 2.
    const double b00 = (a00 - q) / p, b11 = (a11 - q) / p, b22 = (a22 - q) / p, b01 = a01 / p, b02 = a02 / p,
                 b12 = a12 / p;
    const double det =
        b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
    const double phi = std::acos(std::clamp(det / 2, -1.0, 1.0)) / 3;
    const double l0 = q + 2 * p * std::cos(phi), l2 = q + 2 * p * std::cos(phi + 2 * std::numbers::pi / 3);
    return {l0, 3 * q - l0 - l2, l2};
  }

  // A unit vector spanning the image of (A - x I)(A - y I): the eigenvector of the third eigenvalue
  // when x and y are the other two. False if that product vanishes.
  bool eigenvector(double x, double y, Vec3d& u) const {
    const Vec3d r0{a00 - x, a01, a02}, r1{a01, a11 - x, a12}, r2{a02, a12, a22 - x};
    const Vec3d s0{a00 - y, a01, a02}, s1{a01, a11 - y, a12}, s2{a02, a12, a22 - y};
    // Columns of the (symmetric) product.
    const Vec3d col[3] = {{dot(r0, s0), dot(r1, s0), dot(r2, s0)},
                          {dot(r0, s1), dot(r1, s1), dot(r2, s1)},
                          {dot(r0, s2), dot(r1, s2), dot(r2, s2)}};
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (dot(col[i], col[i]) > dot(col[k], col[k])) k = i;
    const double l = norm(col[k]);
    if (!(l > 0)) return false;
    u = col[k] / l;
    return true;
  }

  // The point that minimises the quadric near `mid`, in the directions the quadric determines:
  // A's eigenvectors whose eigenvalue is at least kRankTolerance times the largest (a truncated
  // pseudo-inverse, as in Lindstrom and Turk's placement). Along the others (the plane of a flat
  // patch, the axis of a cylinder, the tangent plane where curvature is low) the point stays at
  // `mid`. The test is a ratio of eigenvalues, so it does not depend on the mesh's scale. If the
  // point lies farther than sqrt(max_dist2) from mid, the weakest direction kept is dropped and the
  // point found again. False if no direction is left or a value is not finite.
  bool minimiser(const Vec3d& mid, double max_dist2, Vec3d& p) const {
    const double tr = a00 + a11 + a22;
    if (!(tr > 0)) return false;
    const Vec3d g{a00 * mid.x + a01 * mid.y + a02 * mid.z + b0, a01 * mid.x + a11 * mid.y + a12 * mid.z + b1,
                  a02 * mid.x + a12 * mid.y + a22 * mid.z + b2};
    auto accept = [&](const Vec3d& d) {
      if (!(dot(d, d) <= max_dist2)) return false;
      p = mid - d;
      return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    // Fast path: full rank is certain without the eigenvalues when a lower bound of the smallest
    // eigenvalue is at least kRankTolerance times an upper bound of the largest. The smallest is at
    // least det / m (m, the sum of the principal 2x2 minors, is at least the product of the two
    // largest) and at least 4 det / tr^2; the largest is at most tr / 3 + 2/3 sqrt(tr^2 - 3 m)
    // (Samuelson's bound: the mean plus sqrt(2) standard deviations of the three) and at most tr.
    // The margin keeps a rounding of the bounds from deciding a case the eigenvalues would not.
    const double det =
        a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02) + a02 * (a01 * a12 - a11 * a02);
    const double m = a00 * a11 - a01 * a01 + a00 * a22 - a02 * a02 + a11 * a22 - a12 * a12;
    const double upper = tr / 3 + (2.0 / 3) * std::sqrt(std::max(0.0, tr * tr - 3 * m));
    Vec3d d;
    const bool full = det >= 0.25 * kRankTolerance * tr * tr * tr ||
                      (m > 0 && det >= (1 + 1e-9) * kRankTolerance * upper * std::min(m, 0.25 * tr * tr));
    if (full && solve({0, 0, 0}, 0, g, d) && accept(d)) return true;
    const std::array<double, 3> l = eigenvalues();
    int rank = 1;
    while (rank < 3 && l[rank] >= kRankTolerance * l[0]) ++rank;
    if (rank == 3 && !full && solve({0, 0, 0}, 0, g, d) && accept(d)) return true;
    Vec3d u;
    // Rank 2: solve in the plane normal to the weakest eigenvector u (A + l0 u u^T has the same
    // eigenvectors, with u's eigenvalue lifted, and g is projected off u).
    if (rank >= 2 && eigenvector(l[0], l[1], u) && solve(u, l[0], g - u * dot(u, g), d) && accept(d))
      return true;
    // Rank 1: along the strongest eigenvector only.
    return eigenvector(l[1], l[2], u) && accept(u * (dot(u, g) / l[0]));
  }
};

inline Quadric sum(const Quadric& a, const Quadric& b) {
  Quadric q = a;
  q.add(b);
  return q;
}

// Squared distance-like error of q at p: the weighted mean of the squared plane distances.
inline double error_at(const Quadric& q, const Vec3d& p) {
  const double e = q.eval(p);
  return q.w > 0 ? std::max(0.0, e) / q.w : std::max(0.0, e);
}

template <typename T>
inline void prefetch(const T* p) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// LSD radix sort of the keys by their upper 32 bits (the costs' float bits, which order like the
// non-negative floats), in three passes of 11 bits. One read counts all three digits; a pass whose
// digit is the same for every key (the float's top bits often are) moves nothing and is skipped.
inline void radix_sort(std::vector<std::uint64_t>& keys, std::vector<std::uint64_t>& scratch) {
  scratch.resize(keys.size());
  std::array<std::array<std::uint32_t, 2048>, 3> count{};
  for (const std::uint64_t k : keys) {
    ++count[0][(k >> 32) & 2047];
    ++count[1][(k >> 43) & 2047];
    ++count[2][(k >> 54) & 2047];
  }
  for (int pass = 0; pass < 3; ++pass) {
    std::array<std::uint32_t, 2048>& c = count[std::size_t(pass)];
    const int shift = 32 + 11 * pass;
    if (!keys.empty() && c[(keys[0] >> shift) & 2047] == keys.size()) continue;
    std::uint32_t total = 0;
    for (std::uint32_t& n : c) {
      const std::uint32_t here = n;
      n = total;
      total += here;
    }
    for (const std::uint64_t k : keys) scratch[c[(k >> shift) & 2047]++] = k;
    keys.swap(scratch);
  }
}

// The barycentric coordinates of the point of triangle x nearest to p, approximately: those of p's
// projection onto the triangle's plane, clamped to the triangle and renormalised. False for a
// degenerate triangle.
inline bool clamped_barycentric(const std::array<Vec3d, 3>& x, const Vec3d& p, double& b0, double& b1,
                                double& b2) {
  const Vec3d e1 = x[1] - x[0], e2 = x[2] - x[0], d = p - x[0];
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0)) return false;
  const double t1 = dot(d, e1), t2 = dot(d, e2);
  b1 = (d22 * t1 - d12 * t2) / det, b2 = (d11 * t2 - d12 * t1) / det, b0 = 1 - b1 - b2;
  b0 = std::max(0.0, b0), b1 = std::max(0.0, b1), b2 = std::max(0.0, b2);
  const double s = b0 + b1 + b2;
  b0 /= s, b1 /= s, b2 /= s;
  return true;
}

}  // namespace hedge::detail::decimation

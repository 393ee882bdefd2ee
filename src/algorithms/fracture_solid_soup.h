// Internals of solid fracture: the soup of the broken region's triangles, the grid that hands each
// cell its triangles, and the numbering of the soup's vertices (fracture_solid_soup.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "fracture_solid_internal.h"

namespace hedge::solid_detail {

//! The soup: every face of `faces` as triangles, a polygon as its fan from fan_start() (as
//! volume() and the picking tree see it: from the first corner unless that fan folds).
std::vector<SoupTriangle> make_soup(const SurfaceMesh& mesh, const std::vector<Face>& faces);

inline bool overlaps(const SoupTriangle& t, const float lo[3], const float hi[3]) {
  for (int a = 0; a < 3; ++a)
    if (t.lo[a] > hi[a] || t.hi[a] < lo[a]) return false;
  return true;
}

//! A uniform grid over the soup's box: each cell of the grid lists, in increasing order, the soup
//! triangles whose boxes meet it. A box query visits the grid cells the box meets; every triangle
//! whose box meets the query box is listed in one of them (the cell of a coordinate is a monotone
//! function of it, so two boxes that meet share a cell).
struct SoupGrid {
  double origin[3] = {0, 0, 0}, scale[3] = {0, 0, 0};
  int n[3] = {1, 1, 1};
  std::vector<std::uint32_t> first;  // per grid cell (x fastest), then one past the last
  std::vector<std::uint32_t> items;

  int cell(float x, int a) const {
    // Clamped first, then truncated: for the values left (0 and up) that is the floor.
    const double c = (double(x) - origin[a]) * scale[a];
    return c <= 0 ? 0 : (c >= n[a] ? n[a] - 1 : int(c));
  }
  //! Calls fn(b) for the buckets (grid cells) the box [lo, hi] meets.
  template <typename Fn>
  void for_buckets(const float lo[3], const float hi[3], Fn&& fn) const {
    const int x0 = cell(lo[0], 0), x1 = cell(hi[0], 0), y0 = cell(lo[1], 1), y1 = cell(hi[1], 1);
    const int z0 = cell(lo[2], 2), z1 = cell(hi[2], 2);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) fn(static_cast<std::size_t>((z * n[1] + y) * n[0] + x));
  }
};

//! A grid of about sqrt(soup.size()) / 2 cells along the box's widest side (at most 32): a surface
//! through the box meets a few triangles per grid cell.
SoupGrid grid_soup(const std::vector<SoupTriangle>& soup);

//! A value -> number table, open addressing with linear probing; only looked up, never iterated,
//! so nothing depends on the order of its slots. Hash maps a value to 64 well-mixed bits.
template <typename T, typename Hash>
class NumberTable {
 public:
  static constexpr std::uint32_t kAbsent = 0xffffffffu;
  //! Room for n values at a load of at most one half.
  explicit NumberTable(std::size_t n) {
    std::size_t size = 16;
    while (size < 2 * n) size <<= 1;
    slots_.assign(size, {T{}, kAbsent});
    mask_ = size - 1;
  }
  //! The number of k, or `value` (stored as k's) if k is new.
  std::uint32_t find_or_add(const T& k, std::uint32_t value) {
    std::size_t at = Hash{}(k)&mask_;
    while (slots_[at].second != kAbsent) {
      if (slots_[at].first == k) return slots_[at].second;
      at = (at + 1) & mask_;
    }
    slots_[at] = {k, value};
    return value;
  }
  //! The number of k, kAbsent if it has none.
  std::uint32_t find(const T& k) const {
    for (std::size_t at = Hash{}(k)&mask_;; at = (at + 1) & mask_) {
      if (slots_[at].second == kAbsent || slots_[at].first == k) return slots_[at].second;
    }
  }

 private:
  std::vector<std::pair<T, std::uint32_t>> slots_;
  std::size_t mask_ = 0;
};

struct HashIndex {
  std::size_t operator()(Index v) const { return std::uint64_t{v} * 0x9E3779B97F4A7C15ull >> 20; }
};
struct HashKey {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = (std::uint64_t{k.kind} << 32 | k.a) * 0x9E3779B97F4A7C15ull;
    h ^= (std::uint64_t{k.b} << 32 | k.c) * 0xBF58476D1CE4E5B9ull;
    return static_cast<std::size_t>((h ^ (h >> 29)) * 0x94D049BB133111EBull >> 32);
  }
};
using KeyTable = NumberTable<Key, HashKey>;

//! The soup's vertices: each triangle's corners as indices into a list of its mesh vertices (in
//! the order of first use; the numbering stays inside the strike).
struct SoupIndex {
  std::vector<Index> vertices;  // unique
  std::vector<std::array<std::uint32_t, 3>> corner;
};

SoupIndex index_soup(const std::vector<SoupTriangle>& soup);

}  // namespace hedge::solid_detail

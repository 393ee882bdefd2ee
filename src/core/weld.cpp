// Welding duplicate positions: exact (bit-identical after folding -0 into +0) or within a
// distance relative to the bounding box, through a uniform grid so that it stays O(n).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "hedge/core/build.h"

namespace hedge {

namespace {

std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 33;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33;
  return x;
}

// -0 and +0 weld: both get the bits of +0.
std::uint32_t bits(float f) { return float_bits(f == 0.0f ? 0.0f : f); }

std::vector<Index> weld_exact(std::span<const Vec3> p, std::vector<Vec3>& unique) {
  const std::size_t n = p.size();
  std::size_t cap = 16;
  while (cap < 2 * n) cap <<= 1;
  std::vector<Index> table(cap, kInvalidIndex);  // open addressing on the unique positions
  std::vector<Index> map(n);
  unique.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t x = bits(p[i].x), y = bits(p[i].y), z = bits(p[i].z);
    std::size_t slot = mix((std::uint64_t(x) << 32 | y) ^ mix(z)) & (cap - 1);
    for (;;) {
      Index u = table[slot];
      if (u == kInvalidIndex) {
        table[slot] = static_cast<Index>(unique.size());
        map[i] = static_cast<Index>(unique.size());
        unique.push_back(p[i]);
        break;
      }
      const Vec3& q = unique[u];
      if (bits(q.x) == x && bits(q.y) == y && bits(q.z) == z) {
        map[i] = u;
        break;
      }
      slot = (slot + 1) & (cap - 1);
    }
  }
  return map;
}

struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell&) const = default;
};
struct CellHash {
  std::size_t operator()(const Cell& c) const {
    return mix(static_cast<std::uint64_t>(c.x) * 73856093ULL ^ mix(static_cast<std::uint64_t>(c.y)) ^
               mix(static_cast<std::uint64_t>(c.z) + 0x9e3779b97f4a7c15ULL));
  }
};

}  // namespace

std::vector<Index> weld_positions(std::span<const Vec3> p, Weld mode, double relative_epsilon,
                                  std::vector<Vec3>& unique) {
  if (mode == Weld::none) {
    unique.assign(p.begin(), p.end());
    std::vector<Index> map(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) map[i] = static_cast<Index>(i);
    return map;
  }
  if (mode == Weld::exact || p.empty()) return weld_exact(p, unique);

  Vec3d lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const Vec3& q : p)
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], double(q[k]));
      hi[k] = std::max(hi[k], double(q[k]));
    }
  const double eps = std::abs(relative_epsilon) * norm(hi - lo);
  // A zero or vanishing tolerance, or one whose grid would overflow, welds exactly.
  const double span = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(eps > 0.0) || !std::isfinite(eps) || span / eps > 1e15) return weld_exact(p, unique);

  std::unordered_map<Cell, std::vector<Index>, CellHash> grid;
  grid.reserve(p.size());
  std::vector<Index> map(p.size());
  unique.clear();
  const double eps2 = eps * eps;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d q = to_double(p[i]);
    const Cell c{static_cast<std::int64_t>(std::floor((q.x - lo.x) / eps)),
                 static_cast<std::int64_t>(std::floor((q.y - lo.y) / eps)),
                 static_cast<std::int64_t>(std::floor((q.z - lo.z) / eps))};
    Index best = kInvalidIndex;
    double best_d2 = eps2;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          auto it = grid.find(Cell{c.x + dx, c.y + dy, c.z + dz});
          if (it == grid.end()) continue;
          for (Index u : it->second) {
            const Vec3d d = to_double(unique[u]) - q;
            const double d2 = dot(d, d);
            if (d2 <= best_d2 && (best == kInvalidIndex || d2 < best_d2 || u < best)) {
              best = u;
              best_d2 = d2;
            }
          }
        }
    if (best == kInvalidIndex) {
      best = static_cast<Index>(unique.size());
      unique.push_back(p[i]);
      grid[c].push_back(best);
    }
    map[i] = best;
  }
  return map;
}

}  // namespace hedge

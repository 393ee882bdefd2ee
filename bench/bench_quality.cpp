// Quality of an operation's result: how far its surface is from the input's (hedge's distance.h),
// and how far its vertices are from another library's result.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "bench_common.h"
#include "hedge/algorithms/distance.h"
#include "hedge/core/build.h"

namespace bench {
namespace {

hedge::SurfaceMesh to_hedge(const Input& in) {
  const std::span<const hedge::Vec3> positions(reinterpret_cast<const hedge::Vec3*>(in.xyz.data()),
                                               in.n_vertices());
  return hedge::build_triangles(positions, in.tri, {.policy = hedge::TopologyPolicy::repair});
}

// The points of an Input binned in a uniform grid of about one point per cell: a sorted list of
// (cell, point) pairs, searched by binary search (no hashing, so the same answers on every run).
class PointGrid {
 public:
  explicit PointGrid(const Input& in) : xyz_(in.xyz) {
    const std::size_t n = in.n_vertices();
    for (int k = 0; k < 3; ++k) {
      lo_[k] = std::numeric_limits<double>::infinity();
      double hi = -lo_[k];
      for (std::size_t i = 0; i < n; ++i) {
        lo_[k] = std::min(lo_[k], double(xyz_[3 * i + k]));
        hi = std::max(hi, double(xyz_[3 * i + k]));
      }
      extent_[k] = n ? hi - lo_[k] : 0;
    }
    const double volume =
        std::max(extent_[0], 1e-30) * std::max(extent_[1], 1e-30) * std::max(extent_[2], 1e-30);
    cell_ = std::max(std::cbrt(volume / double(std::max<std::size_t>(n, 1))), 1e-30);
    for (int k = 0; k < 3; ++k) dims_[k] = std::int64_t(std::min(extent_[k] / cell_, 1e6)) + 1;
    entries_.reserve(n);
    for (std::size_t i = 0; i < n; ++i) entries_.push_back({key(cell_of(i)), std::uint32_t(i)});
    std::sort(entries_.begin(), entries_.end());
  }

  //! The distance from p to the nearest point of the grid (infinity if it has none).
  double nearest(const double* p) const {
    std::array<std::int64_t, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = clamp(std::int64_t(std::floor((p[k] - lo_[k]) / cell_)), k);
    double best = std::numeric_limits<double>::infinity();
    const std::int64_t max_ring = std::max({dims_[0], dims_[1], dims_[2]});
    // Ring r holds the cells at Chebyshev distance r from p's cell; points beyond it are at least
    // r cells away, so the search stops once the best distance is within that.
    for (std::int64_t r = 0; r <= max_ring && best > double(r - 1) * cell_; ++r)
      for (std::int64_t x = c[0] - r; x <= c[0] + r; ++x)
        for (std::int64_t y = c[1] - r; y <= c[1] + r; ++y)
          for (std::int64_t z = c[2] - r; z <= c[2] + r; ++z) {
            if (std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])}) != r) continue;
            if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) continue;
            const std::uint64_t k = key({x, y, z});
            auto it = std::lower_bound(entries_.begin(), entries_.end(),
                                       std::pair<std::uint64_t, std::uint32_t>{k, 0});
            for (; it != entries_.end() && it->first == k; ++it) {
              const float* q = &xyz_[3 * std::size_t(it->second)];
              const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
              best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
            }
          }
    return best;
  }

 private:
  std::int64_t clamp(std::int64_t i, int k) const {
    return std::min(std::max<std::int64_t>(i, 0), dims_[k] - 1);
  }
  std::array<std::int64_t, 3> cell_of(std::size_t i) const {
    std::array<std::int64_t, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = clamp(std::int64_t(std::floor((xyz_[3 * i + k] - lo_[k]) / cell_)), k);
    return c;
  }
  std::uint64_t key(const std::array<std::int64_t, 3>& c) const {
    return (std::uint64_t(c[0]) * std::uint64_t(dims_[1]) + std::uint64_t(c[1])) * std::uint64_t(dims_[2]) +
           std::uint64_t(c[2]);
  }
  const std::vector<float>& xyz_;
  std::array<double, 3> lo_{}, extent_{};
  std::array<std::int64_t, 3> dims_{};
  double cell_ = 1;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries_;
};

double one_sided(const Input& from, const PointGrid& to) {
  double d = 0;
  for (std::size_t i = 0; i < from.n_vertices(); ++i) {
    const double p[3] = {from.xyz[3 * i], from.xyz[3 * i + 1], from.xyz[3 * i + 2]};
    d = std::max(d, to.nearest(p));
  }
  return d;
}

}  // namespace

double max_vertex_distance(const Input& a, const Input& b) {
  if (a.n_vertices() == 0 || b.n_vertices() == 0)
    return a.n_vertices() == b.n_vertices() ? 0 : std::numeric_limits<double>::infinity();
  return std::max(one_sided(a, PointGrid(b)), one_sided(b, PointGrid(a)));
}

Quality surface_distance(const Input& input, const Input& result) {
  const hedge::SurfaceMesh a = to_hedge(input), b = to_hedge(result);
  // About one face sample per input face (at least 10^5) on each surface, besides the vertices.
  const hedge::HausdorffDistance d =
      hedge::hausdorff_distance(a, b, {.samples = std::max<std::size_t>(100000, input.n_faces())});
  return {d.distance, d.mean, result.n_vertices(), result.n_faces()};
}

}  // namespace bench

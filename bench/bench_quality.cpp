// Quality of an operation's result: how far its surface is from the input's (hedge's distance.h).
#include <algorithm>
#include <span>

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

}  // namespace

Quality surface_distance(const Input& input, const Input& result) {
  const hedge::SurfaceMesh a = to_hedge(input), b = to_hedge(result);
  // About one face sample per input face (at least 10^5) on each surface, besides the vertices.
  const hedge::HausdorffDistance d =
      hedge::hausdorff_distance(a, b, {.samples = std::max<std::size_t>(100000, input.n_faces())});
  return {d.distance, d.mean, result.n_vertices(), result.n_faces()};
}

}  // namespace bench

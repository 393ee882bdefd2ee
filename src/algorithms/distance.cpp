#include "hedge/algorithms/distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge {
namespace {

//! The sampled surface of one mesh: its vertices that lie on a face, and its fan triangles with the
//! running sum of their areas (the inverse of that sum maps a uniform number to a triangle).
struct SampledSurface {
  std::vector<Vertex> vertices;
  std::vector<std::array<Vertex, 3>> triangles;
  std::vector<double> area_prefix;  //!< area_prefix[t]: areas of triangles 0..t

  SampledSurface(const SurfaceMesh& m) {
    vertices.reserve(m.n_vertices());
    for (Vertex v : m.vertices())
      if (!m.is_isolated(v)) vertices.push_back(v);
    triangles.reserve(m.n_faces());
    area_prefix.reserve(m.n_faces());
    double total = 0;
    for (Face f : m.faces()) {
      const Vertex c0 = m.to_vertex(m.halfedge(f));
      const Vec3d p0 = to_double(m.position(c0));
      Halfedge h = m.next(m.halfedge(f));
      for (Halfedge last = m.prev(m.halfedge(f)); h != last; h = m.next(h)) {
        const Vertex c1 = m.to_vertex(h), c2 = m.to_vertex(m.next(h));
        total += triangle_area(p0, to_double(m.position(c1)), to_double(m.position(c2)));
        triangles.push_back({c0, c1, c2});
        area_prefix.push_back(total);
      }
    }
  }
  double area() const { return area_prefix.empty() ? 0 : area_prefix.back(); }
};

//! Point k of the sample: a vertex for k < vertices.size(), else a face sample. The face samples
//! are stratified: sample i falls in the i-th of `count` equal slices of the total area.
Vec3d sample_point(const SurfaceMesh& m, const SampledSurface& s, std::size_t k, std::size_t count,
                   std::uint64_t seed) {
  if (k < s.vertices.size()) return to_double(m.position(s.vertices[k]));
  const std::size_t i = k - s.vertices.size();
  // Stateless draws (splitmix64_mix of a counter), so that any point can be drawn on its own, in
  // any order and on any thread.
  const std::uint64_t base = splitmix64_mix(seed * SplitMix64::kGamma + 3 * i + 1);
  const double u = (static_cast<double>(i) + unit_interval(base)) / static_cast<double>(count) * s.area();
  const std::size_t t = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(s.area_prefix.begin(), s.area_prefix.end(), u) -
                               s.area_prefix.begin()),
      s.triangles.size() - 1);
  // Uniform on the triangle: sqrt of one number picks the distance from corner 0, the other the
  // position across.
  const double r1 = std::sqrt(unit_interval(splitmix64_mix(base + 1))),
               r2 = unit_interval(splitmix64_mix(base + 2));
  const Vec3d a = to_double(m.position(s.triangles[t][0])), b = to_double(m.position(s.triangles[t][1])),
              c = to_double(m.position(s.triangles[t][2]));
  return a * (1 - r1) + b * (r1 * (1 - r2)) + c * (r1 * r2);
}

void check_mesh(const SurfaceMesh& m, const char* function, const char* name) {
  if (m.n_faces() == 0)
    throw InvalidInputError(std::string(function) + ": mesh " + name +
                            " has no faces, so it has no surface to measure");
  require_finite_positions(m, (std::string(function) + " (mesh " + name + ")").c_str());
}

OneSidedDistance measure(const SurfaceMesh& from, const SurfaceMesh& to, const DistanceOptions& options) {
  const SampledSurface surface(from);
  // A surface of zero area has no face points to draw; its vertices still count.
  const std::size_t face_samples = surface.area() > 0 ? options.samples : 0;
  const std::size_t n = surface.vertices.size() + face_samples;
  const FaceBvh bvh(to);
  std::vector<double> distance(n);

  // Neighbouring points are near each other, so the previous point's distance plus the step between
  // them bounds this one's (triangle inequality): a bounded query prunes far more of the tree.
  auto run = [&](std::size_t first, std::size_t last) {
    std::optional<Vec3d> previous;
    double previous_distance = 0;
    for (std::size_t k = first; k < last; ++k) {
      const Vec3d p = sample_point(from, surface, k, face_samples, options.seed);
      const Vec3 q = to_float(p);
      std::optional<LocateResult> hit;
      if (previous) {
        const double bound = previous_distance + norm(p - *previous);
        hit = bvh.closest_point(q, bound * (1 + 1e-6) + 1e-30);
      }
      if (!hit) hit = bvh.closest_point(q);
      // Found for every finite point, as `to` has faces and finite positions.
      distance[k] = hit ? std::sqrt(hit->squared_distance) : std::numeric_limits<double>::infinity();
      previous = p;
      previous_distance = distance[k];
    }
  };
  detail::parallel_ranges(n, run, 4096, options.threads);

  OneSidedDistance r;
  r.points = n;
  double sum = 0;
  std::size_t farthest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    sum += distance[k];
    if (distance[k] > distance[farthest]) farthest = k;
  }
  r.mean = n ? sum / static_cast<double>(n) : 0;
  if (n) {
    r.max = distance[farthest];
    r.farthest = to_float(sample_point(from, surface, farthest, face_samples, options.seed));
  }
  return r;
}

void check_options(const DistanceOptions& options, const char* function) {
  if (options.threads == 0)
    throw InvalidInputError(std::string(function) + ": options.threads is 0; it must be 1 or more");
  if (options.samples > kMaxDistanceSamples)
    throw InvalidInputError(std::string(function) + ": options.samples is " +
                            std::to_string(options.samples) + ", more than the limit of " +
                            std::to_string(kMaxDistanceSamples) +
                            " (kMaxDistanceSamples); draw fewer samples");
}

}  // namespace

OneSidedDistance one_sided_distance(const SurfaceMesh& from, const SurfaceMesh& to,
                                    const DistanceOptions& options) {
  check_options(options, "one_sided_distance");
  check_mesh(from, "one_sided_distance", "'from'");
  check_mesh(to, "one_sided_distance", "'to'");
  return measure(from, to, options);
}

HausdorffDistance hausdorff_distance(const SurfaceMesh& a, const SurfaceMesh& b,
                                     const DistanceOptions& options) {
  check_options(options, "hausdorff_distance");
  check_mesh(a, "hausdorff_distance", "a");
  check_mesh(b, "hausdorff_distance", "b");
  HausdorffDistance r;
  r.a_to_b = measure(a, b, options);
  r.b_to_a = measure(b, a, options);
  r.distance = std::max(r.a_to_b.max, r.b_to_a.max);
  const std::size_t n = r.a_to_b.points + r.b_to_a.points;
  r.mean = n ? (r.a_to_b.mean * static_cast<double>(r.a_to_b.points) +
                r.b_to_a.mean * static_cast<double>(r.b_to_a.points)) /
                   static_cast<double>(n)
             : 0;
  return r;
}

}  // namespace hedge

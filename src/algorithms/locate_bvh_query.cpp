// FaceBvh: the queries.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core_private/small_vector.h"
#include "hedge/algorithms/locate.h"
#include "locate_internal.h"

namespace hedge {

using namespace locate_detail;

namespace {

double box_distance_sq(const float* lo, const float* hi, const Vec3d& p) {
  double d = 0;
  for (int a = 0; a < 3; ++a) {
    const double l = double(lo[a]) - p[a];
    const double h = p[a] - double(hi[a]);
    if (l > 0)
      d += l * l;
    else if (h > 0)
      d += h * h;
  }
  if (!(lo[0] <= hi[0])) return kInf;  // empty box
  return d;
}

}  // namespace

// ---- Queries. ----

std::optional<LocateResult> FaceBvh::closest_point(const Vec3& p) const { return closest_point(p, kInf); }

std::optional<LocateResult> FaceBvh::closest_point(const Vec3& p, double max_distance) const {
  if (empty() || !is_finite(p) || !(max_distance >= 0)) return std::nullopt;
  check_fresh();
  ClosestSearch search(*mesh_, to_double(p), sq(max_distance), slack_sq_);
  auto limit = [&] { return search.limit(); };
  SmallVector<std::pair<Index, double>, 96> stack;  // no allocation for the usual depths
  stack.push_back({0, box_distance_sq(nodes_[0].lo, nodes_[0].hi, search.p)});
  while (!stack.empty()) {
    const auto [n, d] = stack.pop_back();
    if (d > limit()) continue;
    const Node& node = nodes_[n];
    if (node.is_leaf()) {
      for (Index k = node.index; k < node.index + node.count; ++k)
        if (entries_[k].face != kInvalidIndex) for_each_triangle(entries_[k], search);
      continue;
    }
    const Index c = node.index;
    double d0 = box_distance_sq(nodes_[c].lo, nodes_[c].hi, search.p);
    double d1 = box_distance_sq(nodes_[c + 1].lo, nodes_[c + 1].hi, search.p);
    Index near = c, far = c + 1;
    if (d1 < d0) {
      std::swap(near, far);
      std::swap(d0, d1);
    }
    const double lim = limit();
    if (d1 <= lim) stack.push_back({far, d1});
    if (d0 <= lim) stack.push_back({near, d0});
  }
  return search.result();
}

std::optional<LocateResult> FaceBvh::face_containing(const Vec3& p, double tolerance) const {
  return closest_point(p, tolerance);
}

std::optional<SurfacePoint> FaceBvh::face_containing(const Vec2& p, ProjectionPlane plane) const {
  if (empty() || !is_finite(p)) return std::nullopt;
  check_fresh();
  ContainSearch search(*mesh_, p, plane);
  SmallVector<Index, 96> stack;  // no allocation for the usual depths
  stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.pop_back()];
    if (!search.box_contains(node.lo, node.hi)) continue;
    if (!node.is_leaf()) {
      stack.push_back(node.index + 1);
      stack.push_back(node.index);
      continue;
    }
    for (Index k = node.index; k < node.index + node.count; ++k) {
      const Entry& e = entries_[k];
      if (e.face == kInvalidIndex || search.skip(Face(e.face))) continue;
      for_each_triangle(e, search);
    }
  }
  return search.result();
}

void FaceBvh::faces_in_box(const Vec3& lo, const Vec3& hi, std::vector<Face>& out) const {
  if (empty() || !is_finite(lo) || !is_finite(hi) || !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z)) return;
  check_fresh();
  auto overlaps = [&](const float* blo, const float* bhi) {
    for (int a = 0; a < 3; ++a)
      if (blo[a] > hi[a] || bhi[a] < lo[a]) return false;
    return true;
  };
  const std::size_t first = out.size();
  SmallVector<Index, 96> stack;  // no allocation for the usual depths
  stack.push_back(0);
  while (!stack.empty()) {
    const Node& node = nodes_[stack.pop_back()];
    if (!overlaps(node.lo, node.hi)) continue;
    if (!node.is_leaf()) {
      stack.push_back(node.index + 1);
      stack.push_back(node.index);
      continue;
    }
    for (Index k = node.index; k < node.index + node.count; ++k) {
      const Entry& e = entries_[k];
      if (e.face == kInvalidIndex) continue;
      const Box box = entry_box(e);
      if (!box.empty() && overlaps(box.lo, box.hi)) out.push_back(Face(e.face));
    }
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

bool FaceBvh::bounds(Vec3& lo, Vec3& hi) const {
  if (empty()) return false;
  const bool tight = !(bounds_lo_[0] <= bounds_hi_[0]);  // no finite face: the root's (empty) box
  const float* l = tight ? nodes_[0].lo : bounds_lo_;
  const float* h = tight ? nodes_[0].hi : bounds_hi_;
  lo = {l[0], l[1], l[2]};
  hi = {h[0], h[1], h[2]};
  return true;
}

std::optional<RayHit> FaceBvh::first_hit(const Vec3& origin, const Vec3& direction, double t_max) const {
  if (empty() || !is_finite(origin) || !valid_direction(direction) || !(t_max >= 0)) return std::nullopt;
  check_fresh();
  const PreparedRay ray(origin, direction);
  RaySearch search(*mesh_, ray, t_max);
  auto limit = [&] { return search.best + std::fabs(search.best) * kRelSlack; };
  SmallVector<std::pair<Index, float>, 96> stack;  // no allocation for the usual depths
  float t0 = 0, t1 = 0;
  if (!ray.enters(nodes_[0].lo, nodes_[0].hi, limit(), t0)) return std::nullopt;
  stack.push_back({0, t0});
  while (!stack.empty()) {
    const auto [n, t_near] = stack.pop_back();
    if (double(t_near) > limit()) continue;
    const Node& node = nodes_[n];
    if (node.is_leaf()) {
      for (Index k = node.index; k < node.index + node.count; ++k)
        if (entries_[k].face != kInvalidIndex) for_each_triangle(entries_[k], search);
      continue;
    }
    const Index c = node.index;
    const double lim = limit();
    const bool h0 = ray.enters(nodes_[c].lo, nodes_[c].hi, lim, t0);
    const bool h1 = ray.enters(nodes_[c + 1].lo, nodes_[c + 1].hi, lim, t1);
    if (h0 && h1) {
      if (t0 <= t1) {
        stack.push_back({c + 1, t1});
        stack.push_back({c, t0});
      } else {
        stack.push_back({c, t0});
        stack.push_back({c + 1, t1});
      }
    } else if (h0) {
      stack.push_back({c, t0});
    } else if (h1) {
      stack.push_back({c + 1, t1});
    }
  }
  return search.result();
}

std::size_t FaceBvh::memory_bytes() const {
  return nodes_.capacity() * sizeof(Node) + entries_.capacity() * sizeof(Entry) +
         height_.capacity() * sizeof(std::uint32_t) + young_.capacity() * sizeof(Index) +
         slot_of_face_.capacity() * sizeof(Index) + parent_.capacity() * sizeof(Index) +
         leaf_of_.capacity() * sizeof(Index) + dirty_.capacity() * sizeof(Index);
}

FaceBvh::Stats FaceBvh::stats() const {
  Stats s;
  s.nodes = nodes_.size();
  s.live_faces = live_;
  s.dead_slots = dead_;
  s.height = nodes_.empty() ? 0 : height_[0];
  s.height_at_build = height_at_build_;
  s.builds = builds_;
  s.compactions = compactions_;
  s.orphan_nodes = orphan_nodes_;
  s.inserted_subtrees = inserted_;
  s.merged_subtrees = merged_;
  if (!nodes_.empty()) {
    SmallVector<Index, 96> stack;  // no allocation for the usual depths
    stack.push_back(0);
    while (!stack.empty()) {
      const Node& node = nodes_[stack.pop_back()];
      if (node.is_leaf()) {
        ++s.leaves;
      } else {
        stack.push_back(node.index);
        stack.push_back(node.index + 1);
      }
    }
  }
  return s;
}

}  // namespace hedge

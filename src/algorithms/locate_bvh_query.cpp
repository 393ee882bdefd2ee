// FaceBvh: refit, update after local edits, and the queries.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core_private/small_vector.h"
#include "hedge/algorithms/locate.h"
#include "hedge/error.h"
#include "locate_internal.h"

namespace hedge {

using namespace locate_detail;

namespace {

// update() policy, for k faces in one call. Removed and replaced entries are tombstoned in their
// leaves, O(1) each. The k new entries get a subtree, built in O(k log k) and placed by one descent
// from the root that, at each node, either stops or goes down to the child whose box grows least
// (surface area):
//  - reaching a subtree made by an earlier update() (a young one), the new entries are merged into
//    it and it is rebuilt: in place for the latest one while it holds up to kMergeLimit faces, by
//    copying (which leaves tombstones) for an older one of up to kCopyMergeLimit faces; a larger one
//    is descended into;
//  - otherwise, at a leaf or where stopping is cheaper, the new subtree is hung next to the node.
// So repeated edits in one spot refine one small subtree instead of stacking levels. Boxes and
// heights on the path are then refit. One call costs O(m log m + height), m <= k + kMergeLimit.
// The whole tree is rebuilt when the tombstoned slots (removed and replaced faces, and copies left
// by merges) exceed rebuild_fraction of all slots, or the height exceeds kHeightFactor times its
// height after the last build plus kHeightSlack (both in the header's contract of update()).
constexpr Index kMergeLimit = 128;
constexpr Index kCopyMergeLimit = 32;
constexpr unsigned kHeightFactor = 2;
constexpr unsigned kHeightSlack = 16;

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

// ---- Refit and update. ----

void FaceBvh::refit_leaf(Index n) {
  Box box;
  const Node& node = nodes_[n];
  for (Index k = node.index; k < node.index + node.count; ++k) box.grow(entry_box(entries_[k]));
  std::copy(box.lo, box.lo + 3, nodes_[n].lo);
  std::copy(box.hi, box.hi + 3, nodes_[n].hi);
}

void FaceBvh::refit_internal(Index n) {
  Node& node = nodes_[n];
  const Node& a = nodes_[node.index];
  const Node& b = nodes_[node.index + 1];
  for (int i = 0; i < 3; ++i) {
    node.lo[i] = std::min(a.lo[i], b.lo[i]);
    node.hi[i] = std::max(a.hi[i], b.hi[i]);
  }
  set_height(n);
}

void FaceBvh::refit() {
  if (nodes_.empty()) return;
  check_fresh();
  // Post-order without recursion: update() may have placed children before their parents.
  SmallVector<std::pair<Index, bool>, 96> stack;  // no allocation for the usual depths
  stack.push_back({0, false});
  while (!stack.empty()) {
    const auto [n, children_done] = stack.pop_back();
    if (nodes_[n].is_leaf()) {
      refit_leaf(n);
    } else if (children_done) {
      refit_internal(n);
    } else {
      stack.push_back({n, true});
      stack.push_back({nodes_[n].index, false});
      stack.push_back({nodes_[n].index + 1, false});
    }
  }
  update_slack();
}

void FaceBvh::insert_entries(Index first, Index count) {
  if (nodes_.empty()) {
    nodes_.resize(1);
    height_.assign(1, 0);
    young_.assign(1, 0);
    tail_root_ = 0;
    tail_first_entry_ = first;
    tail_first_node_ = 1;
    build_subtree(first, count, 0);
    young_[0] = count;
    height_at_build_ = height_[0];
    return;
  }
  Box s;
  for (Index k = first; k < first + count; ++k) s.grow(entry_box(entries_[k]));

  // Descend to the node whose pairing with the new subtree costs the least added area: pairing at n
  // creates a node of area(n + s); going down instead grows n by the same amount, plus the area of
  // the pair made lower down.
  auto box_of = [&](Index n) {
    Box b;
    std::copy(nodes_[n].lo, nodes_[n].lo + 3, b.lo);
    std::copy(nodes_[n].hi, nodes_[n].hi + 3, b.hi);
    return b;
  };
  std::vector<Index> path;
  Index n = 0;
  bool merge = false;
  for (;;) {
    // A young subtree is merged with the new entries if that is cheap: in place when it is the
    // tail (no garbage), by copying when it is small; a larger one is descended like any other.
    if (young_[n] != 0 && young_[n] + count <= (n == tail_root_ ? kMergeLimit : kCopyMergeLimit)) {
      merge = true;
      break;
    }
    if (nodes_[n].is_leaf()) break;
    const Box b = box_of(n);
    const double here = b.merged(s).half_area();
    const double inherited = here - b.half_area();
    const Index c = nodes_[n].index;
    const double down0 = inherited + box_of(c).merged(s).half_area();
    const double down1 = inherited + box_of(c + 1).merged(s).half_area();
    if (here <= std::min(down0, down1)) break;
    path.push_back(n);
    n = down0 <= down1 ? c : c + 1;
  }

  if (merge && n == tail_root_) {
    // The young subtree made last: its entries end where the new ones start and its nodes end the
    // node array, so it is rebuilt in place, and its tombstones are dropped.
    Index w = tail_first_entry_;
    for (Index k = tail_first_entry_; k < entries_.size(); ++k) {
      if (entries_[k].face != kInvalidIndex)
        entries_[w++] = entries_[k];
      else
        --dead_;
    }
    entries_.resize(w);
    nodes_.resize(tail_first_node_);
    height_.resize(tail_first_node_);
    young_.resize(tail_first_node_);
    build_subtree(tail_first_entry_, w - tail_first_entry_, n);
    young_[n] = w - tail_first_entry_;
    ++merged_;
  } else if (merge) {
    // An older young subtree: its live entries move next to the new ones (leaving tombstones) and
    // the lot is rebuilt at its root; its old nodes are orphaned until the next build.
    SmallVector<Index, 96> stack;  // no allocation for the usual depths
    stack.push_back(n);
    while (!stack.empty()) {
      const Index x = stack.pop_back();
      const Node node = nodes_[x];
      if (x != n) ++orphan_nodes_;
      if (!node.is_leaf()) {
        stack.push_back(node.index);
        stack.push_back(node.index + 1);
        continue;
      }
      for (Index k = node.index; k < node.index + node.count; ++k) {
        if (entries_[k].face == kInvalidIndex) continue;
        entries_.push_back(entries_[k]);
        entries_[k].face = kInvalidIndex;
        ++dead_;
      }
    }
    const Index total = static_cast<Index>(entries_.size()) - first;
    tail_root_ = n;
    tail_first_entry_ = first;
    tail_first_node_ = static_cast<Index>(nodes_.size());
    build_subtree(first, total, n);
    young_[n] = total;
    ++merged_;
  } else {
    // Hang the new subtree next to n: n's content moves to a new slot, n becomes their parent.
    const Index j = static_cast<Index>(nodes_.size());
    nodes_.resize(j + 2);
    height_.resize(j + 2, 0);
    young_.resize(j + 2, 0);
    nodes_[j] = nodes_[n];
    height_[j] = height_[n];
    young_[j] = young_[n];
    tail_root_ = j + 1;
    tail_first_entry_ = first;
    tail_first_node_ = j + 2;
    build_subtree(first, count, j + 1);
    young_[j + 1] = count;
    nodes_[n].index = j;
    nodes_[n].count = 0;
    young_[n] = 0;
    refit_internal(n);
    ++inserted_;
  }
  for (std::size_t i = path.size(); i-- > 0;) refit_internal(path[i]);
}

void FaceBvh::update(std::span<const Face> changed_or_added, std::span<const Face> removed) {
  if (!mesh_) throw InvalidInputError("FaceBvh::update: the tree was never built over a mesh");
  check_fresh();
  const SurfaceMesh& m = *mesh_;
  for (std::span<const Face> list : {changed_or_added, removed})
    for (Face f : list)
      if (!m.is_valid(f))
        throw InvalidInputError("FaceBvh::update: face " + std::to_string(f.idx()) +
                                " is not a face slot of the mesh (" + std::to_string(m.face_slots()) +
                                " slots)");
  if (!changed_or_added.empty() || !removed.empty()) closed_ = -1;  // mesh_closed() asks again
  slot_of_face_.resize(m.face_slots(), kInvalidIndex);
  auto tombstone = [&](Face f) {
    Index& slot = slot_of_face_[f.idx()];
    if (slot == kInvalidIndex) return;
    entries_[slot].face = kInvalidIndex;
    slot = kInvalidIndex;
    --live_;
    ++dead_;
  };
  for (Face f : removed) tombstone(f);
  for (Face f : changed_or_added) tombstone(f);
  const Index first = static_cast<Index>(entries_.size());
  for (Face f : changed_or_added) {
    if (m.is_deleted(f) || slot_of_face_[f.idx()] != kInvalidIndex) continue;
    slot_of_face_[f.idx()] = static_cast<Index>(entries_.size());
    entries_.push_back(make_entry(f));
    ++live_;
  }
  const Index count = static_cast<Index>(entries_.size()) - first;
  if (double(dead_) > options_.rebuild_fraction * double(entries_.size())) {
    rebuild();
    return;
  }
  if (count > 0) insert_entries(first, count);
  if (dead_ > 0 && double(dead_) > options_.rebuild_fraction * double(entries_.size())) {
    rebuild();
    return;
  }
  if (!nodes_.empty() && height_[0] > kHeightFactor * height_at_build_ + kHeightSlack) {
    rebuild();
    return;
  }
  update_slack();
}

void FaceBvh::update() {
  if (!mesh_) return;
  const ChangeLog::Pending pending = changes_.pending();
  if (pending.reset) {
    rebuild();  // consumes
    return;
  }
  if (pending.empty()) return;
  const SurfaceMesh& m = *mesh_;
  // Copied: a rebuild inside update(faces) consumes the log, which the spans point into.
  std::vector<Face> changed(pending.faces.begin(), pending.faces.end());
  // Moved vertices: their faces are re-inserted, unless so many are affected that refitting the
  // whole tree is cheaper (a smoothing pass, say).
  bool refit_all = false;
  std::size_t budget = live_ / 8;
  for (Vertex v : pending.vertices) {
    if (!m.is_live(v) || m.is_isolated(v)) continue;
    for (Face f : m.faces(v)) {
      if (!f.is_valid()) continue;
      if (budget == 0) {
        refit_all = true;
        break;
      }
      --budget;
      changed.push_back(f);
    }
    if (refit_all) break;
  }
  const std::size_t builds = builds_;
  update(changed, {});
  if (refit_all && builds_ == builds) refit();  // a rebuild has read the current positions already
  changes_.consume();
}

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
  const Node& root = nodes_[0];
  lo = {root.lo[0], root.lo[1], root.lo[2]};
  hi = {root.hi[0], root.hi[1], root.hi[2]};
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
         slot_of_face_.capacity() * sizeof(Index);
}

FaceBvh::Stats FaceBvh::stats() const {
  Stats s;
  s.nodes = nodes_.size();
  s.live_faces = live_;
  s.dead_slots = dead_;
  s.height = nodes_.empty() ? 0 : height_[0];
  s.height_at_build = height_at_build_;
  s.builds = builds_;
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

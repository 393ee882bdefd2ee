// FaceBvh: refit, and update after local edits (tombstones, refits of what they touch, inserted
// subtrees, compaction).
#include <algorithm>
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
// The leaves that lost entries are refitted first, with the nodes above them until a box stays
// the same (parent_ and leaf_of_ find them), so the tree keeps pruning where faces were removed.
// When the tombstoned slots (removed and replaced faces, and copies left by merges) exceed
// rebuild_fraction of all slots, compact() reclaims them in one pass without sorting. The whole
// tree is rebuilt only when its height exceeds kHeightFactor times its height after the last build
// plus kHeightSlack, or its unreachable node slots outnumber the reachable ones (both in the
// header's contract of update()).
constexpr Index kMergeLimit = 128;
constexpr Index kCopyMergeLimit = 32;
constexpr unsigned kHeightFactor = 2;
constexpr unsigned kHeightSlack = 16;

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

void FaceBvh::refit_dirty() {
  // Each leaf once, however many of its entries went (a strike empties whole leaves).
  std::sort(dirty_.begin(), dirty_.end());
  dirty_.erase(std::unique(dirty_.begin(), dirty_.end()), dirty_.end());
  for (const Index leaf : dirty_) {
    refit_leaf(leaf);
    for (Index n = parent_[leaf]; n != kInvalidIndex; n = parent_[n]) {
      const Node before = nodes_[n];
      refit_internal(n);
      if (std::equal(before.lo, before.lo + 3, nodes_[n].lo) &&
          std::equal(before.hi, before.hi + 3, nodes_[n].hi))
        break;  // the nodes above were made from this box
    }
  }
  dirty_.clear();
}

void FaceBvh::compact() {
  // Post-order: a leaf without a live entry is empty, and so is a node with two empty children; a
  // node with one takes the other child's place (its content moves up; the empty subtree's nodes
  // and the moved child's slot are orphaned). cut[n]: the nodes of n's subtree when it is empty.
  std::vector<Index> cut(nodes_.size(), 0);
  SmallVector<std::pair<Index, bool>, 96> stack;  // no allocation for the usual depths
  stack.push_back({0, false});
  while (!stack.empty()) {
    const auto [n, children_done] = stack.pop_back();
    Node& node = nodes_[n];
    if (node.is_leaf()) {
      bool any = false;
      for (Index k = node.index; k < node.index + node.count && !any; ++k)
        any = entries_[k].face != kInvalidIndex;
      cut[n] = any ? 0 : 1;
      continue;
    }
    if (!children_done) {
      stack.push_back({n, true});
      stack.push_back({node.index, false});
      stack.push_back({node.index + 1, false});
      continue;
    }
    const Index c = node.index;
    if (cut[c] && cut[c + 1]) {
      cut[n] = 1 + cut[c] + cut[c + 1];
      continue;
    }
    if (cut[c] || cut[c + 1]) {
      const Index keep = cut[c] ? c + 1 : c;
      orphan_nodes_ += 1 + cut[keep == c ? c + 1 : c];
      node = nodes_[keep];
      young_[n] = young_[keep];
      if (node.is_leaf())
        std::fill(leaf_of_.begin() + node.index, leaf_of_.begin() + node.index + node.count, n);
      else
        parent_[node.index] = parent_[node.index + 1] = n;
      if (node.is_leaf()) {
        set_height(n);
        continue;
      }
    }
    refit_internal(n);  // the boxes below are tight already; this redoes the heights too
  }
  // The reachable leaves, then the entries closed up in the order of their slots (a leaf's entries
  // are adjacent, so each leaf's range stays one range).
  std::vector<char> reachable(nodes_.size(), 0);
  SmallVector<Index, 96> walk;
  walk.push_back(0);
  while (!walk.empty()) {
    const Index n = walk.pop_back();
    if (nodes_[n].is_leaf()) {
      reachable[n] = 1;
    } else {
      walk.push_back(nodes_[n].index);
      walk.push_back(nodes_[n].index + 1);
    }
  }
  const Index old_tail = tail_first_entry_;
  Index new_tail = kInvalidIndex;
  Index w = 0;
  dead_ = 0;
  for (Index s = 0; s < entries_.size();) {
    if (new_tail == kInvalidIndex && s >= old_tail) new_tail = w;
    const Index leaf = leaf_of_[s];
    if (leaf == kInvalidIndex || leaf >= nodes_.size() || !reachable[leaf] || nodes_[leaf].index != s) {
      ++s;  // a slot of an orphaned or cut-out leaf: only tombstones
      continue;
    }
    Node& node = nodes_[leaf];
    const Index begin = w;
    for (Index k = s; k < s + node.count; ++k) {
      if (entries_[k].face == kInvalidIndex) continue;
      entries_[w] = entries_[k];
      leaf_of_[w] = leaf;
      slot_of_face_[entries_[w].face] = w;
      ++w;
    }
    if (w == begin) {  // only the root can be an empty leaf here (and then live_ is 0)
      entries_[w] = entries_[s];
      leaf_of_[w] = leaf;
      ++w;
      ++dead_;
    }
    s += node.count;
    node.index = begin;
    node.count = w - begin;
  }
  entries_.resize(w);
  leaf_of_.resize(w);
  tail_first_entry_ = new_tail == kInvalidIndex ? w : new_tail;
  tail_root_ = kInvalidIndex;  // the tail's nodes may have moved up: it is merged by copying now
  if (nodes_[0].is_leaf()) refit_leaf(0);
  bounds_lo_[0] = 0;
  bounds_hi_[0] = -1;
  grow_bounds();
  ++compactions_;
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
  dirty_.clear();
  bounds_lo_[0] = 0;
  bounds_hi_[0] = -1;
  grow_bounds();
  update_slack();
}

void FaceBvh::insert_entries(Index first, Index count) {
  if (nodes_.empty()) {
    nodes_.resize(1);
    height_.assign(1, 0);
    young_.assign(1, 0);
    parent_.assign(1, kInvalidIndex);
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
    parent_.resize(tail_first_node_);
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
    parent_.resize(j + 2);
    nodes_[j] = nodes_[n];
    height_[j] = height_[n];
    young_[j] = young_[n];
    parent_[j] = parent_[j + 1] = n;
    if (nodes_[j].is_leaf())
      std::fill(leaf_of_.begin() + nodes_[j].index, leaf_of_.begin() + nodes_[j].index + nodes_[j].count, j);
    else
      parent_[nodes_[j].index] = parent_[nodes_[j].index + 1] = j;
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
    dirty_.push_back(leaf_of_[slot]);
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
  if (live_ == 0) {
    rebuild();  // nothing left: the empty tree
    return;
  }
  refit_dirty();
  if (count > 0) insert_entries(first, count);
  if (dead_ > 0 && double(dead_) > options_.rebuild_fraction * double(entries_.size())) compact();
  if (!nodes_.empty() &&
      (height_[0] > kHeightFactor * height_at_build_ + kHeightSlack || 2 * orphan_nodes_ > nodes_.size())) {
    rebuild();
    return;
  }
  grow_bounds();
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

}  // namespace hedge

// FaceBvh: building the whole tree, and the pieces update() builds (subtrees over a range of
// entries). Nodes are split by a binned surface-area heuristic or at the median; see BvhSplit.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/algorithms/locate.h"
#include "hedge/error.h"
#include "locate_internal.h"

namespace hedge {

using namespace locate_detail;

namespace {

constexpr int kBins = 16;
// Nodes with fewer faces are split at the median instead of by SAH (see Builder::split).
constexpr unsigned kMinSahItems = 32;

}  // namespace

// ---- FaceBvh: building. ----

//! Builds one subtree over a contiguous range of entries (binned SAH or median split), writing its
//! root into a given node slot and appending the other nodes. The entries' boxes are partitioned
//! in place, so every pass over a node's range reads memory in order.
struct FaceBvh::Builder {
  struct Item {
    Box box;
    Index entry;  // offset in the range
    //! Twice the box centre: the halving is left out, it changes no comparison.
    float centre2(int a) const { return box.lo[a] + box.hi[a]; }
  };
  //! The box of some items. Splits bin the centres over the box's extent rather than the centres'
  //! own, which spares a second box per node and loses little.
  struct Bounds {
    Box box;
    void grow(const Item& it) { box.grow(it.box); }
    void grow(const Bounds& o) { box.grow(o.box); }
    int widest_axis() const {
      int axis = 0;
      for (int a = 1; a < 3; ++a)
        if (box.hi[a] - box.lo[a] > box.hi[axis] - box.lo[axis]) axis = a;
      return axis;
    }
  };
  struct Task {
    Index node, begin, end;
    Bounds bounds;
  };
  //! A node's split: the right child starts at mid (== begin for a leaf).
  struct Split {
    Index mid;
    Bounds left, right;
  };

  FaceBvh& t;
  Index first;
  std::vector<Item> items;

  Builder(FaceBvh& tree, Index first_entry, Index count) : t(tree), first(first_entry), items(count) {
    for (Index i = 0; i < count; ++i) items[i] = {t.entry_box(t.entries_[first + i]), i};
  }

  Bounds bounds(Index begin, Index end) const {
    Bounds b;
    for (Index k = begin; k < end; ++k) b.grow(items[k]);
    return b;
  }

  static int bin_of(float c, float cmin, float scale) {
    return std::clamp(static_cast<int>((c - cmin) * scale), 0, kBins - 1);
  }

  //! Halves at the median centre along the widest axis.
  Split median_split(Index begin, Index end, const Bounds& b) {
    const int axis = b.widest_axis();
    const Index mid = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                     [axis](const Item& x, const Item& y) { return x.centre2(axis) < y.centre2(axis); });
    return {mid, bounds(begin, mid), bounds(mid, end)};
  }

  //! Bins the centres along the widest axis in one pass (which also gives the children's bounds),
  //! prices every cut between bins as left count x left area + right count x right area, and
  //! partitions at the cheapest.
  Split sah_split(Index begin, Index end, const Bounds& b) {
    const int a = b.widest_axis();
    const float lo = 2 * b.box.lo[a];  // in centre2 units
    const float extent = 2 * b.box.hi[a] - lo;
    if (!(extent > 0)) return median_split(begin, end, b);  // coincident centres: any halving
    const float scale = float(kBins) / extent;
    std::array<Index, kBins> count{};
    std::array<Bounds, kBins> bin;
    for (Index k = begin; k < end; ++k) {
      const int i = bin_of(items[k].centre2(a), lo, scale);
      ++count[i];
      bin[i].grow(items[k]);
    }
    std::array<Bounds, kBins> right;  // right[i]: bins i.. (i >= 1)
    std::array<Index, kBins> right_count{};
    for (int i = kBins - 1; i > 0; --i) {
      right[i] = bin[i];
      if (i + 1 < kBins) right[i].grow(right[i + 1]);
      right_count[i] = count[i] + (i + 1 < kBins ? right_count[i + 1] : 0);
    }
    Bounds left, best_left;
    Index n = 0;
    int best = -1;
    double best_cost = kInf;
    for (int i = 0; i < kBins - 1; ++i) {
      left.grow(bin[i]);
      n += count[i];
      if (n == 0 || right_count[i + 1] == 0) continue;
      const double cost = n * left.box.half_area() + right_count[i + 1] * right[i + 1].box.half_area();
      if (cost < best_cost) {
        best_cost = cost;
        best = i;
        best_left = left;
      }
    }
    if (best < 0) return median_split(begin, end, b);
    const auto it = std::partition(items.begin() + begin, items.begin() + end,
                                   [&](const Item& x) { return bin_of(x.centre2(a), lo, scale) <= best; });
    return {static_cast<Index>(it - items.begin()), best_left, right[best + 1]};
  }

  Split split(Index begin, Index end, const Bounds& b) {
    const Index n = end - begin;
    if (n <= 1 || n <= t.options_.max_leaf_size) return {begin, {}, {}};
    // Binning costs a fixed sweep per node, more than it saves on small nodes: halve those.
    if (t.options_.split == BvhSplit::median || n < kMinSahItems) return median_split(begin, end, b);
    return sah_split(begin, end, b);
  }

  void run(Index root) {
    const std::size_t first_new_node = t.nodes_.size();
    t.leaf_of_.resize(t.entries_.size(), kInvalidIndex);
    t.parent_.resize(t.nodes_.size(), kInvalidIndex);
    std::vector<Task> tasks{{root, 0, Index(items.size()), bounds(0, Index(items.size()))}};
    while (!tasks.empty()) {
      const Task task = tasks.back();
      tasks.pop_back();
      const Split s = split(task.begin, task.end, task.bounds);
      Node& node = t.nodes_[task.node];
      std::copy(task.bounds.box.lo, task.bounds.box.lo + 3, node.lo);
      std::copy(task.bounds.box.hi, task.bounds.box.hi + 3, node.hi);
      if (s.mid == task.begin) {
        node.index = first + task.begin;
        node.count = task.end - task.begin;
        std::fill(t.leaf_of_.begin() + node.index, t.leaf_of_.begin() + node.index + node.count, task.node);
        continue;
      }
      const Index children = static_cast<Index>(t.nodes_.size());
      node.index = children;
      node.count = 0;
      t.nodes_.resize(t.nodes_.size() + 2);  // invalidates `node`
      t.parent_.resize(t.nodes_.size());
      t.parent_[children] = t.parent_[children + 1] = task.node;
      tasks.push_back({children + 1, s.mid, task.end, s.right});
      tasks.push_back({children, task.begin, s.mid, s.left});
    }

    // Entries into leaf order.
    std::vector<Entry> sorted(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) sorted[k] = t.entries_[first + items[k].entry];
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      t.entries_[first + k] = sorted[k];
      if (sorted[k].face != kInvalidIndex) t.slot_of_face_[sorted[k].face] = first + Index(k);
    }
    // Heights: every new node's children come after it, so a reverse sweep sees children first.
    t.height_.resize(t.nodes_.size(), 0);
    t.young_.resize(t.nodes_.size(), 0);
    for (std::size_t k = t.nodes_.size(); k-- > first_new_node;) t.set_height(Index(k));
    t.set_height(root);
  }
};

FaceBvh::FaceBvh(const SurfaceMesh& mesh, const BvhOptions& options) { build(mesh, options); }

FaceBvh::Entry FaceBvh::make_entry(Face f) const {
  const SurfaceMesh& m = *mesh_;
  Entry e{f.idx(), {kInvalidIndex, kInvalidIndex, kInvalidIndex}};
  const Halfedge h0 = m.halfedge(f);
  if (!h0.is_valid()) return e;
  const Halfedge h1 = m.next(h0);
  const Halfedge h2 = m.next(h1);
  if (m.next(h2) == h0) {
    e.corner[0] = m.to_vertex(h0).idx();
    e.corner[1] = m.to_vertex(h1).idx();
    e.corner[2] = m.to_vertex(h2).idx();
  }
  return e;
}

FaceBvh::Box FaceBvh::entry_box(const Entry& e) const {
  Box box;
  if (e.face == kInvalidIndex) return box;
  bool finite = true;
  for_each_triangle(e, [&](Face, Vertex a, Vertex b, Vertex c) {
    for (const Vertex v : {a, b, c}) {
      finite = finite && is_finite(mesh_->position(v));
      box.grow(mesh_->position(v));
    }
    return false;
  });
  // A face with a corner that is not finite (written after the tree was made, without the change
  // log's notice) gets the empty box: no query reaches it, and the boxes above it stay finite.
  return finite ? box : Box{};
}

void FaceBvh::set_height(Index n) {
  const Node& node = nodes_[n];
  height_[n] = node.is_leaf() ? 0 : 1 + std::max(height_[node.index], height_[node.index + 1]);
}

void FaceBvh::build_subtree(Index first_entry, Index count, Index root) {
  Builder(*this, first_entry, count).run(root);
}

void FaceBvh::build(const SurfaceMesh& mesh, const BvhOptions& options) {
  if (options.max_leaf_size < 1 || options.max_leaf_size > 255)
    throw InvalidInputError("FaceBvh: max_leaf_size must be in 1..255, got " +
                            std::to_string(options.max_leaf_size));
  if (!(options.rebuild_fraction > 0 && options.rebuild_fraction <= 1))
    throw InvalidInputError("FaceBvh: rebuild_fraction must be in (0, 1]");
  require_finite_positions(mesh, "FaceBvh");
  build_tree(mesh, options);
}

// A new tree refuses a position that is not finite, by name (build()). A rebuild by update() does
// not: it must not fail halfway through an edit that called it, so it leaves such faces out
// (entry_box()).
void FaceBvh::build_tree(const SurfaceMesh& mesh, const BvhOptions& options) {
  if (mesh_ != &mesh || !changes_.attached()) changes_ = ChangeConsumer(mesh.watch_changes());
  changes_.consume();  // the new tree holds every edit so far
  mesh_ = &mesh;
  options_ = options;
  nodes_.clear();
  entries_.clear();
  height_.clear();
  young_.clear();
  parent_.clear();
  leaf_of_.clear();
  dirty_.clear();
  slot_of_face_.assign(mesh.face_slots(), kInvalidIndex);
  entries_.reserve(mesh.n_faces());
  for (Face f : mesh.faces()) entries_.push_back(make_entry(f));
  live_ = entries_.size();
  dead_ = 0;
  orphan_nodes_ = 0;
  tail_root_ = kInvalidIndex;
  ++builds_;
  if (live_ > 0) {
    nodes_.reserve(live_ + 1);  // enough for leaves of two faces on average; trimmed below
    nodes_.resize(1);
    parent_.assign(1, kInvalidIndex);
    build_subtree(0, static_cast<Index>(entries_.size()), 0);
    nodes_.shrink_to_fit();
    height_.shrink_to_fit();
    young_.shrink_to_fit();
    parent_.shrink_to_fit();
  }
  height_at_build_ = nodes_.empty() ? 0 : height_[0];
  closed_ = -1;
  bounds_lo_[0] = 0;
  bounds_hi_[0] = -1;  // empty until grown
  grow_bounds();
  update_slack();
}

bool FaceBvh::mesh_closed(Halfedge* boundary) {
  if (closed_ < 0 && mesh_) {
    closed_ = 1;
    first_boundary_ = Halfedge{};
    for (Halfedge h : mesh_->halfedges())
      if (mesh_->is_boundary(h)) {
        closed_ = 0;
        first_boundary_ = h;
        break;
      }
  }
  if (boundary) *boundary = first_boundary_;
  return closed_ == 1;
}

void FaceBvh::note_closed(bool closed, Halfedge boundary) {
  closed_ = closed ? 1 : 0;
  first_boundary_ = closed ? Halfedge{} : boundary;
}

void FaceBvh::rebuild() {
  if (mesh_) build_tree(*mesh_, options_);
}

void FaceBvh::update_slack() {
  // Absolute slack for distances near zero, where the double triangle code's error is absolute
  // (about 1e-16 of the squared extent); this is far larger and still negligible.
  slack_sq_ = 0;
  if (nodes_.empty() || !(bounds_lo_[0] <= bounds_hi_[0])) return;
  double diag2 = 0;
  for (int a = 0; a < 3; ++a) diag2 += sq(double(bounds_hi_[a]) - bounds_lo_[a]);
  slack_sq_ = diag2 * 1e-12;
}

void FaceBvh::grow_bounds() {
  if (nodes_.empty()) return;
  const Node& r = nodes_[0];
  if (!(r.lo[0] <= r.hi[0])) return;
  const bool was_empty = !(bounds_lo_[0] <= bounds_hi_[0]);
  for (int a = 0; a < 3; ++a) {
    bounds_lo_[a] = was_empty ? r.lo[a] : std::min(bounds_lo_[a], r.lo[a]);
    bounds_hi_[a] = was_empty ? r.hi[a] : std::max(bounds_hi_[a], r.hi[a]);
  }
}

BoundingBox FaceBvh::bounds() const {
  BoundingBox box;
  if (empty() || !(bounds_lo_[0] <= bounds_hi_[0])) return box;
  box.min = {bounds_lo_[0], bounds_lo_[1], bounds_lo_[2]};
  box.max = {bounds_hi_[0], bounds_hi_[1], bounds_hi_[2]};
  box.empty = false;
  return box;
}

void FaceBvh::check_fresh() const {
  if (changes_.reset_pending())
    throw InvalidInputError(
        "FaceBvh: the mesh was renumbered (garbage_collection() or assignment) since the tree was "
        "built; call update() or rebuild() first");
}

}  // namespace hedge

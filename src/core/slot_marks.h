// A set of a mesh's elements (faces, vertices, ...) as one flag per slot, in an array the thread
// keeps from one call to the next: a test and an insertion are O(1), and neither making nor
// dropping a set passes over the mesh. The flags a set raised are lowered when it goes, also when
// an exception passes. Sets of the same (H, Tag) on one thread share the array, so only one of
// them may live at a time: each user names its own Tag.
#pragma once

#include <cstddef>
#include <vector>

namespace hedge::detail {

template <typename H, typename Tag>
class SlotMarks {
 public:
  //! A set for handles below `slots`, empty.
  explicit SlotMarks(std::size_t slots) : flags_(storage()) {
    if (flags_.size() < slots) flags_.resize(slots, 0);
  }
  SlotMarks(const SlotMarks&) = delete;
  SlotMarks& operator=(const SlotMarks&) = delete;
  ~SlotMarks() { clear(); }

  bool operator()(H h) const { return flags_[h.idx()] != 0; }
  //! Adds h; false if it was there already.
  bool mark(H h) {
    if (flags_[h.idx()]) return false;
    marked_.push_back(h);
    flags_[h.idx()] = 1;
    return true;
  }
  //! The handles added, in the order they were.
  const std::vector<H>& marked() const { return marked_; }
  void clear() {
    for (H h : marked_) flags_[h.idx()] = 0;
    marked_.clear();
  }

 private:
  static std::vector<char>& storage() {
    thread_local std::vector<char> flags;
    return flags;
  }
  std::vector<char>& flags_;
  std::vector<H> marked_;
};

}  // namespace hedge::detail

// SmallVector: a sequence that keeps its first N elements inline and spills the rest to the heap.
// Local operations and BVH traversals keep short per-call lists (a one-ring, a traversal stack)
// whose size is almost always small: inline storage makes them allocation-free in that case and
// still correct for any size. Private to the library: core includes it as "small_vector.h", the
// layers that use core as "core_private/small_vector.h" (src/CMakeLists.txt links it there).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace hedge {

//! T must be default-constructible and copyable. Elements are stored in order: indices
//! [0, min(size, N)) inline, the rest in the spill vector. No iterators: index with operator[].
template <typename T, std::size_t N = 16>
class SmallVector {
 public:
  void push_back(const T& t) {
    if (n_ < N)
      inline_[n_] = t;
    else
      spill_.push_back(t);
    ++n_;
  }
  //! Removes and returns the last element. \pre !empty()
  T pop_back() {
    --n_;
    if (n_ < N) return inline_[n_];
    T t = spill_.back();
    spill_.pop_back();
    return t;
  }
  const T& operator[](std::size_t i) const { return i < N ? inline_[i] : spill_[i - N]; }
  T& operator[](std::size_t i) { return i < N ? inline_[i] : spill_[i - N]; }
  //! True if an element equals t. O(size).
  bool contains(const T& t) const {
    const auto in = inline_.begin();
    if (std::find(in, in + static_cast<std::ptrdiff_t>(std::min(n_, N)), t) !=
        in + static_cast<std::ptrdiff_t>(std::min(n_, N)))
      return true;
    return std::find(spill_.begin(), spill_.end(), t) != spill_.end();
  }
  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  void clear() {
    n_ = 0;
    spill_.clear();
  }

 private:
  std::array<T, N> inline_{};
  std::vector<T> spill_;
  std::size_t n_ = 0;
};

}  // namespace hedge

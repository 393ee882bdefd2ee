// Light ranges over mesh elements for range-for: element ranges that skip deleted slots, and
// circulators about a vertex or along a face loop. They hold a pointer to the mesh and a handle;
// nothing is allocated.
//
// Edits while a range or circulator is in use:
//  - An element range reads the deletion flags as it advances, over the slots that existed when it
//    was made: an element deleted ahead of the iterator is skipped, elements added meanwhile are not
//    visited, and the element at the iterator may be deleted (the loop goes on to the next live
//    one). So "for (Face f : mesh.faces()) if (...) delete or split f" is safe.
//  - A circulator follows the links (next, twin) as it goes and stops when it is back at its start.
//    An edit that changes the links around its vertex or face (splitting, collapsing, flipping
//    or deleting an element there) leaves it meaningless: it may visit elements twice, miss some
//    or never end. Collect what it yields into a vector first, then edit. Edits elsewhere in the
//    mesh do not affect it.
//  - garbage_collection() (and renumber()) invalidates every range and circulator in progress:
//    indices move, so neither may be used again; make new ones.
// A range or circulator in use on one thread while another edits the mesh is a data race
// (see surface_mesh.h for the thread rule).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "hedge/core/handles.h"

namespace hedge {

//! All live elements of one kind, in index order.
template <typename H>
class ElementRange {
 public:
  //! For half-edges, deleted is the per-edge vector and shift is 1.
  ElementRange(const std::vector<bool>& deleted, std::size_t size, unsigned shift = 0)
      : deleted_(&deleted), size_(static_cast<Index>(size)), shift_(shift) {}

  class iterator {
   public:
    using value_type = H;
    using difference_type = std::ptrdiff_t;
    iterator() = default;
    iterator(const ElementRange* r, Index i) : r_(r), i_(i) { skip(); }
    H operator*() const { return H(i_); }
    iterator& operator++() {
      ++i_;
      skip();
      return *this;
    }
    iterator operator++(int) {
      iterator t = *this;
      ++*this;
      return t;
    }
    friend bool operator==(const iterator& a, const iterator& b) { return a.i_ == b.i_; }

   private:
    void skip() {
      while (i_ < r_->size_ && (*r_->deleted_)[i_ >> r_->shift_]) ++i_;
    }
    const ElementRange* r_ = nullptr;
    Index i_ = 0;
  };

  iterator begin() const { return iterator(this, 0); }
  iterator end() const { return iterator(this, size_); }

 private:
  const std::vector<bool>* deleted_;
  Index size_;
  unsigned shift_;
};

// What a circulator yields for each half-edge it visits (get), and which half-edges it passes over
// (skip). Most pass over none.
struct SkipNone {
  template <typename M>
  static bool skip(const M&, Halfedge) {
    return false;
  }
};
struct HalfedgeOf : SkipNone {
  template <typename M>
  static Halfedge get(const M&, Halfedge h) {
    return h;
  }
};
struct TargetOf : SkipNone {
  template <typename M>
  static Vertex get(const M& m, Halfedge h) {
    return m.to_vertex(h);
  }
};
struct EdgeOf : SkipNone {
  template <typename M>
  static Edge get(const M& m, Halfedge h) {
    return m.edge(h);
  }
};
// Passes over the half-edges whose element is invalid (a face across the boundary).
template <typename Of>
struct SkipInvalid {
  template <typename M>
  static bool skip(const M& m, Halfedge h) {
    return !Of::get(m, h).is_valid();
  }
};
struct FaceOf : SkipInvalid<FaceOf> {
  template <typename M>
  static Face get(const M& m, Halfedge h) {
    return m.face(h);
  }
};
struct TwinFaceOf : SkipInvalid<TwinFaceOf> {
  template <typename M>
  static Face get(const M& m, Halfedge h) {
    return m.face(m.twin(h));
  }
};

struct CirculatorEnd {};

// Steps of the two circulator kinds.
template <bool CCW>
struct RotateStep {
  template <typename M>
  static Halfedge step(const M& m, Halfedge h) {
    if constexpr (CCW)
      return m.rotate_ccw(h);
    else
      return m.rotate_cw(h);
  }
};
struct NextStep {
  template <typename M>
  static Halfedge step(const M& m, Halfedge h) {
    return m.next(h);
  }
};

template <typename M, typename Get, typename Step>
class Circulator {
 public:
  Circulator(const M* mesh, Halfedge start) : mesh_(mesh), start_(start) {}

  class iterator {
   public:
    using value_type = decltype(Get::get(std::declval<const M&>(), Halfedge()));
    using difference_type = std::ptrdiff_t;
    iterator(const M* m, Halfedge start) : m_(m), start_(start), cur_(start), done_(!start.is_valid()) {
      if (!done_ && Get::skip(*m_, cur_)) ++*this;
    }
    value_type operator*() const { return Get::get(*m_, cur_); }
    //! The half-edge the circulator is at.
    Halfedge halfedge() const { return cur_; }
    iterator& operator++() {
      do {
        cur_ = Step::step(*m_, cur_);
        if (cur_ == start_) {
          done_ = true;
          break;
        }
      } while (Get::skip(*m_, cur_));
      return *this;
    }
    friend bool operator==(const iterator& it, CirculatorEnd) { return it.done_; }

   private:
    const M* m_;
    Halfedge start_, cur_;
    bool done_;
  };

  iterator begin() const { return iterator(mesh_, start_); }
  CirculatorEnd end() const { return {}; }
  //! Number of elements visited. O(length).
  std::size_t count() const {
    std::size_t n = 0;
    for (auto it = begin(); it != end(); ++it) ++n;
    return n;
  }
  bool empty() const { return begin() == end(); }

 private:
  const M* mesh_;
  Halfedge start_;
};

template <typename M, typename Get, bool CCW = false>
using VertexCirculator = Circulator<M, Get, RotateStep<CCW>>;
template <typename M, typename Get>
using LoopCirculator = Circulator<M, Get, NextStep>;

//! Up to N handles, for queries with a small bounded answer (the faces of an edge).
template <typename T, std::size_t N>
class FixedList {
 public:
  void push_back(T t) { items_[size_++] = t; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const T* begin() const { return items_; }
  const T* end() const { return items_ + size_; }
  const T& operator[](std::size_t i) const { return items_[i]; }

 private:
  T items_[N] = {};
  std::size_t size_ = 0;
};

}  // namespace hedge

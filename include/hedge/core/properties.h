// Named, typed per-element arrays. A PropertyContainer holds every array of one element kind
// (vertices, half-edges, edges or faces) and keeps them the same length as the element count.
#pragma once

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "hedge/core/handles.h"
#include "hedge/error.h"

namespace hedge {

//! The face property of a face's submesh (its material slot in an engine), std::int32_t in
//! [0, kMaxSubmesh]; the faces of a mesh without it are in submesh 0. Face properties follow their
//! faces through edits, subdivision, decimation, detach and fracture, so the submesh does too.
inline constexpr const char* kSubmeshProperty = "f:submesh";
//! The largest submesh a face takes: render buffers give every id up to the largest one a region
//! of the index buffer, even an empty one (engines allow far fewer materials).
inline constexpr std::int32_t kMaxSubmesh = 65535;

class BasePropertyArray {
 public:
  explicit BasePropertyArray(std::string name) : name_(std::move(name)) {}
  virtual ~BasePropertyArray() = default;
  BasePropertyArray(const BasePropertyArray&) = default;
  BasePropertyArray& operator=(const BasePropertyArray&) = default;

  const std::string& name() const { return name_; }
  virtual const std::type_info& type() const = 0;
  virtual void resize(std::size_t n) = 0;
  //! Appends one element with the default value (amortized O(1): the array grows geometrically).
  virtual void push_back() = 0;
  virtual void reserve(std::size_t n) = 0;
  virtual void shrink_to_fit() = 0;
  //! Copies element `from` onto element `to` (used when an element is duplicated).
  virtual void copy(std::size_t from, std::size_t to) = 0;
  //! Keeps element i at new_index[i], dropping elements whose new index is invalid; new size n.
  virtual void compact(const std::vector<Index>& new_index, std::size_t n) = 0;
  virtual std::unique_ptr<BasePropertyArray> clone() const = 0;
  //! A new, empty array of the same name, type and default value.
  virtual std::unique_ptr<BasePropertyArray> empty_clone() const = 0;
  //! Sets element dst to the weighted combination of elements src[0..n) (weights sum to 1).
  //! Types with + and scalar * (floats, doubles, Vec2, Vec3, ...) blend linearly; any other type
  //! takes the value of the source with the largest weight.
  virtual void interpolate(std::size_t dst, const Index* src, const float* weights, std::size_t n) = 0;
  //! Copies element si of `other` (an array of the same type) onto element di of this one.
  virtual void copy_from(const BasePropertyArray& other, std::size_t si, std::size_t di) = 0;
  //! Exchanges the values (not the name, default or interpolator) with `other`, an array of the
  //! same type. O(1), never throws.
  virtual void swap_values(BasePropertyArray& other) noexcept = 0;
  //! Bytes held by this array (its capacity), for memory accounting.
  virtual std::size_t bytes() const = 0;
  //! Bytes of one element (sizeof the value type), for estimates of memory to come.
  virtual std::size_t element_bytes() const = 0;
  //! True if elements i and j hold equal values (==); always true for a type without ==.
  virtual bool equal(std::size_t i, std::size_t j) const = 0;

 private:
  std::string name_;
};

template <typename T>
class PropertyArray final : public BasePropertyArray {
  static_assert(!std::is_same_v<T, bool>, "use std::uint8_t for flags: std::vector<bool> has no references");

 public:
  //! A user policy for new elements: the value from the sources' values and weights (n of each).
  using Interpolator = std::function<T(const T* values, const float* weights, std::size_t n)>;

  PropertyArray(std::string name, T default_value)
      : BasePropertyArray(std::move(name)), default_(std::move(default_value)) {}

  const std::type_info& type() const override { return typeid(T); }
  void resize(std::size_t n) override { data_.resize(n, default_); }
  void push_back() override { data_.push_back(default_); }
  void reserve(std::size_t n) override { data_.reserve(n); }
  void shrink_to_fit() override { data_.shrink_to_fit(); }
  void copy(std::size_t from, std::size_t to) override { data_[to] = data_[from]; }
  void compact(const std::vector<Index>& new_index, std::size_t n) override {
    std::vector<T> out(n, default_);
    for (std::size_t i = 0; i < data_.size() && i < new_index.size(); ++i)
      if (new_index[i] != kInvalidIndex) out[new_index[i]] = std::move(data_[i]);
    data_.swap(out);
  }
  std::unique_ptr<BasePropertyArray> clone() const override {
    return std::make_unique<PropertyArray<T>>(*this);
  }
  std::unique_ptr<BasePropertyArray> empty_clone() const override {
    return std::make_unique<PropertyArray<T>>(name(), default_);
  }
  void interpolate(std::size_t dst, const Index* src, const float* w, std::size_t n) override {
    if (n == 0) return;
    if (interpolator_) {
      T values[16];
      std::vector<T> many;
      T* v = values;
      if (n > 16) {
        many.resize(n);
        v = many.data();
      }
      for (std::size_t i = 0; i < n; ++i) v[i] = data_[src[i]];
      data_[dst] = interpolator_(v, w, n);
      return;
    }
    if constexpr (!std::is_integral_v<T> && requires(T a, float f) { a = a * f + a * f; }) {
      T acc = data_[src[0]] * w[0];
      for (std::size_t i = 1; i < n; ++i) acc = acc + data_[src[i]] * w[i];
      data_[dst] = acc;
    } else {
      std::size_t best = 0;
      for (std::size_t i = 1; i < n; ++i)
        if (w[i] > w[best]) best = i;
      data_[dst] = data_[src[best]];
    }
  }
  void copy_from(const BasePropertyArray& other, std::size_t si, std::size_t di) override {
    data_[di] = static_cast<const PropertyArray<T>&>(other).data_[si];
  }
  void swap_values(BasePropertyArray& other) noexcept override {
    data_.swap(static_cast<PropertyArray<T>&>(other).data_);
  }
  std::size_t bytes() const override { return data_.capacity() * sizeof(T); }
  std::size_t element_bytes() const override { return sizeof(T); }
  bool equal(std::size_t i, std::size_t j) const override {
    if constexpr (std::equality_comparable<T>)
      return data_[i] == data_[j];
    else
      return true;
  }

  std::vector<T>& vector() { return data_; }
  const std::vector<T>& vector() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  const T& default_value() const { return default_; }
  //! Replaces the default interpolation of this property; an empty function restores it.
  void set_interpolator(Interpolator f) { interpolator_ = std::move(f); }

 private:
  std::vector<T> data_;
  T default_;
  Interpolator interpolator_;
};

//! A typed view of one property array, indexed by the element handle type H.
//! Cheap to copy; stays valid while the property exists (the mesh may grow).
template <typename H, typename T>
class Property {
 public:
  Property() = default;
  explicit Property(PropertyArray<T>* array) : array_(array) {}

  explicit operator bool() const { return array_ != nullptr; }
  T& operator[](H h) { return (*array_)[h.idx()]; }
  const T& operator[](H h) const { return (*array_)[h.idx()]; }
  std::vector<T>& vector() { return array_->vector(); }
  const std::vector<T>& vector() const { return array_->vector(); }
  const std::string& name() const { return array_->name(); }
  PropertyArray<T>* array() const { return array_; }
  //! How the operations fill this property on new elements (see PropertyArray::set_interpolator).
  void set_interpolator(typename PropertyArray<T>::Interpolator f) { array_->set_interpolator(std::move(f)); }

 private:
  PropertyArray<T>* array_ = nullptr;
};

template <typename T>
using VertexProperty = Property<Vertex, T>;
template <typename T>
using HalfedgeProperty = Property<Halfedge, T>;
template <typename T>
using EdgeProperty = Property<Edge, T>;
template <typename T>
using FaceProperty = Property<Face, T>;

//! Every property array of one element kind.
class PropertyContainer {
 public:
  PropertyContainer() = default;
  PropertyContainer(const PropertyContainer& o) : size_(o.size_) {
    arrays_.reserve(o.arrays_.size());
    for (const auto& a : o.arrays_) arrays_.push_back(a->clone());
  }
  PropertyContainer& operator=(const PropertyContainer& o) {
    if (this != &o) {
      PropertyContainer copy(o);
      *this = std::move(copy);
    }
    return *this;
  }
  PropertyContainer(PropertyContainer&&) noexcept = default;
  PropertyContainer& operator=(PropertyContainer&&) noexcept = default;

  std::size_t size() const { return size_; }

  //! Adds a property. Throws InvalidInputError if one of that name exists already.
  template <typename T>
  PropertyArray<T>* add(std::string_view name, T default_value) {
    if (find_base(name))
      throw InvalidInputError("a property named '" + std::string(name) + "' exists already");
    auto array = std::make_unique<PropertyArray<T>>(std::string(name), std::move(default_value));
    array->resize(size_);
    auto* raw = array.get();
    arrays_.push_back(std::move(array));
    return raw;
  }
  //! The property of that name and type, or nullptr.
  template <typename T>
  PropertyArray<T>* get(std::string_view name) const {
    BasePropertyArray* a = find_base(name);
    if (!a || a->type() != typeid(T)) return nullptr;
    return static_cast<PropertyArray<T>*>(a);
  }
  BasePropertyArray* find_base(std::string_view name) const {
    for (const auto& a : arrays_)
      if (a->name() == name) return a.get();
    return nullptr;
  }
  //! Removes the property; returns false if there is none of that name.
  bool remove(std::string_view name) {
    auto it = std::find_if(arrays_.begin(), arrays_.end(), [&](const auto& a) { return a->name() == name; });
    if (it == arrays_.end()) return false;
    arrays_.erase(it);
    return true;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& a : arrays_) out.push_back(a->name());
    return out;
  }

  void resize(std::size_t n) {
    for (auto& a : arrays_) a->resize(n);
    size_ = n;
  }
  void reserve(std::size_t n) {
    for (auto& a : arrays_) a->reserve(n);
  }
  bool empty() const { return arrays_.empty(); }
  //! Number of property arrays held.
  std::size_t array_count() const { return arrays_.size(); }
  //! Appends one element to every array. Operations add elements one at a time: this is a
  //! push_back per array (no call at all when the container holds no array).
  void push_back() {
    for (auto& a : arrays_) a->push_back();
    ++size_;
  }
  //! Appends n elements to every array.
  void push_back(std::size_t n) {
    for (auto& a : arrays_)
      for (std::size_t i = 0; i < n; ++i) a->push_back();
    size_ += n;
  }
  //! Appends one element to every array but `appended`, which the caller has grown itself (with
  //! a value rather than the default: a new vertex's position).
  void push_back_except(const BasePropertyArray* appended) {
    if (arrays_.size() != 1 || arrays_.front().get() != appended) [[unlikely]]
      for (auto& a : arrays_)
        if (a.get() != appended) a->push_back();
    ++size_;
  }
  void copy(std::size_t from, std::size_t to) {
    for (auto& a : arrays_) a->copy(from, to);
  }
  //! True if elements i and j hold equal values in every array (see BasePropertyArray::equal).
  bool equal(std::size_t i, std::size_t j) const {
    for (const auto& a : arrays_)
      if (!a->equal(i, j)) return false;
    return true;
  }
  void compact(const std::vector<Index>& new_index, std::size_t n) {
    for (auto& a : arrays_) a->compact(new_index, n);
    size_ = n;
  }
  //! Interpolates every property onto element dst (see BasePropertyArray::interpolate), except
  //! `skip` if given: an array the caller sets itself (a new vertex's position).
  void interpolate(std::size_t dst, const Index* src, const float* weights, std::size_t n,
                   const BasePropertyArray* skip = nullptr) {
    for (auto& a : arrays_)
      if (a.get() != skip) a->interpolate(dst, src, weights, n);
  }
  //! Adds, empty, every array of `other` that this container lacks (same name and type).
  void add_missing_from(const PropertyContainer& other) {
    for (const auto& a : other.arrays_) {
      BasePropertyArray* mine = find_base(a->name());
      if (mine && mine->type() == a->type()) continue;
      if (mine) remove(a->name());
      auto copy = a->empty_clone();
      copy->resize(size_);
      arrays_.push_back(std::move(copy));
    }
  }
  //! Copies element si of `other` onto element di, for every array both containers hold.
  void copy_element_from(const PropertyContainer& other, std::size_t si, std::size_t di) {
    for (auto& a : arrays_) {
      BasePropertyArray* src = other.find_base(a->name());
      if (src && src->type() == a->type()) a->copy_from(*src, si, di);
    }
  }
  //! Exchanges the values of every array with those of the array of the same name and type in
  //! `other`, and the sizes; the arrays themselves (and handles to them) stay where they are. An
  //! array that `other` lacks keeps its values, so `other` should hold every array of this one (as
  //! add_missing_from() makes it). O(arrays^2) name comparisons, never throws.
  void swap_values(PropertyContainer& other) noexcept {
    for (auto& a : arrays_) {
      BasePropertyArray* theirs = other.find_base(a->name());
      if (theirs && theirs->type() == a->type()) a->swap_values(*theirs);
    }
    std::swap(size_, other.size_);
  }
  void shrink_to_fit() {
    for (auto& a : arrays_) a->shrink_to_fit();
  }
  std::size_t bytes() const {
    std::size_t b = 0;
    for (const auto& a : arrays_) b += a->bytes();
    return b;
  }
  //! Bytes of one element over all arrays.
  std::size_t element_bytes() const {
    std::size_t b = 0;
    for (const auto& a : arrays_) b += a->element_bytes();
    return b;
  }

 private:
  std::vector<std::unique_ptr<BasePropertyArray>> arrays_;
  std::size_t size_ = 0;
};

}  // namespace hedge

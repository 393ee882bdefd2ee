// Typed 32-bit element handles. Vertex, Halfedge, Edge and Face are distinct types, so they cannot
// be mixed up; the invalid handle has all bits set.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>

namespace hedge {

using Index = std::uint32_t;
inline constexpr Index kInvalidIndex = std::numeric_limits<Index>::max();

template <typename Tag>
class Handle {
 public:
  constexpr Handle() = default;
  constexpr explicit Handle(Index idx) : idx_(idx) {}
  constexpr Index idx() const { return idx_; }
  constexpr bool is_valid() const { return idx_ != kInvalidIndex; }
  friend constexpr bool operator==(Handle a, Handle b) = default;
  friend constexpr auto operator<=>(Handle a, Handle b) = default;

 private:
  Index idx_ = kInvalidIndex;
};

struct VertexTag {};
struct HalfedgeTag {};
struct EdgeTag {};
struct FaceTag {};

using Vertex = Handle<VertexTag>;
using Halfedge = Handle<HalfedgeTag>;
using Edge = Handle<EdgeTag>;
using Face = Handle<FaceTag>;

}  // namespace hedge

template <typename Tag>
struct std::hash<hedge::Handle<Tag>> {
  std::size_t operator()(hedge::Handle<Tag> h) const noexcept { return std::hash<hedge::Index>{}(h.idx()); }
};

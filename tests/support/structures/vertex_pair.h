// An edge named by its two vertices: how the structures without edge elements name an edge, and
// the common currency in which the tests compare every structure's answers.
#pragma once

#include <compare>
#include <utility>

#include "hedge/core/handles.h"

namespace hedge::structures {

struct VertexPair {
  Index a = kInvalidIndex;
  Index b = kInvalidIndex;

  //! The pair with a < b, so that both directions of an edge compare equal.
  static constexpr VertexPair ordered(Index x, Index y) {
    return x < y ? VertexPair{x, y} : VertexPair{y, x};
  }
  friend constexpr bool operator==(const VertexPair&, const VertexPair&) = default;
  friend constexpr auto operator<=>(const VertexPair&, const VertexPair&) = default;
};

}  // namespace hedge::structures

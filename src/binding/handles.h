// Element handles from a binding: indices checked against a mesh before the library sees them, with
// one message format for every binding ("edge 7 is deleted", "face 12 is out of range (the mesh has
// 9 face slots)"). Each check throws a BindingError (HEDGE_ERROR_BAD_HANDLE).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>

#include "hedge/core/surface_mesh.h"

namespace hedge::binding {

//! The word for an element of type H in messages: "vertex", "halfedge", "edge" or "face".
template <typename H>
constexpr const char* element_kind() {
  if constexpr (std::is_same_v<H, Vertex>)
    return "vertex";
  else if constexpr (std::is_same_v<H, Halfedge>)
    return "halfedge";
  else if constexpr (std::is_same_v<H, Edge>)
    return "edge";
  else
    return "face";
}

//! "edge 7": how messages name an element.
std::string element_name(const char* kind, std::uint32_t index);

//! \throw BindingError (HEDGE_ERROR_BAD_HANDLE) unless i < slots; `kind` names the element.
void check_range(const char* kind, std::uint32_t i, std::size_t slots);

//! A live element of the mesh. \throw BindingError (HEDGE_ERROR_BAD_HANDLE) if out of range or
//! deleted.
Vertex live_vertex(const SurfaceMesh& m, std::uint32_t v);
Halfedge live_halfedge(const SurfaceMesh& m, std::uint32_t h);
Edge live_edge(const SurfaceMesh& m, std::uint32_t e);
Face live_face(const SurfaceMesh& m, std::uint32_t f);

//! A live element of type H (see live_vertex and the others).
template <typename H>
H live_element(const SurfaceMesh& m, std::uint32_t index) {
  if constexpr (std::is_same_v<H, Vertex>)
    return live_vertex(m, index);
  else if constexpr (std::is_same_v<H, Halfedge>)
    return live_halfedge(m, index);
  else if constexpr (std::is_same_v<H, Edge>)
    return live_edge(m, index);
  else
    return live_face(m, index);
}

}  // namespace hedge::binding

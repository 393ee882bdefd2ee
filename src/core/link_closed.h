// Links a closed, manifold set of triangles whose vertex indices are already dense into a
// SurfaceMesh, without build()'s input checks, welding, repairs or report: for the algorithms that
// make such sets themselves (the convex hull's faces, a solid fracture's pieces). Included by the
// other layers as "core_private/link_closed.h".
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "hedge/core/surface_mesh.h"

namespace hedge::link_detail {

//! Why a triangle set is not closed and manifold: the first defect found, in the order of kind.
struct ClosedLinkDefect {
  enum class Kind {
    none,
    //! triangle's corner `a` is not below the vertex count
    vertex_out_of_range,
    //! triangle repeats a vertex
    repeated_vertex,
    //! two triangles run along the edge from a to b the same way
    edge_used_twice,
    //! no triangle runs along the edge from a to b's reverse, b to a: the set is open there
    open_edge,
    //! the triangles around vertex a form more than one fan
    several_fans,
    //! the twin the caller gave corner `corner` does not run the other way along its edge
    wrong_twin,
  };
  Kind kind = Kind::none;
  std::size_t triangle = 0;  // vertex_out_of_range, repeated_vertex
  std::size_t corner = 0;    // wrong_twin
  std::uint32_t a = 0, b = 0;
  explicit operator bool() const { return kind != Kind::none; }
};

//! A sentence naming the defect in the set's own indices ("" for none).
std::string describe(const ClosedLinkDefect& d);

//! Links the triangles corners[3 t .. 3 t + 2] (vertex indices below n_vertices) into `mesh`,
//! replaced on success with the numbering build_triangles() gives clean input: triangle t is face
//! t, vertex i is vertex i (its position left at zero for the caller to write); an edge is made by
//! the first corner that crosses it, as half-edge 2e, and its other half-edge 2e + 1 is taken by
//! the second; a vertex holds its last corner's half-edge, a face the half-edge entering its first
//! corner. A vertex no triangle uses stays isolated, as in build(). Checks what build() would, in
//! this order: every index is in range, no triangle repeats a vertex, every directed edge is used
//! once and its reverse once (the smallest vertex with a doubled edge is named, then the first
//! corner without a reverse), the triangles around every vertex form one fan (the smallest vertex
//! that does not is named). On a defect `mesh` is left as it was. A corner count that is not a
//! multiple of 3 is a programming error (std::logic_error). O(corners x valence).
ClosedLinkDefect link_closed_triangles(std::span<const std::uint32_t> corners, std::size_t n_vertices,
                                       SurfaceMesh& mesh);

//! The same, for a caller that knows each corner's twin already (twins[c]: the corner running the
//! other way along corner c's edge; a corner c runs from corners[c] to the next corner of its
//! triangle), so that no search pairs them: the twins are checked (wrong_twin names the first
//! corner whose twin is out of range, not its own twin's twin, or not the reverse of its edge),
//! then linked and the fans checked as above. Two edges joining the same two vertices are not
//! looked for: the caller's twins vouch for them (a convex hull has none). O(corners).
ClosedLinkDefect link_closed_triangles(std::span<const std::uint32_t> corners,
                                       std::span<const std::uint32_t> twins, std::size_t n_vertices,
                                       SurfaceMesh& mesh);

}  // namespace hedge::link_detail

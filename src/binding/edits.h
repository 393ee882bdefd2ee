// The refusable edits as every binding does them: the element handles are checked first
// (HEDGE_ERROR_BAD_HANDLE, see handles.h), then the library's refusal of the edit
// (hedge/core/operations.h, hedge/algorithms/fill_hole.h), then the edit is done. A refused edit
// throws a BindingError of HEDGE_ERROR_REFUSED whose message says what was refused and why
// ("flip of edge 3 refused: the edge is on the boundary (...); nothing was changed") and whose
// refusal is the library's reason alone; the mesh is then unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hedge/core/surface_mesh.h"

namespace hedge::binding {

//! The refusable edits. Their names in messages are the library's ("split_edge", "collapse", ...).
enum class Edit { split_edge, collapse, flip, split_face, cut_face, fill_hole, remove_face };
//! The spelling of edit names a binding's callers use: the library's and Python's snake_case
//! ("split_edge"), or the JS API's camelCase method names ("splitEdge").
enum class EditNaming { snake_case, camel_case };
//! The edit's name in messages: the library function's ("split_edge", ...).
const char* edit_name(Edit edit) noexcept;
//! The edit that `name` names in the caller's spelling: snake_case, the library function's name
//! ("split_edge", as Python has it), or camel_case, the JS API's method name ("splitEdge"; remove_face
//! has none, as the JS API has no such edit), which also takes the library's names as it always did. \throw
//! BindingError (HEDGE_ERROR_INVALID_ARGUMENT) "unknown edit 'x' (...)" for another, listing the edits in
//! that spelling.
Edit parse_edit(std::string_view name, EditNaming naming);
//! How many elements the edit takes (cut_face: 2 half-edges; the others: 1).
std::size_t edit_arity(Edit edit) noexcept;

//! Why the edit of these elements (indices, as a binding got them) is refused: the library's
//! refusal (a static string, "the edge is not live" for a dead or out-of-range element), or null if
//! it is allowed. \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT) if the count of elements is not
//! the edit's arity.
const char* refusal(const SurfaceMesh& m, Edit edit, std::span<const std::uint32_t> elements);

//! A finite point, given to the call `what` names. \throw BindingError (HEDGE_ERROR_INVALID_ARGUMENT)
//! "WHAT: point (x, y, z) is not finite" otherwise.
Vec3 need_point(const Vec3& p, const char* what);

//! Splits `edge` at `point` (none: its midpoint). \return the new vertex.
Vertex split_edge(SurfaceMesh& m, std::uint32_t edge, const std::optional<Vec3>& point);
//! Collapses `halfedge` (its origin merges into its target). \return the surviving vertex.
Vertex collapse(SurfaceMesh& m, std::uint32_t halfedge);
//! Flips `edge`. \return the edge.
Edge flip(SurfaceMesh& m, std::uint32_t edge);
//! Splits `face` at `point` (none: its centroid). \return the new vertex.
Vertex split_face(SurfaceMesh& m, std::uint32_t face, const std::optional<Vec3>& point);
//! Cuts the face of two half-edges between their targets. \return the new half-edge.
Halfedge cut_face(SurfaceMesh& m, std::uint32_t halfedge0, std::uint32_t halfedge1);
//! Checks that the hole at `halfedge` can be filled (handle, then refusal) without filling it, for
//! a binding that has more to check before the edit. \return the half-edge.
Halfedge require_fill_hole(const SurfaceMesh& m, std::uint32_t halfedge);
//! Fills the hole at `halfedge`. \return the new faces.
std::vector<Face> fill_hole(SurfaceMesh& m, std::uint32_t halfedge);
//! The live vertices a binding names, checked (handles) for add_face.
std::vector<Vertex> live_vertices(const SurfaceMesh& m, std::span<const std::uint32_t> vertices);
//! Adds a face with these corners (checked with live_vertices()). \return the new face.
Face add_face(SurfaceMesh& m, std::span<const Vertex> corners);
//! Removes `face`, and the edges and vertices it leaves unused.
void remove_face(SurfaceMesh& m, std::uint32_t face);
//! Removes `vertex` with its faces, and what they leave unused.
void remove_vertex(SurfaceMesh& m, std::uint32_t vertex);

}  // namespace hedge::binding

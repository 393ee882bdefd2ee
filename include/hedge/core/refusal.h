// The refusals of the library's edits, one table: each refusal a *_refusal() function can return
// (core/edge_operations.h, core/face_operations.h, algorithms/fill_hole.h) has a stable code and a
// text, and those functions return the texts of this table, nothing else. The codes are what a
// program checks without comparing strings or allocating (the C ABI's hedge_refusal,
// hedge_last_refusal_code(); C#'s RefusalCode); the texts say it in a few words.
//
// The codes are part of the C ABI: a code keeps its value for good. A new refusal takes the next
// value at the end of the table; a refusal that goes away leaves its value unused.
#pragma once

#include <cstdint>
#include <iterator>
#include <span>

namespace hedge {

//! A refusal's stable code (the C ABI's HEDGE_REFUSAL_*, C#'s RefusalCode, in PascalCase there).
enum class Refusal : std::int32_t {
  none = 0,  //!< not refused
  // An element that is deleted or out of range.
  edge_not_live = 1,
  halfedge_not_live = 2,
  face_not_live = 3,
  vertex_not_live = 4,
  // collapse
  collapse_joins_seam_sides = 5,
  collapse_pulls_seam_vertex = 6,
  collapse_shortens_seam = 7,
  collapse_same_face_both_sides = 8,
  collapse_pinches_boundary = 9,
  collapse_second_edge = 10,
  collapse_link_condition = 11,
  collapse_dangling_edge = 12,
  collapse_tip_too_few_edges = 13,
  collapse_survivor_too_few_edges = 14,
  // flip
  flip_tips_shared = 15,
  flip_valence_three = 16,
  flip_tips_joined = 17,
  flip_boundary_edge = 18,
  flip_not_triangle = 19,
  // cut_face
  cut_halfedge_not_live = 20,
  cut_same_halfedge = 21,
  cut_on_boundary = 22,
  cut_different_faces = 23,
  cut_neighbour_targets = 24,
  cut_targets_joined = 25,
  // add_face
  add_face_too_few_corners = 26,
  add_face_corner_not_live = 27,
  add_face_corner_repeated = 28,
  add_face_edge_taken = 29,
  add_face_interior_corner = 30,
  add_face_second_gap = 31,
  // remove_face, remove_vertex
  remove_face_pinches = 32,
  remove_vertex_pinches = 33,
  // fill_hole
  fill_hole_not_boundary = 34,
  fill_hole_loop_damaged = 35,
  fill_hole_loop_too_short = 36,
};

//! One entry of the table: the code, its name (the enumerator's) and its text.
struct RefusalEntry {
  Refusal code;
  const char* name;
  const char* text;
};

//! Every refusal, in code order (entry i has code i); entry 0 is none (name "none", text "").
inline constexpr RefusalEntry kRefusals[] = {
    {Refusal::none, "none", ""},
    {Refusal::edge_not_live, "edge_not_live", "the edge is not live"},
    {Refusal::halfedge_not_live, "halfedge_not_live", "the half-edge is not live"},
    {Refusal::face_not_live, "face_not_live", "the face is not live"},
    {Refusal::vertex_not_live, "vertex_not_live", "the vertex is not live"},
    {Refusal::collapse_joins_seam_sides, "collapse_joins_seam_sides",
     "it would join the two sides of a seam at the surviving vertex"},
    {Refusal::collapse_pulls_seam_vertex, "collapse_pulls_seam_vertex",
     "it would pull a seam vertex off its seam"},
    {Refusal::collapse_shortens_seam, "collapse_shortens_seam",
     "it would shorten a seam that ends at the merged vertex"},
    {Refusal::collapse_same_face_both_sides, "collapse_same_face_both_sides",
     "the edge has the same face on both sides"},
    {Refusal::collapse_pinches_boundary, "collapse_pinches_boundary",
     "an interior edge joins two boundary vertices (the surface would pinch)"},
    {Refusal::collapse_second_edge, "collapse_second_edge", "a second edge joins its ends"},
    {Refusal::collapse_link_condition, "collapse_link_condition",
     "its ends share a neighbour besides the tips of its triangles (the link condition)"},
    {Refusal::collapse_dangling_edge, "collapse_dangling_edge",
     "a triangle on the edge has the boundary on both other sides (an edge would dangle)"},
    {Refusal::collapse_tip_too_few_edges, "collapse_tip_too_few_edges",
     "a tip of its triangles would be left with too few edges"},
    {Refusal::collapse_survivor_too_few_edges, "collapse_survivor_too_few_edges",
     "the surviving vertex would be left with too few edges"},
    {Refusal::flip_tips_shared, "flip_tips_shared", "the two triangles on the edge share their tip"},
    {Refusal::flip_valence_three, "flip_valence_three",
     "an end is an interior vertex of valence 3 (the flip would leave it with 2)"},
    {Refusal::flip_tips_joined, "flip_tips_joined",
     "the tips of its triangles are already joined by an edge"},
    {Refusal::flip_boundary_edge, "flip_boundary_edge",
     "the edge is on the boundary (a flip needs a triangle on both sides)"},
    {Refusal::flip_not_triangle, "flip_not_triangle", "a face on the edge is not a triangle"},
    {Refusal::cut_halfedge_not_live, "cut_halfedge_not_live", "a half-edge is not live"},
    {Refusal::cut_same_halfedge, "cut_same_halfedge", "the two half-edges are the same"},
    {Refusal::cut_on_boundary, "cut_on_boundary", "the half-edges are on a boundary, not in a face"},
    {Refusal::cut_different_faces, "cut_different_faces", "the half-edges are in different faces"},
    {Refusal::cut_neighbour_targets, "cut_neighbour_targets",
     "their targets are neighbours in the face (the cut would double an edge)"},
    {Refusal::cut_targets_joined, "cut_targets_joined", "an edge already joins their targets"},
    {Refusal::add_face_too_few_corners, "add_face_too_few_corners", "a face needs at least 3 corners"},
    {Refusal::add_face_corner_not_live, "add_face_corner_not_live", "a corner is not a live vertex"},
    {Refusal::add_face_corner_repeated, "add_face_corner_repeated", "a corner is repeated"},
    {Refusal::add_face_edge_taken, "add_face_edge_taken",
     "an edge of the face already has a face on that side"},
    {Refusal::add_face_interior_corner, "add_face_interior_corner",
     "a corner is an interior vertex (its fan of faces is closed)"},
    {Refusal::add_face_second_gap, "add_face_second_gap",
     "the face would meet a corner's faces at the vertex only (a second gap in its fan)"},
    {Refusal::remove_face_pinches, "remove_face_pinches",
     "a corner would be left with two gaps in its fan of faces (pinched)"},
    {Refusal::remove_vertex_pinches, "remove_vertex_pinches",
     "a corner of its faces would be left with two gaps in its fan of faces (pinched)"},
    {Refusal::fill_hole_not_boundary, "fill_hole_not_boundary",
     "the half-edge is not on a boundary (it has a face)"},
    {Refusal::fill_hole_loop_damaged, "fill_hole_loop_damaged",
     "its boundary loop is damaged (it never closes)"},
    {Refusal::fill_hole_loop_too_short, "fill_hole_loop_too_short",
     "its boundary loop has fewer than 3 edges (no room for a face)"},
};

//! How many codes there are (one past the largest).
inline constexpr std::int32_t kRefusalCount = static_cast<std::int32_t>(std::size(kRefusals));

namespace detail {
constexpr bool refusals_in_code_order() {
  for (std::int32_t i = 0; i < kRefusalCount; ++i)
    if (static_cast<std::int32_t>(kRefusals[i].code) != i) return false;
  return true;
}
}  // namespace detail
static_assert(detail::refusals_in_code_order(), "kRefusals: entry i must have code i");

//! The refusal's text (static storage), what the *_refusal() functions return for it; "" for none.
//! Defined out of line on purpose: every text pointer then comes from the one table object, so a
//! text can be told by its address in every build (string literals are not merged across
//! translation units under AddressSanitizer, nor promised to be by the language).
const char* refusal_text(Refusal r) noexcept;

//! The code of a text a *_refusal() function returned: Refusal::none for null or "". O(table) with
//! no allocation (the texts are compared as pointers first, then as strings).
//! \return the code, or none if `text` is not in the table (which the library never returns).
Refusal refusal_code(const char* text) noexcept;

//! The table, for walking every refusal.
inline std::span<const RefusalEntry> refusals() noexcept { return kRefusals; }

}  // namespace hedge

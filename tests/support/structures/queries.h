// The eight adjacency queries of Table 1, the four structures, and what the paper claims for each.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace hedge::structures {

enum class Query : int {
  edge_vertices,
  edge_faces,
  edge_edges,  //!< edges sharing a vertex with the edge
  vertex_edges,
  vertex_faces,
  face_edges,
  face_vertices,
  face_faces,  //!< faces sharing an edge with the face
};
inline constexpr std::size_t kQueryCount = 8;
inline constexpr std::array<Query, kQueryCount> kQueries = {
    Query::edge_vertices, Query::edge_faces, Query::edge_edges,    Query::vertex_edges,
    Query::vertex_faces,  Query::face_edges, Query::face_vertices, Query::face_faces};

enum class Structure : int { indexed, triangle_neighbors, winged_edge, half_edge };
inline constexpr std::size_t kStructureCount = 4;

//! Growth of a query's cost with the mesh. `none` is the paper's N/A.
enum class Growth { none, constant, valence, linear };

constexpr std::string_view query_name(Query q) {
  constexpr std::array<std::string_view, kQueryCount> names = {
      "Edge → Vertices", "Edge → Faces", "Edge → adjacent Edges", "Vertex → Edges",
      "Vertex → Faces",  "Face → Edges", "Face → Vertices",       "Face → adjacent Faces"};
  return names[static_cast<int>(q)];
}

constexpr std::string_view structure_name(Structure s) {
  constexpr std::array<std::string_view, kStructureCount> names = {"Indexed mesh", "Triangle-neighbour (TNS)",
                                                                   "Winged-edge (WEM)", "hedge half-edge"};
  return names[static_cast<int>(s)];
}
constexpr std::string_view structure_short_name(Structure s) {
  constexpr std::array<std::string_view, kStructureCount> names = {"Indexed", "TNS", "WEM", "hedge"};
  return names[static_cast<int>(s)];
}

//! Table 1 of the paper: bytes per vertex (C#, 8-byte references, n_t ~ 2 n_v).
inline constexpr std::array<double, kStructureCount> kPaperBytesPerVertex = {36, 116, 228, 228};

//! Table 1 of the paper: the cost of each query, per structure (rows: structures, in Structure order).
inline constexpr std::array<std::array<Growth, kQueryCount>, kStructureCount> kPaperGrowth = {{
    {Growth::none, Growth::none, Growth::none, Growth::linear, Growth::linear, Growth::constant,
     Growth::constant, Growth::linear},
    {Growth::none, Growth::none, Growth::none, Growth::valence, Growth::valence, Growth::constant,
     Growth::constant, Growth::constant},
    {Growth::constant, Growth::constant, Growth::valence, Growth::valence, Growth::valence, Growth::constant,
     Growth::constant, Growth::constant},
    {Growth::constant, Growth::constant, Growth::valence, Growth::valence, Growth::valence, Growth::constant,
     Growth::constant, Growth::constant},
}};

//! What the implementations here should show, where the paper has N/A: the indexed mesh names an
//! edge by its vertex pair (finding its faces is a search), the TNS by one of its corner edges.
inline constexpr std::array<std::array<Growth, kQueryCount>, kStructureCount> kExpectedGrowth = {{
    {Growth::constant, Growth::linear, Growth::linear, Growth::linear, Growth::linear, Growth::constant,
     Growth::constant, Growth::linear},
    {Growth::constant, Growth::constant, Growth::valence, Growth::valence, Growth::valence, Growth::constant,
     Growth::constant, Growth::constant},
    kPaperGrowth[2],
    kPaperGrowth[3],
}};

constexpr std::string_view growth_name(Growth g) {
  // In the order of Growth.
  constexpr std::array<std::string_view, 4> names = {"N/A", "O(1)", "O(n_ev)", "O(n_t)"};
  const auto i = static_cast<std::size_t>(g);
  return i < names.size() ? names[i] : "?";
}

}  // namespace hedge::structures

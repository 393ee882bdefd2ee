// Linking a closed, manifold triangle set with dense vertex indices (link_closed.h): pairing the
// corners into edges through the corners leaving each vertex, numbering and linking the
// half-edges, checking the fans; the defects named in build()'s order.
#include "link_closed.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace hedge::link_detail {

namespace {

using Kind = ClosedLinkDefect::Kind;

std::size_t next_corner(std::size_t c) { return c % 3 == 2 ? c - 2 : c + 1; }

//! The first triangle with an index out of range or a repeated vertex.
ClosedLinkDefect check_triangles(std::span<const std::uint32_t> corners, std::size_t n_vertices) {
  if (corners.size() % 3 != 0)
    throw std::logic_error("link_closed_triangles: " + std::to_string(corners.size()) +
                           " corners are not whole triangles");
  for (std::size_t t = 0; 3 * t < corners.size(); ++t) {
    const std::uint32_t* v = &corners[3 * t];
    for (int k = 0; k < 3; ++k)
      if (v[k] >= n_vertices) return {Kind::vertex_out_of_range, t, 0, v[k], 0};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) return {Kind::repeated_vertex, t, 0, 0, 0};
  }
  return {};
}

//! The corners leaving each vertex: row v is out[first[v] .. first[v + 1]), each entry (the
//! corner's next vertex << 32 | corner), in corner order. Indices must be in range.
void rows_by_origin(std::span<const std::uint32_t> corners, std::size_t n_vertices,
                    std::vector<std::uint32_t>& first, std::vector<std::uint64_t>& out) {
  const std::size_t nc = corners.size();
  first.assign(n_vertices + 1, 0);
  out.resize(nc);
  for (std::size_t c = 0; c < nc; ++c) ++first[corners[c]];
  for (std::size_t v = 1; v < n_vertices; ++v) first[v] += first[v - 1];  // each row's end
  for (std::size_t c = nc; c-- > 0;)  // filled backwards: each row ends in corner order, and
    out[--first[corners[c]]] = std::uint64_t{corners[next_corner(c)]} << 32 | c;  // first[v] its start
  first[n_vertices] = static_cast<std::uint32_t>(nc);
}

//! The first doubled directed edge (by its start, then its end), else the first corner whose edge
//! has no reverse: called once the fast pairing has found one of them.
ClosedLinkDefect find_edge_defect(std::span<const std::uint32_t> corners, std::size_t n_vertices,
                                  const std::vector<std::uint32_t>& first,
                                  const std::vector<std::uint64_t>& out) {
  std::vector<std::uint64_t> row;
  for (std::size_t v = 0; v < n_vertices; ++v) {
    row.assign(out.begin() + first[v], out.begin() + first[v + 1]);
    std::sort(row.begin(), row.end());
    for (std::size_t i = 1; i < row.size(); ++i)
      if (row[i] >> 32 == row[i - 1] >> 32)
        return {Kind::edge_used_twice, 0, 0, static_cast<std::uint32_t>(v),
                static_cast<std::uint32_t>(row[i] >> 32)};
  }
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const std::uint32_t a = corners[c], b = corners[next_corner(c)];
    const auto row_b = out.begin() + first[b], row_end = out.begin() + first[b + 1];
    if (std::none_of(row_b, row_end, [a](std::uint64_t e) { return e >> 32 == a; }))
      return {Kind::open_edge, 0, 0, a, b};
  }
  throw std::logic_error("link_closed_triangles: the corners did not pair, yet no edge is doubled or open");
}

//! Numbers the edges (twin[c] must be an involution without fixed points), links the half-edges
//! and checks the fans; `first` gives each vertex's number of corners as first[v + 1] - first[v].
ClosedLinkDefect link(std::span<const std::uint32_t> corners, const std::uint32_t* twin,
                      const std::uint32_t* first, std::size_t n_vertices, SurfaceMesh& mesh) {
  const std::size_t nc = corners.size(), nf = nc / 3;
  std::vector<Index> he(nc, kInvalidIndex);
  Index n_edges = 0;
  for (std::size_t c = 0; c < nc; ++c)
    if (he[c] == kInvalidIndex) {
      he[c] = 2 * n_edges;
      he[twin[c]] = 2 * n_edges + 1;
      ++n_edges;
    }
  SurfaceMesh m;
  m.resize(n_vertices, n_edges, nf);
  for (std::size_t c = 0; c < nc; ++c) {
    const std::size_t cn = next_corner(c);
    const Halfedge h(he[c]);
    m.set_vertex(h, Vertex(corners[cn]));
    m.set_next(h, Halfedge(he[cn]));
    m.set_face(h, Face(static_cast<Index>(c / 3)));
    m.set_halfedge(Vertex(corners[c]), h);
    if (c % 3 == 2) m.set_halfedge(Face(static_cast<Index>(c / 3)), h);
  }
  // One fan per vertex: turning about it from its half-edge visits all the corners leaving it.
  for (std::size_t v = 0; v < n_vertices; ++v) {
    const std::uint32_t valence = first[v + 1] - first[v];
    if (valence == 0) continue;
    const Halfedge h0 = m.halfedge(Vertex(static_cast<Index>(v)));
    Halfedge h = h0;
    std::uint32_t seen = 0;
    do {
      h = m.next(SurfaceMesh::twin(h));
      ++seen;
    } while (h != h0 && seen <= valence);
    if (seen != valence) return {Kind::several_fans, 0, 0, static_cast<std::uint32_t>(v), 0};
  }
  mesh = std::move(m);
  return {};
}

}  // namespace

std::string describe(const ClosedLinkDefect& d) {
  const std::string a = std::to_string(d.a), b = std::to_string(d.b);
  switch (d.kind) {
    case Kind::none:
      return "";
    case Kind::vertex_out_of_range:
      return "triangle " + std::to_string(d.triangle) + " uses vertex " + a + ", beyond the vertices";
    case Kind::repeated_vertex:
      return "triangle " + std::to_string(d.triangle) + " repeats a vertex";
    case Kind::edge_used_twice:
      return "two triangles run along the edge from vertex " + a + " to vertex " + b + " the same way";
    case Kind::open_edge:
      return "the set is open: no triangle runs along the edge from vertex " + a + " to vertex " + b +
             " the other way";
    case Kind::several_fans:
      return "the triangles around vertex " + a + " form more than one fan";
    case Kind::wrong_twin:
      return "the twin given to corner " + std::to_string(d.corner) +
             " does not run the other way along its edge";
  }
  return "";
}

ClosedLinkDefect link_closed_triangles(std::span<const std::uint32_t> corners, std::size_t n_vertices,
                                       SurfaceMesh& mesh) {
  if (const ClosedLinkDefect d = check_triangles(corners, n_vertices)) return d;
  std::vector<std::uint32_t> first;
  std::vector<std::uint64_t> out;
  rows_by_origin(corners, n_vertices, first, out);
  // Each corner's twin: the first corner leaving its end for its start. The pairing is right when
  // twin is an involution (each directed edge used once, its reverse once); else the defect is
  // looked for and named.
  const std::size_t nc = corners.size();
  std::vector<std::uint32_t> twin(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const std::uint64_t a = corners[c];
    const std::uint64_t* e = out.data() + first[corners[next_corner(c)]];
    const std::uint64_t* end = out.data() + first[corners[next_corner(c)] + 1];
    while (e != end && *e >> 32 != a) ++e;
    if (e == end) return find_edge_defect(corners, n_vertices, first, out);
    twin[c] = static_cast<std::uint32_t>(*e);
  }
  for (std::size_t c = 0; c < nc; ++c)
    if (twin[twin[c]] != c) return find_edge_defect(corners, n_vertices, first, out);
  return link(corners, twin.data(), first.data(), n_vertices, mesh);
}

ClosedLinkDefect link_closed_triangles(std::span<const std::uint32_t> corners,
                                       std::span<const std::uint32_t> twins, std::size_t n_vertices,
                                       SurfaceMesh& mesh) {
  if (const ClosedLinkDefect d = check_triangles(corners, n_vertices)) return d;
  const std::size_t nc = corners.size();
  if (twins.size() != nc) return {Kind::wrong_twin, 0, std::min(nc, twins.size()), 0, 0};
  for (std::size_t c = 0; c < nc; ++c) {
    const std::uint32_t t = twins[c];
    if (t >= nc || twins[t] != c || corners[t] != corners[next_corner(c)] ||
        corners[next_corner(t)] != corners[c])
      return {Kind::wrong_twin, 0, c, 0, 0};
  }
  std::vector<std::uint32_t> first(n_vertices + 1, 0);
  for (std::size_t c = 0; c < nc; ++c) ++first[corners[c] + 1];
  for (std::size_t v = 0; v < n_vertices; ++v) first[v + 1] += first[v];
  return link(corners, twins.data(), first.data(), n_vertices, mesh);
}

}  // namespace hedge::link_detail

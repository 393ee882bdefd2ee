// Linking a closed, manifold triangle set with dense vertex indices (link_closed.h): pairing the
// corners into edges through the corners leaving each vertex, numbering and linking the
// half-edges, checking the fans; the defects named in build()'s order.
#include "link_closed.h"

#include <algorithm>
#include <memory>
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
  const std::size_t nc = corners.size();
  bool bad = false;  // a pass without branches first; the defect is looked for only if there is one
  for (std::size_t c = 0; c < nc; c += 3) {
    const std::uint32_t a = corners[c], b = corners[c + 1], d = corners[c + 2];
    bad |= (a >= n_vertices) | (b >= n_vertices) | (d >= n_vertices) | (a == b) | (b == d) | (d == a);
  }
  if (!bad) return {};
  for (std::size_t t = 0; 3 * t < nc; ++t) {
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
                    std::vector<std::uint32_t>& first, std::unique_ptr<std::uint64_t[]>& out) {
  const std::size_t nc = corners.size();
  first.assign(n_vertices + 1, 0);
  out.reset(new std::uint64_t[nc]);  // every entry is written below
  for (std::size_t c = 0; c < nc; ++c) ++first[corners[c]];
  for (std::size_t v = 1; v < n_vertices; ++v) first[v] += first[v - 1];  // each row's end
  // Filled backwards, so that each row is in corner order and first[v] ends at its start.
  for (std::size_t c = nc; c != 0; c -= 3) {
    const std::uint64_t a = corners[c - 3], b = corners[c - 2], d = corners[c - 1];
    out[--first[d]] = a << 32 | (c - 1);
    out[--first[b]] = d << 32 | (c - 2);
    out[--first[a]] = b << 32 | (c - 3);
  }
  first[n_vertices] = static_cast<std::uint32_t>(nc);
}

//! The first doubled directed edge (by its start, then its end), else the first corner whose edge
//! has no reverse: called once the fast pairing has found one of them.
ClosedLinkDefect find_edge_defect(std::span<const std::uint32_t> corners, std::size_t n_vertices,
                                  const std::vector<std::uint32_t>& first, const std::uint64_t* out) {
  std::vector<std::uint64_t> row;
  for (std::size_t v = 0; v < n_vertices; ++v) {
    row.assign(out + first[v], out + first[v + 1]);
    std::sort(row.begin(), row.end());
    for (std::size_t i = 1; i < row.size(); ++i)
      if (row[i] >> 32 == row[i - 1] >> 32)
        return {Kind::edge_used_twice, 0, 0, static_cast<std::uint32_t>(v),
                static_cast<std::uint32_t>(row[i] >> 32)};
  }
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const std::uint32_t a = corners[c], b = corners[next_corner(c)];
    const std::uint64_t *row_b = out + first[b], *row_end = out + first[b + 1];
    if (std::none_of(row_b, row_end, [a](std::uint64_t e) { return e >> 32 == a; }))
      return {Kind::open_edge, 0, 0, a, b};
  }
  throw std::logic_error("link_closed_triangles: the corners did not pair, yet no edge is doubled or open");
}

//! Numbers the edges (twin[c] must be an involution without fixed points), links the half-edges
//! and checks the fans.
ClosedLinkDefect link(std::span<const std::uint32_t> corners, const std::uint32_t* twin,
                      std::size_t n_vertices, SurfaceMesh& mesh) {
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
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t* v = &corners[3 * f];
    const Halfedge h0(he[3 * f]), h1(he[3 * f + 1]), h2(he[3 * f + 2]);
    m.set_vertex(h0, Vertex(v[1]));
    m.set_vertex(h1, Vertex(v[2]));
    m.set_vertex(h2, Vertex(v[0]));
    m.set_next(h0, h1);
    m.set_next(h1, h2);
    m.set_next(h2, h0);
    m.set_face(h0, Face(static_cast<Index>(f)));
    m.set_face(h1, Face(static_cast<Index>(f)));
    m.set_face(h2, Face(static_cast<Index>(f)));
    m.set_halfedge(Vertex(v[0]), h0);
    m.set_halfedge(Vertex(v[1]), h1);
    m.set_halfedge(Vertex(v[2]), h2);
    m.set_halfedge(Face(static_cast<Index>(f)), h2);
  }
  // One fan per vertex: turning about each vertex from its half-edge comes back to it (the
  // half-edges are paired), and the turns visit all the corners only if no vertex has a second fan.
  auto fan = [&m](std::size_t v) {
    const Halfedge h0 = m.halfedge(Vertex(static_cast<Index>(v)));
    if (!h0.is_valid()) return std::size_t{0};
    std::size_t seen = 0;
    Halfedge h = h0;
    do {
      h = m.next(SurfaceMesh::twin(h));
      ++seen;
    } while (h != h0);
    return seen;
  };
  std::size_t visited = 0;
  for (std::size_t v = 0; v < n_vertices; ++v) visited += fan(v);
  if (visited != nc) {
    std::vector<std::size_t> valence(n_vertices, 0);
    for (std::uint32_t v : corners) ++valence[v];
    for (std::size_t v = 0; v < n_vertices; ++v)
      if (fan(v) != valence[v]) return {Kind::several_fans, 0, 0, static_cast<std::uint32_t>(v), 0};
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
  std::unique_ptr<std::uint64_t[]> out;
  rows_by_origin(corners, n_vertices, first, out);
  // Each corner's twin: the first corner leaving its end for its start. The pairing is right when
  // twin is an involution (each directed edge used once, its reverse once); else the defect is
  // looked for and named.
  const std::size_t nc = corners.size();
  const std::uint64_t* rows = out.get();
  auto find = [&](std::uint64_t a, std::uint32_t b, std::uint32_t& found) {
    const std::uint64_t *e = rows + first[b], *end = rows + first[b + 1];
    while (e != end && *e >> 32 != a) ++e;
    found = static_cast<std::uint32_t>(*(e == end ? e - 1 : e));  // rows are never empty here
    return e != end;
  };
  std::unique_ptr<std::uint32_t[]> twin(new std::uint32_t[nc]);  // every entry is written below
  bool paired = true;
  for (std::size_t c = 0; c < nc; c += 3) {
    const std::uint32_t a = corners[c], b = corners[c + 1], d = corners[c + 2];
    paired &= find(a, b, twin[c]) & find(b, d, twin[c + 1]) & find(d, a, twin[c + 2]);
  }
  for (std::size_t c = 0; c < nc && paired; ++c) paired = twin[twin[c]] == c;
  if (!paired) return find_edge_defect(corners, n_vertices, first, rows);
  return link(corners, twin.get(), n_vertices, mesh);
}

ClosedLinkDefect link_closed_triangles(std::span<const std::uint32_t> corners,
                                       std::span<const std::uint32_t> twins, std::size_t n_vertices,
                                       SurfaceMesh& mesh) {
  if (const ClosedLinkDefect d = check_triangles(corners, n_vertices)) return d;
  const std::size_t nc = corners.size();
  if (twins.size() != nc) return {Kind::wrong_twin, 0, std::min(nc, twins.size()), 0, 0};
  // twins[t] == c and t starting where c ends, for every c, also make t end where c starts.
  auto wrong = [&](std::size_t c, std::uint32_t end) {
    const std::uint32_t t = twins[c];
    return t >= nc || twins[t] != c || corners[t] != end;
  };
  for (std::size_t c = 0; c < nc; c += 3) {
    const std::uint32_t a = corners[c], b = corners[c + 1], d = corners[c + 2];
    if (wrong(c, b) | wrong(c + 1, d) | wrong(c + 2, a)) {
      const std::size_t k = wrong(c, b) ? 0 : wrong(c + 1, d) ? 1 : 2;
      return {Kind::wrong_twin, 0, c + k, 0, 0};
    }
  }
  return link(corners, twins.data(), n_vertices, mesh);
}

}  // namespace hedge::link_detail

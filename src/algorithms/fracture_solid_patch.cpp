// Solid fracture: the patch that replaces the broken region in the remaining object, checked to
// fit the hole it fills before the mesh is touched.
#include <algorithm>
#include <map>

#include "core_private/slot_marks.h"
#include "fracture_solid_strike.h"
#include "hedge/algorithms/geometry.h"

namespace hedge::solid_detail {

namespace {

// The patch's sets of faces and vertices (core_private/slot_marks.h): flags kept by the thread.
struct PatchTag;
template <typename H>
using Marks = detail::SlotMarks<H, PatchTag>;
using FaceMarks = Marks<Face>;

//! Adds the faces around each vertex of `faces` whose other faces would form several fans once
//! `faces` left (remove_faces() would split such a vertex): all its faces join. Until none is left.
//! `in` marks `faces` (sorted), and then the faces added.
void close_pinches(const SurfaceMesh& mesh, std::vector<Face>& faces, FaceMarks& in) {
  // The vertices to check, each once per round (in any order: a round's faces are added together).
  std::vector<Vertex> check;
  Marks<Vertex> listed(mesh.vertex_slots());
  for (Face f : faces)
    for (Vertex v : mesh.vertices(f))
      if (listed.mark(v)) check.push_back(v);
  while (!check.empty()) {
    listed.clear();
    std::vector<Face> added;
    for (Vertex v : check) {
      int changes = 0;
      bool any_kept = false;
      for (Halfedge h : mesh.halfedges(v)) {
        const Face a = mesh.face(h), b = mesh.face(SurfaceMesh::twin(h));
        const bool ta = !a.is_valid() || in(a), tb = !b.is_valid() || in(b);
        changes += ta != tb;
        any_kept = any_kept || !ta;
      }
      if (any_kept && changes > 2)
        for (Face f : mesh.faces(v))
          if (!in(f)) added.push_back(f);
    }
    check.clear();
    if (added.empty()) break;
    std::sort(added.begin(), added.end());
    added.erase(std::unique(added.begin(), added.end()), added.end());
    for (Face f : added) {
      in.mark(f);
      for (Vertex v : mesh.vertices(f))
        if (listed.mark(v)) check.push_back(v);
    }
    faces.insert(faces.end(), added.begin(), added.end());
    std::sort(faces.begin(), faces.end());
  }
}

//! The part of soup triangle t outside P (inside_p: t within P), as keyed triangles.
bool outside_part(const Geometry& g, std::uint32_t t, const ClipPolygon& inside_p, KeyedSurface& out) {
  const SoupTriangle& tri = (*g.soup)[t];
  RegionInput r;
  for (int k = 0; k < 3; ++k) {
    r.corners.push_back({Key::vertex, tri.v[k], 0, 0});
    r.corner_pos.push_back(g.vertex(tri.v[k]));
  }
  bool on_sides = false;
  const std::size_t n = inside_p.keys.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (inside_p.support[i] == kNoPlane) {
      on_sides = true;
      continue;
    }
    const std::size_t j = (i + 1) % n;
    r.chain.push_back({inside_p.keys[j], inside_p.keys[i], inside_p.pos[j], inside_p.pos[i]});
  }
  r.side = [&](const Key& k) -> int {
    if (k.kind != Key::edge) return -2;
    for (int s = 0; s < 3; ++s) {
      const Index a = tri.v[s], b = tri.v[(s + 1) % 3];
      if (std::min(a, b) == k.a && std::max(a, b) == k.b) return s;
    }
    return -2;
  };
  r.inside = [&]() { return !on_sides; };
  const Vec3d normal = cross(r.corner_pos[1] - r.corner_pos[0], r.corner_pos[2] - r.corner_pos[0]);
  r.normal = dot(normal, normal) > 0 ? normalize(normal) : Vec3d{0, 0, 1};
  std::vector<std::array<Key, 3>> tris;
  if (!fill_region(r, tris, out.points)) return false;
  for (const auto& k : tris) out.add(k, t);
  return true;
}

}  // namespace

bool patch_outside(const StrikeInput& in, const Geometry& g, const std::vector<ClipPolygon>& inside_p,
                   std::vector<char> touched, Strike& strike) {
  const SurfaceMesh& mesh = in.mesh;
  std::vector<Face>& faces = strike.touched;
  faces.clear();
  for (std::size_t t = 0; t < touched.size(); ++t)
    if (touched[t]) faces.push_back(strike.soup[t].face);
  if (!std::is_sorted(faces.begin(), faces.end())) std::sort(faces.begin(), faces.end());  // as a rule
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  FaceMarks in_faces(mesh.face_slots());
  for (Face f : faces) in_faces.mark(f);
  close_pinches(mesh, faces, in_faces);
  // Soup triangles of each touched face, as (face, triangle) sorted; faces beyond the soup (joined
  // to close a pinch) get theirs.
  std::vector<std::pair<Face, std::uint32_t>> tris_of;
  for (std::uint32_t t = 0; t < strike.soup.size(); ++t)
    if (in_faces(strike.soup[t].face)) tris_of.emplace_back(strike.soup[t].face, t);
  // The soup lists a face's triangles together and the faces in order: sorted already, as a rule.
  if (!std::is_sorted(tris_of.begin(), tris_of.end())) std::sort(tris_of.begin(), tris_of.end());
  const std::size_t in_soup = tris_of.size();
  std::size_t next = 0;  // faces and tris_of[0, in_soup) are both sorted: walk them together
  for (Face f : faces) {
    while (next < in_soup && tris_of[next].first < f) ++next;
    if (next < in_soup && tris_of[next].first == f) continue;
    const std::size_t before = strike.soup.size();
    // make the triangles of f as the soup does, by appending them.
    std::vector<Halfedge> hs;
    for (Halfedge h : mesh.halfedges(f)) hs.push_back(h);
    for (std::size_t k = 1; k + 1 < hs.size(); ++k) {
      SoupTriangle s;
      s.face = f;
      const std::array<Halfedge, 3> c{hs[0], hs[k], hs[k + 1]};
      for (int i = 0; i < 3; ++i) {
        s.corner[i] = c[i];
        s.v[i] = mesh.to_vertex(c[i]).idx();
        for (int a = 0; a < 3; ++a) s.lo[a] = s.hi[a] = 0;
      }
      strike.soup.push_back(s);
    }
    for (std::size_t t = before; t < strike.soup.size(); ++t)
      tris_of.emplace_back(f, static_cast<std::uint32_t>(t));
    touched.resize(strike.soup.size(), 0);
  }
  // The faces added come in order, with their triangles: the two sorted runs are merged.
  std::inplace_merge(tris_of.begin(), tris_of.begin() + std::ptrdiff_t(in_soup), tris_of.end());
  for (const auto& [f, t] : tris_of) {
    if (t < inside_p.size() && touched[t]) {
      const std::vector<std::uint32_t>& support = inside_p[t].support;
      if (std::all_of(support.begin(), support.end(), [](std::uint32_t p) { return p == kNoPlane; }))
        continue;  // all of it inside P: nothing stays
      if (!outside_part(g, t, inside_p[t], strike.patch)) {
        strike.failure = "the part of a face outside the region did not close";
        return false;
      }
      continue;
    }
    const SoupTriangle& s = strike.soup[t];
    std::array<Key, 3> k;
    for (int i = 0; i < 3; ++i) {
      k[i] = {Key::vertex, s.v[i], 0, 0};
      strike.patch.points.emplace_back(k[i], g.vertex(s.v[i]));
    }
    strike.patch.add(k, t);
  }
  // The patch must fit the hole: each of its directed edges is used once, and those without their
  // twin in the patch are exactly the hole's rim, edges of the mesh whose other face stays.
  std::vector<std::pair<Key, Key>> edges;
  for (const auto& t : strike.patch.tris)
    for (int i = 0; i < 3; ++i) edges.emplace_back(t[i], t[(i + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) {
    strike.failure = "the patch uses an edge twice";
    return false;
  }
  std::size_t rim = 0;
  for (const auto& [a, b] : edges) {
    if (std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) continue;
    if (a.kind != Key::vertex || b.kind != Key::vertex) {
      strike.failure = "the patch is open inside the region";
      return false;
    }
    const Halfedge h = mesh.find_halfedge(Vertex(b.a), Vertex(a.a));
    if (!h.is_valid() || mesh.is_boundary(h) || in_faces(mesh.face(h))) {
      strike.failure = "the patch does not fit the hole";
      return false;
    }
    ++rim;
  }
  std::size_t hole = 0;
  for (Face f : faces)
    for (Halfedge h : mesh.halfedges(f)) {
      const Face o = mesh.face(SurfaceMesh::twin(h));
      hole += o.is_valid() && !in_faces(o);
    }
  if (rim != hole) {
    strike.failure = "the patch does not fill the hole";
    return false;
  }
  // Every vertex of the patch stays manifold: its corners in the patch and in the faces that stay
  // around it form one closed fan (the corner after (p, v, n) is the one whose previous point is n).
  strike.patch.finish_points();
  std::vector<std::pair<Key, std::array<Key, 2>>> corners;  // v -> (previous, next)
  for (const auto& t : strike.patch.tris)
    for (int i = 0; i < 3; ++i) corners.push_back({t[i], {t[(i + 2) % 3], t[(i + 1) % 3]}});
  std::vector<Face> ring;
  for (const auto& [k, x] : strike.patch.points)
    if (k.kind == Key::vertex)
      for (Halfedge h : mesh.halfedges(Vertex(k.a))) {
        const Face f = mesh.face(h);
        if (!f.is_valid() || in_faces(f)) continue;
        // h leaves v in f: the corner at v runs from the point before v to to_vertex(h).
        const Vertex before = mesh.from_vertex(mesh.prev(h));
        corners.push_back(
            {k, {Key{Key::vertex, before.idx(), 0, 0}, Key{Key::vertex, mesh.to_vertex(h).idx(), 0, 0}}});
      }
  std::sort(corners.begin(), corners.end());
  for (std::size_t i = 0; i < corners.size();) {
    std::size_t j = i;
    while (j < corners.size() && corners[j].first == corners[i].first) ++j;
    // Corners of one vertex, i..j, sorted by previous point: follow them around.
    std::size_t seen = 0, c = i;
    do {
      const Key& n = corners[c].second[1];
      const auto it =
          std::lower_bound(corners.begin() + std::ptrdiff_t(i), corners.begin() + std::ptrdiff_t(j),
                           std::make_pair(corners[i].first, std::array<Key, 2>{n, Key{}}));
      if (it == corners.begin() + std::ptrdiff_t(j) || it->second[0] != n ||
          (it + 1 != corners.begin() + std::ptrdiff_t(j) && (it + 1)->second[0] == n)) {
        strike.failure = "the patch would leave a vertex open or pinched";
        return false;
      }
      c = static_cast<std::size_t>(it - corners.begin());
      ++seen;
    } while (c != i && seen <= j - i);
    if (seen != j - i) {
      strike.failure = "the patch would leave a vertex non-manifold";
      return false;
    }
    i = j;
  }
  return true;
}

}  // namespace hedge::solid_detail

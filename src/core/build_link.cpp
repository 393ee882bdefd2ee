// build(), last steps on either path: numbers the edges (general path), writes the mesh arrays,
// checks that every vertex has one fan and splits those that have several, and links the
// boundary loops.
#include <cstdint>
#include <string>
#include <vector>

#include "build_internal.h"

namespace hedge {

using build_detail::advise_huge_pages;
using build_detail::for_each_corner;
using build_detail::kMaxNamed;
using build_detail::kNoPartner;
using build_detail::kNumbered;
using build_detail::list_str;

namespace {

// v.resize(n), with the storage advised for huge pages before it is first written.
template <typename T>
void sized_vector(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

}  // namespace

void MeshBuilder::number_edges() {
  // Edge e is made when its first corner comes up; the partner corner gets half-edge 2e + 1.
  Index* slot = corner_he_.data();
  const Index nc = f_.n_corners();
  Index e = 0;
  for (Index c = 0; c < nc; ++c) {
    const Index p = slot[c];
    if (p & kNumbered) continue;
    slot[c] = (2 * e) | kNumbered;
    if (p != kNoPartner) slot[p] = (2 * e + 1) | kNumbered;
    ++e;
  }
  for (Index c = 0; c < nc; ++c) slot[c] &= ~kNumbered;
  n_edges_ = e;
}

namespace {
// Walks the fan about a vertex from its outgoing interior half-edge h0, rotating clockwise with
// h -> next(twin(h)): one load a step, as boundary half-edges still have an invalid next. Returns
// the number of corners in the fan. An open fan is completed counter-clockwise from h0; then `vh`
// takes the boundary half-edge at its start, as the invariant asks, and the boundary half-edge
// entering the vertex is appended to `boundary` for link_boundaries(). `pv` gives the half-edge
// before each interior one in its face; without it (nullptr, for triangles) the face is walked.
Index walk_fan(const Halfedge* nx, const Index* pv, Index h0, Halfedge& vh, std::vector<Index>& boundary) {
  Index k = h0, seen = 1;
  for (;;) {
    const Index t = nx[k ^ 1u].idx();
    if (t == h0) return seen;
    if (t == kInvalidIndex) break;
    k = t;
    ++seen;
  }
  boundary.push_back(k ^ 1u);
  for (Index s = h0;;) {
    Index p = s;  // the half-edge before s in its face
    if (pv != nullptr)
      p = pv[s];
    else
      for (Index n = nx[p].idx(); n != s; n = nx[n].idx()) p = n;
    const Index b = p ^ 1u;
    if (!nx[b].is_valid()) {
      vh = Halfedge(b);
      return seen;
    }
    s = b;
    ++seen;
  }
}
}  // namespace

void MeshBuilder::link(SurfaceMesh& m) {
  // Every half-edge is written from its corner: the even half-edge of an edge by the corner that
  // made it, which also sets its twin's target (a boundary half-edge points back to that corner's
  // vertex); the odd one by the partner corner, if any. Boundary half-edges keep the invalid next
  // and face that resize() gave them until link_boundaries(). The vertex half-edges come from
  // pair_fast(), or are set here on the general path (last corner wins, as there).
  const Index nv = n_vertices();
  auto& pos = m.positions_.vector();
  if (positions_.empty())
    pos.assign(in_.positions.begin(), in_.positions.end());
  else
    pos.assign(positions_.begin(), positions_.end());
  const bool have_vh = !vh_.empty() || nv == 0;
  if (have_vh) m.v_halfedge_ = std::move(vh_);
  sized_vector(m.h_vertex_, 2 * std::size_t(n_edges_));
  sized_vector(m.h_next_, 2 * std::size_t(n_edges_));
  sized_vector(m.h_face_, 2 * std::size_t(n_edges_));
  m.resize(nv, n_edges_, f_.n_faces);

  Vertex* to = m.h_vertex_.data();
  Halfedge* nx = m.h_next_.data();
  Face* fc = m.h_face_.data();
  Halfedge* vh = m.v_halfedge_.data();
  Halfedge* fh = m.f_halfedge_.data();
  const Index* cv = f_.corners.data();
  const Index* che = corner_he_.data();
  const Index nc = f_.n_corners();
  Vertex sink[2];
  auto put = [&](Index c, Index cn, Index f) {
    const Index h = che[c];
    nx[h] = Halfedge(che[cn]);
    fc[h] = Face(f);
    Vertex* t = (h & 1u) ? sink : to + h;  // the partner corner's targets are already set
    t[0] = Vertex(cv[cn]);
    t[1] = Vertex(cv[c]);
  };
  // put() with the values loaded: h -> hn in face f, from vertex v to vertex vn.
  auto put3 = [&](Index h, Index hn, Index v, Index vn, Index f) {
    nx[h] = Halfedge(hn);
    fc[h] = Face(f);
    Vertex* t = (h & 1u) ? sink : to + h;  // the partner corner's targets are already set
    t[0] = Vertex(vn);
    t[1] = Vertex(v);
  };
  if (f_.triangles()) {
    // An odd half-edge lies where its edge was made, possibly far back: fetch it early.
    constexpr Index kAhead = 3 * 8;
    // With the half-edges from pair_fast(), each vertex's fan is walked (the fans_are_simple()
    // check) soon after its last corner is linked, the one whose half-edge the vertex holds: all
    // its faces are linked then, and the lines just written are still cached. The walks wait for a
    // batch of such corners, to keep them out of the way of the linking loop.
    const bool walk = have_vh;
    constexpr Index kBatch = 192;
    Index pending[kBatch], n_pending = 0;
    boundary_hes_.clear();
    std::size_t covered = 0;
    for (Index c = 0, f = 0; c < nc; c += 3, ++f) {
      if (c + kAhead + 3 <= nc) {
        for (Index i = 0; i < 3; ++i) {
          __builtin_prefetch(nx + che[c + kAhead + i], 1);
          __builtin_prefetch(fc + che[c + kAhead + i], 1);
          __builtin_prefetch(vh + cv[c + kAhead + i]);
        }
      }
      // All loads first: a store through a handle might alias them as far as the compiler knows.
      const Index h0 = che[c], h1 = che[c + 1], h2 = che[c + 2];
      const Index v0 = cv[c], v1 = cv[c + 1], v2 = cv[c + 2];
      const bool last0 = vh[v0].idx() == h0, last1 = vh[v1].idx() == h1, last2 = vh[v2].idx() == h2;
      put3(h0, h1, v0, v1, f);
      put3(h1, h2, v1, v2, f);
      put3(h2, h0, v2, v0, f);
      fh[f] = Halfedge(h2);  // the last corner's half-edge enters the first corner
      if (walk) {
        pending[n_pending] = c;
        n_pending += last0;
        pending[n_pending] = c + 1;
        n_pending += last1;
        pending[n_pending] = c + 2;
        n_pending += last2;
        if (n_pending > kBatch - 3 || c + 3 == nc) {
          for (Index j = 0; j < n_pending; ++j) {
            const Index pc = pending[j];
            covered += walk_fan(nx, nullptr, che[pc], vh[cv[pc]], boundary_hes_);
          }
          n_pending = 0;
        }
      }
    }
    if (walk) {
      fans_checked_ = true;
      fans_simple_ = covered == nc;
      for (Index v = 0; v < nv; ++v) rep_.isolated_vertices += !vh[v].is_valid();
    }
  } else {
    for_each_corner(f_, [&](Index c, Index cn, Index f) {
      put(c, cn, f);
      if (cn < c) fh[f] = Halfedge(che[c]);
    });
  }
  if (!have_vh)
    for (Index c = 0; c < nc; ++c) vh[cv[c]] = Halfedge(che[c]);
}

namespace {
// The half-edge before h in its face: h is an interior half-edge of a face that is fully linked.
Halfedge prev_in_face(const SurfaceMesh& m, Halfedge h) {
  Halfedge p = h;
  for (Halfedge n = m.next(p); n != h; n = m.next(n)) p = n;
  return p;
}
}  // namespace

Halfedge MeshBuilder::prev_interior(const SurfaceMesh& m, Halfedge h) const {
  return prev_.empty() ? prev_in_face(m, h) : Halfedge(prev_[h.idx()]);
}

bool MeshBuilder::fans_are_simple(SurfaceMesh& m) {
  // Each walk covers one fan, so every vertex is manifold exactly when the walks cover all corners.
  const Index nv = static_cast<Index>(m.vertex_slots());
  const Halfedge* nx = m.h_next_.data();
  Halfedge* vh = m.v_halfedge_.data();
  // Walking a face to find the half-edge before another costs its size: done at every corner of a
  // polygon of n corners on the boundary, that is n^2 steps (a minute for a polygon of 100,000
  // corners in a 2 MB file). Polygons get the table instead; a triangle's walk is two steps.
  prev_.clear();
  if (!f_.triangles()) {
    sized_vector(prev_, m.halfedge_slots());
    const Index* che = corner_he_.data();
    for_each_corner(f_, [&](Index c, Index cn, Index) { prev_[che[cn]] = che[c]; });
  }
  boundary_hes_.clear();
  std::size_t covered = 0;
  for (Index v = 0; v < nv; ++v) {
    if (!vh[v].is_valid())
      ++rep_.isolated_vertices;
    else
      covered += walk_fan(nx, prev_.empty() ? nullptr : prev_.data(), vh[v].idx(), vh[v], boundary_hes_);
  }
  return covered == f_.n_corners();
}

void MeshBuilder::split_fans(SurfaceMesh& m) {
  const Index nv0 = static_cast<Index>(m.vertex_slots());
  std::vector<std::uint8_t> seen(m.halfedge_slots(), 0);
  std::vector<std::uint8_t> has_fan(nv0, 0), counted(nv0, 0);
  std::vector<Halfedge> fan;
  std::vector<std::string> named;
  std::size_t bad = 0;
  for (Index c = 0; c < f_.n_corners(); ++c) {
    const Halfedge h(corner_he_[c]);
    if (seen[h.idx()]) continue;
    const Vertex v(f_.corners[c]);
    fan.clear();
    // Clockwise from h until the fan closes or a boundary gap is reached ...
    Halfedge k = h;
    bool open = false;
    for (;;) {
      seen[k.idx()] = 1;
      fan.push_back(k);
      const Halfedge t = SurfaceMesh::twin(k);
      if (m.is_boundary(t)) {
        open = true;
        break;
      }
      k = m.next(t);
      if (k == h) break;
    }
    // ... then counter-clockwise from h to the other gap, where the fan starts.
    Halfedge start = h;
    if (open) {
      for (;;) {
        const Halfedge t = SurfaceMesh::twin(prev_interior(m, start));
        if (m.is_boundary(t)) break;
        start = t;
        seen[start.idx()] = 1;
        fan.push_back(start);
      }
    }
    Vertex owner = v;
    if (has_fan[v.idx()]) {
      if (!counted[v.idx()]) {
        counted[v.idx()] = 1;
        ++bad;
        ++rep_.non_manifold_vertices;
        if (named.size() < kMaxNamed) named.push_back("vertex " + std::to_string(input_vertex(v.idx())));
        if (opt_.policy == TopologyPolicy::strict) bad_vertices_.push_back(input_vertex(v.idx()));
      }
      if (opt_.policy == TopologyPolicy::strict) continue;
      // A further fan gets its own copy of the vertex: rename every half-edge entering it.
      owner = m.add_vertex(m.position(v));
      ++rep_.duplicated_vertices;
      vertex_origin_.push_back(v.idx());
      for (Halfedge g : fan) {
        m.set_vertex(prev_interior(m, g), owner);
        const Halfedge t = SurfaceMesh::twin(g);
        if (m.is_boundary(t)) m.set_vertex(t, owner);
      }
    }
    has_fan[v.idx()] = 1;
    m.set_halfedge(owner, open ? SurfaceMesh::twin(prev_interior(m, start)) : start);
  }
  if (bad > 0 && opt_.policy == TopologyPolicy::strict) {
    if (!problems_.empty()) problems_ += "; ";
    problems_ += "non-manifold vertices (their faces form several fans): " + list_str(named, bad);
  }
}

void MeshBuilder::link_boundaries(SurfaceMesh& m) {
  // Every vertex now has one fan, so its half-edge is its only outgoing boundary half-edge.
  for (Index b : boundary_hes_) m.set_next(Halfedge(b), m.halfedge(m.to_vertex(Halfedge(b))));
}

}  // namespace hedge

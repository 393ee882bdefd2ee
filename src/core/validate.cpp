// SurfaceMesh::validate(): checks every invariant of docs/design.md and names what is broken.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include "hedge/core/surface_mesh.h"
#include "hedge/error.h"

namespace hedge {

namespace {

constexpr std::size_t kMaxProblems = 1000;

class Report {
 public:
  void add(std::string s) {
    if (lines_.size() < kMaxProblems)
      lines_.push_back(std::move(s));
    else
      ++dropped_;
  }
  std::vector<std::string> finish() {
    if (dropped_ > 0) lines_.push_back("... and " + std::to_string(dropped_) + " more problems");
    return std::move(lines_);
  }
  //! Whether a problem was added since mark() (since the start without one).
  bool empty() const { return lines_.size() + dropped_ == marked_; }
  //! Problems added so far no longer count for empty(): for problems that do not stop later checks.
  void mark() { marked_ = lines_.size() + dropped_; }

 private:
  std::vector<std::string> lines_;
  std::size_t dropped_ = 0;
  std::size_t marked_ = 0;
};

std::string str(Vertex v) { return "vertex " + (v.is_valid() ? std::to_string(v.idx()) : "<invalid>"); }
std::string str(Halfedge h) { return "halfedge " + (h.is_valid() ? std::to_string(h.idx()) : "<invalid>"); }
std::string str(Face f) { return "face " + (f.is_valid() ? std::to_string(f.idx()) : "<invalid>"); }

struct DisjointSets {
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index(0)); }
  Index find(Index i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(Index a, Index b) { parent[find(a)] = find(b); }
  std::vector<Index> parent;
};

std::string non_finite_position(Vertex v, const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, " has a non-finite position (%g, %g, %g)", double(p.x), double(p.y),
                double(p.z));
  return str(v) + text;
}

}  // namespace

void require_finite_positions(const SurfaceMesh& m, const char* what) {
  // A first pass without branches over every slot, deleted ones too: a float is not finite exactly
  // when its exponent bits are all set. Only if one is found does the loop below look for the first
  // live vertex to name (a deleted vertex's position does not count).
  constexpr std::uint32_t kExponent = 0x7f800000u;
  static_assert(sizeof(Vec3) == 3 * sizeof(float), "positions are packed floats");
  const auto* bytes = reinterpret_cast<const unsigned char*>(m.positions().vector().data());
  const std::size_t n = 3 * m.positions().vector().size();
  std::uint32_t any_not_finite = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t b;
    std::memcpy(&b, bytes + 4 * i, 4);
    any_not_finite |= (b & kExponent) == kExponent;
  }
  if (!any_not_finite) return;
  for (Vertex v : m.vertices())
    if (!is_finite(m.position(v)))
      throw InvalidInputError(std::string(what) + ": " + non_finite_position(v, m.position(v)));
}

std::vector<std::string> SurfaceMesh::validate() const {
  Report r;
  const std::size_t nh = halfedge_slots(), nv = vertex_slots(), nf = face_slots();

  // Sizes and cached counters.
  // The deletion flags may be longer than their element arrays (they grow ahead of them); the
  // flags past the last element are false, which the counts below check.
  if (h_next_.size() != nh || h_face_.size() != nh || nh % 2 != 0 || e_deleted_.size() * 2 < nh)
    r.add("half-edge arrays have inconsistent sizes");
  if (v_deleted_.size() < nv || f_deleted_.size() < nf)
    r.add("deletion flags and element arrays have inconsistent sizes");
  if (!r.empty()) return r.finish();

  // Positions: every live vertex's is finite. A bad position does not stop the connectivity checks.
  for (Vertex v : vertices())
    if (!is_finite(position(v))) r.add(non_finite_position(v, position(v)));
  r.mark();

  auto count_set = [](const std::vector<bool>& b) {
    return static_cast<std::size_t>(std::count(b.begin(), b.end(), true));
  };
  if (count_set(v_deleted_) != deleted_vertices_ || count_set(e_deleted_) != deleted_edges_ ||
      count_set(f_deleted_) != deleted_faces_)
    r.add("cached deleted-element counts disagree with the deletion flags");

  // The array sizes agree from here on, so is_live() may be trusted.

  // Per half-edge references; links are only followed once every reference is known to be live.
  std::vector<Index> predecessors(nh, 0);
  std::size_t bad_refs = 0;
  for (Halfedge h : halfedges()) {
    bool ok = true;
    if (!is_live(to_vertex(h))) {
      r.add(str(h) + " points to dead or invalid " + str(to_vertex(h)));
      ok = false;
    }
    if (!is_live(next(h))) {
      r.add(str(h) + " has dead or invalid next " + str(next(h)));
      ok = false;
    }
    if (face(h).is_valid() && !is_live(face(h))) {
      r.add(str(h) + " lies in dead or invalid " + str(face(h)));
      ok = false;
    }
    if (!ok) {
      ++bad_refs;
      continue;
    }
    ++predecessors[next(h).idx()];
  }
  for (Vertex v : vertices()) {
    Halfedge h = halfedge(v);
    if (h.is_valid() && !is_live(h)) {
      r.add(str(v) + " has dead or invalid " + str(h));
      ++bad_refs;
    }
  }
  for (Face f : faces()) {
    if (!is_live(halfedge(f))) {
      r.add(str(f) + " has dead or invalid " + str(halfedge(f)));
      ++bad_refs;
    }
  }
  if (bad_refs > 0) return r.finish();

  // Twin involution, next/prev inverse, and loop consistency.
  for (Halfedge h : halfedges()) {
    if (to_vertex(h) == from_vertex(h)) r.add(str(h) + " is a loop at " + str(to_vertex(h)));
    if (predecessors[h.idx()] != 1)
      r.add(str(h) + " is the next of " + std::to_string(predecessors[h.idx()]) +
            " half-edges, expected 1 (next/prev not inverse)");
    Halfedge n = next(h);
    if (from_vertex(n) != to_vertex(h))
      r.add(str(h) + " ends at " + str(to_vertex(h)) + " but its next " + str(n) + " starts at " +
            str(from_vertex(n)));
    if (face(n) != face(h)) r.add(str(h) + " and its next " + str(n) + " lie in different faces");
    if (is_boundary(h) && is_boundary(twin(h)))
      r.add(str(h) + " and its twin are both boundary: a dangling edge");
  }
  if (!r.empty()) return r.finish();

  // Face cycles: closed (guaranteed now that next is a permutation), each holds its face, >= 3 sides.
  for (Face f : faces()) {
    Halfedge h0 = halfedge(f);
    if (face(h0) != f) {
      r.add(str(f) + ": its " + str(h0) + " belongs to " + str(face(h0)));
      continue;
    }
    std::size_t n = 0;
    for (Halfedge h = h0; n <= nh; h = next(h)) {
      ++n;
      if (next(h) == h0) break;
    }
    if (n < 3) r.add(str(f) + " has " + std::to_string(n) + " sides, expected at least 3");
  }
  // Every half-edge of a face reaches that face's cycle: the face's half-edge count must add up.
  {
    std::vector<std::size_t> in_face(nf, 0), cycle(nf, 0);
    for (Halfedge h : halfedges())
      if (face(h).is_valid()) ++in_face[face(h).idx()];
    for (Face f : faces()) cycle[f.idx()] = halfedges(f).count();
    for (Face f : faces())
      if (in_face[f.idx()] != cycle[f.idx()])
        r.add(str(f) + " is named by " + std::to_string(in_face[f.idx()]) + " half-edges but its cycle has " +
              std::to_string(cycle[f.idx()]) + " (two cycles share one face)");
  }

  // Vertices: outgoing half-edge, boundary preference, one fan, isolated vertices unreferenced.
  std::vector<Index> outgoing(nv, 0);
  std::vector<bool> has_boundary_out(nv, false);
  for (Halfedge h : halfedges()) {
    Vertex v = from_vertex(h);
    ++outgoing[v.idx()];
    if (is_boundary(h)) has_boundary_out[v.idx()] = true;
  }
  for (Vertex v : vertices()) {
    Halfedge h = halfedge(v);
    if (!h.is_valid()) {
      if (outgoing[v.idx()] > 0)
        r.add(str(v) + " is marked isolated but has " + std::to_string(outgoing[v.idx()]) +
              " outgoing half-edges");
      continue;
    }
    if (from_vertex(h) != v) {
      r.add(str(v) + ": its " + str(h) + " does not start there");
      continue;
    }
    if (has_boundary_out[v.idx()] && !is_boundary(h))
      r.add(str(v) + " is on a boundary but its half-edge " + str(h) + " is not a boundary one");
    std::size_t fan = 0;
    Halfedge g = h;
    do {
      ++fan;
      g = rotate_cw(g);
    } while (g != h && fan <= outgoing[v.idx()]);
    if (fan != outgoing[v.idx()])
      r.add(str(v) + " is non-manifold: rotation visits " + std::to_string(fan) + " of its " +
            std::to_string(outgoing[v.idx()]) + " outgoing half-edges");
  }

  // Two edges may join the same pair of vertices: repairing a non-manifold edge can leave a
  // boundary loop of two edges. That is a valid surface, so it is not reported; the local
  // operations never create such an edge themselves.

  // Euler characteristic per connected component: an orientable surface with b boundary loops has
  // V - E + F = 2 - 2g - b with g >= 0, so chi + b is even and at most 2.
  if (r.empty()) {
    DisjointSets ds(nv);
    for (Edge e : edges()) ds.unite(vertex(e, 0).idx(), vertex(e, 1).idx());
    struct Tally {
      long long chi = 0;
      long long loops = 0;
      bool used = false;
    };
    std::vector<Tally> comp(nv);
    for (Vertex v : vertices())
      if (halfedge(v).is_valid()) {
        auto& t = comp[ds.find(v.idx())];
        t.chi += 1;
        t.used = true;
      }
    for (Edge e : edges()) comp[ds.find(vertex(e, 0).idx())].chi -= 1;
    for (Face f : faces()) comp[ds.find(to_vertex(halfedge(f)).idx())].chi += 1;
    for (Halfedge h : boundary_loops()) comp[ds.find(to_vertex(h).idx())].loops += 1;
    for (Index i = 0; i < nv; ++i) {
      const Tally& t = comp[i];
      if (!t.used) continue;
      long long s = t.chi + t.loops;
      if (s > 2 || (s % 2) != 0)
        r.add("component of " + str(Vertex(i)) + " has Euler characteristic " + std::to_string(t.chi) +
              " with " + std::to_string(t.loops) +
              " boundary loops: not an orientable surface (chi + loops must be even and <= 2)");
    }
  }
  return r.finish();
}

}  // namespace hedge

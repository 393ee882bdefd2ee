// Local edits of edges: split_edge, collapse and flip. See include/hedge/core/edge_operations.h for the
// contract of each; the face edits are in face_operations.cpp.
#include "hedge/core/edge_operations.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "hedge/core/refusal.h"
#include "operations_internal.h"
#include "small_vector.h"

namespace hedge {

using namespace operations_detail;

namespace {

bool is_triangle(const Mesh& m, Halfedge h) { return m.next(m.next(m.next(h))) == h; }

// True if v has more than k edges; stops counting there (O(min(valence, k))).
bool valence_above(const Mesh& m, Vertex v, std::size_t k) {
  std::size_t n = 0;
  for (auto it = m.halfedges(v).begin(); !(it == CirculatorEnd{}); ++it)
    if (++n > k) return true;
  return false;
}

// Interpolation parameter of point p along segment a-b, clamped to it.
float segment_parameter(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3d d = to_double(b) - to_double(a);
  const double len2 = dot(d, d);
  if (!(len2 > 0)) return 0.5f;
  const double s = dot(to_double(p) - to_double(a), d) / len2;
  return static_cast<float>(std::clamp(std::isfinite(s) ? s : 0.5, 0.0, 1.0));
}

// What split_edge read about the edge and its two sides: the two half-edges, their next ones,
// the half-edges before them (hp, tp), the ends, the faces, and whether each face is a triangle.
struct EdgeSplit {
  Halfedge h, t, hn, tn, hp, tp;
  Vertex a, b;
  Face fh, ft;
  bool tri1, tri2;
};

// Properties of the elements split_edge created: v (the new vertex), g (v -> b), s1 and s2 (to
// the tips; invalid if that side is no triangle), f1 and f2 (the new faces; likewise).
[[gnu::noinline]] void carry_split_properties(Mesh& m, Edge e, const Vec3& point, const EdgeSplit& k,
                                              Vertex v, Halfedge g, Halfedge s1, Halfedge s2, Face f1,
                                              Face f2) {
  PropertyContainer& vprops = m.vertex_properties();
  PropertyContainer& hprops = m.halfedge_properties();
  // The weights serve properties other than the position (which is `point`): a mesh without any
  // skips computing them.
  if (vprops.array_count() > 1 || !hprops.empty()) {
    const float s = segment_parameter(m.position(k.a), m.position(k.b), point);
    const float w[2] = {1 - s, s};
    const Index src[2] = {k.a.idx(), k.b.idx()};
    vprops.interpolate(v.idx(), src, w, 2, m.positions().array());
    if (!hprops.empty()) {
      // Corner data: g takes h's corner at b; h and gt get the blend at the new vertex; a cutting
      // edge takes the tip's corner (s1, s2) and its twin the new vertex's.
      const Halfedge gt = Mesh::twin(g);
      const Index src1[2] = {k.hp.idx(), k.h.idx()};
      const Index src2[2] = {k.t.idx(), k.tp.idx()};
      hprops.copy(k.h.idx(), g.idx());
      hprops.interpolate(gt.idx(), src2, w, 2);
      hprops.interpolate(k.h.idx(), src1, w, 2);
      if (k.tri1) {
        hprops.copy(k.hn.idx(), s1.idx());
        hprops.copy(k.h.idx(), Mesh::twin(s1).idx());
      }
      if (k.tri2) {
        hprops.copy(k.tn.idx(), s2.idx());
        hprops.copy(gt.idx(), Mesh::twin(s2).idx());
      }
    }
  }
  m.edge_properties().copy(e.idx(), Mesh::edge(g).idx());
  if (k.tri1) m.face_properties().copy(k.fh.idx(), f1.idx());
  if (k.tri2) m.face_properties().copy(k.ft.idx(), f2.idx());
}

// The same after split_between_triangles, which has just made v: what it read is found again in
// the new connectivity (kept out of the common path, so that none of it stays live there).
[[gnu::noinline]] void carry_split_properties(Mesh& m, Edge e, const Vec3& point, Vertex v) {
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Halfedge g = m.halfedge(v), s1(g.idx() + 2), s2(g.idx() + 4);
  const Face f1 = m.face(g), f2(f1.idx() + 1);
  const EdgeSplit k{h,
                    t,
                    m.next(g),
                    m.next(t),
                    m.next(s1),
                    m.next(s2),
                    m.to_vertex(t),
                    m.to_vertex(g),
                    m.face(h),
                    m.face(Mesh::twin(g)),
                    true,
                    true};
  carry_split_properties(m, e, point, k, v, g, s1, s2, f1, f2);
}

// True if the mesh holds a property besides the positions.
bool has_properties(const Mesh& m) {
  return m.vertex_properties().array_count() > 1 || !m.halfedge_properties().empty() ||
         !m.edge_properties().empty() || !m.face_properties().empty();
}

// Splits a triangle that a split edge has given a fourth corner, the new vertex v: `into` enters v
// and stays in `keep` with `last`; `out_of` leaves v, and with `mid` it goes to `f`, a new face.
// The new edge s runs from v to the tip and joins them: keep becomes into -> s -> last, f becomes
// out_of -> mid -> twin(s). Sets the links and faces; s's vertices are the caller's.
void link_triangle_split(Mesh& m, Halfedge into, Halfedge out_of, Halfedge mid, Halfedge last, Face keep,
                         Halfedge s, Face f) {
  const Halfedge st = Mesh::twin(s);
  m.set_next(into, s);
  m.set_next(s, last);
  m.set_next(mid, st);
  m.set_next(st, out_of);
  m.set_face(s, keep);
  m.set_face(out_of, f);
  m.set_face(mid, f);
  m.set_face(st, f);
  m.set_halfedge(keep, into);
  m.set_halfedge(f, out_of);
}

// split_edge on an interior edge between two triangles, the common case. The new elements are
// appended first; then what the edit needs is read (cache hits: split_edge has just walked it)
// and written. Few values are live across the appends, which may move the arrays, so little is
// saved to the stack and reloaded.
//   side h: h -> hn -> hnn becomes h -> s1 -> hnn (fh) and g -> hn -> s1t (f1);
//   side t: t -> tn -> tnn becomes gt -> s2 -> tnn (ft) and t -> tn -> s2t (f2).
[[gnu::noinline]] Vertex split_between_triangles(Mesh& m, Edge e, const Vec3& point) {
  const Vec3 p = point;  // point may live in the position array, which add_vertex may move
  const Vertex v = m.add_vertex(p);
  const Halfedge g = m.new_edges<3>(), s1(g.idx() + 2), s2(g.idx() + 4);
  const Halfedge gt = Mesh::twin(g), s1t = Mesh::twin(s1), s2t = Mesh::twin(s2);
  const Face f1 = m.new_faces<2>(), f2(f1.idx() + 1);
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Vertex b = m.to_vertex(h);
  const Halfedge b_out = m.halfedge(b);
  {
    const Halfedge hn = m.next(h), hnn = m.next(hn);
    const Face fh = m.face(h);
    m.set_vertex(g, b);
    m.set_vertex(s1, m.to_vertex(hn));
    m.set_vertex(h, v);
    m.set_vertex(s1t, v);
    m.set_next(g, hn);
    link_triangle_split(m, h, g, hn, hnn, fh, s1, f1);
  }
  {
    const Halfedge tn = m.next(t), tnn = m.next(tn);
    const Face ft = m.face(t);
    m.set_vertex(gt, v);
    m.set_vertex(s2, m.to_vertex(tn));
    m.set_vertex(s2t, v);
    m.set_next(tnn, gt);
    m.set_face(gt, ft);
    link_triangle_split(m, gt, t, tn, tnn, ft, s2, f2);
  }
  m.set_halfedge(b, b_out == t ? gt : b_out);  // a store, not a branch on a likely cache miss
  m.set_halfedge(v, g);
  if (has_properties(m)) [[unlikely]]
    carry_split_properties(m, e, p, v);
  mark_split(m, v);
  return v;
}

// split_edge with a boundary or a polygon on one side at least.
[[gnu::noinline]] Vertex split_near_boundary_or_polygon(Mesh& m, Edge e, const Vec3& point) {
  const Vec3 p = point;  // point may live in the position array, which add_vertex may move
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Vertex b = m.to_vertex(h);
  const Face fh = m.face(h), ft = m.face(t);
  const Halfedge hn = m.next(h), hnn = m.next(hn), tn = m.next(t), tnn = m.next(tn);
  const bool tri1 = fh.is_valid() && m.next(hnn) == h;
  const bool tri2 = ft.is_valid() && m.next(tnn) == t;
  // Read before any link changes: prev() walks them.
  const EdgeSplit k{h,  t,  hn,   tn,  tri1 ? hnn : m.prev(h), tri2 ? tnn : m.prev(t), m.from_vertex(h), b,
                    fh, ft, tri1, tri2};
  const Vertex v = m.add_vertex(p);
  const Halfedge g = m.new_edge(v, b), gt = Mesh::twin(g);
  Halfedge s1, s2;
  Face f1, f2;
  m.set_vertex(h, v);
  m.set_face(g, fh);
  m.set_face(gt, ft);
  m.set_next(g, hn);
  m.set_next(gt, t);
  if (tri1) {  // h -> hn -> hnn becomes h -> s1 -> hnn (fh) and g -> hn -> s1t (f1)
    s1 = m.new_edge(v, m.to_vertex(hn));
    f1 = m.new_face();
    link_triangle_split(m, h, g, hn, hnn, fh, s1, f1);
  } else {  // a polygon or the boundary loop gets g after h
    m.set_next(h, g);
  }
  if (tri2) {  // t -> tn -> tnn becomes gt -> s2 -> tnn (ft) and t -> tn -> s2t (f2)
    s2 = m.new_edge(v, m.to_vertex(tn));
    f2 = m.new_face();
    link_triangle_split(m, gt, t, tn, tnn, ft, s2, f2);
  }
  m.set_next(k.tp, gt);
  const Halfedge b_out = m.halfedge(b);
  if (b_out == t) m.set_halfedge(b, gt);
  m.set_halfedge(v, ft.is_valid() ? g : t);  // t is a boundary half-edge if ft is invalid
  if (has_properties(m)) carry_split_properties(m, e, p, k, v, g, s1, s2, f1, f2);
  mark_split(m, v);
  return v;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
bool can_split_edge(const SurfaceMesh& m, Edge e) { return split_refusal(m, e) == nullptr; }

const char* split_refusal(const SurfaceMesh& m, Edge e) {
  return m.is_live(e) ? nullptr : refusal_text(Refusal::edge_not_live);
}

// Both cases are out of line: split_edge itself is the test and a tail call, and neither case's
// register use weighs on the other.
Vertex split_edge(SurfaceMesh& m, Edge e, const Vec3& point) {
  if (!can_split_edge(m, e) || !is_finite(point)) return {};
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  // A triangle on each side? (next(next(next(h))) == h, with a face.)
  const Halfedge hnn = m.next(m.next(h)), tnn = m.next(m.next(t));
  if (m.face(h).is_valid() && m.face(t).is_valid() && m.next(hnn) == h && m.next(tnn) == t)
    return split_between_triangles(m, e, point);
  return split_near_boundary_or_polygon(m, e, point);
}

// ---------------------------------------------------------------------------------------------
namespace {
// True if corners a and b hold the same values in every corner property.
bool same_corner(const Mesh& m, Halfedge a, Halfedge b) {
  return m.halfedge_properties().equal(a.idx(), b.idx());
}

// True if the edge of o (an interior edge) is a seam: its two faces hold different corner values at
// either end. The corner of vertex x in face f is stored on the half-edge entering x in f.
bool is_seam(const Mesh& m, Halfedge o) {
  const Halfedge t = Mesh::twin(o);
  return !same_corner(m, o, m.prev(t)) || !same_corner(m, m.prev(o), t);
}

// The corner rule of collapse(h) (see operations.h): the faces about both ends are grouped into
// charts, faces joined across spoke edges that are no seams; each corner of from_vertex(h) takes
// the value of the corners of to_vertex(h) in its chart.
class CollapseCorners {
 public:
  //! Plans the corner copies. \return null, or why the collapse would break or stretch a seam.
  const char* plan(const Mesh& m, Halfedge h);
  //! Copies the planned values. Called before the collapse relinks anything.
  void apply(Mesh& m) const {
    for (std::size_t i = 0; i < copies_.size(); ++i)
      m.halfedge_properties().copy(copies_[i].second.idx(), copies_[i].first.idx());
  }

 private:
  std::size_t slot(Face f) {
    for (std::size_t i = 0; i < faces_.size(); ++i)
      if (faces_[i] == f) return i;
    faces_.push_back(f);
    parent_.push_back(faces_.size() - 1);
    v1_corner_.push_back(Halfedge());
    v0_corner_.push_back(Halfedge());
    return faces_.size() - 1;
  }
  std::size_t root(std::size_t i) const {
    while (parent_[i] != i) i = parent_[i];
    return i;
  }

  SmallVector<Face, 32> faces_;
  SmallVector<std::size_t, 32> parent_;
  SmallVector<Halfedge, 32> v1_corner_;  // per chart root: a corner of the survivor
  SmallVector<Halfedge, 32> v0_corner_;  // per chart root: a corner of the vertex merged away
  SmallVector<std::pair<Halfedge, Halfedge>, 16> copies_;  // (corner of v0, corner of v1)
};

const char* CollapseCorners::plan(const Mesh& m, Halfedge h) {
  const Halfedge t = Mesh::twin(h);
  for (const Halfedge start : {h, t}) {  // the spokes of from_vertex(h), then of to_vertex(h)
    Halfedge x = start;
    do {
      const Face a = m.face(x), b = m.face(Mesh::twin(x));
      if (a.is_valid() && b.is_valid()) {
        const std::size_t i = root(slot(a)), j = root(slot(b));
        if (i != j && !is_seam(m, x)) parent_[i] = j;
      }
      x = m.rotate_cw(x);
    } while (x != start);
  }
  // The survivor's corners: one value per chart, else two sides of a seam would meet.
  Halfedge x = t;
  do {
    const Halfedge c = Mesh::twin(x);  // enters to_vertex(h)
    if (m.face(c).is_valid()) {
      const std::size_t r = root(slot(m.face(c)));
      if (!v1_corner_[r].is_valid())
        v1_corner_[r] = c;
      else if (!same_corner(m, v1_corner_[r], c))
        return refusal_text(Refusal::collapse_joins_seam_sides);
    }
    x = m.rotate_cw(x);
  } while (x != t);
  // The merged vertex's corners: each chart must reach the survivor (else the collapse pulls a seam
  // vertex off its seam) and hold one value (else a seam would lose its end there).
  const Face fl = m.face(h), fr = m.face(t);
  const bool tri_l = fl.is_valid() && is_triangle(m, h), tri_r = fr.is_valid() && is_triangle(m, t);
  x = h;
  do {
    const Halfedge c = Mesh::twin(x);  // enters from_vertex(h)
    const Face f = m.face(c);
    if (f.is_valid()) {
      const std::size_t r = root(slot(f));
      if (!v1_corner_[r].is_valid()) return refusal_text(Refusal::collapse_pulls_seam_vertex);
      if (!v0_corner_[r].is_valid())
        v0_corner_[r] = c;
      else if (!same_corner(m, v0_corner_[r], c))
        return refusal_text(Refusal::collapse_shortens_seam);
      // A triangle on h vanishes; its corners are taken care of as it goes.
      if (!(f == fl && tri_l) && !(f == fr && tri_r)) copies_.push_back({c, v1_corner_[r]});
    }
    x = m.rotate_cw(x);
  } while (x != h);
  return nullptr;
}
}  // namespace

namespace {
// collapse_refusal(); with corner properties it plans their copies into `corners` (collapse() plans
// once), or into a plan of its own, out of line, if `corners` is null: the plan is large, and the
// common case (no corner property) does not set it up.
const char* check_collapse(const SurfaceMesh& m, Halfedge h, CollapseCorners* corners);

[[gnu::noinline]] const char* plan_corners(const Mesh& m, Halfedge h) {
  CollapseCorners corners;
  return corners.plan(m, h);
}
}  // namespace

bool can_collapse(const SurfaceMesh& m, Halfedge h) { return collapse_refusal(m, h) == nullptr; }

const char* collapse_refusal(const SurfaceMesh& m, Halfedge h) { return check_collapse(m, h, nullptr); }

namespace {
const char* check_collapse(const SurfaceMesh& m, Halfedge h, CollapseCorners* corners) {
  if (!m.is_live(h)) return refusal_text(Refusal::halfedge_not_live);
  const Halfedge t = Mesh::twin(h);
  const Vertex v0 = m.from_vertex(h), v1 = m.to_vertex(h);
  const Face fl = m.face(h), fr = m.face(t);
  if (fl.is_valid() && fl == fr) return refusal_text(Refusal::collapse_same_face_both_sides);
  if (!m.is_boundary(Mesh::edge(h)) && m.is_boundary(v0) && m.is_boundary(v1))
    return refusal_text(Refusal::collapse_pinches_boundary);
  const Vertex tl = fl.is_valid() && is_triangle(m, h) ? m.to_vertex(m.next(h)) : Vertex();
  const Vertex tr = fr.is_valid() && is_triangle(m, t) ? m.to_vertex(m.next(t)) : Vertex();

  // Link condition, and no second edge between v0 and v1. The rotations start from h (leaving
  // v0) and t (leaving v1), at hand, rather than from the vertices' stored half-edges.
  SmallVector<Vertex, 32> n0;  // the hot predicates must not allocate per call
  std::size_t to_v1 = 0;
  Halfedge x = h;
  do {
    const Vertex w = m.to_vertex(x);
    n0.push_back(w);
    to_v1 += w == v1;
    x = m.rotate_cw(x);
  } while (x != h);
  if (to_v1 != 1) return refusal_text(Refusal::collapse_second_edge);
  std::size_t val1 = 0;
  x = t;
  do {
    const Vertex w = m.to_vertex(x);
    ++val1;
    if (w != v0 && w != tl && w != tr && n0.contains(w))
      return refusal_text(Refusal::collapse_link_condition);
    x = m.rotate_cw(x);
  } while (x != t);
  // Tips lose an edge; merged edges must keep a face on one side.
  for (int side = 0; side < 2; ++side) {
    const Vertex tip = side == 0 ? tl : tr;
    if (!tip.is_valid()) continue;
    const Halfedge s = side == 0 ? h : t;
    if (m.is_boundary(Mesh::twin(m.next(s))) && m.is_boundary(Mesh::twin(m.next(m.next(s)))))
      return refusal_text(Refusal::collapse_dangling_edge);
    if (!valence_above(m, tip, m.is_boundary(tip) ? 2u : 3u))
      return refusal_text(Refusal::collapse_tip_too_few_edges);
  }
  // The survivor must keep valence 3 if interior.
  const std::size_t tips = (tl.is_valid() ? 1 : 0) + (tr.is_valid() ? 1 : 0);
  const std::size_t val_after = n0.size() + val1 - 2 - tips;
  const bool boundary_after = m.is_boundary(v0) || m.is_boundary(v1);
  if (val_after < (boundary_after ? 2u : 3u)) return refusal_text(Refusal::collapse_survivor_too_few_edges);
  if (!m.halfedge_properties().empty()) [[unlikely]]
    return corners ? corners->plan(m, h) : plan_corners(m, h);
  return nullptr;
}
}  // namespace

namespace {
// Removes the two-sided face left by a collapse: g and next(g) join the same two vertices. The
// edge of g goes; next(g) takes the place of twin(g) in its loop.
void remove_two_gon(Mesh& m, Halfedge g) {
  const Halfedge g2 = m.next(g);
  const Face f = m.face(g);
  const Halfedge o = Mesh::twin(g);
  const Halfedge op = m.prev(o), on = m.next(o);
  const Vertex x = m.from_vertex(g), y = m.to_vertex(g);
  m.set_next(op, g2);
  m.set_next(g2, on);
  m.set_face(g2, m.face(o));
  if (m.face(o).is_valid() && m.halfedge(m.face(o)) == o) m.set_halfedge(m.face(o), g2);
  m.halfedge_properties().copy(o.idx(), g2.idx());
  if (m.halfedge(y) == o) m.set_halfedge(y, g2);
  if (m.halfedge(x) == g) m.set_halfedge(x, Mesh::twin(g2));
  m.mark_deleted(f);
  m.mark_deleted(Mesh::edge(g));
}
}  // namespace

Vertex collapse(SurfaceMesh& m, Halfedge h) {
  if (!m.halfedge_properties().empty()) [[unlikely]] {
    CollapseCorners corners;
    if (check_collapse(m, h, &corners)) return {};
    corners.apply(m);
  } else if (check_collapse(m, h, nullptr)) {
    return {};
  }
  const Halfedge t = Mesh::twin(h);
  const Vertex v0 = m.from_vertex(h), v1 = m.to_vertex(h);
  const Halfedge hn = m.next(h), hp = m.prev(h), tn = m.next(t), tp = m.prev(t);
  const Face fl = m.face(h), fr = m.face(t);
  // Two interior ends make an interior survivor, whose stored half-edge needs no boundary search.
  const bool on_boundary = m.is_boundary(v0) || m.is_boundary(v1);

  // Renaming targets leaves every next link intact, so the rotation about v0 (from h, which leaves
  // it) can go on meanwhile.
  Halfedge o = h;
  do {
    m.set_vertex(Mesh::twin(o), v1);
    o = m.rotate_cw(o);
  } while (o != h);
  m.set_next(hp, hn);
  m.set_next(tp, tn);
  if (fl.is_valid() && m.halfedge(fl) == h) m.set_halfedge(fl, hn);
  if (fr.is_valid() && m.halfedge(fr) == t) m.set_halfedge(fr, tn);
  if (m.halfedge(v1) == t) m.set_halfedge(v1, hn);
  m.mark_deleted(Mesh::edge(h));
  m.mark_deleted(v0);
  m.set_halfedge(v0, Halfedge());
  if (fl.is_valid() && m.next(m.next(hn)) == hn) remove_two_gon(m, hn);
  if (fr.is_valid() && m.next(m.next(tn)) == tn) remove_two_gon(m, tn);
  if (on_boundary) m.adjust_outgoing_halfedge(v1);
  if (m.changes().active()) {
    // A triangle on h is deleted by now; a polygon on h lost a corner. Either way it is marked.
    if (fl.is_valid())
      m.mark_changed(fl, m.is_deleted(fl) ? ChangeEvent::faces_removed : ChangeEvent::faces_changed);
    if (fr.is_valid())
      m.mark_changed(fr, m.is_deleted(fr) ? ChangeEvent::faces_removed : ChangeEvent::faces_changed);
    m.mark_changed(v0, ChangeEvent::vertices_removed);
    mark_faces_around(m, v1, ChangeEvent::faces_changed);
    m.changes().notify();
  }
  return v1;
}

// ---------------------------------------------------------------------------------------------
namespace {
// False if from_vertex(out) is an interior vertex with at most 3 edges (a flip would leave it with
// 2). Rotates from `out`, a half-edge at hand, rather than from the vertex's stored half-edge (one
// dependent load less), and looks at faces only when there are 3 edges or fewer. O(1).
[[gnu::always_inline]] inline bool keeps_enough_edges(const Mesh& m, Halfedge out) {
  const Halfedge x1 = m.rotate_cw(out), x2 = m.rotate_cw(x1), x3 = m.rotate_cw(x2);
  if (x1 != out && x2 != out && x3 != out) return true;  // more than 3 edges
  // 3 edges or fewer, all among out, x1, x2: fine if one is a boundary half-edge.
  return m.is_boundary(out) || m.is_boundary(x1) || m.is_boundary(x2);
}

// True if an edge joins from_vertex(out) and w: rotates about from_vertex(out) from `out`.
bool joined(const Mesh& m, Halfedge out, Vertex w) {
  Halfedge x = out;
  do {
    if (m.to_vertex(x) == w) return true;
    x = m.rotate_cw(x);
  } while (x != out);
  return false;
}

// flip_refusal's tests once the two triangles are known: h -> h1 -> h2 and t -> t1 -> t2.
[[gnu::always_inline]] inline const char* flip_check(const Mesh& m, Halfedge h, Halfedge t, Halfedge h1,
                                                     Halfedge h2, Halfedge t1) {
  const Vertex c = m.to_vertex(h1), d = m.to_vertex(t1);
  // h2 leaves c, h leaves a and t leaves b: the walks start there. The two short fixed walks come
  // first: the loop about c ends on a mispredicted branch, which would restart them.
  if (c == d) return refusal_text(Refusal::flip_tips_shared);
  if (!keeps_enough_edges(m, h) || !keeps_enough_edges(m, t))
    return refusal_text(Refusal::flip_valence_three);
  if (joined(m, h2, d)) return refusal_text(Refusal::flip_tips_joined);
  return nullptr;
}

// flip_refusal(), inlined into can_flip() too: there each reason folds into "refused", so the hot
// predicate costs what a yes-or-no test costs.
[[gnu::always_inline]] inline const char* flip_refusal_of(const Mesh& m, Edge e) {
  if (!m.is_live(e)) return refusal_text(Refusal::edge_not_live);
  if (m.is_boundary(e)) return refusal_text(Refusal::flip_boundary_edge);
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Halfedge h1 = m.next(h), h2 = m.next(h1), t1 = m.next(t), t2 = m.next(t1);
  if (m.next(h2) != h || m.next(t2) != t) return refusal_text(Refusal::flip_not_triangle);
  return flip_check(m, h, t, h1, h2, t1);
}
}  // namespace

bool can_flip(const SurfaceMesh& m, Edge e) { return flip_refusal_of(m, e) == nullptr; }

const char* flip_refusal(const SurfaceMesh& m, Edge e) { return flip_refusal_of(m, e); }

// flip_refusal()'s tests again, inline: the edit needs the half-edges they find.
Edge flip(SurfaceMesh& m, Edge e) {
  if (!m.is_live(e) || m.is_boundary(e)) return {};
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Halfedge h1 = m.next(h), h2 = m.next(h1), t1 = m.next(t), t2 = m.next(t1);
  if (m.next(h2) != h || m.next(t2) != t || flip_check(m, h, t, h1, h2, t1) != nullptr) return {};
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  const Vertex c = m.to_vertex(h1), d = m.to_vertex(t1);
  const Face f1 = m.face(h), f2 = m.face(t);
  m.halfedge_properties().copy(h1.idx(), h.idx());
  m.halfedge_properties().copy(t1.idx(), t.idx());
  // Stores rather than branches on the (likely missing) vertex half-edges.
  const Halfedge a_out = m.halfedge(a), b_out = m.halfedge(b);
  m.set_halfedge(a, a_out == h ? t1 : a_out);
  m.set_halfedge(b, b_out == t ? h1 : b_out);
  m.set_vertex(h, c);
  m.set_vertex(t, d);
  m.set_next(t1, h);
  m.set_next(h, h2);
  m.set_next(h2, t1);
  m.set_face(t1, f1);
  m.set_next(h1, t);
  m.set_next(t, t2);
  m.set_next(t2, h1);
  m.set_face(h1, f2);
  m.set_halfedge(f1, h);
  m.set_halfedge(f2, t);
  if (m.changes().active()) {  // nothing to mark or tell when nobody listens
    m.mark_changed(f1);
    m.mark_changed(f2);
    m.changes().notify();
  }
  return e;
}

}  // namespace hedge

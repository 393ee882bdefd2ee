// Local topology edits. See include/hedge/core/operations.h for the contract of each.
#include "hedge/core/operations.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "hedge/core/build.h"

namespace hedge {

namespace {

using Mesh = SurfaceMesh;

bool live(const Mesh& m, Halfedge h) { return h.is_valid() && m.is_valid(h) && !m.is_deleted(h); }
bool live(const Mesh& m, Edge e) { return e.is_valid() && m.is_valid(e) && !m.is_deleted(e); }
bool live(const Mesh& m, Face f) { return f.is_valid() && m.is_valid(f) && !m.is_deleted(f); }
bool live(const Mesh& m, Vertex v) { return v.is_valid() && m.is_valid(v) && !m.is_deleted(v); }

bool is_triangle(const Mesh& m, Halfedge h) { return m.next(m.next(m.next(h))) == h; }

// True if v has more than k edges; stops counting there (O(min(valence, k))).
bool valence_above(const Mesh& m, Vertex v, std::size_t k) {
  std::size_t n = 0;
  for (auto it = m.halfedges(v).begin(); !(it == CirculatorEnd{}); ++it)
    if (++n > k) return true;
  return false;
}

// A list of a few handles kept on the stack, spilling to the heap past N: the hot predicates
// must not allocate per call.
template <typename T, std::size_t N = 32>
class SmallList {
 public:
  void push_back(T t) {
    if (n_ < N) inline_[n_] = t;
    else spill_.push_back(t);
    ++n_;
  }
  bool contains(T t) const {
    for (std::size_t i = 0; i < std::min(n_, N); ++i)
      if (inline_[i] == t) return true;
    return std::find(spill_.begin(), spill_.end(), t) != spill_.end();
  }
  std::size_t size() const { return n_; }

 private:
  T inline_[N];
  std::vector<T> spill_;
  std::size_t n_ = 0;
};

// Outgoing half-edges of v in clockwise order, starting at its half-edge.
std::vector<Halfedge> outgoing(const Mesh& m, Vertex v) {
  std::vector<Halfedge> out;
  for (Halfedge h : m.halfedges(v)) out.push_back(h);
  return out;
}

// Gaps (boundary wedges) v would have if the faces for which `removed` is true were gone.
// Wedge i lies between out[i-1] and out[i] and holds face(out[i]).
template <typename Pred>
std::size_t gaps_after(const Mesh& m, Vertex v, Pred&& removed) {
  const std::vector<Halfedge> out = outgoing(m, v);
  const std::size_t k = out.size();
  if (k == 0) return 0;
  std::vector<std::uint8_t> gap(k);
  std::size_t n_gap = 0;
  for (std::size_t i = 0; i < k; ++i) {
    const Face f = m.face(out[i]);
    gap[i] = !f.is_valid() || removed(f);
    n_gap += gap[i];
  }
  if (n_gap == k) return 0;  // v is left isolated
  std::size_t runs = 0;
  for (std::size_t i = 0; i < k; ++i) runs += gap[i] && !gap[(i + k - 1) % k];
  return runs;
}

// After faces around v were removed (their half-edges made boundary, edges with no face left
// deleted), relinks the boundary loops through v, gives each further fan a copy of v, and points
// v at a boundary half-edge. `out` is v's clockwise outgoing list from before the removal.
// Returns false if v was left with no edge.
bool relink_vertex(Mesh& m, Vertex v, const std::vector<Halfedge>& out) {
  std::vector<Halfedge> alive;
  for (Halfedge o : out)
    if (!m.is_deleted(o)) alive.push_back(o);
  if (alive.empty()) {
    m.set_halfedge(v, Halfedge());
    return false;
  }
  const std::size_t k = alive.size();
  std::size_t first_gap = k;
  for (std::size_t i = 0; i < k && first_gap == k; ++i)
    if (m.is_boundary(alive[i])) first_gap = i;
  if (first_gap == k) {  // no gap: v is interior
    m.set_halfedge(v, alive[0]);
    return true;
  }
  // Each fan runs clockwise from an outgoing boundary half-edge to the next gap. The boundary
  // half-edge entering v at the fan's end continues with the one leaving at its start, so that a
  // fan given its own copy of v is a complete boundary vertex; the first fan keeps v.
  Vertex owner = v;
  std::size_t start = first_gap;
  for (std::size_t s = 0; s < k; ++s) {
    const std::size_t i = (first_gap + s) % k;
    const Halfedge o = alive[i];
    if (m.is_boundary(o)) {
      start = i;
      if (s > 0) {
        owner = m.add_vertex(m.position(v));
        m.vertex_properties().copy(v.idx(), owner.idx());
      }
      m.set_halfedge(owner, o);
    }
    if (owner != v) m.set_vertex(Mesh::twin(o), owner);
    const bool fan_ends = m.is_boundary(alive[(i + 1) % k]);
    if (fan_ends) m.set_next(Mesh::twin(o), alive[start]);
  }
  return true;
}

// Removes a set of faces (sorted, unique, live). Vertices left pinched get one copy per fan.
void remove_faces_impl(Mesh& m, const std::vector<Face>& faces) {
  std::vector<Vertex> verts;
  for (Face f : faces)
    for (Vertex v : m.vertices(f)) verts.push_back(v);
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  std::vector<std::vector<Halfedge>> outs;
  outs.reserve(verts.size());
  for (Vertex v : verts) outs.push_back(outgoing(m, v));

  std::vector<Halfedge> hs;
  for (Face f : faces) {
    for (Halfedge h : m.halfedges(f)) hs.push_back(h);
    m.mark_deleted(f);
  }
  for (Halfedge h : hs) m.set_face(h, Face());
  for (Halfedge h : hs)
    if (m.is_boundary(Mesh::twin(h))) m.mark_deleted(Mesh::edge(h));
  for (std::size_t i = 0; i < verts.size(); ++i)
    if (!relink_vertex(m, verts[i], outs[i])) m.mark_deleted(verts[i]);
}

// Interpolation parameter of point p along segment a-b, clamped to it.
float segment_parameter(const Vec3& a, const Vec3& b, const Vec3& p) {
  const Vec3d d = to_double(b) - to_double(a);
  const double len2 = dot(d, d);
  if (!(len2 > 0)) return 0.5f;
  const double s = dot(to_double(p) - to_double(a), d) / len2;
  return static_cast<float>(std::clamp(std::isfinite(s) ? s : 0.5, 0.0, 1.0));
}

// Barycentric weights of p in triangle abc, clamped to the triangle; equal weights if degenerate.
std::array<float, 3> barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
  const Vec3d A = to_double(a), B = to_double(b), C = to_double(c), P = to_double(p);
  const Vec3d n = cross(B - A, C - A);
  const double nn = dot(n, n);
  if (!(nn > 0)) return {1.f / 3, 1.f / 3, 1.f / 3};
  double wa = std::max(0.0, dot(cross(C - B, P - B), n) / nn);
  double wb = std::max(0.0, dot(cross(A - C, P - C), n) / nn);
  double wc = std::max(0.0, dot(cross(B - A, P - A), n) / nn);
  const double s = wa + wb + wc;
  if (!(s > 0) || !std::isfinite(s)) return {1.f / 3, 1.f / 3, 1.f / 3};
  return {float(wa / s), float(wb / s), float(wc / s)};
}

// Splits the triangle of h, whose loop is h -> n1 -> n2 with h entering the new vertex, by an edge
// from to(h) to the tip to(n1). Returns the new face (the part holding next(h)).
Face cut_triangle_after(Mesh& m, Halfedge h) {
  const Face f = m.face(h);
  const Halfedge g = m.next(h);       // from the new vertex
  const Halfedge n1 = m.next(g);
  const Halfedge n2 = m.next(n1);
  // Loop now: h -> g -> n1 -> n2 -> h (a quad). Cut between to(h) and to(n1).
  const Halfedge s = m.new_edge(m.to_vertex(h), m.to_vertex(n1));
  const Halfedge st = Mesh::twin(s);
  const Face f2 = m.new_face();
  m.face_properties().copy(f.idx(), f2.idx());
  m.set_next(h, s);
  m.set_next(s, n2);
  m.set_face(s, f);
  m.set_next(n1, st);
  m.set_next(st, g);
  m.set_face(st, f2);
  m.set_face(g, f2);
  m.set_face(n1, f2);
  m.set_halfedge(f, h);
  m.set_halfedge(f2, g);
  // Corner data: s enters the tip in f, st enters the new vertex in f2.
  m.halfedge_properties().copy(n1.idx(), s.idx());
  m.halfedge_properties().copy(h.idx(), st.idx());
  return f2;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
bool can_split_edge(const SurfaceMesh& m, Edge e) { return live(m, e); }

Vertex split_edge(SurfaceMesh& m, Edge e, const Vec3& point) {
  if (!can_split_edge(m, e) || !is_finite(point)) return {};
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  // On a triangle the previous half-edge is next(next): one walk serves both questions.
  const Halfedge hn = m.next(h), hnn = m.next(hn), tnn = m.next(m.next(t));
  const bool tri1 = !m.is_boundary(h) && m.next(hnn) == h;
  const bool tri2 = !m.is_boundary(t) && m.next(tnn) == t;
  const Halfedge hp = tri1 ? hnn : m.prev(h), tp = tri2 ? tnn : m.prev(t);
  const float s = segment_parameter(m.position(a), m.position(b), point);

  const Vertex v = m.add_vertex(point);
  {
    const Index src[2] = {a.idx(), b.idx()};
    const float w[2] = {1 - s, s};
    m.vertex_properties().interpolate(v.idx(), src, w, 2);
    m.position(v) = point;
  }
  const Halfedge g = m.new_edge(v, b), gt = Mesh::twin(g);
  m.edge_properties().copy(e.idx(), Mesh::edge(g).idx());
  auto& hprops = m.halfedge_properties();
  // Corner data: g takes h's corner at b; h and gt get the blend at the new vertex.
  hprops.copy(h.idx(), g.idx());
  {
    const Index src1[2] = {hp.idx(), h.idx()};
    const Index src2[2] = {t.idx(), tp.idx()};
    const float w[2] = {1 - s, s};
    hprops.interpolate(gt.idx(), src2, w, 2);
    hprops.interpolate(h.idx(), src1, w, 2);
  }
  m.set_vertex(h, v);
  m.set_next(h, g);
  m.set_next(g, hn);
  m.set_face(g, m.face(h));
  m.set_next(tp, gt);
  m.set_next(gt, t);
  m.set_face(gt, m.face(t));
  if (m.halfedge(b) == t) m.set_halfedge(b, gt);
  m.set_halfedge(v, m.is_boundary(t) ? t : g);

  if (tri1) cut_triangle_after(m, h);
  if (tri2) cut_triangle_after(m, gt);
  return v;
}

// ---------------------------------------------------------------------------------------------
bool can_collapse(const SurfaceMesh& m, Halfedge h) {
  if (!live(m, h)) return false;
  const Halfedge t = Mesh::twin(h);
  const Vertex v0 = m.from_vertex(h), v1 = m.to_vertex(h);
  const Face fl = m.face(h), fr = m.face(t);
  if (fl.is_valid() && fl == fr) return false;
  if (!m.is_boundary(Mesh::edge(h)) && m.is_boundary(v0) && m.is_boundary(v1)) return false;
  const Vertex tl = fl.is_valid() && is_triangle(m, h) ? m.to_vertex(m.next(h)) : Vertex();
  const Vertex tr = fr.is_valid() && is_triangle(m, t) ? m.to_vertex(m.next(t)) : Vertex();

  // Link condition, and no second edge between v0 and v1.
  SmallList<Vertex> n0;
  std::size_t to_v1 = 0;
  for (Vertex w : m.vertices(v0)) {
    n0.push_back(w);
    to_v1 += w == v1;
  }
  if (to_v1 != 1) return false;
  std::size_t val1 = 0;
  for (Vertex w : m.vertices(v1)) {
    ++val1;
    if (w == v0 || w == tl || w == tr) continue;
    if (n0.contains(w)) return false;
  }
  // Tips lose an edge; merged edges must keep a face on one side.
  for (int side = 0; side < 2; ++side) {
    const Vertex tip = side == 0 ? tl : tr;
    if (!tip.is_valid()) continue;
    const Halfedge s = side == 0 ? h : t;
    if (m.is_boundary(Mesh::twin(m.next(s))) && m.is_boundary(Mesh::twin(m.next(m.next(s))))) return false;
    if (!valence_above(m, tip, m.is_boundary(tip) ? 2u : 3u)) return false;
  }
  // The survivor must keep valence 3 if interior.
  const std::size_t tips = (tl.is_valid() ? 1 : 0) + (tr.is_valid() ? 1 : 0);
  const std::size_t val_after = n0.size() + val1 - 2 - tips;
  const bool boundary_after = m.is_boundary(v0) || m.is_boundary(v1);
  if (val_after < (boundary_after ? 2u : 3u)) return false;
  return true;
}

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
  if (!can_collapse(m, h)) return {};
  const Halfedge t = Mesh::twin(h);
  const Vertex v0 = m.from_vertex(h), v1 = m.to_vertex(h);
  const Halfedge hn = m.next(h), hp = m.prev(h), tn = m.next(t), tp = m.prev(t);
  const Face fl = m.face(h), fr = m.face(t);

  // Renaming targets leaves every next link intact, so the rotation about v0 can go on meanwhile.
  for (Halfedge o : m.halfedges(v0)) m.set_vertex(Mesh::twin(o), v1);
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
  m.adjust_outgoing_halfedge(v1);
  return v1;
}

// ---------------------------------------------------------------------------------------------
bool can_flip(const SurfaceMesh& m, Edge e) {
  if (!live(m, e) || m.is_boundary(e)) return false;
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  if (!is_triangle(m, h) || !is_triangle(m, t)) return false;
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  const Vertex c = m.to_vertex(m.next(h)), d = m.to_vertex(m.next(t));
  if (c == d || m.find_halfedge(c, d).is_valid()) return false;
  for (Vertex v : {a, b})
    if (!m.is_boundary(v) && !valence_above(m, v, 3)) return false;
  return true;
}

Edge flip(SurfaceMesh& m, Edge e) {
  if (!can_flip(m, e)) return {};
  const Halfedge h = Mesh::halfedge(e, 0), t = Mesh::twin(h);
  const Halfedge h1 = m.next(h), h2 = m.next(h1), t1 = m.next(t), t2 = m.next(t1);
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  const Vertex c = m.to_vertex(h1), d = m.to_vertex(t1);
  const Face f1 = m.face(h), f2 = m.face(t);
  m.halfedge_properties().copy(h1.idx(), h.idx());
  m.halfedge_properties().copy(t1.idx(), t.idx());
  if (m.halfedge(a) == h) m.set_halfedge(a, t1);
  if (m.halfedge(b) == t) m.set_halfedge(b, h1);
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
  return e;
}

// ---------------------------------------------------------------------------------------------
bool can_split_face(const SurfaceMesh& m, Face f) { return live(m, f); }

Vertex split_face(SurfaceMesh& m, Face f, const Vec3& point) {
  if (!can_split_face(m, f) || !is_finite(point)) return {};
  std::vector<Halfedge> hs;
  for (Halfedge h : m.halfedges(f)) hs.push_back(h);
  const std::size_t n = hs.size();
  // Corner u_i = from(hs[i]); its corner data sits on hs[i-1], the half-edge entering it.
  std::vector<Index> corner_v(n), corner_h(n);
  for (std::size_t i = 0; i < n; ++i) {
    corner_v[i] = m.from_vertex(hs[i]).idx();
    corner_h[i] = hs[(i + n - 1) % n].idx();
  }
  std::vector<float> w(n, 1.0f / static_cast<float>(n));
  if (n == 3) {
    auto bc = barycentric(m.position(Vertex(corner_v[0])), m.position(Vertex(corner_v[1])),
                          m.position(Vertex(corner_v[2])), point);
    w.assign(bc.begin(), bc.end());
  }
  const Vertex v = m.add_vertex(point);
  m.vertex_properties().interpolate(v.idx(), corner_v.data(), w.data(), n);
  m.position(v) = point;

  std::vector<Halfedge> out(n);  // out[i]: v -> u_i
  for (std::size_t i = 0; i < n; ++i) out[i] = m.new_edge(v, Vertex(corner_v[i]));
  auto& hprops = m.halfedge_properties();
  hprops.interpolate(Mesh::twin(out[0]).idx(), corner_h.data(), w.data(), n);
  for (std::size_t i = 1; i < n; ++i) hprops.copy(Mesh::twin(out[0]).idx(), Mesh::twin(out[i]).idx());
  for (std::size_t i = 0; i < n; ++i) hprops.copy(corner_h[i], out[i].idx());

  for (std::size_t i = 0; i < n; ++i) {
    Face fi = f;
    if (i > 0) {
      fi = m.new_face();
      m.face_properties().copy(f.idx(), fi.idx());
    }
    const Halfedge in_next = Mesh::twin(out[(i + 1) % n]);  // u_{i+1} -> v
    m.set_next(out[i], hs[i]);
    m.set_next(hs[i], in_next);
    m.set_next(in_next, out[i]);
    m.set_face(out[i], fi);
    m.set_face(hs[i], fi);
    m.set_face(in_next, fi);
    m.set_halfedge(fi, hs[i]);
  }
  m.set_halfedge(v, out[0]);
  return v;
}

bool can_split_face(const SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  if (!live(m, h0) || !live(m, h1) || h0 == h1) return false;
  const Face f = m.face(h0);
  if (!f.is_valid() || m.face(h1) != f) return false;
  if (m.next(h0) == h1 || m.next(h1) == h0) return false;
  return !m.find_halfedge(m.to_vertex(h0), m.to_vertex(h1)).is_valid();
}

Halfedge split_face(SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  if (!can_split_face(m, h0, h1)) return {};
  const Face f = m.face(h0);
  const Halfedge a0 = m.next(h0), a1 = m.next(h1);
  const Halfedge n = m.new_edge(m.to_vertex(h0), m.to_vertex(h1)), nt = Mesh::twin(n);
  const Face g = m.new_face();
  m.face_properties().copy(f.idx(), g.idx());
  m.halfedge_properties().copy(h0.idx(), nt.idx());
  m.halfedge_properties().copy(h1.idx(), n.idx());
  m.set_next(h1, nt);
  m.set_next(nt, a0);
  m.set_face(nt, f);
  m.set_next(h0, n);
  m.set_next(n, a1);
  for (Halfedge x = a1;; x = m.next(x)) {
    m.set_face(x, g);
    if (x == n) break;
  }
  m.set_halfedge(f, h1);
  m.set_halfedge(g, h0);
  return n;
}

Vec3 face_centroid(const SurfaceMesh& m, Face f) {
  Vec3d c{0, 0, 0};
  std::size_t n = 0;
  for (Vertex v : m.vertices(f)) {
    c += to_double(m.position(v));
    ++n;
  }
  return n ? to_float(c / double(n)) : Vec3{};
}

std::vector<Vertex> split_all_faces(SurfaceMesh& m) {
  std::vector<Face> faces;
  for (Face f : m.faces()) faces.push_back(f);
  std::vector<Vertex> out;
  out.reserve(faces.size());
  for (Face f : faces) out.push_back(split_face(m, f, face_centroid(m, f)));
  return out;
}

// ---------------------------------------------------------------------------------------------
namespace {
struct AddPlan {
  std::vector<Halfedge> existing;  // existing[i]: v_i -> v_{i+1}, or invalid
};

bool plan_add_face(const Mesh& m, std::span<const Vertex> vs, AddPlan& plan) {
  const std::size_t n = vs.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if (!live(m, vs[i])) return false;
    for (std::size_t j = i + 1; j < n; ++j)
      if (vs[i] == vs[j]) return false;
  }
  plan.existing.assign(n, Halfedge());
  for (std::size_t i = 0; i < n; ++i) {
    const Halfedge h = m.find_halfedge(vs[i], vs[(i + 1) % n]);
    if (h.is_valid() && !m.is_boundary(h)) return false;  // that side already has a face
    plan.existing[i] = h;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex v = vs[i];
    if (m.is_isolated(v)) continue;
    if (!m.is_boundary(v)) return false;  // a closed fan has no room
    const Halfedge in = plan.existing[(i + n - 1) % n], out = plan.existing[i];
    if (!in.is_valid() && !out.is_valid()) return false;  // would touch v at a second gap
  }
  return true;
}
}  // namespace

bool can_add_face(const SurfaceMesh& m, std::span<const Vertex> vs) {
  AddPlan plan;
  return plan_add_face(m, vs, plan);
}

Face add_face(SurfaceMesh& m, std::span<const Vertex> vs) {
  AddPlan plan;
  if (!plan_add_face(m, vs, plan)) return {};
  const std::size_t n = vs.size();
  // The boundary half-edges into and out of each vertex's gap, read before anything changes (a
  // vertex has one gap, so an existing boundary edge of the new face at v is one of these).
  std::vector<Halfedge> gap_in(n), gap_out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex v = vs[i];
    if (m.is_isolated(v)) continue;
    gap_out[i] = m.halfedge(v);  // the boundary half-edge leaving v
    gap_in[i] = m.prev(gap_out[i]);
  }
  std::vector<Halfedge> hs(n);
  std::vector<std::uint8_t> fresh(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (plan.existing[i].is_valid()) {
      hs[i] = plan.existing[i];
    } else {
      hs[i] = m.new_edge(vs[i], vs[(i + 1) % n]);
      fresh[i] = 1;
    }
  }
  // Boundary links at each corner, for the four cases of old or new edges in and out.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t ip = (i + n - 1) % n;
    const Halfedge in = hs[ip], out = hs[i];
    const bool in_new = fresh[ip], out_new = fresh[i];
    if (in_new && out_new) {
      m.set_next(Mesh::twin(out), Mesh::twin(in));  // v was isolated (the plan ensures it)
    } else if (in_new) {
      m.set_next(gap_in[i], Mesh::twin(in));
    } else if (out_new) {
      m.set_next(Mesh::twin(out), gap_out[i]);
    }
  }
  const Face f = m.new_face();
  for (std::size_t i = 0; i < n; ++i) {
    m.set_next(hs[i], hs[(i + 1) % n]);
    m.set_face(hs[i], f);
  }
  m.set_halfedge(f, hs[n - 1]);
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex v = vs[i];
    if (!m.halfedge(v).is_valid() || !m.is_boundary(m.halfedge(v))) m.set_halfedge(v, hs[i]);
    m.adjust_outgoing_halfedge(v);
  }
  return f;
}

// ---------------------------------------------------------------------------------------------
bool can_remove_face(const SurfaceMesh& m, Face f) {
  if (!live(m, f)) return false;
  for (Vertex v : m.vertices(f))
    if (gaps_after(m, v, [&](Face g) { return g == f; }) > 1) return false;
  return true;
}

bool remove_face(SurfaceMesh& m, Face f) {
  if (!can_remove_face(m, f)) return false;
  remove_faces_impl(m, {f});
  return true;
}

namespace {
std::vector<Face> faces_of(const Mesh& m, Vertex v) {
  std::vector<Face> fs;
  for (Face f : m.faces(v)) fs.push_back(f);
  std::sort(fs.begin(), fs.end());
  return fs;
}
}  // namespace

bool can_remove_vertex(const SurfaceMesh& m, Vertex v) {
  if (!live(m, v)) return false;
  const std::vector<Face> fs = faces_of(m, v);
  auto removed = [&](Face g) { return std::binary_search(fs.begin(), fs.end(), g); };
  // Every corner of the removed faces is affected, not only v's neighbours (polygons).
  for (Face f : fs)
    for (Vertex w : m.vertices(f))
      if (w != v && gaps_after(m, w, removed) > 1) return false;
  return true;
}

bool remove_vertex(SurfaceMesh& m, Vertex v) {
  if (!can_remove_vertex(m, v)) return false;
  const std::vector<Face> fs = faces_of(m, v);
  if (fs.empty()) {
    // Isolated, or only dangling edges (not possible in a valid mesh): just the vertex.
    m.set_halfedge(v, Halfedge());
    m.mark_deleted(v);
    return true;
  }
  remove_faces_impl(m, fs);
  if (!m.is_deleted(v)) {
    m.set_halfedge(v, Halfedge());
    m.mark_deleted(v);
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
std::vector<Face> fill_hole(SurfaceMesh& m, Halfedge h) {
  if (!live(m, h) || !m.is_boundary(h)) return {};
  std::vector<Halfedge> loop;
  for (Halfedge g : m.loop(h)) {
    loop.push_back(g);
    if (loop.size() > m.halfedges_size()) return {};  // a damaged loop
  }
  if (loop.size() < 3) return {};
  const Face f = m.new_face();
  for (Halfedge g : loop) m.set_face(g, f);
  m.set_halfedge(f, h);
  for (Halfedge g : loop) m.adjust_outgoing_halfedge(m.to_vertex(g));
  std::vector<Face> faces{f};
  Face rest = f;
  while (m.valence(rest) > 3) {
    Halfedge best0, best1;
    double best = HUGE_VAL;
    for (Halfedge h0 : m.halfedges(rest)) {
      const Halfedge h1 = m.next(m.next(h0));
      if (!can_split_face(m, h0, h1)) continue;
      const Vec3d d = to_double(m.position(m.to_vertex(h0))) - to_double(m.position(m.to_vertex(h1)));
      const double len = dot(d, d);
      if (len < best) {
        best = len;
        best0 = h0;
        best1 = h1;
      }
    }
    if (!best0.is_valid()) break;
    const Halfedge n = split_face(m, best0, best1);
    rest = m.face(n);
    faces.push_back(rest);
  }
  return faces;
}

// ---------------------------------------------------------------------------------------------
SurfaceMesh detach_faces(SurfaceMesh& m, std::span<const Face> faces_in, std::vector<Vertex>* vertex_origin) {
  std::vector<Face> faces;
  for (Face f : faces_in)
    if (live(m, f)) faces.push_back(f);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  // The set as an indexed mesh over its own vertices.
  std::vector<Vertex> verts;
  for (Face f : faces)
    for (Vertex v : m.vertices(f)) verts.push_back(v);
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  auto local = [&](Vertex v) {
    return static_cast<Index>(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin());
  };
  IndexedMesh part;
  for (Vertex v : verts) part.positions.push_back(m.position(v));
  std::vector<Halfedge> corner_src;
  for (Face f : faces) {
    std::size_t n = 0;
    for (Halfedge h : m.halfedges(f)) {
      part.indices.push_back(local(m.to_vertex(h)));
      corner_src.push_back(h);
      ++n;
    }
    part.face_sizes.push_back(static_cast<Index>(n));
  }
  BuildOptions opt;
  opt.policy = TopologyPolicy::repair;  // faces of the set may touch at a vertex only
  BuildReport rep;
  SurfaceMesh out = build(part, opt, &rep);

  // Every property comes along.
  out.vertex_properties().add_missing_from(m.vertex_properties());
  out.halfedge_properties().add_missing_from(m.halfedge_properties());
  out.edge_properties().add_missing_from(m.edge_properties());
  out.face_properties().add_missing_from(m.face_properties());
  std::vector<Vertex> origin(out.vertices_size());
  for (Vertex v : out.vertices()) {
    origin[v.idx()] = verts[rep.vertex_origin[v.idx()]];
    out.vertex_properties().copy_element_from(m.vertex_properties(), origin[v.idx()].idx(), v.idx());
  }
  std::size_t c = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Face nf(rep.face_map[i]);
    out.face_properties().copy_element_from(m.face_properties(), faces[i].idx(), nf.idx());
    for (Halfedge h : out.halfedges(nf)) {
      const Halfedge src = corner_src[c++];
      out.halfedge_properties().copy_element_from(m.halfedge_properties(), src.idx(), h.idx());
      out.edge_properties().copy_element_from(m.edge_properties(), Mesh::edge(src).idx(), Mesh::edge(h).idx());
    }
  }
  remove_faces_impl(m, faces);
  if (vertex_origin) *vertex_origin = std::move(origin);
  return out;
}

}  // namespace hedge

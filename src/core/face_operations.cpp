// Local edits of faces: split_face, cut_face, add_face, and the removals (remove_face,
// remove_vertex, remove_faces). See include/hedge/core/face_operations.h for the contract of each; the
// edge edits are in edge_operations.cpp.
#include "hedge/core/face_operations.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <type_traits>
#include <vector>

#include "hedge/core/refusal.h"
#include "operations_internal.h"
#include "slot_marks.h"

namespace hedge {

using namespace operations_detail;

namespace {

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
// v at a boundary half-edge. `out` is v's clockwise outgoing list from before the removal; `alive`
// is scratch. Returns false if v was left with no edge.
bool relink_vertex(Mesh& m, Vertex v, std::span<const Halfedge> out, std::vector<Halfedge>& alive) {
  alive.clear();
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
    if (owner != v) {
      m.set_vertex(Mesh::twin(o), owner);
      if (m.face(o).is_valid())
        m.mark_changed(m.face(o), ChangeEvent::faces_changed | ChangeEvent::vertices_added);
    }
    const bool fan_ends = m.is_boundary(alive[(i + 1) % k]);
    if (fan_ends) m.set_next(Mesh::twin(o), alive[start]);
  }
  return true;
}

// The vertices remove_faces_impl() lists, once each (core_private/slot_marks.h).
struct RemoveFacesTag;

// Removes a set of faces (sorted, unique, live). Vertices left pinched get one copy per fan.
void remove_faces_impl(Mesh& m, const std::vector<Face>& faces) {
  // The faces' vertices, sorted: each listed once (a flag per vertex slot, kept by the thread and
  // cleared after), so that only the distinct ones are sorted.
  std::vector<Vertex> verts;
  {
    detail::SlotMarks<Vertex, RemoveFacesTag> listed(m.vertex_slots());
    for (Face f : faces)
      for (Vertex v : m.vertices(f)) listed.mark(v);
    verts = listed.marked();
  }
  std::sort(verts.begin(), verts.end());
  // The vertices' outgoing lists, one after another: vertex i's are out[first[i], first[i + 1]).
  std::vector<Halfedge> out;
  out.reserve(6 * verts.size());
  std::vector<std::size_t> first;
  first.reserve(verts.size() + 1);
  for (Vertex v : verts) {
    first.push_back(out.size());
    for (Halfedge h : m.halfedges(v)) out.push_back(h);
  }
  first.push_back(out.size());

  std::vector<Halfedge> hs;
  hs.reserve(3 * faces.size());
  for (Face f : faces) {
    for (Halfedge h : m.halfedges(f)) hs.push_back(h);
    m.mark_deleted(f);
  }
  for (Halfedge h : hs) m.set_face(h, Face());
  for (Halfedge h : hs)
    if (m.is_boundary(Mesh::twin(h))) m.mark_deleted(Mesh::edge(h));
  for (Face f : faces) m.mark_changed(f, ChangeEvent::faces_removed);
  std::vector<Halfedge> alive;
  for (std::size_t i = 0; i < verts.size(); ++i) {
    const std::span<const Halfedge> around(out.data() + first[i], first[i + 1] - first[i]);
    if (!relink_vertex(m, verts[i], around, alive)) {
      m.mark_deleted(verts[i]);
      m.mark_changed(verts[i], ChangeEvent::vertices_removed);
    }
  }
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

}  // namespace

// ---------------------------------------------------------------------------------------------
bool can_split_face(const SurfaceMesh& m, Face f) { return split_face_refusal(m, f) == nullptr; }

const char* split_face_refusal(const SurfaceMesh& m, Face f) {
  return m.is_live(f) ? nullptr : refusal_text(Refusal::face_not_live);
}

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
  // add_vertex() stores the position; `point` may refer into the position array it may move.
  const Vertex v = m.add_vertex(point);
  m.vertex_properties().interpolate(v.idx(), corner_v.data(), w.data(), n, m.positions().array());

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
  mark_split(m, v);
  return v;
}

bool can_cut_face(const SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  return cut_face_refusal(m, h0, h1) == nullptr;
}

const char* cut_face_refusal(const SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  if (!m.is_live(h0) || !m.is_live(h1)) return refusal_text(Refusal::cut_halfedge_not_live);
  if (h0 == h1) return refusal_text(Refusal::cut_same_halfedge);
  const Face f = m.face(h0);
  if (!f.is_valid()) return refusal_text(Refusal::cut_on_boundary);
  if (m.face(h1) != f) return refusal_text(Refusal::cut_different_faces);
  if (m.next(h0) == h1 || m.next(h1) == h0) return refusal_text(Refusal::cut_neighbour_targets);
  if (m.find_halfedge(m.to_vertex(h0), m.to_vertex(h1)).is_valid())
    return refusal_text(Refusal::cut_targets_joined);
  return nullptr;
}

Halfedge cut_face(SurfaceMesh& m, Halfedge h0, Halfedge h1) {
  if (!can_cut_face(m, h0, h1)) return {};
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
  m.mark_changed(f);
  m.mark_changed(g, ChangeEvent::faces_added);
  m.changes().notify();
  return n;
}

template <typename T>
VecN<T, 3> face_centroid(const SurfaceMesh& m, Face f) {
  Vec3d c{0, 0, 0};
  std::size_t n = 0;
  for (Vertex v : m.vertices(f)) {
    c += to_double(m.position(v));
    ++n;
  }
  if (n) c = c / double(n);
  if constexpr (std::is_same_v<T, double>)
    return c;
  else
    return to_float(c);
}
template Vec3 face_centroid<float>(const SurfaceMesh&, Face);
template Vec3d face_centroid<double>(const SurfaceMesh&, Face);

// ---------------------------------------------------------------------------------------------
namespace {
struct AddPlan {
  std::vector<Halfedge> existing;  // existing[i]: v_i -> v_{i+1}, or invalid
};

// add_face_refusal(), planning the face's existing edges into `plan` when it is allowed.
const char* plan_add_face(const Mesh& m, std::span<const Vertex> vs, AddPlan& plan) {
  const std::size_t n = vs.size();
  if (n < 3) return refusal_text(Refusal::add_face_too_few_corners);
  for (std::size_t i = 0; i < n; ++i) {
    if (!m.is_live(vs[i])) return refusal_text(Refusal::add_face_corner_not_live);
    for (std::size_t j = i + 1; j < n; ++j)
      if (vs[i] == vs[j]) return refusal_text(Refusal::add_face_corner_repeated);
  }
  plan.existing.assign(n, Halfedge());
  for (std::size_t i = 0; i < n; ++i) {
    const Halfedge h = m.find_halfedge(vs[i], vs[(i + 1) % n]);
    if (h.is_valid() && !m.is_boundary(h)) return refusal_text(Refusal::add_face_edge_taken);
    plan.existing[i] = h;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex v = vs[i];
    if (m.is_isolated(v)) continue;
    if (!m.is_boundary(v)) return refusal_text(Refusal::add_face_interior_corner);
    const Halfedge in = plan.existing[(i + n - 1) % n], out = plan.existing[i];
    if (!in.is_valid() && !out.is_valid()) return refusal_text(Refusal::add_face_second_gap);
  }
  return nullptr;
}
}  // namespace

bool can_add_face(const SurfaceMesh& m, std::span<const Vertex> vs) {
  return add_face_refusal(m, vs) == nullptr;
}

const char* add_face_refusal(const SurfaceMesh& m, std::span<const Vertex> vertices) {
  AddPlan plan;
  return plan_add_face(m, vertices, plan);
}

Face add_face(SurfaceMesh& m, std::span<const Vertex> vs) {
  AddPlan plan;
  if (plan_add_face(m, vs, plan) != nullptr) return {};
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
  m.mark_changed(f, ChangeEvent::faces_added);
  m.changes().notify();
  return f;
}

// ---------------------------------------------------------------------------------------------
bool can_remove_face(const SurfaceMesh& m, Face f) { return remove_face_refusal(m, f) == nullptr; }

const char* remove_face_refusal(const SurfaceMesh& m, Face f) {
  if (!m.is_live(f)) return refusal_text(Refusal::face_not_live);
  for (Vertex v : m.vertices(f))
    if (gaps_after(m, v, [&](Face g) { return g == f; }) > 1)
      return refusal_text(Refusal::remove_face_pinches);
  return nullptr;
}

bool remove_face(SurfaceMesh& m, Face f) {
  if (!can_remove_face(m, f)) return false;
  remove_faces_impl(m, {f});
  m.changes().notify();
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

bool can_remove_vertex(const SurfaceMesh& m, Vertex v) { return remove_vertex_refusal(m, v) == nullptr; }

const char* remove_vertex_refusal(const SurfaceMesh& m, Vertex v) {
  if (!m.is_live(v)) return refusal_text(Refusal::vertex_not_live);
  const std::vector<Face> fs = faces_of(m, v);
  auto removed = [&](Face g) { return std::binary_search(fs.begin(), fs.end(), g); };
  // Every corner of the removed faces is affected, not only v's neighbours (polygons).
  for (Face f : fs)
    for (Vertex w : m.vertices(f))
      if (w != v && gaps_after(m, w, removed) > 1) return refusal_text(Refusal::remove_vertex_pinches);
  return nullptr;
}

bool remove_vertex(SurfaceMesh& m, Vertex v) {
  if (!can_remove_vertex(m, v)) return false;
  const std::vector<Face> fs = faces_of(m, v);
  // An isolated vertex (or one with only dangling edges, impossible in a valid mesh) has no faces.
  if (!fs.empty()) remove_faces_impl(m, fs);
  if (!m.is_deleted(v)) {
    m.set_halfedge(v, Halfedge());
    m.mark_deleted(v);
    m.mark_changed(v, ChangeEvent::vertices_removed);
  }
  m.changes().notify();
  return true;
}

void remove_faces(SurfaceMesh& m, std::span<const Face> faces_in) {
  std::vector<Face> faces;
  for (Face f : faces_in)
    if (m.is_live(f)) faces.push_back(f);
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  remove_faces_impl(m, faces);
  m.changes().notify();
}

}  // namespace hedge

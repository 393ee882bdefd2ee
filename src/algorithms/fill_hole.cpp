// Hole filling. See include/hedge/algorithms/fill_hole.h for the contract.
#include "hedge/algorithms/fill_hole.h"

#include <cmath>

#include "hedge/core/face_operations.h"
#include "hedge/core/refusal.h"

namespace hedge {

bool can_fill_hole(const SurfaceMesh& m, Halfedge h) { return fill_hole_refusal(m, h) == nullptr; }

const char* fill_hole_refusal(const SurfaceMesh& m, Halfedge h) {
  if (!m.is_live(h)) return refusal_text(Refusal::halfedge_not_live);
  if (!m.is_boundary(h)) return refusal_text(Refusal::fill_hole_not_boundary);
  std::size_t n = 0;
  for ([[maybe_unused]] Halfedge g : m.loop(h))
    if (++n > m.halfedge_slots()) return refusal_text(Refusal::fill_hole_loop_damaged);
  if (n < 3) return refusal_text(Refusal::fill_hole_loop_too_short);
  return nullptr;
}

std::vector<Face> fill_hole(SurfaceMesh& m, Halfedge h) {
  if (!can_fill_hole(m, h)) return {};
  std::vector<Halfedge> loop;
  for (Halfedge g : m.loop(h)) loop.push_back(g);
  m.changes().begin();  // one notification for the whole fill
  const Face f = m.new_face();
  m.mark_changed(f, ChangeEvent::faces_added);
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
      if (!can_cut_face(m, h0, h1)) continue;
      const Vec3d d = to_double(m.position(m.to_vertex(h0))) - to_double(m.position(m.to_vertex(h1)));
      const double len = dot(d, d);
      if (len < best) {
        best = len;
        best0 = h0;
        best1 = h1;
      }
    }
    if (!best0.is_valid()) break;
    const Halfedge n = cut_face(m, best0, best1);
    rest = m.face(n);
    faces.push_back(rest);
  }
  m.changes().commit();
  return faces;
}

}  // namespace hedge

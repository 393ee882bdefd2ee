#include "edits/random_edits.h"

#include <algorithm>

#include "hedge/algorithms/fill_hole.h"
#include "hedge/core/operations.h"

namespace hedge {

const char* edit_name(EditKind k) {
  // In the order of EditKind.
  static constexpr const char* kNames[kEditKinds] = {
      "split_edge", "collapse", "flip", "split_face", "cut_face", "remove_face", "remove_vertex"};
  const auto i = static_cast<std::size_t>(k);
  return i < kEditKinds ? kNames[i] : "?";
}

std::size_t RandomEditReport::total_applied() const {
  std::size_t n = 0;
  for (auto a : applied) n += a;
  return n;
}
std::size_t RandomEditReport::total_refused() const {
  std::size_t n = 0;
  for (auto r : refused) n += r;
  return n;
}

namespace {

// std::mt19937_64's output is specified, its distributions are not: draws use its raw output, so a
// seed gives the same sequence on every platform.
std::uint64_t below(std::mt19937_64& g, std::uint64_t n) { return n == 0 ? 0 : g() % n; }
float unit(std::mt19937_64& g) { return static_cast<float>(g() >> 40) / static_cast<float>(1ull << 24); }

long long euler(const SurfaceMesh& m) {
  return static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
         static_cast<long long>(m.n_faces());
}

template <typename H>
H pick(const SurfaceMesh& m, std::mt19937_64& rng, std::size_t size) {
  for (int tries = 0; tries < 64; ++tries) {
    H h(static_cast<Index>(below(rng, size)));
    if (!m.is_deleted(h)) return h;
  }
  return H();
}

}  // namespace

RandomEditor::RandomEditor(SurfaceMesh& mesh, std::uint64_t seed)
    : mesh_(&mesh), rng_(seed), start_faces_(std::max<std::size_t>(mesh.n_faces(), 4)) {}

RandomEditor::Step RandomEditor::step() {
  SurfaceMesh& m = *mesh_;
  auto& rng = rng_;
  Step out;
  if (m.n_faces() == 0) return out;
  // Steer the size: grow while small, shrink while large.
  const std::uint64_t r = below(rng, 100);
  EditKind kind;
  if (m.n_faces() > 4 * start_faces_)
    kind = r < 70 ? EditKind::collapse : EditKind::flip;
  else if (m.n_faces() < start_faces_ / 4)
    kind = r < 50 ? EditKind::split_edge : EditKind::split_face;
  else
    kind = static_cast<EditKind>(below(rng, kEditKinds));
  out.kind = kind;
  const long long chi = euler(m);
  bool applied = false;
  bool check_euler = true;
  switch (kind) {
    case EditKind::split_edge: {
      Edge e = pick<Edge>(m, rng, m.edge_slots());
      if (!e.is_valid()) break;
      Vec3 a = m.position(m.vertex(e, 0)), b = m.position(m.vertex(e, 1));
      float s = unit(rng);
      applied = split_edge(m, e, a + (b - a) * s).is_valid();
      break;
    }
    case EditKind::collapse: {
      Halfedge h = pick<Halfedge>(m, rng, m.halfedge_slots());
      if (!h.is_valid()) break;
      applied = collapse(m, h).is_valid();
      break;
    }
    case EditKind::flip: {
      Edge e = pick<Edge>(m, rng, m.edge_slots());
      if (!e.is_valid()) break;
      applied = flip(m, e).is_valid();
      break;
    }
    case EditKind::split_face: {
      Face f = pick<Face>(m, rng, m.face_slots());
      if (!f.is_valid()) break;
      applied = split_face(m, f, face_centroid(m, f)).is_valid();
      break;
    }
    case EditKind::cut_face: {
      Face f = pick<Face>(m, rng, m.face_slots());
      if (!f.is_valid()) break;
      std::vector<Halfedge> hs;
      for (Halfedge h : m.halfedges(f)) hs.push_back(h);
      Halfedge h0 = hs[below(rng, hs.size())], h1 = hs[below(rng, hs.size())];
      applied = cut_face(m, h0, h1).is_valid();
      break;
    }
    case EditKind::remove_face: {
      Face f = pick<Face>(m, rng, m.face_slots());
      if (!f.is_valid()) break;
      std::vector<Vertex> corners;
      for (Vertex v : m.vertices(f)) corners.push_back(v);
      if (!remove_face(m, f)) break;
      applied = true;
      // Put it back where the corners survived; then nothing has changed topologically.
      check_euler = add_face(m, corners).is_valid();
      break;
    }
    case EditKind::remove_vertex: {
      Vertex v = pick<Vertex>(m, rng, m.vertex_slots());
      if (!v.is_valid() || m.is_boundary(v)) break;  // interior only: the hole is then one loop
      Halfedge ring = m.halfedge(v);
      if (!ring.is_valid()) break;
      Halfedge outer = m.next(ring);  // an edge of the ring, which becomes the hole's boundary
      if (!remove_vertex(m, v)) break;
      applied = true;
      check_euler = false;
      if (!m.is_deleted(outer) && m.is_boundary(outer)) fill_hole(m, outer);
      break;
    }
    case EditKind::count:
      break;
  }
  out.applied = applied;
  out.euler_kept = !(applied && check_euler && euler(m) != chi);
  return out;
}

RandomEditReport random_edits(SurfaceMesh& m, const RandomEditOptions& opt) {
  RandomEditReport rep;
  RandomEditor editor(m, opt.seed);
  for (std::size_t op = 0; op < opt.operations; ++op) {
    if (m.n_faces() == 0) break;
    const RandomEditor::Step s = editor.step();
    const std::size_t k = static_cast<std::size_t>(s.kind);
    if (s.applied)
      ++rep.applied[k];
    else
      ++rep.refused[k];
    if (!s.euler_kept) ++rep.euler_mismatches;
    if (opt.collect_every && (op + 1) % opt.collect_every == 0) m.garbage_collection();
    if (opt.validate_every && (op + 1) % opt.validate_every == 0) {
      auto problems = m.validate();
      if (!problems.empty()) {
        rep.valid = false;
        rep.first_invalid_operation = op;
        rep.first_invalid_kind = s.kind;
        rep.problems = std::move(problems);
        return rep;
      }
    }
  }
  // The last operation was checked in the loop already when validate_every divides the count.
  if (opt.validate_every && opt.operations % opt.validate_every == 0) return rep;
  auto problems = m.validate();
  if (!problems.empty()) {
    rep.valid = false;
    rep.first_invalid_operation = opt.operations;
    rep.problems = std::move(problems);
  }
  return rep;
}

}  // namespace hedge

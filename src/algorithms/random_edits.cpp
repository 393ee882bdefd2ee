#include "hedge/algorithms/random_edits.h"

#include <algorithm>
#include <random>

#include "hedge/algorithms/fill_hole.h"
#include "hedge/core/operations.h"

namespace hedge {

const char* edit_name(EditKind k) {
  switch (k) {
    case EditKind::split_edge: return "split_edge";
    case EditKind::collapse: return "collapse";
    case EditKind::flip: return "flip";
    case EditKind::split_face: return "split_face";
    case EditKind::cut_face: return "cut_face";
    case EditKind::remove_face: return "remove_face";
    case EditKind::remove_vertex: return "remove_vertex";
    case EditKind::count: break;
  }
  return "?";
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

// A small, portable generator (std::mt19937_64's output is specified; its distributions are not).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : g_() % n; }
  float unit() { return static_cast<float>(g_() >> 40) / static_cast<float>(1ull << 24); }

 private:
  std::mt19937_64 g_;
};

long long euler(const SurfaceMesh& m) {
  return static_cast<long long>(m.n_vertices()) - static_cast<long long>(m.n_edges()) +
         static_cast<long long>(m.n_faces());
}

template <typename H>
H pick(const SurfaceMesh& m, Rng& rng, std::size_t size) {
  for (int tries = 0; tries < 64; ++tries) {
    H h(static_cast<Index>(rng.below(size)));
    if (!m.is_deleted(h)) return h;
  }
  return H();
}

}  // namespace

RandomEditReport random_edits(SurfaceMesh& m, const RandomEditOptions& opt) {
  RandomEditReport rep;
  Rng rng(opt.seed);
  const std::size_t start_faces = std::max<std::size_t>(m.n_faces(), 4);
  for (std::size_t op = 0; op < opt.operations; ++op) {
    if (m.n_faces() == 0) break;
    // Steer the size: grow while small, shrink while large.
    std::uint64_t r = rng.below(100);
    EditKind kind;
    if (m.n_faces() > 4 * start_faces) kind = r < 70 ? EditKind::collapse : EditKind::flip;
    else if (m.n_faces() < start_faces / 4) kind = r < 50 ? EditKind::split_edge : EditKind::split_face;
    else kind = static_cast<EditKind>(rng.below(kEditKinds));
    const long long chi = euler(m);
    bool applied = false;
    bool check_euler = true;
    switch (kind) {
      case EditKind::split_edge: {
        Edge e = pick<Edge>(m, rng, m.edge_slots());
        if (!e.is_valid()) break;
        Vec3 a = m.position(m.vertex(e, 0)), b = m.position(m.vertex(e, 1));
        float s = rng.unit();
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
        Halfedge h0 = hs[rng.below(hs.size())], h1 = hs[rng.below(hs.size())];
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
      case EditKind::count: break;
    }
    const std::size_t k = static_cast<std::size_t>(kind);
    if (applied) ++rep.applied[k];
    else ++rep.refused[k];
    if (applied && check_euler && euler(m) != chi) ++rep.euler_mismatches;
    if (opt.collect_every && (op + 1) % opt.collect_every == 0) m.garbage_collection();
    if (opt.validate_every && (op + 1) % opt.validate_every == 0) {
      auto problems = m.validate();
      if (!problems.empty()) {
        rep.valid = false;
        rep.first_invalid_operation = op;
        rep.first_invalid_kind = kind;
        rep.problems = std::move(problems);
        return rep;
      }
    }
  }
  // The last operation was checked in the loop already when validate_every divides the count.
  const bool checked_last = opt.validate_every && opt.operations % opt.validate_every == 0;
  if (!opt.validate_at_end || checked_last) return rep;
  auto problems = m.validate();
  if (!problems.empty()) {
    rep.valid = false;
    rep.first_invalid_operation = opt.operations;
    rep.problems = std::move(problems);
  }
  return rep;
}

}  // namespace hedge

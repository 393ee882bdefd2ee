// build(): index buffers -> SurfaceMesh in O(n).
//
// Twins are found without hashing: every corner's edge is bucketed by its smaller vertex (a
// counting sort), and each bucket, a handful of entries long, is sorted by the larger vertex.
// Equal neighbours in a bucket are the corners sharing an undirected edge.
//
// Clean input takes one pass of each step. Defects switch on the repair steps (re-orientation,
// cutting non-manifold edges, splitting vertex fans) or, under the strict policy, an error that
// names the offending input elements.
#include "hedge/core/build.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "hedge/error.h"

namespace hedge {

namespace {

constexpr std::size_t kMaxNamed = 8;  // offending elements named in one error message
constexpr Index kReversed = 0x80000000u;  // edge-run entry flag: the corner's edge runs from larger to smaller vertex

// Corner arrays of the faces being built, after welding and cleaning.
struct Faces {
  std::vector<Index> corners;       // vertex of each corner
  std::vector<Index> start;         // #F + 1 offsets into corners
  std::vector<Index> face_origin;   // face -> input face
  std::vector<Index> corner_origin; // corner -> input corner

  Index size() const { return static_cast<Index>(start.size() - 1); }
  Index next_corner(Index c, Index f) const { return c + 1 == start[f + 1] ? start[f] : c + 1; }
};

// The corners of each undirected edge, grouped: entries[run_start[i] .. run_start[i+1]).
struct EdgeRuns {
  std::vector<Index> entries;
  std::vector<Index> run_start;
  Index runs() const { return static_cast<Index>(run_start.size() - 1); }
};

std::string list_str(const std::vector<std::string>& items, std::size_t total) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? "; " : "") + items[i];
  if (total > items.size()) s += "; and " + std::to_string(total - items.size()) + " more";
  return s;
}

}  // namespace

//! The builder's input: spans, so that build_triangles() need not copy the caller's arrays.
struct BuildInput {
  std::span<const Vec3> positions;
  std::span<const Index> indices;
  std::span<const Index> face_sizes;
  std::span<const Vec2> texcoords;
  std::span<const Index> texcoord_indices;
  std::span<const Vec3> normals;
  std::span<const Index> normal_indices;
  std::size_t face_count() const { return face_sizes.empty() ? indices.size() / 3 : face_sizes.size(); }
};

// Friend of SurfaceMesh: writes its arrays directly.
class MeshBuilder {
 public:
  MeshBuilder(const BuildInput& in, const BuildOptions& opt, BuildReport& rep) : in_(in), opt_(opt), rep_(rep) {}
  SurfaceMesh run();

 private:
  void check_input() const;
  void weld();
  void clean_faces();
  EdgeRuns group_edges(Index n_vertices) const;
  bool classify(const EdgeRuns& runs, bool repair);
  void reorient(const EdgeRuns& runs);
  void link(SurfaceMesh& m);
  void split_fans(SurfaceMesh& m);
  void link_boundaries(SurfaceMesh& m);
  void attach_attributes(SurfaceMesh& m) const;

  //! The corner after c in its face (finds the face by binary search: for error paths only).
  Index next_corner(Index c) const {
    Index f = static_cast<Index>(std::upper_bound(f_.start.begin(), f_.start.end(), c) - f_.start.begin()) - 1;
    return f_.next_corner(c, f);
  }
  //! The input vertex a welded vertex came from (its first occurrence).
  Index input_vertex(Index v) const { return weld_first_.empty() ? v : weld_first_[v]; }

  const BuildInput& in_;
  const BuildOptions& opt_;
  BuildReport& rep_;

  std::vector<Vec3> positions_;        // after welding
  std::vector<Index> weld_map_;        // input vertex -> welded vertex (empty: identity)
  Faces f_;
  // Pairing result: corner -> its half-edge; edges are numbered in emission order.
  std::vector<Halfedge> corner_he_;
  Index n_edges_ = 0;
  std::vector<Index> vertex_origin_;   // added vertex (from #V on) -> welded vertex it was split from
  std::vector<Index> weld_first_;      // welded vertex -> first input vertex (empty: identity)
  std::string problems_;               // strict-mode description of the defects found
  std::vector<Index> bad_vertices_;    // strict-mode offending input vertices
};


void MeshBuilder::check_input() const {
  const std::size_t nv = in_.positions.size();
  if (nv >= kInvalidIndex) throw InvalidInputError("too many vertices for 32-bit indices");
  for (std::size_t i = 0; i < nv; ++i)
    if (!is_finite(in_.positions[i]))
      throw InvalidInputError("vertex " + std::to_string(i) + " has a non-finite coordinate");
  if (in_.face_sizes.empty()) {
    if (in_.indices.size() % 3 != 0)
      throw InvalidInputError("triangle index count " + std::to_string(in_.indices.size()) +
                              " is not a multiple of 3");
  } else {
    std::size_t sum = 0;
    for (auto s : in_.face_sizes) sum += s;
    if (sum != in_.indices.size())
      throw InvalidInputError("face sizes add up to " + std::to_string(sum) + " corners but there are " +
                              std::to_string(in_.indices.size()) + " indices");
  }
  if (in_.indices.size() >= kInvalidIndex / 2) throw InvalidInputError("too many corners for 32-bit indices");
  for (std::size_t c = 0; c < in_.indices.size(); ++c)
    if (in_.indices[c] >= nv)
      throw InvalidInputError("corner " + std::to_string(c) + " refers to vertex " + std::to_string(in_.indices[c]) +
                              " but there are " + std::to_string(nv) + " vertices");
  auto check_pool = [&](std::span<const Index> idx, std::size_t pool, const char* what) {
    if (idx.empty()) return;
    if (idx.size() != in_.indices.size())
      throw InvalidInputError(std::string(what) + " index count differs from the corner count");
    for (std::size_t c = 0; c < idx.size(); ++c)
      if (idx[c] >= pool)
        throw InvalidInputError("corner " + std::to_string(c) + " refers to " + what + " " + std::to_string(idx[c]) +
                                " but there are " + std::to_string(pool));
  };
  check_pool(in_.texcoord_indices, in_.texcoords.size(), "texcoord");
  check_pool(in_.normal_indices, in_.normals.size(), "normal");
}

void MeshBuilder::weld() {
  if (opt_.weld == Weld::none) return;  // positions_ stays empty: the input's are used
  weld_map_ = weld_positions(in_.positions, opt_.weld, opt_.weld_epsilon, positions_);
  rep_.welded_vertices = in_.positions.size() - positions_.size();
  weld_first_.assign(positions_.size(), kInvalidIndex);
  for (Index i = static_cast<Index>(weld_map_.size()); i-- > 0;) weld_first_[weld_map_[i]] = i;
}

void MeshBuilder::clean_faces() {
  const bool tri = in_.face_sizes.empty();
  const std::size_t nf = in_.face_count();
  auto vert = [&](std::size_t c) { return weld_map_.empty() ? in_.indices[c] : weld_map_[in_.indices[c]]; };

  f_.corners.clear();
  f_.corners.reserve(in_.indices.size());
  f_.start.clear();
  f_.start.reserve(nf + 1);
  f_.start.push_back(0);
  f_.face_origin.clear();
  f_.corner_origin.clear();
  bool changed = false;
  std::vector<std::string> named;
  std::size_t bad = 0;
  std::vector<Index> face;  // scratch for one polygon
  std::vector<Index> origin;

  std::size_t c0 = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t n = tri ? 3 : in_.face_sizes[f];
    face.clear();
    origin.clear();
    for (std::size_t k = 0; k < n; ++k) {
      Index v = vert(c0 + k);
      if (!face.empty() && face.back() == v) continue;  // consecutive repeat
      face.push_back(v);
      origin.push_back(static_cast<Index>(c0 + k));
    }
    while (face.size() > 1 && face.front() == face.back()) {
      face.pop_back();
      origin.pop_back();
    }
    std::size_t repeated = n - face.size();
    bool degenerate = face.size() < 3;
    if (!degenerate) {
      // Any other repeat pinches the face into two loops: it has no disk to fill.
      if (face.size() <= 16) {
        for (std::size_t i = 0; i < face.size() && !degenerate; ++i)
          for (std::size_t j = i + 1; j < face.size(); ++j)
            if (face[i] == face[j]) { degenerate = true; break; }
      } else {
        std::vector<Index> sorted = face;
        std::sort(sorted.begin(), sorted.end());
        degenerate = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      }
    }
    if (degenerate || repeated > 0) {
      changed = true;
      if (opt_.policy == TopologyPolicy::strict) {
        ++bad;
        if (named.size() < kMaxNamed) named.push_back("face " + std::to_string(f) + " repeats a vertex or has fewer than 3 corners");
      }
    }
    if (degenerate) {
      ++rep_.degenerate_faces;
    } else {
      rep_.repeated_corners += repeated;
      if (changed && f_.corner_origin.empty()) {
        // First change: materialise the identity origins of the faces kept so far.
        f_.corner_origin.resize(f_.corners.size());
        for (std::size_t i = 0; i < f_.corners.size(); ++i) f_.corner_origin[i] = static_cast<Index>(i);
        f_.face_origin.resize(f_.start.size() - 1);
        for (std::size_t i = 0; i + 1 < f_.start.size(); ++i) f_.face_origin[i] = static_cast<Index>(i);
      }
      f_.corners.insert(f_.corners.end(), face.begin(), face.end());
      if (!f_.corner_origin.empty()) {
        f_.corner_origin.insert(f_.corner_origin.end(), origin.begin(), origin.end());
        f_.face_origin.push_back(static_cast<Index>(f));
      }
      f_.start.push_back(static_cast<Index>(f_.corners.size()));
    }
    c0 += n;
  }
  if (bad > 0)
    throw TopologyError("degenerate faces: " + list_str(named, bad), {}, {});
}

EdgeRuns MeshBuilder::group_edges(Index nv) const {
  const Index nc = static_cast<Index>(f_.corners.size());
  EdgeRuns r;
  // Counting sort of corners by the smaller vertex of their edge.
  std::vector<Index> offset(static_cast<std::size_t>(nv) + 1, 0);
  for (Index f = 0; f < f_.size(); ++f)
    for (Index c = f_.start[f]; c < f_.start[f + 1]; ++c) {
      Index a = f_.corners[c], b = f_.corners[f_.next_corner(c, f)];
      ++offset[std::min(a, b) + 1];
    }
  for (Index v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  r.entries.resize(nc);
  std::vector<Index> hi(nc);  // larger vertex of each entry's edge, parallel to entries
  {
    std::vector<Index> fill(offset.begin(), offset.end() - 1);
    for (Index f = 0; f < f_.size(); ++f)
      for (Index c = f_.start[f]; c < f_.start[f + 1]; ++c) {
        Index a = f_.corners[c], b = f_.corners[f_.next_corner(c, f)];
        Index slot = fill[std::min(a, b)]++;
        r.entries[slot] = c | (a > b ? kReversed : 0u);
        hi[slot] = std::max(a, b);
      }
  }
  // Sort each bucket by (larger vertex, corner); buckets are short, so insertion sort.
  r.run_start.reserve(nc / 2 + 2);
  for (Index v = 0; v < nv; ++v) {
    const Index b = offset[v], e = offset[v + 1];
    if (e - b > 32) {
      std::vector<std::pair<Index, Index>> tmp;
      for (Index i = b; i < e; ++i) tmp.emplace_back(hi[i], r.entries[i]);
      std::sort(tmp.begin(), tmp.end());
      for (Index i = b; i < e; ++i) std::tie(hi[i], r.entries[i]) = tmp[i - b];
    } else {
      for (Index i = b + 1; i < e; ++i) {
        Index kh = hi[i], kc = r.entries[i], j = i;
        while (j > b && (hi[j - 1] > kh || (hi[j - 1] == kh && r.entries[j - 1] > kc))) {
          hi[j] = hi[j - 1];
          r.entries[j] = r.entries[j - 1];
          --j;
        }
        hi[j] = kh;
        r.entries[j] = kc;
      }
    }
    for (Index i = b; i < e; ++i)
      if (i == b || hi[i] != hi[i - 1]) r.run_start.push_back(i);
  }
  r.run_start.push_back(nc);
  return r;
}

bool MeshBuilder::classify(const EdgeRuns& runs, bool repair) {
  corner_he_.assign(f_.corners.size(), Halfedge());
  n_edges_ = 0;
  std::vector<std::string> named;
  std::size_t bad = 0;
  auto emit = [&](Index c1, Index c2) {
    corner_he_[c1] = Halfedge(2 * n_edges_);
    if (c2 != kInvalidIndex) corner_he_[c2] = Halfedge(2 * n_edges_ + 1);
    ++n_edges_;
  };
  auto corner_of = [](Index entry) { return entry & ~kReversed; };
  auto reversed = [](Index entry) { return (entry & kReversed) != 0; };
  for (Index r = 0; r < runs.runs(); ++r) {
    const Index b = runs.run_start[r], k = runs.run_start[r + 1] - b;
    const Index* e = runs.entries.data() + b;
    if (k == 1) {
      emit(corner_of(e[0]), kInvalidIndex);
      continue;
    }
    if (k == 2 && reversed(e[0]) != reversed(e[1])) {
      emit(corner_of(e[0]), corner_of(e[1]));
      continue;
    }
    if (!repair) {
      ++bad;
      if (named.size() < kMaxNamed) {
        Index c = corner_of(e[0]);
        Index a = f_.corners[c];
        std::string what = k == 2 ? "two faces traverse the edge in the same direction"
                                  : std::to_string(k) + " faces share the edge";
        Index bv = f_.corners[next_corner(c)];
        named.push_back("edge " + std::to_string(input_vertex(a)) + "-" + std::to_string(input_vertex(bv)) + ": " + what);
        bad_vertices_.push_back(input_vertex(a));
        bad_vertices_.push_back(input_vertex(bv));
      }
      continue;
    }
    // Repair: keep one consistently oriented pair if there is one, cut the rest apart.
    ++rep_.non_manifold_edges;
    Index fwd = kInvalidIndex, bwd = kInvalidIndex;
    for (Index i = 0; i < k; ++i) {
      if (!reversed(e[i]) && fwd == kInvalidIndex) fwd = i;
      if (reversed(e[i]) && bwd == kInvalidIndex) bwd = i;
    }
    const bool pair = fwd != kInvalidIndex && bwd != kInvalidIndex;
    if (pair) emit(corner_of(e[fwd]), corner_of(e[bwd]));
    for (Index i = 0; i < k; ++i)
      if (!pair || (i != fwd && i != bwd)) emit(corner_of(e[i]), kInvalidIndex);
  }
  if (bad > 0) {
    problems_ = "non-manifold or inconsistently oriented edges (input vertex pairs): " + list_str(named, bad);
    return false;
  }
  return true;
}

void MeshBuilder::reorient(const EdgeRuns& runs) {
  const Index nf = f_.size();
  std::vector<Index> corner_face(f_.corners.size());
  for (Index f = 0; f < nf; ++f)
    for (Index c = f_.start[f]; c < f_.start[f + 1]; ++c) corner_face[c] = f;

  // Face graph over edges with exactly two faces; `same` marks neighbours that traverse the
  // shared edge in the same direction, i.e. that disagree in orientation.
  std::vector<Index> deg(static_cast<std::size_t>(nf) + 1, 0);
  for (Index r = 0; r < runs.runs(); ++r)
    if (runs.run_start[r + 1] - runs.run_start[r] == 2) {
      const Index* e = runs.entries.data() + runs.run_start[r];
      ++deg[corner_face[e[0] & ~kReversed] + 1];
      ++deg[corner_face[e[1] & ~kReversed] + 1];
    }
  for (Index f = 0; f < nf; ++f) deg[f + 1] += deg[f];
  std::vector<Index> adj(deg[nf]);
  std::vector<std::uint8_t> same(deg[nf]);
  {
    std::vector<Index> fill(deg.begin(), deg.end() - 1);
    for (Index r = 0; r < runs.runs(); ++r)
      if (runs.run_start[r + 1] - runs.run_start[r] == 2) {
        const Index* e = runs.entries.data() + runs.run_start[r];
        Index f0 = corner_face[e[0] & ~kReversed], f1 = corner_face[e[1] & ~kReversed];
        std::uint8_t s = ((e[0] ^ e[1]) & kReversed) == 0;
        adj[fill[f0]] = f1; same[fill[f0]++] = s;
        adj[fill[f1]] = f0; same[fill[f1]++] = s;
      }
  }
  // Breadth-first 2-colouring; a component keeps the orientation of most of its faces.
  std::vector<std::int8_t> flip(nf, -1);
  std::vector<Index> queue;
  for (Index seed = 0; seed < nf; ++seed) {
    if (flip[seed] >= 0) continue;
    queue.clear();
    queue.push_back(seed);
    flip[seed] = 0;
    std::size_t flipped = 0;
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      Index f = queue[qi];
      for (Index i = deg[f]; i < deg[f + 1]; ++i) {
        Index g = adj[i];
        if (flip[g] >= 0) continue;  // a disagreement here is a non-orientable cut
        flip[g] = static_cast<std::int8_t>(flip[f] ^ same[i]);
        flipped += flip[g];
        queue.push_back(g);
      }
    }
    if (2 * flipped > queue.size())
      for (Index f : queue) flip[f] ^= 1;
  }
  for (Index f = 0; f < nf; ++f) {
    if (flip[f] != 1) continue;
    if (f_.corner_origin.empty()) {
      f_.corner_origin.resize(f_.corners.size());
      for (std::size_t i = 0; i < f_.corners.size(); ++i) f_.corner_origin[i] = static_cast<Index>(i);
    }
    // Reversed after the first corner, so the face keeps its first corner.
    std::reverse(f_.corners.begin() + f_.start[f] + 1, f_.corners.begin() + f_.start[f + 1]);
    std::reverse(f_.corner_origin.begin() + f_.start[f] + 1, f_.corner_origin.begin() + f_.start[f + 1]);
    ++rep_.reoriented_faces;
  }
}

void MeshBuilder::link(SurfaceMesh& m) {
  const Index nv = static_cast<Index>(positions_.empty() ? in_.positions.size() : positions_.size());
  const Index nf = f_.size();
  m.resize(nv, n_edges_, nf);
  if (positions_.empty()) std::copy(in_.positions.begin(), in_.positions.end(), m.positions_.vector().begin());
  else std::copy(positions_.begin(), positions_.end(), m.positions_.vector().begin());

  Vertex* to = m.h_vertex_.data();
  Halfedge* nx = m.h_next_.data();
  Face* fc = m.h_face_.data();
  Halfedge* vh = m.v_halfedge_.data();
  const Index* cv = f_.corners.data();
  const Halfedge* che = corner_he_.data();
  for (Index f = 0; f < nf; ++f) {
    const Index b = f_.start[f], e = f_.start[f + 1];
    for (Index c = b; c < e; ++c) {
      const Index cn = c + 1 == e ? b : c + 1;
      const Index h = che[c].idx();
      to[h] = Vertex(cv[cn]);
      nx[h] = che[cn];
      fc[h] = Face(f);
      to[h ^ 1u] = Vertex(cv[c]);  // overwritten by the twin's corner when the edge is interior
      vh[cv[c]] = che[c];
    }
    m.f_halfedge_[f] = che[e - 1];
  }
}

void MeshBuilder::split_fans(SurfaceMesh& m) {
  const Index nv0 = static_cast<Index>(m.vertices_size());
  std::vector<std::uint8_t> seen(m.halfedges_size(), 0);
  std::vector<std::uint8_t> has_fan(nv0, 0);
  std::vector<Halfedge> fan;
  std::vector<std::string> named;
  std::size_t bad = 0;
  std::vector<std::uint8_t> counted(nv0, 0);

  auto prev_in_face = [&](Halfedge h) {
    Halfedge p = h;
    for (Halfedge n = m.next(p); n != h; n = m.next(n)) p = n;
    return p;
  };
  for (Index c = 0; c < corner_he_.size(); ++c) {
    const Halfedge h = corner_he_[c];
    if (seen[h.idx()]) continue;
    const Vertex v(f_.corners[c]);
    fan.clear();
    // Clockwise from h until the fan closes or a boundary gap is reached.
    Halfedge k = h;
    bool open = false;
    for (;;) {
      seen[k.idx()] = 1;
      fan.push_back(k);
      Halfedge t = SurfaceMesh::twin(k);
      if (m.is_boundary(t)) { open = true; break; }
      k = m.next(t);
      if (k == h) break;
    }
    Halfedge start = h;
    if (open) {
      // Counter-clockwise from h to the other gap: that is where the fan starts.
      for (;;) {
        Halfedge t = SurfaceMesh::twin(prev_in_face(start));
        if (m.is_boundary(t)) break;
        start = t;
        seen[start.idx()] = 1;
        fan.push_back(start);
      }
    }
    Vertex owner = v;
    if (has_fan[v.idx()]) {
      if (opt_.policy == TopologyPolicy::strict) {
        if (!counted[v.idx()]) {
          counted[v.idx()] = 1;
          ++bad;
          bad_vertices_.push_back(input_vertex(v.idx()));
          if (named.size() < kMaxNamed) named.push_back("vertex " + std::to_string(input_vertex(v.idx())));
        }
        continue;
      }
      if (!counted[v.idx()]) {
        counted[v.idx()] = 1;
        ++rep_.non_manifold_vertices;
      }
      owner = m.add_vertex(m.position(v));
      ++rep_.duplicated_vertices;
      vertex_origin_.push_back(v.idx());
      for (Halfedge g : fan) {
        m.set_vertex(prev_in_face(g), owner);
        Halfedge t = SurfaceMesh::twin(g);
        if (m.is_boundary(t)) m.set_vertex(t, owner);
      }
      // A boundary half-edge leaving the fan's start also starts at the new vertex: its twin is
      // prev(start), renamed above.
    }
    has_fan[v.idx()] = 1;
    m.set_halfedge(owner, open ? SurfaceMesh::twin(prev_in_face(start)) : start);
  }
  if (bad > 0) {
    if (!problems_.empty()) problems_ += "; ";
    problems_ += "non-manifold vertices (their faces form several fans): " + list_str(named, bad);
  }
}

void MeshBuilder::link_boundaries(SurfaceMesh& m) {
  // Every vertex now has one fan, so its half-edge is its only outgoing boundary half-edge.
  for (Index c = 0; c < corner_he_.size(); ++c) {
    Halfedge b = SurfaceMesh::twin(corner_he_[c]);
    if (m.is_boundary(b)) m.set_next(b, m.halfedge(m.to_vertex(b)));
  }
}

void MeshBuilder::attach_attributes(SurfaceMesh& m) const {
  if (!opt_.corner_attributes) return;
  auto origin = [&](Index c) { return f_.corner_origin.empty() ? c : f_.corner_origin[c]; };
  // The attribute of corner c (vertex c of face f) is stored on the half-edge entering it: the
  // half-edge of the corner before c.
  auto each_corner = [&](auto&& fn) {
    for (Index f = 0; f < f_.size(); ++f) {
      const Index b = f_.start[f], e = f_.start[f + 1];
      for (Index c = b; c < e; ++c) fn(c, corner_he_[c == b ? e - 1 : c - 1]);
    }
  };
  if (!in_.texcoord_indices.empty()) {
    auto uv = m.halfedge_property<Vec2>("h:texcoord");
    each_corner([&](Index c, Halfedge h) { uv[h] = in_.texcoords[in_.texcoord_indices[origin(c)]]; });
  }
  if (!in_.normal_indices.empty()) {
    auto nrm = m.halfedge_property<Vec3>("h:normal");
    each_corner([&](Index c, Halfedge h) { nrm[h] = in_.normals[in_.normal_indices[origin(c)]]; });
  }
}

SurfaceMesh MeshBuilder::run() {
  check_input();
  weld();
  clean_faces();
  const Index nv = static_cast<Index>(positions_.empty() ? in_.positions.size() : positions_.size());
  EdgeRuns runs = group_edges(nv);
  if (!classify(runs, false)) {
    if (opt_.policy == TopologyPolicy::strict) throw TopologyError(problems_, bad_vertices_);
    problems_.clear();
    bad_vertices_.clear();
    reorient(runs);
    runs = group_edges(nv);
    classify(runs, true);
  }
  runs = EdgeRuns{};

  SurfaceMesh m;
  link(m);
  split_fans(m);
  if (!problems_.empty()) throw TopologyError(problems_, bad_vertices_);
  link_boundaries(m);
  for (Vertex v : m.vertices())
    if (m.is_isolated(v)) ++rep_.isolated_vertices;
  attach_attributes(m);
  if (rep_.duplicated_vertices > 0) m.shrink_to_fit();

  // Maps for the caller.
  const std::size_t n_in = in_.positions.size();
  rep_.vertex_map.resize(n_in);
  for (std::size_t i = 0; i < n_in; ++i) rep_.vertex_map[i] = weld_map_.empty() ? Index(i) : weld_map_[i];
  rep_.vertex_origin.resize(m.vertices_size());
  for (Index v = 0; v < nv; ++v) rep_.vertex_origin[v] = input_vertex(v);
  for (std::size_t i = 0; i < vertex_origin_.size(); ++i) rep_.vertex_origin[nv + i] = input_vertex(vertex_origin_[i]);
  rep_.face_map.assign(in_.face_count(), kInvalidIndex);
  for (Index f = 0; f < f_.size(); ++f) rep_.face_map[f_.face_origin.empty() ? f : f_.face_origin[f]] = f;
  return m;
}

SurfaceMesh build(const IndexedMesh& input, const BuildOptions& options, BuildReport* report) {
  BuildInput view{input.positions, input.indices, input.face_sizes, input.texcoords,
                  input.texcoord_indices, input.normals, input.normal_indices};
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  rep = BuildReport{};
  return MeshBuilder(view, options, rep).run();
}

SurfaceMesh build_triangles(std::span<const Vec3> positions, std::span<const std::uint32_t> triangles,
                            const BuildOptions& options, BuildReport* report) {
  BuildInput view{positions, triangles, {}, {}, {}, {}, {}};
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  rep = BuildReport{};
  return MeshBuilder(view, options, rep).run();
}

}  // namespace hedge

// build(): index buffers -> SurfaceMesh in O(n).
//
// Twins are found without hashing: every corner's edge is bucketed by its smaller vertex (a
// counting sort), and each bucket, a handful of entries long, is sorted by the larger vertex.
// Equal neighbours in a bucket are the corners sharing an undirected edge. Edges are then
// numbered in corner order, so a face's half-edges sit together in memory, as a scan of the
// input would visit them.
//
// Clean input takes one pass of each step and copies nothing it need not. Defects switch on the
// repair steps (re-orientation, cutting non-manifold edges, splitting vertex fans) or, under the
// strict policy, an error that names the offending input elements.
#include "hedge/core/build.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "hedge/error.h"

namespace hedge {

namespace {

constexpr std::size_t kMaxNamed = 8;        // offending elements named in one error message
constexpr Index kReversed = 0x80000000u;    // corner flag: its edge runs from larger to smaller vertex
constexpr Index kNoPartner = 0x7fffffffu;   // a corner whose edge has no twin corner: a boundary edge
constexpr Index kNumbered = 0x80000000u;    // pairing slot already holds a half-edge index

std::string list_str(const std::vector<std::string>& items, std::size_t total) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? "; " : "") + items[i];
  if (total > items.size()) s += "; and " + std::to_string(total - items.size()) + " more";
  return s;
}

// The faces being built: the caller's triangle indices as they are, or cleaned copies.
struct Faces {
  std::span<const Index> corners;    // vertex of each corner
  std::vector<Index> own_corners;    // storage when corners had to be rewritten
  std::vector<Index> start;          // #F + 1 offsets; empty for triangles
  std::vector<Index> face_origin;    // face -> input face (empty: identity)
  std::vector<Index> corner_origin;  // corner -> input corner (empty: identity)
  Index n_faces = 0;

  bool triangles() const { return start.empty(); }
  Index begin(Index f) const { return triangles() ? 3 * f : start[f]; }
  Index end(Index f) const { return triangles() ? 3 * f + 3 : start[f + 1]; }
  Index n_corners() const { return static_cast<Index>(corners.size()); }
  //! The face of corner c (binary search on polygons: for error and repair paths).
  Index face_of(Index c) const {
    if (triangles()) return c / 3;
    return static_cast<Index>(std::upper_bound(start.begin(), start.end(), c) - start.begin()) - 1;
  }
  Index next_corner(Index c) const {
    Index f = face_of(c);
    return c + 1 == end(f) ? begin(f) : c + 1;
  }
  void materialise_origins() {
    if (!corner_origin.empty()) return;
    corner_origin.resize(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) corner_origin[i] = static_cast<Index>(i);
  }
};

// Calls fn(c, next corner, face) for every corner; specialised for triangles.
template <typename Fn>
void for_each_corner(const Faces& F, Fn&& fn) {
  if (F.triangles()) {
    for (Index f = 0, c = 0; f < F.n_faces; ++f, c += 3) {
      fn(c, c + 1, f);
      fn(c + 1, c + 2, f);
      fn(c + 2, c, f);
    }
  } else {
    for (Index f = 0; f < F.n_faces; ++f) {
      const Index b = F.start[f], e = F.start[f + 1];
      for (Index c = b; c + 1 < e; ++c) fn(c, c + 1, f);
      fn(e - 1, b, f);
    }
  }
}

// Corners grouped by undirected edge: bucket v holds keys[offset[v] .. offset[v+1]), each key
// (larger vertex << 32 | corner | kReversed-if-reversed), sorted; a run of equal larger vertices
// is one undirected edge.
struct EdgeGroups {
  std::vector<Index> offset;
  std::vector<std::uint64_t> keys;

  template <typename Fn>
  void for_each_run(Fn&& fn) const {
    const Index nv = static_cast<Index>(offset.size() - 1);
    for (Index v = 0; v < nv; ++v) {
      Index i = offset[v];
      const Index e = offset[v + 1];
      while (i < e) {
        Index j = i + 1;
        while (j < e && (keys[j] >> 32) == (keys[i] >> 32)) ++j;
        fn(keys.data() + i, j - i);
        i = j;
      }
    }
  }
};

Index entry_corner(std::uint64_t key) { return static_cast<Index>(key) & ~kReversed; }
bool entry_reversed(std::uint64_t key) { return (static_cast<Index>(key) & kReversed) != 0; }

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
  void clean_faces_general();
  EdgeGroups group_edges() const;
  bool pair_corners(const EdgeGroups& groups, bool repair);
  void number_edges();
  void reorient(const EdgeGroups& groups);
  void link(SurfaceMesh& m);
  bool fans_are_simple(SurfaceMesh& m);
  void split_fans(SurfaceMesh& m);
  void link_boundaries(SurfaceMesh& m);
  void attach_attributes(SurfaceMesh& m) const;

  Index n_vertices() const {
    return static_cast<Index>(positions_.empty() ? in_.positions.size() : positions_.size());
  }
  //! The input vertex a welded vertex came from (its first occurrence).
  Index input_vertex(Index v) const { return weld_first_.empty() ? v : weld_first_[v]; }

  const BuildInput& in_;
  const BuildOptions& opt_;
  BuildReport& rep_;

  std::vector<Vec3> positions_;        // after welding (empty: the input's are used)
  std::vector<Index> weld_map_;        // input vertex -> welded vertex (empty: identity)
  std::vector<Index> weld_first_;      // welded vertex -> first input vertex (empty: identity)
  Faces f_;
  // Per corner: first its partner corner (or kNoPartner), then, after number_edges(), its half-edge.
  std::vector<Index> corner_he_;
  std::vector<Index> boundary_corners_;  // corners whose edge has no twin corner
  std::vector<Index> corner_count_;    // corners per vertex
  Index n_edges_ = 0;
  std::vector<Index> vertex_origin_;   // added vertex (from #V on) -> welded vertex it was split from
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
  const std::size_t nf = in_.face_count();
  f_.n_faces = static_cast<Index>(nf);
  if (in_.face_sizes.empty() && weld_map_.empty()) {
    // Fast path: the caller's triangles, used in place unless one of them is degenerate.
    const Index* t = in_.indices.data();
    bool clean = true;
    for (std::size_t i = 0; i < 3 * nf; i += 3)
      clean &= (t[i] != t[i + 1]) & (t[i + 1] != t[i + 2]) & (t[i + 2] != t[i]);
    if (clean) {
      f_.corners = in_.indices;
      return;
    }
  }
  clean_faces_general();
}

void MeshBuilder::clean_faces_general() {
  const bool tri = in_.face_sizes.empty();
  const std::size_t nf = in_.face_count();
  auto vert = [&](std::size_t c) { return weld_map_.empty() ? in_.indices[c] : weld_map_[in_.indices[c]]; };

  f_.own_corners.clear();
  f_.own_corners.reserve(in_.indices.size());
  f_.start.assign(1, 0);
  f_.start.reserve(nf + 1);
  f_.face_origin.clear();
  f_.corner_origin.clear();
  f_.corner_origin.reserve(in_.indices.size());
  std::vector<std::string> named;
  std::size_t bad = 0;
  std::vector<Index> face, origin;  // scratch for one polygon

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
    const std::size_t repeated = n - face.size();
    bool degenerate = face.size() < 3;
    if (!degenerate) {
      // Any other repeat pinches the face into two loops: it has no disk to fill.
      if (face.size() <= 16) {
        for (std::size_t i = 0; i < face.size() && !degenerate; ++i)
          for (std::size_t j = i + 1; j < face.size() && !degenerate; ++j) degenerate = face[i] == face[j];
      } else {
        std::vector<Index> sorted = face;
        std::sort(sorted.begin(), sorted.end());
        degenerate = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
      }
    }
    if ((degenerate || repeated > 0) && opt_.policy == TopologyPolicy::strict) {
      ++bad;
      if (named.size() < kMaxNamed)
        named.push_back("face " + std::to_string(f) + " repeats a vertex or has fewer than 3 corners");
    }
    if (degenerate) {
      ++rep_.degenerate_faces;
    } else {
      rep_.repeated_corners += repeated;
      f_.own_corners.insert(f_.own_corners.end(), face.begin(), face.end());
      f_.corner_origin.insert(f_.corner_origin.end(), origin.begin(), origin.end());
      f_.face_origin.push_back(static_cast<Index>(f));
      f_.start.push_back(static_cast<Index>(f_.own_corners.size()));
    }
    c0 += n;
  }
  if (bad > 0) throw TopologyError("degenerate faces: " + list_str(named, bad));
  f_.corners = f_.own_corners;
  f_.n_faces = static_cast<Index>(f_.start.size() - 1);
}

EdgeGroups MeshBuilder::group_edges() const {
  const Index nv = n_vertices();
  const Index* cv = f_.corners.data();
  EdgeGroups g;
  // Counting sort of corners by the smaller vertex of their edge.
  g.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
  Index* off = g.offset.data();
  for_each_corner(f_, [&](Index c, Index cn, Index) { ++off[std::min(cv[c], cv[cn]) + 1]; });
  for (Index v = 0; v < nv; ++v) off[v + 1] += off[v];
  g.keys.resize(f_.n_corners());
  {
    std::vector<Index> fill(g.offset.begin(), g.offset.end() - 1);
    std::uint64_t* keys = g.keys.data();
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      const Index a = cv[c], b = cv[cn];
      const Index lo = a < b ? a : b, hi = a < b ? b : a;
      keys[fill[lo]++] = (std::uint64_t(hi) << 32) | c | (a > b ? kReversed : 0u);
    });
  }
  // Buckets are a handful of keys long: insertion sort, or a real sort at a high-valence vertex.
  std::uint64_t* keys = g.keys.data();
  for (Index v = 0; v < nv; ++v) {
    const Index b = off[v], e = off[v + 1];
    if (e - b > 32) {
      std::sort(keys + b, keys + e);
      continue;
    }
    for (Index i = b + 1; i < e; ++i) {
      const std::uint64_t k = keys[i];
      Index j = i;
      for (; j > b && keys[j - 1] > k; --j) keys[j] = keys[j - 1];
      keys[j] = k;
    }
  }
  return g;
}

bool MeshBuilder::pair_corners(const EdgeGroups& groups, bool repair) {
  corner_he_.assign(f_.n_corners(), kNoPartner);
  Index* partner = corner_he_.data();
  std::vector<std::string> named;
  std::size_t bad = 0;
  groups.for_each_run([&](const std::uint64_t* e, Index k) {
    if (k == 1) return;  // a boundary edge
    if (k == 2 && entry_reversed(e[0]) != entry_reversed(e[1])) {
      partner[entry_corner(e[0])] = entry_corner(e[1]);
      partner[entry_corner(e[1])] = entry_corner(e[0]);
      return;
    }
    if (!repair) {
      ++bad;
      const Index a = static_cast<Index>(e[0] >> 32);
      const Index c = entry_corner(e[0]);
      const Index b = f_.corners[c] == a ? f_.corners[f_.next_corner(c)] : f_.corners[c];
      if (named.size() < kMaxNamed) {
        std::string what = k == 2 ? "two faces traverse the edge in the same direction"
                                  : std::to_string(k) + " faces share the edge";
        named.push_back("edge " + std::to_string(input_vertex(b)) + "-" + std::to_string(input_vertex(a)) + ": " + what);
        bad_vertices_.push_back(input_vertex(b));
        bad_vertices_.push_back(input_vertex(a));
      }
      return;
    }
    // Repair: keep one consistently oriented pair if there is one; the rest become boundary.
    ++rep_.non_manifold_edges;
    Index fwd = kInvalidIndex, bwd = kInvalidIndex;
    for (Index i = 0; i < k; ++i) {
      if (!entry_reversed(e[i]) && fwd == kInvalidIndex) fwd = i;
      if (entry_reversed(e[i]) && bwd == kInvalidIndex) bwd = i;
    }
    if (fwd != kInvalidIndex && bwd != kInvalidIndex) {
      partner[entry_corner(e[fwd])] = entry_corner(e[bwd]);
      partner[entry_corner(e[bwd])] = entry_corner(e[fwd]);
    }
  });
  if (bad > 0) {
    problems_ = "non-manifold or inconsistently oriented edges (input vertex pairs): " + list_str(named, bad);
    return false;
  }
  return true;
}

void MeshBuilder::number_edges() {
  // Edge e is made when its first corner comes up; the partner corner gets half-edge 2e + 1.
  Index* slot = corner_he_.data();
  const Index nc = f_.n_corners();
  Index e = 0;
  boundary_corners_.clear();
  for (Index c = 0; c < nc; ++c) {
    const Index p = slot[c];
    if (p & kNumbered) continue;
    slot[c] = (2 * e) | kNumbered;
    if (p == kNoPartner) boundary_corners_.push_back(c);
    else slot[p] = (2 * e + 1) | kNumbered;
    ++e;
  }
  for (Index c = 0; c < nc; ++c) slot[c] &= ~kNumbered;
  n_edges_ = e;
}

void MeshBuilder::reorient(const EdgeGroups& groups) {
  const Index nf = f_.n_faces;
  // Face graph over edges with exactly two faces; `same` marks neighbours that traverse the
  // shared edge in the same direction, i.e. that disagree in orientation.
  std::vector<Index> deg(static_cast<std::size_t>(nf) + 1, 0);
  groups.for_each_run([&](const std::uint64_t* e, Index k) {
    if (k != 2) return;
    ++deg[f_.face_of(entry_corner(e[0])) + 1];
    ++deg[f_.face_of(entry_corner(e[1])) + 1];
  });
  for (Index f = 0; f < nf; ++f) deg[f + 1] += deg[f];
  std::vector<Index> adj(deg[nf]);
  std::vector<std::uint8_t> same(deg[nf]);
  {
    std::vector<Index> fill(deg.begin(), deg.end() - 1);
    groups.for_each_run([&](const std::uint64_t* e, Index k) {
      if (k != 2) return;
      const Index f0 = f_.face_of(entry_corner(e[0])), f1 = f_.face_of(entry_corner(e[1]));
      const std::uint8_t s = entry_reversed(e[0]) == entry_reversed(e[1]);
      adj[fill[f0]] = f1;
      same[fill[f0]++] = s;
      adj[fill[f1]] = f0;
      same[fill[f1]++] = s;
    });
  }
  // Breadth-first 2-colouring; a component keeps the orientation of most of its faces.
  std::vector<std::int8_t> flip(nf, -1);
  std::vector<Index> queue;
  for (Index seed = 0; seed < nf; ++seed) {
    if (flip[seed] >= 0) continue;
    queue.assign(1, seed);
    flip[seed] = 0;
    std::size_t flipped = 0;
    for (std::size_t qi = 0; qi < queue.size(); ++qi) {
      const Index f = queue[qi];
      for (Index i = deg[f]; i < deg[f + 1]; ++i) {
        const Index g = adj[i];
        if (flip[g] >= 0) continue;  // a disagreement here is a non-orientable cut
        flip[g] = static_cast<std::int8_t>(flip[f] ^ same[i]);
        flipped += static_cast<std::size_t>(flip[g]);
        queue.push_back(g);
      }
    }
    if (2 * flipped > queue.size())
      for (Index f : queue) flip[f] ^= 1;
  }
  for (Index f = 0; f < nf; ++f) {
    if (flip[f] != 1) continue;
    if (f_.own_corners.empty()) {
      f_.own_corners.assign(f_.corners.begin(), f_.corners.end());
      f_.corners = f_.own_corners;
    }
    f_.materialise_origins();
    // Reversed after the first corner, so the face keeps its first corner.
    std::reverse(f_.own_corners.begin() + f_.begin(f) + 1, f_.own_corners.begin() + f_.end(f));
    std::reverse(f_.corner_origin.begin() + f_.begin(f) + 1, f_.corner_origin.begin() + f_.end(f));
    ++rep_.reoriented_faces;
  }
}

void MeshBuilder::link(SurfaceMesh& m) {
  const Index nv = n_vertices();
  m.resize(nv, n_edges_, f_.n_faces);
  auto& pos = m.positions_.vector();
  if (positions_.empty()) std::copy(in_.positions.begin(), in_.positions.end(), pos.begin());
  else std::copy(positions_.begin(), positions_.end(), pos.begin());

  Vertex* to = m.h_vertex_.data();
  Halfedge* nx = m.h_next_.data();
  Face* fc = m.h_face_.data();
  Halfedge* vh = m.v_halfedge_.data();
  Halfedge* fh = m.f_halfedge_.data();
  const Index* cv = f_.corners.data();
  const Index* che = corner_he_.data();
  corner_count_.assign(nv, 0);
  Index* count = corner_count_.data();
  for_each_corner(f_, [&](Index c, Index cn, Index f) {
    const Index h = che[c];
    to[h] = Vertex(cv[cn]);
    nx[h] = Halfedge(che[cn]);
    fc[h] = Face(f);
    vh[cv[c]] = Halfedge(h);
    ++count[cv[c]];
    if (cn < c) fh[f] = Halfedge(h);  // the last corner's half-edge enters the first corner
  });
  // A boundary half-edge points back to the origin of its twin's corner.
  for (Index c : boundary_corners_) to[che[c] ^ 1u] = Vertex(cv[c]);
}

namespace {
// The half-edge before h in its face: h is an interior half-edge of a face that is fully linked.
Halfedge prev_in_face(const SurfaceMesh& m, Halfedge h) {
  Halfedge p = h;
  for (Halfedge n = m.next(p); n != h; n = m.next(n)) p = n;
  return p;
}
}  // namespace

bool MeshBuilder::fans_are_simple(SurfaceMesh& m) {
  // Rotate about each vertex from its half-edge; a vertex is manifold when one fan holds all its
  // corners. Open fans are completed counter-clockwise, and the vertex takes the boundary
  // half-edge at their start, as the invariant asks.
  const Index nv = static_cast<Index>(m.vertices_size());
  bool simple = true;
  for (Index vi = 0; vi < nv; ++vi) {
    const Index expected = corner_count_[vi];
    if (expected == 0) {
      ++rep_.isolated_vertices;
      continue;
    }
    const Halfedge h0 = m.halfedge(Vertex(vi));
    Index seen = 0;
    Halfedge k = h0;
    bool open = false;
    do {
      ++seen;
      const Halfedge t = SurfaceMesh::twin(k);
      if (m.is_boundary(t)) {
        open = true;
        break;
      }
      k = m.next(t);
    } while (k != h0 && seen <= expected);
    if (open) {
      Halfedge s = h0;
      for (;;) {
        const Halfedge t = SurfaceMesh::twin(prev_in_face(m, s));
        if (m.is_boundary(t)) {
          m.set_halfedge(Vertex(vi), t);
          break;
        }
        s = t;
        if (++seen > expected) break;
      }
    }
    simple &= seen == expected;
  }
  return simple;
}

void MeshBuilder::split_fans(SurfaceMesh& m) {
  const Index nv0 = static_cast<Index>(m.vertices_size());
  std::vector<std::uint8_t> seen(m.halfedges_size(), 0);
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
        const Halfedge t = SurfaceMesh::twin(prev_in_face(m, start));
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
        m.set_vertex(prev_in_face(m, g), owner);
        const Halfedge t = SurfaceMesh::twin(g);
        if (m.is_boundary(t)) m.set_vertex(t, owner);
      }
    }
    has_fan[v.idx()] = 1;
    m.set_halfedge(owner, open ? SurfaceMesh::twin(prev_in_face(m, start)) : start);
  }
  if (bad > 0 && opt_.policy == TopologyPolicy::strict) {
    if (!problems_.empty()) problems_ += "; ";
    problems_ += "non-manifold vertices (their faces form several fans): " + list_str(named, bad);
  }
}

void MeshBuilder::link_boundaries(SurfaceMesh& m) {
  // Every vertex now has one fan, so its half-edge is its only outgoing boundary half-edge.
  for (Index c : boundary_corners_) {
    const Halfedge b(corner_he_[c] ^ 1u);
    m.set_next(b, m.halfedge(m.to_vertex(b)));
  }
}

void MeshBuilder::attach_attributes(SurfaceMesh& m) const {
  if (!opt_.corner_attributes) return;
  auto origin = [&](Index c) { return f_.corner_origin.empty() ? c : f_.corner_origin[c]; };
  // The attribute of corner cn (a vertex of face f) is stored on the half-edge entering it: the
  // half-edge of the corner before it.
  if (!in_.texcoord_indices.empty()) {
    auto uv = m.halfedge_property<Vec2>("h:texcoord");
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      uv[Halfedge(corner_he_[c])] = in_.texcoords[in_.texcoord_indices[origin(cn)]];
    });
  }
  if (!in_.normal_indices.empty()) {
    auto nrm = m.halfedge_property<Vec3>("h:normal");
    for_each_corner(f_, [&](Index c, Index cn, Index) {
      nrm[Halfedge(corner_he_[c])] = in_.normals[in_.normal_indices[origin(cn)]];
    });
  }
}

SurfaceMesh MeshBuilder::run() {
  check_input();
  weld();
  clean_faces();
  {
    EdgeGroups groups = group_edges();
    if (!pair_corners(groups, false)) {
      if (opt_.policy == TopologyPolicy::strict) throw TopologyError(problems_, bad_vertices_);
      problems_.clear();
      bad_vertices_.clear();
      reorient(groups);
      groups = group_edges();
      pair_corners(groups, true);
    }
  }
  number_edges();

  SurfaceMesh m;
  link(m);
  if (!fans_are_simple(m)) {
    split_fans(m);
    if (!problems_.empty()) throw TopologyError(problems_, bad_vertices_);
  }
  link_boundaries(m);
  attach_attributes(m);
  if (rep_.duplicated_vertices > 0) m.shrink_to_fit();

  // Maps for the caller.
  const Index nv = n_vertices();
  const std::size_t n_in = in_.positions.size();
  rep_.vertex_map.resize(n_in);
  for (std::size_t i = 0; i < n_in; ++i) rep_.vertex_map[i] = weld_map_.empty() ? Index(i) : weld_map_[i];
  rep_.vertex_origin.resize(m.vertices_size());
  for (Index v = 0; v < nv; ++v) rep_.vertex_origin[v] = input_vertex(v);
  for (std::size_t i = 0; i < vertex_origin_.size(); ++i) rep_.vertex_origin[nv + i] = input_vertex(vertex_origin_[i]);
  rep_.face_map.assign(in_.face_count(), kInvalidIndex);
  for (Index f = 0; f < f_.n_faces; ++f) rep_.face_map[f_.face_origin.empty() ? f : f_.face_origin[f]] = f;
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

// build(): index buffers -> SurfaceMesh in O(n).
//
// Clean input takes two passes over the corners:
//  - pair_fast() finds twins without hashing: each undirected edge lives in a table line of its
//    smaller vertex (one cache line per vertex, scanned with a few SIMD compares), so the second
//    corner of an edge finds the first one there. Edges are numbered as their first corner comes
//    up, so a face's half-edges sit together in memory, as a scan of the input would visit them;
//  - link() writes the mesh arrays from the corners and, on triangles, walks every vertex fan
//    soon after the vertex's last corner is linked, which checks that each vertex is manifold
//    (polygons get a separate pass for that).
// An edge that is not a simple manifold edge, or a degenerate face, sends the pairing to the
// general path (bucketing by smaller vertex, then sorting each bucket), which handles every
// defect: the repair steps (re-orientation, cutting non-manifold edges, splitting vertex fans) or,
// under the strict policy, an error that names the offending input elements.
//
// The large passes are memory-bound on big meshes, hence the software prefetches ahead of the
// scattered accesses and the huge-page advice on the large arrays.
#include "hedge/core/build.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "hedge/error.h"

namespace hedge {

namespace {

// Asks for transparent huge pages on a large, not yet touched block: fewer page faults while it
// is first written, fewer TLB misses in the random-access passes. Advisory only.
void advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  if (bytes < 4 * kHuge) return;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

// v.resize(n), with the storage advised for huge pages before it is first written.
template <typename T>
void sized_vector(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), n * sizeof(T));
  v.resize(n);
}

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

// A per-corner array that is not value-initialised: its passes write every element.
class CornerArray {
 public:
  void resize_for_overwrite(std::size_t n) {
    if (n != size_) {
      data_.reset(new Index[n]);  // default-initialised: no clearing pass
      size_ = n;
    }
    advise_huge_pages(data_.get(), n * sizeof(Index));
  }
  void assign(std::size_t n, Index value) {
    resize_for_overwrite(n);
    std::fill_n(data_.get(), n, value);
  }
  Index* data() { return data_.get(); }
  const Index* data() const { return data_.get(); }
  Index& operator[](std::size_t i) { return data_[i]; }
  Index operator[](std::size_t i) const { return data_[i]; }

 private:
  std::unique_ptr<Index[]> data_;
  std::size_t size_ = 0;
};

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
  //! want_maps: fill the report's vertex and face maps (not needed when the caller passed no report).
  MeshBuilder(const BuildInput& in, const BuildOptions& opt, BuildReport& rep, bool want_maps)
      : in_(in), opt_(opt), rep_(rep), want_maps_(want_maps) {}
  SurfaceMesh run();

 private:
  void check_input() const;
  void weld();
  bool clean_faces();
  bool triangles_are_clean() const;
  void clean_faces_general();
  enum class Paired { ok, degenerate, not_simple };
  Paired pair_fast(bool unchecked);
  template <bool kTriangles>
  Paired pair_fast_impl(bool unchecked);
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
  const bool want_maps_;

  std::vector<Vec3> positions_;        // after welding (empty: the input's are used)
  std::vector<Index> weld_map_;        // input vertex -> welded vertex (empty: identity)
  std::vector<Index> weld_first_;      // welded vertex -> first input vertex (empty: identity)
  Faces f_;
  // Per corner: first its partner corner (or kNoPartner), then, after number_edges(), its half-edge.
  CornerArray corner_he_;
  std::vector<Halfedge> vh_;           // vertex -> half-edge of its last corner (moved into the mesh)
  std::vector<Index> boundary_hes_;    // boundary half-edges, found by fans_are_simple()
  bool fans_checked_ = false;          // link() walked the fans already ...
  bool fans_simple_ = false;           // ... and found one fan at every vertex
  Index n_edges_ = 0;
  std::vector<Index> vertex_origin_;   // added vertex (from #V on) -> welded vertex it was split from
  std::string problems_;               // strict-mode description of the defects found
  std::vector<Index> bad_vertices_;    // strict-mode offending input vertices
};

void MeshBuilder::check_input() const {
  const std::size_t nv = in_.positions.size();
  if (nv >= kInvalidIndex) throw InvalidInputError("too many vertices for 32-bit indices");
  // The scans below test whole blocks without branching (so that they vectorise) and look for the
  // first offending element only in a block that has one.
  constexpr std::size_t kBlock = 1024;
  constexpr auto kMaxCoordinate = std::numeric_limits<decltype(Vec3::x)>::max();  // NaN compares false
  for (std::size_t b = 0; b < nv; b += kBlock) {
    const std::size_t e = std::min(nv, b + kBlock);
    bool finite = true;
    for (std::size_t i = b; i < e; ++i) {
      const Vec3& p = in_.positions[i];
      finite &= (int(std::fabs(p.x) <= kMaxCoordinate) & int(std::fabs(p.y) <= kMaxCoordinate) &
                 int(std::fabs(p.z) <= kMaxCoordinate)) != 0;
    }
    if (finite) continue;
    for (std::size_t i = b; i < e; ++i)
      if (!is_finite(in_.positions[i]))
        throw InvalidInputError("vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
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
  const std::size_t ni = in_.indices.size();
  const Index* corner_vertex = in_.indices.data();
  const Index n_vert = static_cast<Index>(nv);  // 32-bit compares vectorise
  for (std::size_t b = 0; b < ni; b += kBlock) {
    const std::size_t e = std::min(ni, b + kBlock);
    Index out_of_range = 0;
    for (std::size_t c = b; c < e; ++c) out_of_range |= Index(corner_vertex[c] >= n_vert);
    if (!out_of_range) continue;
    for (std::size_t c = b; c < e; ++c)
      if (corner_vertex[c] >= nv)
        throw InvalidInputError("corner " + std::to_string(c) + " refers to vertex " +
                                std::to_string(corner_vertex[c]) + " but there are " + std::to_string(nv) +
                                " vertices");
  }
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

bool MeshBuilder::clean_faces() {
  f_.n_faces = static_cast<Index>(in_.face_count());
  if (in_.face_sizes.empty() && weld_map_.empty()) {
    // Fast path: the caller's triangles, used in place. pair_fast() checks for degenerate ones on
    // the way; triangles_are_clean() does when it cannot.
    f_.corners = in_.indices;
    return true;
  }
  clean_faces_general();
  return false;
}

bool MeshBuilder::triangles_are_clean() const {
  const Index* t = f_.corners.data();
  bool clean = true;
  for (std::size_t i = 0; i < f_.corners.size(); i += 3)
    clean &= (t[i] != t[i + 1]) & (t[i + 1] != t[i + 2]) & (t[i + 2] != t[i]);
  return clean;
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

// Undirected edges seen so far, bucketed by their smaller vertex: one 64-byte line per vertex with
// room for kSlots edges (their larger vertices, then their states), the rest in an overflow map.
// A state is edge << 2 | paired << 1 | reversed (the first corner's edge runs larger -> smaller).
// (A vertex has about three edges to larger vertices on average, rarely more than eight.)
class EdgeTable {
 public:
  static constexpr unsigned kSlots = 8;
  static constexpr std::size_t kLine = 2 * kSlots;  // Index entries per vertex

  explicit EdgeTable(Index nv) : storage_(new Index[kLine * (static_cast<std::size_t>(nv) + 1)]) {
    // Align to 64 bytes (operator new[] gives 16): a vertex's bucket is one cache line.
    auto addr = reinterpret_cast<std::uintptr_t>(storage_.get());
    lines_ = storage_.get() + ((64 - (addr & 63)) & 63) / sizeof(Index);
    advise_huge_pages(lines_, sizeof(Index) * kLine * static_cast<std::size_t>(nv));
    std::memset(lines_, 0, sizeof(Index) * kLine * static_cast<std::size_t>(nv));
  }
  Index* line(Index lo) const { return lines_ + kLine * static_cast<std::size_t>(lo); }
  //! Stores key in slot i (the same value if it is there already). The whole half-line is written,
  //! so that the next scan of this line can take its data from the store in flight.
  static void put_key(Index* line, Index i, Index key) {
#if defined(__SSE2__)
    alignas(16) static constexpr Index kLane[4][4] = {
        {~0u, 0, 0, 0}, {0, ~0u, 0, 0}, {0, 0, ~0u, 0}, {0, 0, 0, ~0u}};
    const __m128i lane = _mm_load_si128(reinterpret_cast<const __m128i*>(kLane[i & 3u]));
    __m128i* half = reinterpret_cast<__m128i*>(line + (i & 4u));
    const __m128i k = _mm_set1_epi32(static_cast<int>(key));
    _mm_store_si128(half, _mm_or_si128(_mm_andnot_si128(lane, _mm_load_si128(half)), _mm_and_si128(lane, k)));
#else
    line[i] = key;
#endif
  }
  //! Bit i (0-7) is set if slot i holds hi, bit 8 + i if slot i is free (a larger vertex is never 0).
  static unsigned scan(const Index* line, Index hi) {
#if defined(__SSE2__)
    const __m128i key = _mm_set1_epi32(static_cast<int>(hi)), zero = _mm_setzero_si128();
    const __m128i a = _mm_load_si128(reinterpret_cast<const __m128i*>(line));
    const __m128i b = _mm_load_si128(reinterpret_cast<const __m128i*>(line + 4));
    const __m128i m = _mm_packs_epi32(_mm_cmpeq_epi32(a, key), _mm_cmpeq_epi32(b, key));
    const __m128i z = _mm_packs_epi32(_mm_cmpeq_epi32(a, zero), _mm_cmpeq_epi32(b, zero));
    return static_cast<unsigned>(_mm_movemask_epi8(_mm_packs_epi16(m, z)));
#else
    unsigned bits = 0;
    for (unsigned i = 0; i < kSlots; ++i)
      bits |= (unsigned(line[i] == hi) << i) | (unsigned(line[i] == 0) << (kSlots + i));
    return bits;
#endif
  }
  //! The state of edge lo-hi in the overflow map (for vertices with more than kSlots edges to
  //! larger vertices), inserted if absent.
  [[gnu::noinline]] Index* overflow(Index lo, Index hi, bool& found) {
    auto [it, inserted] = overflow_.try_emplace((std::uint64_t(lo) << 32) | hi, 0);
    found = !inserted;
    return &it->second;
  }

 private:
  std::unique_ptr<Index[]> storage_;
  Index* lines_ = nullptr;
  std::unordered_map<std::uint64_t, Index> overflow_;
};

}  // namespace

//! unchecked: the faces are the caller's triangles, not yet checked for degenerate ones.
MeshBuilder::Paired MeshBuilder::pair_fast(bool unchecked) {
  // The table takes a line per vertex: worth it when there are more corners than vertices (a
  // closed triangle mesh has about six times more), not for, say, a point cloud with a few faces.
  // The state encoding also limits edge numbers to 30 bits.
  const Index nc = f_.n_corners();
  if (n_vertices() > nc || nc >= (Index(1) << 30))
    return unchecked && !triangles_are_clean() ? Paired::degenerate : Paired::not_simple;
  return f_.triangles() ? pair_fast_impl<true>(unchecked) : pair_fast_impl<false>(unchecked);
}

// Pairs and numbers the corners in one pass, in corner order: a corner whose undirected edge is
// new makes edge e (half-edge 2e), the next corner on that edge takes half-edge 2e + 1. Gives the
// same numbering as group_edges() + pair_corners() + number_edges() on clean input, and gives up,
// leaving the work to them, if an edge is not a simple manifold edge (a second corner of the same
// direction, or a third corner) or a triangle is degenerate. Twins meet in one table line, no
// sorting. Also sets each vertex's half-edge to its last corner's.
template <bool kTriangles>
MeshBuilder::Paired MeshBuilder::pair_fast_impl(bool unchecked) {
  const Index nc = f_.n_corners();
  const Index* cv = f_.corners.data();
  EdgeTable table(n_vertices());
  corner_he_.resize_for_overwrite(nc);
  Index* he = corner_he_.data();
  Index ne = 0;
  Index bad = 0;  // nonzero once an edge has a third corner or two of one direction
  auto visit = [&](Index a, Index b) -> Index {
    const Index lo = a < b ? a : b, hi = a < b ? b : a;
    const Index rev = a > b ? 1u : 0u;
    Index* line = table.line(lo);
    const unsigned mask = EdgeTable::scan(line, hi);
    Index* st;
    Index found;  // all ones if the edge is known
    if (mask != 0) [[likely]] {
      // Branch-free, as whether the edge is new is a coin toss for the branch predictor: the
      // lowest set bit is the slot holding hi if there is one (bits 0-7), else the first free slot.
      const unsigned t = static_cast<unsigned>(std::countr_zero(mask));
      found = Index(0) - Index(t < 8);
      st = line + EdgeTable::kSlots + (t & 7u);
      EdgeTable::put_key(line, t & 7u, hi);
    } else {
      bool known;
      st = table.overflow(lo, hi, known);
      found = known ? ~Index(0) : 0;
    }
    const Index s = *st;                    // 0 for a new edge
    bad |= found & ((s & 3u) ^ rev ^ 1u);  // must be unpaired, and of the other direction
    // A known edge becomes paired (s + 2, as it was unpaired), a new one gets its state; either
    // way the state shifted right is the corner's half-edge: 2e + 1, or 2 ne.
    const Index fresh = (ne << 2) | rev;
    const Index state = s + (fresh ^ ((fresh ^ 2u) & found));
    *st = state;
    ne += 1u + found;  // found is -1 or 0
    return state >> 1;
  };
  // Each vertex takes the half-edge of its last corner (the fan walk fixes boundary vertices).
  vh_.assign(n_vertices(), Halfedge());
  Halfedge* vh = vh_.data();
  if constexpr (kTriangles) {
    // Table lines are fetched kAhead triangles early: on large meshes most lines are not cached.
    // A degenerate triangle (which cannot make the pass go astray) is noted with the other
    // defects; the end of the pass tells them apart.
    constexpr Index kAhead = 3 * 8;
    const Index* t = cv;
    const Index* const end = cv + nc;
    const Index* const last = nc >= 3 ? end - 3 : cv;
    for (Index* out = he; t != end; t += 3, out += 3) {
      const Index* p = t + std::min<std::ptrdiff_t>(kAhead, last - t);
      const Index pa = p[0], pb = p[1], pd = p[2];
      __builtin_prefetch(table.line(pa < pb ? pa : pb), 1);
      __builtin_prefetch(table.line(pb < pd ? pb : pd), 1);
      __builtin_prefetch(table.line(pd < pa ? pd : pa), 1);
      const Index a = t[0], b = t[1], d = t[2];
      bad |= Index((a == b) | (b == d) | (d == a));
      const Index h0 = visit(a, b), h1 = visit(b, d), h2 = visit(d, a);
      out[0] = h0;
      out[1] = h1;
      out[2] = h2;
      vh[a] = Halfedge(h0);
      vh[b] = Halfedge(h1);
      vh[d] = Halfedge(h2);
    }
  } else {
    for (Index f = 0; f < f_.n_faces && !bad; ++f) {
      const Index b = f_.start[f], e = f_.start[f + 1];
      for (Index c = b; c < e; ++c) {
        he[c] = visit(cv[c], cv[c + 1 == e ? b : c + 1]);
        vh[cv[c]] = Halfedge(he[c]);
      }
    }
  }
  n_edges_ = ne;
  if (bad == 0) return Paired::ok;
  vh_.clear();  // the general path numbers the edges again
  // Degenerate faces come first: unless they are ruled out, the faces must be cleaned.
  return unchecked && !triangles_are_clean() ? Paired::degenerate : Paired::not_simple;
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

namespace {
// Walks the fan about a vertex from its outgoing interior half-edge h0, rotating clockwise with
// h -> next(twin(h)): one load a step, as boundary half-edges still have an invalid next. Returns
// the number of corners in the fan. An open fan is completed counter-clockwise from h0; then `vh`
// takes the boundary half-edge at its start, as the invariant asks, and the boundary half-edge
// entering the vertex is appended to `boundary` for link_boundaries().
Index walk_fan(const Halfedge* nx, Index h0, Halfedge& vh, std::vector<Index>& boundary) {
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
  if (positions_.empty()) pos.assign(in_.positions.begin(), in_.positions.end());
  else pos.assign(positions_.begin(), positions_.end());
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
            covered += walk_fan(nx, che[pc], vh[cv[pc]], boundary_hes_);
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

bool MeshBuilder::fans_are_simple(SurfaceMesh& m) {
  // Each walk covers one fan, so every vertex is manifold exactly when the walks cover all corners.
  const Index nv = static_cast<Index>(m.vertex_slots());
  const Halfedge* nx = m.h_next_.data();
  Halfedge* vh = m.v_halfedge_.data();
  boundary_hes_.clear();
  std::size_t covered = 0;
  for (Index v = 0; v < nv; ++v) {
    if (!vh[v].is_valid()) ++rep_.isolated_vertices;
    else covered += walk_fan(nx, vh[v].idx(), vh[v], boundary_hes_);
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
  for (Index b : boundary_hes_) m.set_next(Halfedge(b), m.halfedge(m.to_vertex(Halfedge(b))));
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
  Paired paired = pair_fast(clean_faces());
  if (paired == Paired::degenerate) {
    clean_faces_general();
    paired = pair_fast(false);
  }
  if (paired != Paired::ok) {
    EdgeGroups groups = group_edges();
    if (!pair_corners(groups, false)) {
      if (opt_.policy == TopologyPolicy::strict) throw TopologyError(problems_, bad_vertices_);
      problems_.clear();
      bad_vertices_.clear();
      reorient(groups);
      groups = group_edges();
      pair_corners(groups, true);
    }
    number_edges();
  }

  SurfaceMesh m;
  link(m);
  if (!(fans_checked_ ? fans_simple_ : fans_are_simple(m))) {
    split_fans(m);
    if (!problems_.empty()) throw TopologyError(problems_, bad_vertices_);
    // The walks listed the boundary half-edges of the fans they saw; the split ones need all.
    boundary_hes_.clear();
    for (Index h = 0; h < m.halfedge_slots(); ++h)
      if (m.is_boundary(Halfedge(h))) boundary_hes_.push_back(h);
  }
  link_boundaries(m);
  attach_attributes(m);
  if (rep_.duplicated_vertices > 0) m.shrink_to_fit();
  if (!want_maps_) return m;

  // Maps for the caller.
  const Index nv = n_vertices();
  const std::size_t n_in = in_.positions.size();
  rep_.vertex_map.resize(n_in);
  for (std::size_t i = 0; i < n_in; ++i) rep_.vertex_map[i] = weld_map_.empty() ? Index(i) : weld_map_[i];
  rep_.vertex_origin.resize(m.vertex_slots());
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
  return MeshBuilder(view, options, rep, report != nullptr).run();
}

SurfaceMesh build_triangles(std::span<const Vec3> positions, std::span<const std::uint32_t> triangles,
                            const BuildOptions& options, BuildReport* report) {
  BuildInput view{positions, triangles, {}, {}, {}, {}, {}};
  BuildReport local;
  BuildReport& rep = report ? *report : local;
  rep = BuildReport{};
  return MeshBuilder(view, options, rep, report != nullptr).run();
}

}  // namespace hedge

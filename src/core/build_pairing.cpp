// build(), fast path: pairs the corners of clean input into edges in one pass (see build.cpp),
// and gives up on the first defect, leaving it to the general path (build_repair.cpp).
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <unordered_map>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "build_internal.h"

namespace hedge {

using build_detail::advise_huge_pages;

bool MeshBuilder::triangles_are_clean() const {
  const Index* t = f_.corners.data();
  bool clean = true;
  for (std::size_t i = 0; i < f_.corners.size(); i += 3)
    clean &= (t[i] != t[i + 1]) & (t[i + 1] != t[i + 2]) & (t[i + 2] != t[i]);
  return clean;
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
    const Index s = *st;                   // 0 for a new edge
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

}  // namespace hedge

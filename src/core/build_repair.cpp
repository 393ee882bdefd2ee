// build(), general path: pairs corners by sorting each vertex's bucket of edges, which sees every
// defect. Under the strict policy it names them; under the repair policy it re-orients faces where
// the mesh is orientable and cuts the remaining non-manifold edges apart.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "build_internal.h"

namespace hedge {

using build_detail::EdgeGroups;
using build_detail::entry_corner;
using build_detail::entry_reversed;
using build_detail::for_each_corner;
using build_detail::kMaxNamed;
using build_detail::kNoPartner;
using build_detail::kReversed;
using build_detail::list_str;

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
        named.push_back("edge " + std::to_string(input_vertex(b)) + "-" + std::to_string(input_vertex(a)) +
                        ": " + what);
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

}  // namespace hedge

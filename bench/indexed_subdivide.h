// Indexed triangle meshes the benchmarks make: 1-to-4 midpoint subdivision of an indexed triangle
// mesh, to make meshes of a million triangles and more from the shared ones (texcoords, when
// present, are subdivided per corner the same way, so UV seams stay seams), and a flat plate.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "hedge/core/indexed_mesh.h"

namespace bench {

inline hedge::IndexedMesh subdivide(const hedge::IndexedMesh& in) {
  hedge::IndexedMesh out;
  out.positions = in.positions;
  out.texcoords = in.texcoords;
  const bool uv = !in.texcoord_indices.empty();
  // Each midpoint is shared by the two triangles of its edge: keyed by the sorted index pair.
  auto key = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
  };
  std::unordered_map<std::uint64_t, std::uint32_t> pmid, tmid;
  pmid.reserve(in.indices.size());
  if (uv) tmid.reserve(in.indices.size());
  auto mid = [&](auto& pool, auto& table, std::uint32_t a, std::uint32_t b) {
    auto [it, added] = table.try_emplace(key(a, b), static_cast<std::uint32_t>(pool.size()));
    if (added) pool.push_back((pool[a] + pool[b]) * 0.5f);
    return it->second;
  };
  out.indices.reserve(4 * in.indices.size());
  if (uv) out.texcoord_indices.reserve(4 * in.indices.size());
  for (std::size_t t = 0; t < in.indices.size(); t += 3) {
    const std::uint32_t a = in.indices[t], b = in.indices[t + 1], c = in.indices[t + 2];
    const std::uint32_t ab = mid(out.positions, pmid, a, b), bc = mid(out.positions, pmid, b, c),
                        ca = mid(out.positions, pmid, c, a);
    out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    if (!uv) continue;
    const std::uint32_t ta = in.texcoord_indices[t], tb = in.texcoord_indices[t + 1],
                        tc = in.texcoord_indices[t + 2];
    const std::uint32_t tab = mid(out.texcoords, tmid, ta, tb), tbc = mid(out.texcoords, tmid, tb, tc),
                        tca = mid(out.texcoords, tmid, tc, ta);
    out.texcoord_indices.insert(out.texcoord_indices.end(),
                                {ta, tab, tca, tab, tb, tbc, tca, tbc, tc, tab, tbc, tca});
  }
  return out;
}

//! Subdivides until the mesh has at least `min_faces` triangles; returns the number of rounds.
//! \throw std::invalid_argument for a mesh without faces (which would never get there).
inline int subdivide_until(hedge::IndexedMesh& mesh, std::size_t min_faces) {
  int rounds = 0;
  while (mesh.indices.size() / 3 < min_faces) {
    if (mesh.indices.empty()) throw std::invalid_argument("the mesh has no faces to subdivide");
    mesh = subdivide(mesh);
    ++rounds;
  }
  return rounds;
}

//! A flat n x n grid of triangles in the XY plane: 2 n^2 triangles.
inline hedge::IndexedMesh plate(int n) {
  hedge::IndexedMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.positions.push_back({float(i), float(j), 0.f});
  auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.indices.insert(m.indices.end(),
                       {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1)});
  return m;
}

}  // namespace bench

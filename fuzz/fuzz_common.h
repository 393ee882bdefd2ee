// Shared body of the reader fuzz targets: parse, and when parsing succeeds, check the invariants
// every reader promises and that the writer's output reads back to the same mesh.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "hedge/error.h"
#include "hedge/io/io.h"

namespace hedge::fuzz {

inline void require(bool ok) {
  if (!ok) std::abort();
}

inline void check_invariants(const IndexedMesh& m) {
  std::uint64_t corners = m.face_sizes.empty() ? m.indices.size() : 0;
  for (std::uint32_t n : m.face_sizes) corners += n;
  require(corners == m.indices.size());
  require(!m.face_sizes.empty() || m.indices.size() % 3 == 0);
  for (std::uint32_t i : m.indices) require(i < m.positions.size());
  for (const Vec3& p : m.positions) require(is_finite(p));
  require(m.texcoord_indices.empty() || m.texcoord_indices.size() == m.indices.size());
  require(m.normal_indices.empty() || m.normal_indices.size() == m.indices.size());
  for (std::uint32_t i : m.texcoord_indices) require(i < m.texcoords.size());
  for (std::uint32_t i : m.normal_indices) require(i < m.normals.size());
}

inline bool same_geometry(const IndexedMesh& a, const IndexedMesh& b) {
  return a.positions.size() == b.positions.size() &&
         (a.positions.empty() ||
          std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3)) == 0) &&
         a.indices == b.indices && a.face_sizes == b.face_sizes;
}

inline int run(const std::uint8_t* data, std::size_t size, FileFormat format) {
  IndexedMesh mesh;
  try {
    mesh = read_indexed(std::string_view(reinterpret_cast<const char*>(data), size), format, "fuzz");
  } catch (const Error&) {
    return 0;  // rejecting bad input with hedge's exception is the expected outcome
  }
  check_invariants(mesh);
  // What a reader accepted, its writer must reproduce exactly.
  const IndexedMesh back = read_indexed(write_indexed(mesh, format), format, "fuzz round trip");
  require(same_geometry(mesh, back));
  return 0;
}

}  // namespace hedge::fuzz

// Test support for the readers and writers: bitwise comparison of indexed meshes, the IoError a
// reader throws, and the counts of the shipped data files.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "hedge/core/indexed_mesh.h"
#include "hedge/error.h"

namespace hedge::test {

//! Bitwise equality, so that -0 vs +0 or a changed last bit is caught.
template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

//! Positions, corners, faces, texture coordinates and normals are the same, bit for bit.
inline void expect_same(const IndexedMesh& a, const IndexedMesh& b) {
  EXPECT_TRUE(same_bits(a.positions, b.positions));
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.face_sizes, b.face_sizes);
  EXPECT_TRUE(same_bits(a.texcoords, b.texcoords));
  EXPECT_EQ(a.texcoord_indices, b.texcoord_indices);
  EXPECT_TRUE(same_bits(a.normals, b.normals));
  EXPECT_EQ(a.normal_indices, b.normal_indices);
}

//! Runs `f`, expecting an IoError whose message contains `text`, whose line is `line` and whose
//! path is `path`.
template <typename F>
void expect_io_error(F&& f, const std::string& text, std::uint64_t line, const std::string& path) {
  try {
    f();
    ADD_FAILURE() << "no IoError; expected one containing \"" << text << "\"";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
  }
}

//! What a shipped data file holds, as its description in data/README.md says.
struct FileCounts {
  const char* file;
  std::size_t vertices, faces, corners;
};

inline void expect_counts(const IndexedMesh& m, const FileCounts& c) {
  EXPECT_EQ(m.positions.size(), c.vertices) << c.file;
  EXPECT_EQ(m.face_count(), c.faces) << c.file;
  EXPECT_EQ(m.indices.size(), c.corners) << c.file;
}

}  // namespace hedge::test

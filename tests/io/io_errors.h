// Test support for the readers and writers: the IoError a call throws, for checks of its message
// and place.
#pragma once

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "caught.h"
#include "hedge/core/indexed_mesh.h"
#include "hedge/error.h"
#include "test_meshes.h"

namespace hedge::test {

//! The IoError f() throws; a test failure (and an empty error) when it throws none.
template <typename F>
IoError catch_io_error(F&& f) {
  return caught<IoError>(f, IoError("", 0, -1, ""));
}

//! f() throws an IoError whose message holds `what`; the error, for further checks.
template <typename F>
IoError expect_io_error(F&& f, const std::string& what) {
  IoError e = catch_io_error(f);
  EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  return e;
}

//! write(mesh) must refuse a tetrahedron with a NaN or infinite position, texture coordinate,
//! normal or colour, naming it, rather than write a file hedge cannot read back.
template <typename Write>
void expect_writer_refuses_non_finite(Write&& write) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  auto refused = [&](const IndexedMesh& m, const std::string& what) {
    const InvalidInputError e = caught<InvalidInputError>([&] { write(m); }, InvalidInputError(""));
    EXPECT_EQ(std::string(e.what()), "indexed mesh: " + what + " is not finite");
  };
  IndexedMesh m = tetrahedron();
  EXPECT_FALSE(write(m).empty());
  m.positions[2] = {1, nan, 0};
  refused(m, "position 2 (1, nan, 0)");
  m.positions[2] = {0, 0, -inf};
  refused(m, "position 2 (0, 0, -inf)");
  const std::vector<std::uint32_t> first(m.indices.size(), 0);
  IndexedMesh t = tetrahedron();
  t.texcoords = {{0.5f, inf}};
  t.texcoord_indices = first;
  refused(t, "texture coordinate 0 (0.5, inf)");
  IndexedMesh n = tetrahedron();
  n.normals = {{0, 0, 1}, {nan, 0, 0}};
  n.normal_indices = first;
  refused(n, "normal 1 (nan, 0, 0)");
  IndexedMesh c = tetrahedron();
  c.colors = {{1, nan, 0, 1}};
  c.color_indices = first;
  refused(c, "color 0 (1, nan, 0, 1)");
}

}  // namespace hedge::test

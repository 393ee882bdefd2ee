#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "hedge/error.h"
#include "hedge/io/io.h"
#include "io/io_errors.h"
#include "support/io_checks.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::data_path;
using Counts = test::FileCounts;

IndexedMesh read_data(const std::string& name) { return read_off(read_file(data_path(name)), name); }

void expect_off_error(const std::string& text, const std::string& message, std::uint64_t line) {
  test::expect_io_error([&] { read_off(text, "m.off"); }, message, line, "m.off");
}

class OffFiles : public ::testing::TestWithParam<Counts> {};

TEST_P(OffFiles, CountsMatchTheShippedDescription) {
  const Counts c = GetParam();
  const IndexedMesh m = read_data(c.file);
  test::expect_counts(m, c);
  EXPECT_EQ(m.is_triangles(), c.corners == 3 * c.faces);
}

INSTANTIATE_TEST_SUITE_P(Data, OffFiles,
                         ::testing::Values(Counts{"anchor.off", 519, 1050, 3150},
                                           Counts{"fandisk_quads.off", 766, 764, 4 * 764},
                                           Counts{"non_manifold_face_graph.off", 24, 11, 3 + 10 * 4},
                                           Counts{"degtri_four.off", 5, 4, 12},
                                           Counts{"fused_vertices.off", 40, 45, 135},
                                           Counts{"blobby-shuffled.off", 2027, 4050, 12150},
                                           Counts{"elephant-with-holes.off", 2798, 4463, 3 * 4463}));

TEST(OffRead, ExactValuesOfASmallFile) {
  const IndexedMesh m = read_data("degtri_four.off");
  EXPECT_EQ(m.positions[1], (Vec3{2, 0, 0}));
  EXPECT_EQ(m.positions[4], (Vec3{2, 1, 0}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 2, 1, 4, 3, 2, 4}));
  const IndexedMesh f = read_data("fused_vertices.off");
  EXPECT_EQ(f.positions[0], (Vec3{-0.026804100000000001f, -0.30492799999999998f, 0.142542f}));
}

TEST(OffRead, HeaderVariantsAndExtras) {
  // Counts on the header line, colours after vertices and faces.
  const IndexedMesh c = read_off(
      "COFF 4 2 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 1 1 1 1\n1 1 0 0 0 0 0\n"
      "3 0 1 2 255 0 0\n3 1 3 2 0.5 0.5 0.5 1\n");
  EXPECT_EQ(c.positions.size(), 4u);
  EXPECT_EQ(c.positions[3], (Vec3{1, 1, 0}));
  EXPECT_EQ(c.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  // Normals after the coordinates; comments; CRLF; no edge count; mixed polygon sizes.
  const IndexedMesh n = read_off(
      "# leading comment\r\nNOFF\r\n# counts follow\r\n5 2\r\n\r\n"
      "0 0 0 0 0 1\r\n1 0 0 0 0 1\r\n1 1 0 0 0 1\r\n0 1 0 0 0 1 # comment\r\n2 2 0 0 0 1\r\n"
      "4 0 1 2 3\r\n# between faces\r\n3 1 4 2\r\n");
  EXPECT_EQ(n.positions[4], (Vec3{2, 2, 0}));
  EXPECT_EQ(n.face_sizes, (std::vector<std::uint32_t>{4, 3}));
  EXPECT_EQ(n.indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 1, 4, 2}));
  // The keyword is optional.
  const IndexedMesh k = read_off("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(k.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(read_off("STCNOFF\n1 0 0\n1 2 3 0 0 1 1 1 1 1 0.5 0.5\n").positions[0], (Vec3{1, 2, 3}));
}

TEST(OffRead, MalformedHeaders) {
  expect_off_error("", "expected an OFF header, got end of file", 1);
  expect_off_error("PLY\n", "expected an OFF header ('OFF', 'COFF', 'NOFF', ...), got 'PLY'", 1);
  expect_off_error("XOFF\n", "got 'XOFF'", 1);
  expect_off_error("4OFF\n1 0 0\n", "unsupported OFF variant '4OFF'", 1);
  expect_off_error("OFF BINARY\n", "binary OFF is not supported", 1);
  expect_off_error("OFF\nthree 1 0\n", "expected the number of vertices, got 'three'", 2);
  expect_off_error("OFF\n3\n", "expected the number of faces, got end of file", 3);
  expect_off_error("OFF\n-3 1 0\n", "negative number of vertices", 2);
}

TEST(OffRead, LyingCountsFailBeforeAllocating) {
  expect_off_error("OFF\n1000000000000 1 0\n0 0 0\n", "claims 1000000000000 vertices", 2);
  expect_off_error("OFF\n1000000000 2000000000 0\n0 0 0\n",
                   "the header claims 1000000000 vertices and 2000000000 faces, but only", 2);
  expect_off_error("OFF 0 4000000000 0\n", "0 vertices and 4000000000 faces, but only 3 bytes follow", 1);
}

TEST(OffRead, MissingOrShortRecords) {
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n# padding padding\n", "expected vertex 2 of 3, got end of file",
                   6);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
                   "vertex 1: expected 3 coordinates, got end of line", 4);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
                   "face 0: expected 3 vertex indices, got end of line", 6);
  expect_off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "expected face 1 of 2, got end of file", 7);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nx 0 1 2\n",
                   "face 0: expected the number of corners, got 'x'", 6);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0\n", "face 0: invalid number of corners 0", 6);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n", "expected 3 vertex indices, got '2.5'", 6);
}

TEST(OffRead, IndicesOutOfRangeNameTheFaceAndLine) {
  expect_off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 3\n",
                   "face 1: vertex index 3 is out of range (3 vertices)", 7);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "face 0: vertex index -1 is out of range",
                   6);
}

TEST(OffRead, TheFirstBadIndexIsReported) {
  const std::string triangle = "OFF\n3 3 0\n0 0 0\n1 0 0\n0 1 0\n";
  expect_off_error(triangle + "3 0 1 5\n3 0 1 2\n3 0 1 9\n", "face 0: vertex index 5 is out of range", 6);
  expect_off_error(triangle + "3 0 1 2\n3 0 9 5\n3 0 1 4\n", "face 1: vertex index 9 is out of range", 7);
}

TEST(OffRead, NonFiniteCoordinatesNameTheVertexAndLine) {
  expect_off_error("OFF\n3 1 0\n0 0 0\n\n1 nan 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a non-finite coordinate",
                   5);
  expect_off_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n", "vertex 2 has a non-finite coordinate",
                   5);
}

TEST(OffWrite, RoundTripIsExact) {
  for (const char* file :
       {"anchor.off", "fandisk_quads.off", "non_manifold_face_graph.off", "fused_vertices.off"}) {
    SCOPED_TRACE(file);
    const IndexedMesh m = read_data(file);
    const IndexedMesh back = read_off(write_off(m));
    ASSERT_EQ(back.positions.size(), m.positions.size());
    EXPECT_EQ(std::memcmp(back.positions.data(), m.positions.data(), m.positions.size() * sizeof(Vec3)), 0);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.face_sizes, m.face_sizes);
  }
}

TEST(OffWrite, WritesTheExpectedText) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1.5f, 0, 0}, {0, 1, -2}, {1, 1, 0}};
  m.indices = {0, 1, 3, 2, 0, 3, 1};
  m.face_sizes = {4, 3};
  EXPECT_EQ(write_off(m), "OFF\n4 2 0\n0 0 0\n1.5 0 0\n0 1 -2\n1 1 0\n4 0 1 3 2\n3 0 3 1\n");
}

TEST(OffWrite, RefusesANonFiniteValueBeforeWriting) {
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_off(m); });
}

}  // namespace
}  // namespace hedge

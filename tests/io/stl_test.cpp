#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <string>
#include <vector>

#include "hedge/error.h"
#include "hedge/io/io.h"
#include "io/io_errors.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using test::data_path;

using test::catch_io_error;

void expect_stl_error(const std::string& data, const std::string& message) {
  const IoError e = catch_io_error([&] { read_stl(data, "m.stl"); });
  EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
}

std::vector<std::uint32_t> iota(std::size_t n) {
  std::vector<std::uint32_t> v(n);
  std::iota(v.begin(), v.end(), 0u);
  return v;
}

bool same_positions(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

float f32_at(const std::string& s, std::size_t offset) {
  float f;
  std::memcpy(&f, s.data() + offset, 4);
  return f;
}

TEST(StlRead, BinaryFilesAreTriangleSoups) {
  const IndexedMesh ico = read_stl(read_file(data_path("icosahedron_binary.stl")));
  EXPECT_EQ(ico.positions.size(), 60u);
  EXPECT_EQ(ico.face_count(), 20u);
  EXPECT_EQ(ico.indices, iota(60));
  const IndexedMesh spider = read_stl(read_file(data_path("Spider_binary.stl")));
  EXPECT_EQ(spider.positions.size(), 4104u);
  EXPECT_EQ(spider.face_count(), 1368u);
}

TEST(StlRead, BinaryValuesAreReadAtTheRightOffsets) {
  const std::string data = read_file(data_path("icosahedron_binary.stl"));
  const IndexedMesh m = read_stl(data);
  // Triangle 7, vertex 2: 84 + 7 * 50 + 12 (normal) + 2 * 12.
  const std::size_t at = 84 + 7 * 50 + 12 + 24;
  EXPECT_EQ(m.positions[7 * 3 + 2], (Vec3{f32_at(data, at), f32_at(data, at + 4), f32_at(data, at + 8)}));
}

TEST(StlRead, BinaryWhoseHeaderStartsWithSolid) {
  std::string data = read_file(data_path("icosahedron_binary.stl"));
  const IndexedMesh plain = read_stl(data);
  std::memcpy(data.data(), "solid icosahedron", 17);
  const IndexedMesh m = read_stl(data);
  EXPECT_TRUE(same_positions(m.positions, plain.positions));
  EXPECT_EQ(m.indices, plain.indices);
  // Trailing bytes break the size rule, but the NUL bytes still say binary.
  const IndexedMesh padded = read_stl(data + std::string(10, '\0'));
  EXPECT_TRUE(same_positions(padded.positions, plain.positions));
}

const char* kAscii =
    "solid two\n"
    "  facet normal 0 0 1\n"
    "    outer loop\n"
    "      vertex 0 0 0\n"
    "      vertex 1 0 0\n"
    "      vertex 0 1 0\n"
    "    endloop\n"
    "  endfacet\n"
    "  FACET NORMAL -1.#IND -1.#IND -1.#IND\r\n"
    "    OUTER LOOP\r\n"
    "      VERTEX 1.5 -2e-3 +7\r\n"
    "      VERTEX 1 0 0\r\n"
    "      VERTEX 0 1 0\r\n"
    "    ENDLOOP\r\n"
    "  ENDFACET\r\n"
    "endsolid two\n"
    "solid second\n"
    "facet normal 0 0 0 outer loop vertex 5 5 5 vertex 6 5 5 vertex 5 6 5 endloop endfacet\n"
    "endsolid\n";

TEST(StlRead, Ascii) {
  const IndexedMesh m = read_stl(kAscii);
  ASSERT_EQ(m.positions.size(), 9u);
  EXPECT_EQ(m.indices, iota(9));
  EXPECT_EQ(m.positions[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(m.positions[3], (Vec3{1.5f, -2e-3f, 7}));
  EXPECT_EQ(m.positions[8], (Vec3{5, 6, 5}));
  EXPECT_EQ(read_stl("solid empty\nendsolid empty\n").positions.size(), 0u);
}

TEST(StlRead, MalformedAsciiNamesTheLine) {
  auto line_of = [](const std::string& text) { return catch_io_error([&] { read_stl(text); }).line(); };
  expect_stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop\n",
                   "expected a vertex coordinate, got 'endloop'");
  EXPECT_EQ(line_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop\n"), 5u);
  expect_stl_error(
      "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 0 0 0\nvertex 0 0 0\n",
      "expected 'endloop', got 'vertex'");
  expect_stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 0 0\n",
                   "expected 'vertex', got end of file");
  expect_stl_error("solid x\nfacet normal 0 0 1\n", "expected 'outer', got end of file");
  expect_stl_error("solid x\nfacet\n", "expected 'normal'");
  expect_stl_error("solid x\nbanana\n", "expected 'facet' or 'endsolid', got 'banana'");
  expect_stl_error("solid x\n", "expected 'facet' or 'endsolid', got end of file");
  expect_stl_error("solid x\nendsolid\ngarbage", "expected 'solid', got 'garbage'");
  expect_stl_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 nan 0\n",
                   "vertex 1 has a non-finite coordinate");
  EXPECT_EQ(line_of("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 inf 0\n"), 5u);
}

TEST(StlRead, MalformedBinaryNamesTheByteOffset) {
  const std::string data = read_file(data_path("icosahedron_binary.stl"));
  // Truncated: the count claims 20 triangles.
  const IoError t = catch_io_error([&] { read_stl(data.substr(0, data.size() - 7)); });
  EXPECT_NE(std::string(t.what()).find(
                "binary STL header claims 20 triangles (1084 bytes), but the file has 1077 bytes"),
            std::string::npos)
      << t.what();
  EXPECT_EQ(t.byte_offset(), 80);
  // A lying count: 4 billion triangles in a 1 kB file fails without allocating.
  std::string lying = data;
  lying[80] = lying[81] = lying[82] = lying[83] = '\xff';
  expect_stl_error(lying, "claims 4294967295 triangles");
  expect_stl_error("short", "not an STL file: too short");
  expect_stl_error(std::string(83, 'x'), "not an STL file");
  // NaN in triangle 3, vertex 1.
  std::string nan = data;
  const float q = std::nanf("");
  std::memcpy(nan.data() + 84 + 3 * 50 + 12 + 12 + 4, &q, 4);
  const IoError n = catch_io_error([&] { read_stl(nan); });
  EXPECT_NE(std::string(n.what()).find("triangle 3, vertex 1 has a non-finite coordinate"),
            std::string::npos);
  EXPECT_EQ(n.byte_offset(), 84 + 3 * 50 + 12 + 12);
}

TEST(StlWrite, BinaryRoundTripAndLayout) {
  const IndexedMesh m = read_stl(read_file(data_path("icosahedron_binary.stl")));
  const std::string out = write_stl(m);
  ASSERT_EQ(out.size(), 84u + 50u * 20u);
  EXPECT_NE(out.substr(0, 5), "solid");
  const IndexedMesh back = read_stl(out);
  EXPECT_TRUE(same_positions(back.positions, m.positions));
  EXPECT_EQ(back.indices, m.indices);
}

TEST(StlWrite, AsciiRoundTrip) {
  const IndexedMesh m = read_stl(read_file(data_path("Spider_binary.stl")));
  WriteOptions o;
  o.binary = false;
  const std::string out = write_stl(m, o);
  EXPECT_EQ(out.substr(0, 12), "solid hedge\n");
  const IndexedMesh back = read_stl(out);
  EXPECT_TRUE(same_positions(back.positions, m.positions));
  EXPECT_EQ(back.indices, m.indices);
}

TEST(StlWrite, PolygonsAreFannedAndNormalsComputed) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 5}};
  m.indices = {0, 1, 2, 3, 0, 4, 1};
  m.face_sizes = {4, 3};
  const std::string out = write_stl(m);
  ASSERT_EQ(out.size(), 84u + 3 * 50u);
  // The quad's fan (0 1 2) (0 2 3), then the triangle; each starts with its unit normal.
  EXPECT_EQ(f32_at(out, 84 + 8), 1.0f);
  EXPECT_EQ(f32_at(out, 84 + 50 + 8), 1.0f);
  EXPECT_EQ(f32_at(out, 84 + 100 + 4), 1.0f);  // (0,0,0) (0,0,5) (2,0,0) faces +y
  const IndexedMesh back = read_stl(out);
  EXPECT_EQ(back.positions[4], (Vec3{2, 2, 0}));
  EXPECT_EQ(back.positions[5], (Vec3{0, 2, 0}));
  EXPECT_EQ(back.positions[7], (Vec3{0, 0, 5}));

  WriteOptions o;
  o.binary = false;
  const std::string text = write_stl(m, o);
  EXPECT_NE(text.find("facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 2 0 0\n  vertex 2 2 0\n "
                      "endloop\nendfacet\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(read_stl(text).positions.size(), 9u);
}

TEST(StlWrite, DegenerateTrianglesGetAZeroNormal) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  m.indices = {0, 1, 2};
  const std::string out = write_stl(m);
  EXPECT_EQ(f32_at(out, 84), 0.0f);
  EXPECT_EQ(f32_at(out, 88), 0.0f);
  EXPECT_EQ(f32_at(out, 92), 0.0f);
}

TEST(StlWrite, RefusesANonFiniteValueBeforeWriting) {
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_stl(m); });
}

}  // namespace
}  // namespace hedge

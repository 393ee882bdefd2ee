#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
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
using test::expect_same;
using test::same_bits;
using Counts = test::FileCounts;

IndexedMesh read_data(const std::string& name) { return read_obj(read_file(data_path(name)), name); }

void expect_obj_error(const std::string& text, const std::string& message, std::uint64_t line) {
  test::expect_io_error([&] { read_obj(text, "model.obj"); }, message, line, "model.obj");
}

TEST(ObjRead, TetrahedronWithNormals) {
  const IndexedMesh m = read_data("tet.obj");
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.face_count(), 4u);
  EXPECT_TRUE(m.is_triangles());
  EXPECT_EQ(m.positions[0], (Vec3{-6.052902f, -1.910479f, -0.448446f}));
  EXPECT_EQ(m.positions[3], (Vec3{-6.524307f, -3.243812f, 0.368050f}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2}));
  ASSERT_EQ(m.normals.size(), 4u);
  EXPECT_EQ(m.normals[1], (Vec3{-0.942800f, 0.333300f, 0.0f}));
  EXPECT_EQ(m.normal_indices, (std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}));
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_TRUE(m.texcoord_indices.empty());
}

TEST(ObjRead, PolygonsWithTextureCoordinates) {
  const IndexedMesh m = read_data("spot_control_mesh.obj");
  EXPECT_EQ(m.positions.size(), 188u);
  ASSERT_EQ(m.face_count(), 180u);
  ASSERT_FALSE(m.is_triangles());
  int by_size[8] = {};
  for (std::uint32_t n : m.face_sizes) by_size[std::min(n, 7u)]++;
  EXPECT_EQ(by_size[3], 4);
  EXPECT_EQ(by_size[4], 160);
  EXPECT_EQ(by_size[5], 16);
  EXPECT_EQ(m.texcoords.size(), 267u);
  EXPECT_EQ(m.texcoord_indices.size(), m.indices.size());
  // "f 6/1 14/2 10/3 16/4" is the first face.
  EXPECT_EQ((std::vector<std::uint32_t>(m.indices.begin(), m.indices.begin() + 4)),
            (std::vector<std::uint32_t>{5, 13, 9, 15}));
  EXPECT_EQ((std::vector<std::uint32_t>(m.texcoord_indices.begin(), m.texcoord_indices.begin() + 4)),
            (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_TRUE(m.normals.empty());
}

TEST(ObjRead, TriangulatedWithTextureCoordinates) {
  const IndexedMesh m = read_data("spot_triangulated.obj");
  EXPECT_EQ(m.positions.size(), 2930u);
  EXPECT_EQ(m.face_count(), 5856u);
  EXPECT_TRUE(m.is_triangles());
  EXPECT_EQ(m.texcoords.size(), 3225u);
  EXPECT_EQ(m.texcoord_indices.size(), 3u * 5856u);
}

class ObjDefectFiles : public ::testing::TestWithParam<Counts> {};

TEST_P(ObjDefectFiles, CountsMatchTheShippedDescription) {
  const Counts c = GetParam();
  test::expect_counts(read_data(c.file), c);
}

INSTANTIATE_TEST_SUITE_P(Data, ObjDefectFiles,
                         ::testing::Values(Counts{"hourglass_ico.obj", 23, 40, 120},
                                           Counts{"moebius.obj", 280, 224, 896},
                                           Counts{"joined_tetrahedra.obj", 5, 8, 24},
                                           Counts{"cube-minimal-degenerated.obj", 8, 14, 13 * 3 + 5},
                                           Counts{"triple_vierbein.obj", 75, 108, 324}));

TEST(ObjRead, CornerForms) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "vt 0 0\nvt 1 0\nvt 0 1\n"
      "vn 0 0 1\nvn 1 0 0\n"
      "f 1/1/1 2/2/1 3/3/2\n"
      "f 1/3/2 3/2/2 4/1/1\n";
  const IndexedMesh m = read_obj(text);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.texcoord_indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 0}));
  EXPECT_EQ(m.normal_indices, (std::vector<std::uint32_t>{0, 0, 1, 1, 1, 0}));
  EXPECT_EQ(m.texcoords[2], (Vec2{0, 1}));
  EXPECT_EQ(m.normals[1], (Vec3{1, 0, 0}));

  const IndexedMesh vn = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
  EXPECT_EQ(vn.normal_indices, (std::vector<std::uint32_t>{0, 0, 0}));
  EXPECT_TRUE(vn.texcoord_indices.empty());

  const IndexedMesh vt = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.25\nf 1/1 2/1 3/1\n");
  EXPECT_EQ(vt.texcoord_indices, (std::vector<std::uint32_t>{0, 0, 0}));
  EXPECT_EQ(vt.texcoords[0], (Vec2{0.5f, 0.25f}));
  EXPECT_TRUE(vt.normal_indices.empty());
}

TEST(ObjRead, NegativeIndicesAreRelativeToTheVerticesSoFar) {
  const IndexedMesh m = read_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\n"
      "f -3/-2 -2/-1 -1/-1\n"
      "v 5 5 5\n"
      "f -4 -1 -2\n");
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 3, 2}));
  // The second face has no vt: the attribute is dropped (documented behaviour).
  EXPECT_TRUE(m.texcoords.empty());
}

TEST(ObjRead, IgnoresStatementsAndExtrasItDoesNotUse) {
  const std::string text =
      "# comment\r\n"
      "mtllib a.mtl\r\n"
      "o object\n"
      "g group\n"
      "  s 1\n"
      "usemtl red\n"
      "v 1.5 -2 3e2 1.0\n"      // w coordinate
      "v +4 5 6 0.1 0.2 0.3\n"  // vertex colour
      "\tv 7 8 9   # trailing comment\n"
      "\n"
      "l 1 2\n"
      "p 1\n"
      "vp 0.5\n"
      "f 1 2 3 # a comment after a face\r\n";
  const IndexedMesh m = read_obj(text);
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_EQ(m.positions[0], (Vec3{1.5f, -2.0f, 300.0f}));
  EXPECT_EQ(m.positions[1], (Vec3{4, 5, 6}));
  EXPECT_EQ(m.positions[2], (Vec3{7, 8, 9}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(ObjRead, BackslashContinuesALine) {
  const IndexedMesh m = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 \\\n 4 3\n");
  EXPECT_EQ(m.face_sizes, (std::vector<std::uint32_t>{4}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 3, 2}));
  // Line numbers keep counting the continued lines.
  expect_obj_error("v 0 0 0\nf 1 \\\n 1 \\\n 1\nf x\n", "expected a vertex index after 'f', got 'x'", 5);
}

TEST(ObjRead, AttributesOnlySomeCornersHaveAreDropped) {
  const IndexedMesh m = read_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvn 0 0 1\n"
      "f 1/1/1 2/1/1 3/1/1\n"
      "f 2//1 4//1 3//1\n");
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_TRUE(m.texcoord_indices.empty());
  EXPECT_EQ(m.normals.size(), 1u);
  EXPECT_EQ(m.normal_indices, (std::vector<std::uint32_t>(6, 0)));
}

TEST(ObjRead, UnreferencedPoolsAreNotFilled) {
  const IndexedMesh m = read_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1 2 3\n");
  EXPECT_TRUE(m.texcoords.empty());
  EXPECT_TRUE(m.normals.empty());
}

TEST(ObjRead, FacesMayNameVerticesDefinedLater) {
  const IndexedMesh m = read_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_EQ(m.positions.size(), 3u);
}

TEST(ObjRead, EmptyInputIsAnEmptyMesh) {
  const IndexedMesh m = read_obj("");
  EXPECT_TRUE(m.positions.empty());
  EXPECT_EQ(m.face_count(), 0u);
  EXPECT_EQ(read_obj("# nothing\n\n").positions.size(), 0u);
}

TEST(ObjRead, MalformedStatementsNameTheLineAndTheProblem) {
  expect_obj_error("v 0 0 0\nv 1 0 0\nf 1 x 2\n", "model.obj:3: expected a vertex index after 'f', got 'x'",
                   3);
  expect_obj_error("v 0 0 0\nf\n", "expected a vertex index after 'f', got end of line", 2);
  expect_obj_error("v 1 2\n", "expected the third number after 'v', got end of line", 1);
  expect_obj_error("v 1 2 abc\n", "expected the third number after 'v', got 'abc'", 1);
  expect_obj_error("v 1 2 3.5.6\n", "third number", 1);
  expect_obj_error("vn 1 2\n", "after 'vn'", 1);
  expect_obj_error("vt\n", "expected the first number after 'vt'", 1);
  expect_obj_error("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1/x 2 3\n",
                   "expected a texture coordinate index after '/', got 'x'", 4);
  expect_obj_error("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1//y 2 3\n", "expected a normal index after '/'", 4);
  expect_obj_error("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3q\n", "unexpected 'q' in a face corner", 4);
}

TEST(ObjRead, GarbageIsRejected) {
  expect_obj_error("this is not a mesh\n", "unknown keyword 'this'", 1);
  expect_obj_error("v 0 0 0\n\x01\x02\x03\xff\n", "unknown keyword '\\x01\\x02\\x03\\xff'", 2);
  EXPECT_THROW(read_obj(std::string("\0\0\0\0", 4)), IoError);
}

TEST(ObjRead, IndicesOutOfRangeNameTheFaceAndLine) {
  expect_obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 5\n", "face 1: vertex index 5 is out of range",
                   5);
  expect_obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 3\n", "face 0: vertex index 0 is invalid", 4);
  expect_obj_error("v 0 0 0\nv 1 0 0\nf -1 -2 -3\n",
                   "relative vertex index -3 refers before the first vertex", 3);
  expect_obj_error("v 0 0 0\nvt 0 0\nf 1/1 1/2 1/1\n", "texture coordinate index 2 is out of range", 3);
  expect_obj_error("v 0 0 0\nvn 0 0 1\nf 1//1 1//1 1//3\n", "normal index 3 is out of range", 3);
  expect_obj_error("v 0 0 0\nf 1 1 99999999999999999999\n", "expected a vertex index", 2);
  expect_obj_error("v 0 0 0\nf 1 1 9999999999\n", "too large", 2);
}

// An index past its pool can only be judged at the end of the file; the error still names the first
// face that goes out of range, not the last one or the one with the largest index.
TEST(ObjRead, TheFirstIndexOutOfRangeIsReported) {
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_obj_error(triangle + "f 1 2 7\nf 1 2 3\nf 1 2 9\n", "face 0: vertex index 7 is out of range", 4);
  expect_obj_error(triangle + "f 1 2 9\nf 1 2 3\nf 1 2 7\n", "face 0: vertex index 9 is out of range", 4);
  // Bad indices of different pools, and one too large for any pool, in file order.
  expect_obj_error(triangle + "vt 0 0\nf 1/1 2/1 3/4\nf 1/1 2/1 8/1\n",
                   "face 0: texture coordinate index 4 is out of range (the file defines 1)", 5);
  expect_obj_error(triangle + "vt 0 0\nf 1/1 2/1 8/1\nf 1/1 2/1 3/4\n",
                   "face 0: vertex index 8 is out of range (the file defines 3)", 5);
  expect_obj_error(triangle + "f 1 2 5\nf 1 2 9999999999\n", "face 0: vertex index 5 is out of range", 4);
  expect_obj_error(triangle + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1//1 2//9999999999 3//1\nf 1//3 2//1 3//1\n",
                   "face 1: normal index 9999999999 is too large", 6);
  // A face naming vertices defined further down is fine until one of them never comes.
  expect_obj_error("f 1 2 3\nf 1 2 6\nf 4 2 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n",
                   "face 1: vertex index 6 is out of range (the file defines 4)", 2);
}

TEST(ObjRead, NonFiniteCoordinatesNameTheVertexAndLine) {
  expect_obj_error("v 0 0 0\nv 1 nan 0\n", "vertex 1 has a non-finite coordinate", 2);
  expect_obj_error("v 0 0 0\n\nv 1 0 inf\n", "vertex 1 has a non-finite coordinate", 3);
  expect_obj_error("v -1e39 0 0\n", "vertex 0 has a non-finite coordinate", 1);
  expect_obj_error("vn 0 0 nan\n", "normal 0 has a non-finite component", 1);
  expect_obj_error("vt nan 0\n", "texture coordinate 0 has a non-finite component", 1);
  // Values below float's range are not errors: they round to zero.
  EXPECT_EQ(read_obj("v 1e-60 -1e-400 0\n").positions[0], (Vec3{0, 0, 0}));
}

// The reader's numbers must agree bit for bit with std::from_chars<float>, whatever parser it
// uses, including on decimals next to the halfway points between two floats (where a parser that
// goes through double rounds twice) and on numbers with more digits than a 64-bit mantissa holds.
TEST(ObjRead, NumbersMatchFromChars) {
  std::mt19937_64 rng(12345);
  std::vector<std::string> numbers = {"0",
                                      "-0",
                                      "1",
                                      "0.1",
                                      "16777217",
                                      "16777219",
                                      "3.4028235e38",
                                      "1.17549435e-38",
                                      "4.9e-45",
                                      "0.000000000000000000000000000000000000000000001",
                                      "123456789012345678901234567890",
                                      "1.000000059604644775390625",
                                      "1.0000000596046447753906250001",
                                      "7.0e-10",
                                      "1E5",
                                      "+2.5",
                                      "-.5",
                                      "5.",
                                      "0.30000001192092895507812",
                                      "9007199254740993",
                                      "1e22",
                                      "1e23",
                                      "1e-22",
                                      "123.456e-20"};
  char buf[64];
  for (int i = 0; i < 20000; ++i) {
    // A random float and the exact midpoint to its neighbour, printed with 17 digits (so often a
    // hair off the midpoint), and with the last digit nudged.
    std::uint32_t bits = static_cast<std::uint32_t>(rng()) & 0x7fffffffu;
    if ((bits >> 23) >= 0xfe || (bits >> 23) == 0) continue;
    float f;
    std::memcpy(&f, &bits, 4);
    const double mid = (static_cast<double>(f) +
                        static_cast<double>(std::nextafter(f, std::numeric_limits<float>::infinity()))) /
                       2;
    for (const char* fmt : {"%.17g", "%.16g", "%.9g", "%.8g", "%.12e"}) {
      std::snprintf(buf, sizeof buf, fmt, mid);
      numbers.emplace_back(buf);
    }
    // Random digit strings with a decimal point and an exponent.
    std::string r = (rng() & 1) ? "-" : "";
    const int len = 1 + static_cast<int>(rng() % 24);
    const int dot = static_cast<int>(rng() % static_cast<std::uint64_t>(len + 1));
    for (int k = 0; k < len; ++k) {
      if (k == dot) r += '.';
      r += static_cast<char>('0' + rng() % 10);
    }
    if (rng() % 3 == 0) r += "e" + std::to_string(static_cast<int>(rng() % 70) - 40);
    numbers.push_back(r);
  }
  std::string text;
  std::vector<float> expected;
  for (const std::string& n : numbers) {
    float v = 0;
    const std::string_view sv = n[0] == '+' ? std::string_view(n).substr(1) : std::string_view(n);
    auto [ptr, ec] = std::from_chars(sv.data(), sv.data() + sv.size(), v);
    if (ec != std::errc() || ptr != sv.data() + sv.size() || !std::isfinite(v)) continue;
    text += "v " + n + " 0 0\n";
    expected.push_back(v);
  }
  ASSERT_GT(expected.size(), 50000u);
  const IndexedMesh m = read_obj(text);
  ASSERT_EQ(m.positions.size(), expected.size());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (std::memcmp(&m.positions[i].x, &expected[i], 4) != 0 && ++mismatches < 10)
      ADD_FAILURE() << "line " << i + 1 << ": got " << m.positions[i].x << ", from_chars gives "
                    << expected[i];
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(ObjWrite, RoundTripIsExact) {
  for (const char* file :
       {"spot_control_mesh.obj", "tet.obj", "spot_triangulated.obj", "cube-minimal-degenerated.obj"}) {
    SCOPED_TRACE(file);
    const IndexedMesh m = read_data(file);
    expect_same(read_obj(write_obj(m)), m);
  }
}

// Faces' submeshes become runs under "usemtl submesh_N", in face order; the reader ignores them.
TEST(ObjWrite, SubmeshesBecomeUsemtlRuns) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.indices = {0, 1, 2, 1, 3, 2, 0, 2, 3};
  m.face_submeshes = {0, 0, 4};
  const std::string text = write_obj(m);
  EXPECT_NE(text.find("usemtl submesh_0\nf 1 2 3\nf 2 4 3\nusemtl submesh_4\nf 1 3 4\n"), std::string::npos)
      << text;
  const IndexedMesh back = read_obj(text);
  EXPECT_EQ(back.indices, m.indices);
  EXPECT_TRUE(back.face_submeshes.empty());
  // Without one submesh per face, none is written.
  m.face_submeshes = {1};
  EXPECT_EQ(write_obj(m).find("usemtl"), std::string::npos);
}

TEST(ObjWrite, HardFloatsSurviveARoundTrip) {
  IndexedMesh m;
  m.positions = {{0.1f, -0.0f, 1e-45f},
                 {std::numeric_limits<float>::max(), std::numeric_limits<float>::min(), -3.4028233e38f},
                 {1.0f / 3.0f, 16777217.0f, 1.17549421e-38f}};
  m.indices = {0, 1, 2};
  const std::string text = write_obj(m);
  const IndexedMesh back = read_obj(text);
  EXPECT_TRUE(same_bits(back.positions, m.positions)) << text;
  // The shortest exact form: 0.1 is written as "0.1", not "0.100000001".
  EXPECT_NE(text.find("v 0.1 -0 "), std::string::npos) << text;
}

TEST(ObjWrite, LowPrecisionIsHonoured) {
  IndexedMesh m;
  m.positions = {{1.0f / 3.0f, 0, 0}};
  WriteOptions o;
  o.precision = 3;
  EXPECT_NE(write_obj(m, o).find("v 0.333 0 0\n"), std::string::npos);
}

TEST(ObjWrite, WritesCornerFormsMatchingTheAttributes) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  EXPECT_NE(write_obj(m).find("f 1 2 3\n"), std::string::npos);
  m.normals = {{0, 0, 1}};
  m.normal_indices = {0, 0, 0};
  EXPECT_NE(write_obj(m).find("f 1//1 2//1 3//1\n"), std::string::npos);
  m.texcoords = {{0, 0}, {1, 0}};
  m.texcoord_indices = {1, 0, 1};
  EXPECT_NE(write_obj(m).find("f 1/2/1 2/1/1 3/2/1\n"), std::string::npos);
}

TEST(ObjWrite, RejectsAnInconsistentMesh) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}};
  m.indices = {0, 0, 1};
  EXPECT_THROW(write_obj(m), InvalidInputError);
  m.indices = {0, 0};
  EXPECT_THROW(write_obj(m), InvalidInputError);
  m.indices = {0, 0, 0};
  m.texcoord_indices = {0, 0, 0};
  EXPECT_THROW(write_obj(m), InvalidInputError);
  m.face_sizes = {2, 1};
  m.texcoord_indices.clear();
  EXPECT_NO_THROW(write_obj(m));
  m.face_sizes = {2, 2};
  EXPECT_THROW(write_obj(m), InvalidInputError);
}

TEST(ObjWrite, RefusesANonFiniteValueBeforeWriting) {
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_obj(m); });
}

}  // namespace
}  // namespace hedge

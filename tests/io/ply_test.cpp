#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
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

IndexedMesh read_data(const std::string& name) { return read_ply(read_file(data_path(name)), name); }

// A value of a PLY body: its type letter (b B h H i I f d, as Python's struct) and its value.
struct Val {
  char type;
  double value;
};

template <typename T>
void put(std::string& out, T v, bool big) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

// `value` as a T, in the byte order `big` says.
template <typename T>
void put_as(std::string& out, double value, bool big) {
  put(out, static_cast<T>(value), big);
}

std::string encode(const std::vector<Val>& values, bool big) {
  // The type letters of PLY's scalar types, as Python's struct spells them.
  static const std::map<char, void (*)(std::string&, double, bool)> kPut = {
      {'b', put_as<std::int8_t>},   {'B', put_as<std::uint8_t>}, {'h', put_as<std::int16_t>},
      {'H', put_as<std::uint16_t>}, {'i', put_as<std::int32_t>}, {'I', put_as<std::uint32_t>},
      {'f', put_as<float>},         {'d', put_as<double>}};
  std::string out;
  for (const Val& v : values) {
    const auto it = kPut.find(v.type);
    if (it == kPut.end())
      ADD_FAILURE() << "bad type letter";
    else
      it->second(out, v.value, big);
  }
  return out;
}

std::string ascii(const std::vector<Val>& values) {
  std::string out;
  for (const Val& v : values) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g ", v.value);
    out += buf;
  }
  return out + "\n";
}

// One PLY file in the three encodings.
std::string ply(const std::string& format, const std::string& elements, const std::vector<Val>& body) {
  std::string head = "ply\nformat " + format + " 1.0\n" + elements + "end_header\n";
  if (format == "ascii") return head + ascii(body);
  return head + encode(body, format == "binary_big_endian");
}

using test::catch_io_error;

void expect_ply_error(const std::string& text, const std::string& message) {
  const IoError e = catch_io_error([&] { read_ply(text, "m.ply"); });
  EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  EXPECT_EQ(e.path(), "m.ply");
}

const char* kFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};

TEST(PlyRead, BinaryFileFromData) {
  const IndexedMesh m = read_data("bob_small.ply");
  EXPECT_EQ(m.positions.size(), 250u);
  EXPECT_EQ(m.face_count(), 500u);
  EXPECT_TRUE(m.is_triangles());
  EXPECT_TRUE(m.normals.empty());
  for (std::uint32_t i : m.indices) ASSERT_LT(i, 250u);
}

TEST(PlyRead, TriangleStripsFromData) {
  // A 3x3 grid (vertex i at (i % 3, i / 3)) stored as the strips 3 0 4 1 5 2 and 6 3 7 4 8 5,
  // separated by -1, with colour properties to skip.
  const IndexedMesh m = read_data("grid_tristrips.ply");
  ASSERT_EQ(m.positions.size(), 9u);
  EXPECT_EQ(m.positions[5], (Vec3{2, 1, 0}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{3, 0, 4, 4, 0, 1, 4, 1, 5, 5, 1, 2,  //
                                                   6, 3, 7, 7, 3, 4, 7, 4, 8, 8, 4, 5}));
  // Alternating the winding keeps every triangle facing +z, like the strip.
  for (std::size_t t = 0; t < m.face_count(); ++t) {
    const Vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
               c = m.positions[m.indices[3 * t + 2]];
    EXPECT_GT(cross(b - a, c - a).z, 0.0f) << "triangle " << t;
  }
}

TEST(PlyRead, StripsDropDegenerateTrianglesAndRestart) {
  // 0 1 2 2 3: (0,1,2) then (1,2,2) and (2,2,3) carry a repeated index. An unsigned index type
  // stores the restart as its largest value.
  const std::string text =
      ply("ascii",
          "element vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
          "element tristrips 2\nproperty list uchar uint vertex_indices\n",
          {{'f', 0}, {'f', 0}, {'f', 0}, {'f', 1}, {'f', 0}, {'f', 0}, {'f', 0}, {'f', 1},
           {'f', 0}, {'f', 1}, {'f', 1}, {'f', 0}, {'f', 2}, {'f', 2}, {'f', 0}, {'B', 5},
           {'I', 0}, {'I', 1}, {'I', 2}, {'I', 2}, {'I', 3}, {'B', 5}, {'I', 4}, {'I', 4294967295.0},
           {'I', 1}, {'I', 2}, {'I', 3}});
  const IndexedMesh m = read_ply(text);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 2, 3}));
}

TEST(PlyRead, SharedTriangleStripMesh) {
  const std::string path = std::string(HEDGE_SHARED_MESHES_DIR) + "/igea.ply";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared meshes not available";
  const IndexedMesh m = read_indexed_file(path);
  EXPECT_EQ(m.positions.size(), 134345u);
  EXPECT_EQ(m.face_count(), 268686u);
  EXPECT_TRUE(m.is_triangles());
}

TEST(PlyRead, SharedMeshWithVertexNormals) {
  const std::string path = std::string(HEDGE_SHARED_MESHES_DIR) + "/horse.ply";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared meshes not available";
  const IndexedMesh m = read_indexed_file(path);
  EXPECT_EQ(m.positions.size(), 48485u);
  EXPECT_EQ(m.face_count(), 96966u);
  EXPECT_EQ(m.normals.size(), m.positions.size());
  EXPECT_EQ(m.normal_indices, m.indices);
}

// Elements and properties of many types, some to skip, in all three encodings.
const char* kRichHeader =
    "comment a comment\nobj_info some info\n"
    "element edge 1\nproperty int vertex1\nproperty list ushort int stuff\n"
    "element vertex 3\nproperty double x\nproperty short y\nproperty float z\nproperty uchar flags\n"
    "property list uchar float extra\nproperty float nx\nproperty float ny\nproperty float nz\n"
    "property float s\nproperty float t\n"
    "element face 2\nproperty uchar intensity\nproperty list uint ushort vertex_index\n"
    "property list uchar double texcoord\n"
    "element material 1\nproperty list int char name\n";

std::vector<Val> rich_body() {
  return {// edge
          {'i', 7},
          {'H', 2},
          {'i', -1},
          {'i', 5},
          // vertices: x y z flags [n extra] nx ny nz s t
          {'d', 0.5},
          {'h', -3},
          {'f', 1.25},
          {'B', 255},
          {'B', 0},
          {'f', 0},
          {'f', 0},
          {'f', 1},
          {'f', 0.25},
          {'f', 0.5},
          {'d', -2},
          {'h', 4},
          {'f', 0},
          {'B', 1},
          {'B', 2},
          {'f', 9},
          {'f', 8},
          {'f', 0},
          {'f', 1},
          {'f', 0},
          {'f', 1},
          {'f', 0},
          {'d', 1e3},
          {'h', 0},
          {'f', -0.125},
          {'B', 0},
          {'B', 1},
          {'f', 3},
          {'f', 1},
          {'f', 0},
          {'f', 0},
          {'f', 1},
          {'f', 1},
          // faces: intensity, vertex_index list, texcoord list
          {'B', 9},
          {'I', 3},
          {'H', 0},
          {'H', 1},
          {'H', 2},
          {'B', 2},
          {'d', 0.5},
          {'d', 0.5},
          {'B', 8},
          {'I', 4},
          {'H', 2},
          {'H', 1},
          {'H', 0},
          {'H', 1},
          {'B', 0},
          // material
          {'i', 3},
          {'b', 'a'},
          {'b', 'b'},
          {'b', 'c'}};
}

TEST(PlyRead, SkipsUnknownPropertiesOfEveryKindInAllEncodings) {
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    const IndexedMesh m = read_ply(ply(format, kRichHeader, rich_body()));
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[0], (Vec3{0.5f, -3, 1.25f}));
    EXPECT_EQ(m.positions[1], (Vec3{-2, 4, 0}));
    EXPECT_EQ(m.positions[2], (Vec3{1000, 0, -0.125f}));
    EXPECT_EQ(m.face_sizes, (std::vector<std::uint32_t>{3, 4}));
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 0, 1}));
    ASSERT_EQ(m.normals.size(), 3u);
    EXPECT_EQ(m.normals[1], (Vec3{0, 1, 0}));
    EXPECT_EQ(m.normal_indices, m.indices);
    ASSERT_EQ(m.texcoords.size(), 3u);
    EXPECT_EQ(m.texcoords[0], (Vec2{0.25f, 0.5f}));
    EXPECT_EQ(m.texcoord_indices, m.indices);
  }
}

TEST(PlyRead, AllEncodingsGiveTheSameMesh) {
  const IndexedMesh a = read_ply(ply("ascii", kRichHeader, rich_body()));
  expect_same(read_ply(ply("binary_little_endian", kRichHeader, rich_body())), a);
  expect_same(read_ply(ply("binary_big_endian", kRichHeader, rich_body())), a);
}

TEST(PlyRead, FacesBeforeVertices) {
  const std::string elements =
      "element face 1\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  // One triangle (first, 1, 0) over three vertices.
  auto with_first_index = [&](const char* format, double first) {
    return ply(format, elements,
               {{'B', 3},
                {'i', first},
                {'i', 1},
                {'i', 0},
                {'f', 0},
                {'f', 0},
                {'f', 0},
                {'f', 1},
                {'f', 0},
                {'f', 0},
                {'f', 0},
                {'f', 1},
                {'f', 0}});
  };
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    const IndexedMesh m = read_ply(with_first_index(format, 2));
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{2, 1, 0}));
    expect_ply_error(with_first_index(format, 3), "face 0: vertex index 3 is out of range (3 vertices)");
  }
}

TEST(PlyRead, CrlfHeaderAndEmptyElements) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float "
      "z\r\n"
      "element nothing 1000000000000\r\n"  // no properties: takes no bytes at all
      "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
      "0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n";
  const IndexedMesh m = read_ply(text);
  EXPECT_EQ(m.positions[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

const char* kTriangle =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";

std::vector<Val> triangle_body(double bad_coordinate, int bad_index) {
  return {{'f', 0},
          {'f', 0},
          {'f', 0},
          {'f', 1},
          {'f', bad_coordinate},
          {'f', 0},
          {'f', 0},
          {'f', 1},
          {'f', 0},
          {'B', 3},
          {'i', 0},
          {'i', 1},
          {'i', static_cast<double>(bad_index)}};
}

TEST(PlyRead, MalformedHeaders) {
  expect_ply_error("", "not a PLY file: expected 'ply' on the first line");
  expect_ply_error("plyx\nformat ascii 1.0\nend_header\n", "not a PLY file");
  expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\n", "expected 'end_header', got end of file");
  expect_ply_error("ply\nformat binary_middle_endian 1.0\nend_header\n", "got 'binary_middle_endian'");
  expect_ply_error("ply\nelement vertex 1\nproperty float x\nend_header\n", "missing 'format'");
  expect_ply_error("ply\nformat ascii 1.0\nproperty float x\nend_header\n",
                   "'property' before any 'element'");
  expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
                   "expected a property type, got 'float128'");
  expect_ply_error(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n",
      "expected an integer type for the list count, got 'float'");
  expect_ply_error("ply\nformat ascii 1.0\nelement vertex -5\nend_header\n",
                   "expected the number of 'vertex' elements");
  expect_ply_error("ply\nformat ascii 1.0\nbanana\nend_header\n", "unknown header keyword 'banana'");
  expect_ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n",
                   "the vertex element lacks a scalar x, y or z property");
  // No property at all: faces must not index vertices that were never read.
  expect_ply_error(
      "ply\nformat ascii 1.0\nelement vertex 4\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n3 0 1 2\n",
      "the vertex element lacks a scalar x, y or z property");
  expect_ply_error(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int corners\nend_header\n3 0 1 2\n",
      "the 'face' element has no vertex_indices list");
  expect_ply_error(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n3 0 1 "
      "2\n",
      "list must have an integer type");
  const IoError e = catch_io_error([] { read_ply("ply\nformat ascii 1.0\ncomment\nelement\n"); });
  EXPECT_EQ(e.line(), 4u);
}

TEST(PlyRead, LyingCountsFailBeforeAllocating) {
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    expect_ply_error(
        ply(format, "element vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\n",
            {{'f', 0}, {'f', 0}, {'f', 0}}),
        "the header claims 1000000000000 'vertex' elements, but only");
    expect_ply_error(
        ply(format, "element face 1000000000000\nproperty list uchar int vertex_indices\n", {{'B', 0}}),
        "claims 1000000000000 'face' elements");
    expect_ply_error(ply(format, "element blob 1000000000000\nproperty list uint uchar data\n", {{'I', 0}}),
                     "claims 1000000000000 'blob' elements");
    // A list longer than the file.
    expect_ply_error(
        ply(format, "element blob 1\nproperty list uint uchar data\n", {{'I', 4000000000.0}, {'B', 1}}),
        std::string(format) == "ascii" ? "expected a value, got end of file" : "truncated");
  }
}

TEST(PlyRead, TruncatedBinaryReportsTheByteOffset) {
  const std::string full = ply("binary_little_endian", kTriangle, triangle_body(0, 2));
  EXPECT_NO_THROW(read_ply(full));
  const std::size_t header = full.size() - (9 * 4 + 1 + 3 * 4);
  // Cut inside the face list: the error points at the index that is cut short. The indices start
  // at header + 37, after 9 floats and the count byte.
  const std::pair<std::size_t, std::size_t> cuts[] = {
      {full.size() - 1, header + 45}, {full.size() - 5, header + 41}, {header + 37, header + 37}};
  for (const auto& [cut_at, at] : cuts) {
    const std::size_t cut = cut_at;  // clang 14 cannot capture a structured binding
    const IoError e = catch_io_error([&] { read_ply(full.substr(0, cut)); });
    EXPECT_NE(std::string(e.what()).find("unexpected end of file"), std::string::npos) << e.what();
    EXPECT_EQ(e.byte_offset(), static_cast<std::int64_t>(at)) << e.what();
    EXPECT_EQ(e.line(), 0u);
  }
  // Cut inside the vertices: the element cannot fit in what is left.
  for (std::size_t cut : {header + 35, header + 13, header + 1, header}) {
    const IoError e = catch_io_error([&] { read_ply(full.substr(0, cut)); });
    EXPECT_NE(std::string(e.what()).find("the header claims 3 'vertex' elements"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.byte_offset(), static_cast<std::int64_t>(header));
  }
}

TEST(PlyRead, BadIndicesNameTheFace) {
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    expect_ply_error(ply(format, kTriangle, triangle_body(0, 3)),
                     "face 0: vertex index 3 is out of range (3 vertices)");
    expect_ply_error(ply(format, kTriangle, triangle_body(0, -1)), "face 0: vertex index -1 is out of range");
  }
  const std::string full = ply("binary_big_endian", kTriangle, triangle_body(0, 7));
  const IoError e = catch_io_error([&] { read_ply(full); });
  EXPECT_EQ(e.byte_offset(), static_cast<std::int64_t>(full.size() - 4));
  const IoError a = catch_io_error([&] { read_ply(ply("ascii", kTriangle, triangle_body(0, 7)) + "\n"); });
  EXPECT_EQ(a.line(), 10u);
}

// PLY allows faces before vertices: their indices are checked against the header's vertex count,
// so the first bad index is the one reported, not the largest.
TEST(PlyRead, TheFirstBadIndexIsReportedWhenFacesComeFirst) {
  const std::string faces_first =
      "element face 2\nproperty list uchar int vertex_indices\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  auto body = [](double first_bad, double second_bad) {
    return std::vector<Val>{{'B', 3}, {'i', 0},          {'i', 1}, {'i', first_bad}, {'B', 3}, {'i', 0},
                            {'i', 1}, {'i', second_bad}, {'f', 0}, {'f', 0},         {'f', 0}, {'f', 1},
                            {'f', 0}, {'f', 0},          {'f', 0}, {'f', 1},         {'f', 0}};
  };
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    expect_ply_error(ply(format, faces_first, body(5, 9)),
                     "face 0: vertex index 5 is out of range (3 vertices)");
    expect_ply_error(ply(format, faces_first, body(9, 5)),
                     "face 0: vertex index 9 is out of range (3 vertices)");
    expect_ply_error(ply(format, faces_first, body(2, 4)),
                     "face 1: vertex index 4 is out of range (3 vertices)");
  }
  // Where: the byte of the first bad index, after the header and the first face's count and two indices.
  const std::string binary = ply("binary_little_endian", faces_first, body(5, 9));
  const std::size_t header = binary.find("end_header\n") + 11;
  EXPECT_EQ(catch_io_error([&] { read_ply(binary); }).byte_offset(), static_cast<std::int64_t>(header + 9));
  const IndexedMesh m = read_ply(ply("ascii", faces_first, body(2, 1)));
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 1, 1}));
}

TEST(PlyRead, NonFiniteValuesNameTheVertex) {
  for (const char* format : kFormats) {
    SCOPED_TRACE(format);
    expect_ply_error(ply(format, kTriangle, triangle_body(std::nan(""), 2)),
                     "vertex 1 has a non-finite coordinate");
    expect_ply_error(ply(format, kTriangle, triangle_body(-INFINITY, 2)),
                     "vertex 1 has a non-finite coordinate");
  }
  // A double beyond float's range is not finite once stored as float.
  expect_ply_error(ply("binary_little_endian",
                       "element vertex 1\nproperty double x\nproperty double y\nproperty double z\n",
                       {{'d', 1e300}, {'d', 0}, {'d', 0}}),
                   "vertex 0 has a non-finite coordinate");
  const std::string full = ply("binary_little_endian", kTriangle, triangle_body(NAN, 2));
  const IoError e = catch_io_error([&] { read_ply(full); });
  EXPECT_EQ(e.byte_offset(), static_cast<std::int64_t>(full.size() - (13 + 3 * 4 + 4 * 3)));
}

TEST(PlyRead, GarbageBodies) {
  expect_ply_error(
      std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n",
      "expected a number, got 'x'");
  expect_ply_error(
      std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
      "negative list length -3");
  expect_ply_error(
      std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header\n0 0 0\n1 0 0\n0 1 0\n0\n",
      "face 0 has no corners");
  expect_ply_error(
      std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n",
      "expected an integer, got '1.5'");
  expect_ply_error(std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header\n0 0 0\n",
                   "the header claims 3 'vertex' elements");
  expect_ply_error(std::string("ply\nformat ascii 1.0\n") + kTriangle + "end_header extra\n",
                   "expected a newline after 'end_header'");
  expect_ply_error(
      std::string("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                  "property float z\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                  "end_header\n0 0 0\n0 0 0\n"),
      "more than one 'vertex' element");
}

TEST(PlyWrite, RoundTripIsExactInBothEncodings) {
  for (bool binary : {true, false}) {
    SCOPED_TRACE(binary);
    WriteOptions o;
    o.binary = binary;
    for (const char* file : {"bob_small.ply", "grid_tristrips.ply"}) {
      const IndexedMesh m = read_data(file);
      const std::string out = write_ply(m, o);
      EXPECT_EQ(out.find(binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n"), 4u);
      expect_same(read_ply(out), m);
    }
    // Rich: per-vertex normals and texture coordinates, polygons.
    const IndexedMesh r = read_ply(ply("ascii", kRichHeader, rich_body()));
    const std::string out = write_ply(r, o);
    EXPECT_NE(out.find("property float nx\n"), std::string::npos);
    expect_same(read_ply(out), r);
  }
}

TEST(PlyWrite, PerCornerNormalsAreNotWritten) {
  IndexedMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.indices = {0, 1, 2, 2, 1, 3};
  m.normals = {{0, 0, 1}, {0, 0, -1}};
  m.normal_indices = {0, 0, 0, 1, 1, 1};  // vertices 1 and 2 have two normals
  const std::string out = write_ply(m);
  EXPECT_EQ(out.find("nx"), std::string::npos);
  const IndexedMesh back = read_ply(out);
  EXPECT_TRUE(back.normals.empty());
  EXPECT_EQ(back.indices, m.indices);
  // Corners that agree per vertex are written as per-vertex normals.
  m.normal_indices = {0, 0, 0, 0, 0, 1};
  const IndexedMesh agree = read_ply(write_ply(m));
  ASSERT_EQ(agree.normals.size(), 4u);
  EXPECT_EQ(agree.normals[3], (Vec3{0, 0, -1}));
  EXPECT_EQ(agree.normals[0], (Vec3{0, 0, 1}));
}

TEST(PlyWrite, LargePolygonsUseAWideCount) {
  IndexedMesh m;
  for (int i = 0; i < 300; ++i) {
    const float a = static_cast<float>(i) * 0.02f;
    m.positions.push_back({std::cos(a), std::sin(a), 0});
    m.indices.push_back(static_cast<std::uint32_t>(i));
  }
  m.face_sizes = {300};
  for (bool binary : {true, false}) {
    WriteOptions o;
    o.binary = binary;
    const std::string out = write_ply(m, o);
    EXPECT_NE(out.find("property list uint uint vertex_indices"), std::string::npos);
    expect_same(read_ply(out), m);
  }
}

TEST(PlyWrite, BinaryLayoutIsLittleEndianFloat) {
  IndexedMesh m;
  m.positions = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
  m.indices = {0, 1, 2};
  const std::string out = write_ply(m);
  const std::size_t body = out.find("end_header\n") + 11;
  ASSERT_EQ(out.size(), body + 9 * 4 + 1 + 3 * 4);
  EXPECT_EQ(out.substr(body, 4), std::string("\x00\x00\x80\x3f", 4));  // 1.0f
  EXPECT_EQ(out[body + 36], '\x03');
  EXPECT_EQ(out.substr(out.size() - 4), std::string("\x02\x00\x00\x00", 4));
}

TEST(PlyWrite, RefusesANonFiniteValueBeforeWriting) {
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_ply(m); });
}

}  // namespace
}  // namespace hedge

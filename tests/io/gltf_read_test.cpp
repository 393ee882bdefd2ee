// The glTF reader (src/io/gltf_read.cpp): hand-written files, node transforms, sparse accessors,
// external buffers, and the errors of malformed files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io/base64.h"
#include "io/gltf_test_common.h"
#include "io/io_errors.h"
#include "support/io_checks.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace gltf_test;

using test::catch_io_error;
using test::data_path;
using test::same_bits;

using test::base64;

template <typename T>
void put(std::vector<unsigned char>& out, T v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + sizeof(T));
}

// A one-triangle file: positions (3 x float3) at byte 0, u16 indices at byte 36, one buffer in a
// data URI. `edit` changes the document before it is written out.
struct Triangle {
  std::vector<unsigned char> buffer;
  json doc;

  Triangle() {
    for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(buffer, v);
    for (const std::uint16_t i : {0, 1, 2}) put(buffer, i);
    buffer.resize(44, 0);
    doc = json::parse(R"({
      "asset": {"version": "2.0"},
      "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
        {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
      "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": 36},
        {"buffer": 0, "byteOffset": 36, "byteLength": 6}]
    })");
  }
  std::string text() const {
    json d = doc;
    d["buffers"] = json::array(
        {{{"byteLength", buffer.size()}, {"uri", "data:application/octet-stream;base64," + base64(buffer)}}});
    return d.dump();
  }
};

void expect_error(const std::string& text, const std::string& message) {
  const IoError e = catch_io_error([&] { read_gltf(text, "m.gltf"); });
  const std::string what = e.what();
  EXPECT_EQ(what.rfind("m.gltf: ", 0), 0u) << what;
  EXPECT_NE(what.find(message), std::string::npos) << what;
}

TEST(GltfRead, TheHandWrittenFileGivesBothNodesWithTheirAttributes) {
  const IndexedMesh m = read_gltf(read_file(data_path("two_quads.gltf")), "two_quads.gltf");
  ASSERT_EQ(m.positions.size(), 8u);
  // Node 0 as stored, node 1 raised by its translation.
  const std::vector<Vec3> quad = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(same_bits(m.positions[i], quad[i])) << i;
    EXPECT_TRUE(same_bits(m.positions[4 + i], quad[i] + Vec3{0, 0, 1})) << i;
  }
  // The u8 indices of node 0, then the strip of node 1 with its odd triangle flipped back to
  // counter-clockwise; the LINES primitive is skipped with a warning that names it.
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 4, 5, 6, 5, 7, 6}));
  EXPECT_TRUE(m.is_triangles());
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].text().find("mesh 1 primitive 1: mode 1 (lines)"), std::string::npos)
      << m.warnings[0].text();
  // Interleaved normals (byteStride 24) and normalized u16 texcoords, v flipped to a bottom-left origin.
  ASSERT_EQ(m.normals.size(), 8u);
  EXPECT_EQ(m.normal_indices, m.indices);
  for (const Vec3& n : m.normals) EXPECT_TRUE(same_bits(n, Vec3{0, 0, 1}));
  ASSERT_EQ(m.texcoords.size(), 8u);
  EXPECT_EQ(m.texcoord_indices, m.indices);
  const std::vector<Vec2> uv = {{0, 1}, {1, 1}, {0, 0}, {1, 0}};
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(m.texcoords[i].x, uv[i % 4].x) << i;
    EXPECT_EQ(m.texcoords[i].y, uv[i % 4].y) << i;
  }
  // Built: two separate quads, both facing +z.
  BuildReport report;
  const SurfaceMesh mesh = read_mesh(data_path("two_quads.gltf"), &report);
  EXPECT_EQ(mesh.n_vertices(), 8u);
  EXPECT_EQ(mesh.n_faces(), 4u);
  EXPECT_EQ(report.repairs(), 0u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("two_quads.gltf"), std::string::npos);
  EXPECT_TRUE(mesh.validate().empty());
  BuildOptions strict = default_build_options(FileFormat::gltf);
  strict.policy = TopologyPolicy::strict;
  EXPECT_THROW(read_mesh(data_path("two_quads.gltf"), strict), IoError);  // the skipped lines
}

TEST(GltfRead, TheCommittedGlbHoldsTheSameQuads) {
  const IndexedMesh text = read_indexed_file(data_path("two_quads.gltf"));
  const IndexedMesh binary = read_indexed_file(data_path("two_quads.glb"));
  EXPECT_TRUE(binary.warnings.empty());
  ASSERT_EQ(binary.positions.size(), text.positions.size());
  EXPECT_EQ(std::memcmp(binary.positions.data(), text.positions.data(), text.positions.size() * sizeof(Vec3)),
            0);
  EXPECT_EQ(binary.indices, text.indices);
  EXPECT_EQ(binary.texcoords.size(), text.texcoords.size());
  EXPECT_EQ(binary.normals.size(), text.normals.size());
}

TEST(GltfRead, NormalizedByteRgbColoursBecomeOpaqueFloats) {
  Triangle t;
  // COLOR_0 at byte 44: one u8 RGB colour per vertex, each padded to 4 bytes as glTF asks of
  // vertex attributes.
  const unsigned char rgb[3][3] = {{0, 128, 255}, {255, 0, 51}, {10, 20, 30}};
  for (const auto& c : rgb) t.buffer.insert(t.buffer.end(), {c[0], c[1], c[2], 0});
  t.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 12}, {"byteStride", 4}});
  t.doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}});
  t.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 2;
  const IndexedMesh m = read_gltf(t.text(), "m.gltf");
  ASSERT_EQ(m.colors.size(), 3u);
  EXPECT_EQ(m.color_indices, m.indices);
  for (std::size_t v = 0; v < 3; ++v) {
    EXPECT_FLOAT_EQ(m.colors[v].r, rgb[v][0] / 255.0f) << v;
    EXPECT_FLOAT_EQ(m.colors[v].g, rgb[v][1] / 255.0f) << v;
    EXPECT_FLOAT_EQ(m.colors[v].b, rgb[v][2] / 255.0f) << v;
    EXPECT_EQ(m.colors[v].a, 1.0f) << v;
  }
  EXPECT_EQ(m.colors[0].r, 0.0f);
  EXPECT_EQ(m.colors[1].r, 1.0f);
  // Not normalized, a byte colour is refused.
  t.doc["accessors"][2]["normalized"] = false;
  expect_error(t.text(),
               "COLOR_0: accessor 2: componentType 5121 is not FLOAT or a normalized unsigned byte or short");
}

TEST(GltfRead, NodeTransformsAreAppliedAndAMirrorKeepsTheOrientation) {
  Triangle t;
  t.doc["nodes"] = json::parse(R"([{"children": [1], "translation": [10, 0, 0]},
                                   {"mesh": 0, "scale": [-1, 2, 1]}])");
  const IndexedMesh m = read_gltf(t.text(), "m.gltf");
  ASSERT_EQ(m.positions.size(), 3u);
  EXPECT_TRUE(same_bits(m.positions[1], Vec3{9, 0, 0}));
  EXPECT_TRUE(same_bits(m.positions[2], Vec3{10, 2, 0}));
  // Mirrored in x: the triangle is reversed so that its normal still points to +z.
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 2, 1}));
  const Vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]], c = m.positions[m.indices[2]];
  EXPECT_GT(cross(b - a, c - a).z, 0.f);

  // A quarter turn about z (quaternion x y z w) moves x to y, and normals with it.
  Triangle r;
  r.doc["nodes"][0]["rotation"] = {0.0, 0.0, std::sqrt(0.5), std::sqrt(0.5)};
  const IndexedMesh turned = read_gltf(r.text(), "m.gltf");
  EXPECT_NEAR(turned.positions[1].x, 0.f, 1e-6f);
  EXPECT_NEAR(turned.positions[1].y, 1.f, 1e-6f);
  EXPECT_EQ(turned.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(GltfRead, WithoutScenesEveryMeshIsReadOnceAsStored) {
  Triangle t;
  t.doc.erase("scenes");
  t.doc["nodes"][0]["translation"] = {5, 5, 5};
  const IndexedMesh m = read_gltf(t.text(), "m.gltf");
  EXPECT_TRUE(same_bits(m.positions[1], Vec3{1, 0, 0}));
  // Two nodes may place one mesh twice.
  Triangle twice;
  twice.doc["nodes"] =
      json::parse(R"([{"mesh": 0, "children": [1]}, {"mesh": 0, "translation": [0, 0, 1]}])");
  const IndexedMesh two = read_gltf(twice.text(), "m.gltf");
  EXPECT_EQ(two.face_count(), 2u);
  EXPECT_TRUE(same_bits(two.positions[4], Vec3{1, 0, 1}));
}

TEST(GltfRead, SparseAccessorsFansAndNonIndexedPrimitives) {
  Triangle t;
  // Sparse: vertex 2 replaced by (0, 3, 0); index (u8) at byte 44, value at byte 48.
  t.buffer.push_back(2);
  t.buffer.resize(48, 0);
  for (const float v : {0.f, 3.f, 0.f}) put(t.buffer, v);
  t.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 1}});
  t.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}});
  t.doc["accessors"][0]["sparse"] = json::parse(
      R"({"count": 1, "indices": {"bufferView": 2, "componentType": 5121}, "values": {"bufferView": 3}})");
  t.doc["accessors"][0]["max"] = {1, 3, 0};
  const IndexedMesh m = read_gltf(t.text(), "m.gltf");
  EXPECT_TRUE(same_bits(m.positions[2], Vec3{0, 3, 0}));
  EXPECT_TRUE(same_bits(m.positions[1], Vec3{1, 0, 0}));

  // A fan without indices: vertices in order.
  Triangle fan;
  fan.doc["meshes"][0]["primitives"][0].erase("indices");
  fan.doc["meshes"][0]["primitives"][0]["mode"] = 6;
  EXPECT_EQ(read_gltf(fan.text(), "m.gltf").indices, (std::vector<std::uint32_t>{1, 2, 0}));
  Triangle plain;
  plain.doc["meshes"][0]["primitives"][0].erase("indices");
  EXPECT_EQ(read_gltf(plain.text(), "m.gltf").indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(GltfRead, ExternalBuffersAreReadBesideTheFile) {
  const fs::path dir = fs::temp_directory_path() / ("hedge_gltf_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Triangle t;
  {
    std::FILE* f = std::fopen((dir / "tri.bin").c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(t.buffer.data(), 1, t.buffer.size(), f);
    std::fclose(f);
  }
  json doc = t.doc;
  doc["buffers"] = json::array({{{"byteLength", t.buffer.size()}, {"uri", "tri.bin"}}});
  write_file_atomic((dir / "tri.gltf").string(), doc.dump());
  const IndexedMesh m = read_indexed_file((dir / "tri.gltf").string());
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_TRUE(same_bits(m.positions[1], Vec3{1, 0, 0}));
  fs::remove(dir / "tri.bin");
  const IoError e = catch_io_error([&] { read_indexed_file((dir / "tri.gltf").string()); });
  EXPECT_NE(std::string(e.what()).find("tri.bin"), std::string::npos) << e.what();
  fs::remove_all(dir);
}

TEST(GltfRead, MalformedFilesSayWhatAndWhere) {
  expect_error("{\"asset\": {\"version\": \"2.0\"", "malformed glTF");
  // A GLB's framing errors say the byte (the GLB cases are in gltf_guard_test.cpp).
  EXPECT_NE(std::string(
                catch_io_error([&] { read_gltf(std::string("glTF\x02\0\0\0garbage", 15), "m.glb"); }).what())
                .find("m.glb (byte 15): malformed glTF binary: truncated: the file ends at byte 15"),
            std::string::npos);
  {
    Triangle t;  // more elements than the view holds
    t.doc["accessors"][0]["count"] = 4;
    expect_error(t.text(),
                 "accessor 0: 4 elements of 12 bytes (stride 12) from byte 0 do not fit in bufferView 0");
  }
  {
    Triangle t;
    t.doc["bufferViews"][1]["byteOffset"] = 40;
    expect_error(t.text(), "bufferView 1: bytes [40, 40 + 6) are outside buffer 0 (44 bytes)");
  }
  {
    Triangle t;
    t.buffer[38] = 9;  // the second index
    expect_error(t.text(),
                 "mesh 0 primitive 0 indices: accessor 1: index 9 (element 1) is out of range (POSITION has "
                 "3 vertices)");
  }
  for (const int first : {5, 9}) {
    Triangle t;  // two indices out of range: the first is named
    t.buffer[38] = static_cast<unsigned char>(first);
    t.buffer[40] = static_cast<unsigned char>(14 - first);
    expect_error(t.text(), "index " + std::to_string(first) + " (element 1) is out of range");
  }
  {
    Triangle t;
    t.doc["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
    expect_error(t.text(), "mesh 0 primitive 0: has no POSITION attribute");
  }
  {
    Triangle t;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(t.buffer.data() + 16, &nan, 4);  // y of vertex 1
    expect_error(t.text(), "accessor 0: element 1 is not finite");
  }
  {
    Triangle t;
    t.doc["meshes"][0]["primitives"][0]["indices"] = 7;  // tinygltf's own check
    expect_error(t.text(), "malformed glTF: primitive indices accessor out of bounds");
    Triangle n;
    n.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 7;
    expect_error(n.text(), "mesh 0 primitive 0 NORMAL: accessor 7 does not exist (the file has 2)");
    Triangle m;  // a material the file does not have: named, not taken as a submesh number
    m.doc["meshes"][0]["primitives"][0]["material"] = 5;
    expect_error(m.text(), "mesh 0 primitive 0: material 5 does not exist (the file has 0)");
  }
  {
    Triangle t;
    t.doc["nodes"] = json::parse(R"([{"children": [1]}, {"children": [0], "mesh": 0}])");
    expect_error(t.text(), "node 1: node 0 is reached a second time (glTF nodes form trees)");
    Triangle twice;  // a node listed twice among the scene's roots
    twice.doc["scenes"][0]["nodes"] = {0, 0};
    expect_error(twice.text(), "scene 0: node 0 is reached a second time");
    Triangle deep;  // a hierarchy far deeper than a call stack could follow
    json nodes = json::array();
    for (int i = 0; i < 50000; ++i) nodes.push_back({{"children", {i + 1}}});
    nodes.push_back({{"mesh", 0}});
    deep.doc["nodes"] = nodes;
    EXPECT_EQ(read_gltf(deep.text(), "m.gltf").face_count(), 1u);
  }
  {
    Triangle t;
    t.doc["bufferViews"][0]["byteStride"] = 8;
    expect_error(t.text(), "byteStride 8 is smaller than an element (12 bytes)");
  }
  {
    Triangle t;  // integer texture coordinates must be normalized
    t.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2;
    t.doc["accessors"].push_back(
        {{"bufferView", 1}, {"componentType", 5121}, {"count", 3}, {"type", "VEC2"}});
    expect_error(
        t.text(),
        "TEXCOORD_0: accessor 2: componentType 5121 is not FLOAT or a normalized unsigned byte or short");
  }
  {
    Triangle t;  // colours are RGB or RGBA
    t.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 2;
    t.doc["accessors"].push_back(
        {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
    expect_error(t.text(), "COLOR_0: accessor 2: has 2 components, expected 4 or 3");
  }
  {
    Triangle t;
    t.doc["meshes"][0]["primitives"][0]["mode"] = 9;
    expect_error(t.text(), "mode 9 is not a glTF mode");
  }
  {
    Triangle t;
    t.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    t.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    expect_error(t.text(), "requires extension KHR_draco_mesh_compression");
  }
  {
    Triangle t;
    t.doc["meshes"][0]["primitives"][0]["indices"] = 0;  // a VEC3 float accessor
    expect_error(t.text(), "indices must be SCALAR");
  }
}

TEST(GltfFile, ExtensionsChooseTheFormats) {
  EXPECT_EQ(format_from_path("a/b.GLTF"), FileFormat::gltf);
  EXPECT_EQ(format_from_path("b.glb"), FileFormat::glb);
  EXPECT_EQ(default_build_options(FileFormat::glb).weld, Weld::exact);
  // Either is read whatever the extension says: the reader looks at the first bytes.
  Triangle t;
  EXPECT_EQ(read_indexed(t.text(), FileFormat::glb, "t").indices.size(), 3u);
}

}  // namespace
}  // namespace hedge

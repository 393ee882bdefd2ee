#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hedge/core/export.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "hedge/render/render_sync.h"
#include "io/base64.h"
#include "io/io_errors.h"

namespace hedge {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string data_path(const std::string& name) { return std::string(HEDGE_DATA_DIR) + "/" + name; }

using test::catch_io_error;

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

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof(Vec3)) == 0; }

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
  expect_error("glTF\x02\0\0\0garbage", "malformed glTF binary");
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

// Every corner of `a` has the same position (bit for bit), texcoord (within the rounding of the v
// flip) and normal in `b`.
void expect_same_corners(const IndexedMesh& a, const IndexedMesh& b) {
  ASSERT_EQ(a.indices.size(), b.indices.size());
  ASSERT_EQ(a.texcoord_indices.empty(), b.texcoord_indices.empty());
  ASSERT_EQ(a.normal_indices.empty(), b.normal_indices.empty());
  for (std::size_t c = 0; c < a.indices.size(); ++c) {
    ASSERT_TRUE(same_bits(a.positions[a.indices[c]], b.positions[b.indices[c]])) << c;
    if (!a.texcoord_indices.empty()) {
      const Vec2 s = a.texcoords[a.texcoord_indices[c]], t = b.texcoords[b.texcoord_indices[c]];
      ASSERT_EQ(s.x, t.x) << c;
      ASSERT_NEAR(s.y, t.y, 3e-8f) << c;
    }
    if (!a.normal_indices.empty()) {
      ASSERT_TRUE(same_bits(a.normals[a.normal_indices[c]], b.normals[b.normal_indices[c]])) << c;
    }
  }
}

TEST(GltfWrite, BothFormsRoundTripSpotsCornersAndKeepVertexOrder) {
  const IndexedMesh spot = read_obj(read_file(data_path("spot_triangulated.obj")));
  ASSERT_FALSE(spot.texcoord_indices.empty());
  for (const bool binary : {false, true}) {
    const std::string bytes = binary ? write_glb(spot) : write_gltf(spot);
    EXPECT_EQ(bytes.rfind(binary ? "glTF" : "{", 0), 0u);
    const IndexedMesh back = read_gltf(bytes, "spot");
    expect_same_corners(spot, back);
    // Mesh vertex v is glTF vertex v; the copies split off at seams come after.
    ASSERT_GT(back.positions.size(), spot.positions.size());
    EXPECT_EQ(std::memcmp(back.positions.data(), spot.positions.data(), spot.positions.size() * sizeof(Vec3)),
              0);
    EXPECT_TRUE(back.warnings.empty());
  }
}

TEST(GltfWrite, TheUvSeamsSurviveAFileRoundTrip) {
  const fs::path dir = fs::temp_directory_path() / ("hedge_gltf_seams_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  SurfaceMesh spot = read_mesh(data_path("spot_triangulated.obj"));
  RenderOptions uv_only;
  uv_only.normals = NormalSource::none;
  const std::size_t seams = RenderSync(spot, uv_only).seam_splits();
  ASSERT_GT(seams, 0u);
  for (const char* name : {"spot.glb", "spot.gltf"}) {
    const std::string path = (dir / name).string();
    write_mesh(spot, path);
    // The file holds one vertex per render vertex: the engines' split.
    EXPECT_EQ(read_indexed_file(path).positions.size(), spot.n_vertices() + seams) << name;
    SurfaceMesh back = read_mesh(path);
    EXPECT_EQ(back.n_vertices(), spot.n_vertices()) << name;
    EXPECT_EQ(back.n_faces(), spot.n_faces()) << name;
    EXPECT_EQ(RenderSync(back, uv_only).seam_splits(), seams) << name;
    EXPECT_TRUE(back.validate().empty());
    expect_same_corners(to_indexed(spot), to_indexed(back));
  }
  fs::remove_all(dir);
}

TEST(GltfWrite, HardEdgesSplitVerticesAndComeBackAsCornerNormals) {
  // A flat-shaded cube: 8 positions, one normal per side, so every vertex has 3 distinct normals.
  IndexedMesh cube;
  for (int i = 0; i < 8; ++i) cube.positions.push_back({float(i & 1), float(i >> 1 & 1), float(i >> 2 & 1)});
  cube.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                  2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  cube.normals = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  for (std::uint32_t t = 0; t < 12; ++t)
    cube.normal_indices.insert(cube.normal_indices.end(), {t / 2, t / 2, t / 2});
  const IndexedMesh back = read_gltf(write_glb(cube), "cube.glb");
  EXPECT_EQ(back.positions.size(), 24u);  // 8 vertices x 3 sides
  expect_same_corners(cube, back);
  // Built with the default welding: the closed cube again, its normals on the corners.
  const SurfaceMesh mesh = build(back, default_build_options(FileFormat::glb));
  EXPECT_EQ(mesh.n_vertices(), 8u);
  EXPECT_EQ(mesh.n_faces(), 12u);
  EXPECT_TRUE(mesh.boundary_loops().empty());
  EXPECT_TRUE(mesh.validate().empty());
  expect_same_corners(cube, to_indexed(mesh));
}

TEST(GltfWrite, ColoursSurviveAGlbRoundTripPerCorner) {
  // A cube with a colour per side and translucent corners: three colours at every vertex.
  IndexedMesh cube;
  for (int i = 0; i < 8; ++i) cube.positions.push_back({float(i & 1), float(i >> 1 & 1), float(i >> 2 & 1)});
  cube.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                  2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  for (std::uint32_t s = 0; s < 6; ++s)
    cube.colors.push_back({0.1f * float(s), 0.3f, 1.0f / 3.0f, s % 2 ? 0.7f : 1.0f});
  for (std::uint32_t t = 0; t < 12; ++t)
    cube.color_indices.insert(cube.color_indices.end(), {t / 2, t / 2, t / 2});
  const SurfaceMesh mesh = build(cube);
  ASSERT_TRUE(mesh.get_halfedge_property<Color>("h:color"));

  const fs::path dir = fs::temp_directory_path() / ("hedge_gltf_colours_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "cube.glb").string();
  write_mesh(mesh, path);
  const IndexedMesh file = read_indexed_file(path);
  EXPECT_EQ(file.positions.size(), 24u);  // split where the colours differ: 8 vertices x 3 sides
  const SurfaceMesh back = read_mesh(path);
  fs::remove_all(dir);
  EXPECT_EQ(back.n_vertices(), 8u);
  EXPECT_EQ(back.n_faces(), 12u);
  EXPECT_TRUE(back.validate().empty());
  const IndexedMesh a = to_indexed(mesh), b = to_indexed(back);
  ASSERT_EQ(a.indices.size(), b.indices.size());
  ASSERT_EQ(b.color_indices.size(), b.indices.size());
  for (std::size_t c = 0; c < a.indices.size(); ++c) {
    EXPECT_TRUE(same_bits(a.positions[a.indices[c]], b.positions[b.indices[c]])) << c;
    EXPECT_EQ(b.colors[b.color_indices[c]], a.colors[a.color_indices[c]]) << c;  // float: exact
  }
  // Written as float RGBA.
  const json doc = json::parse(write_gltf(cube));
  const json& col = doc["accessors"][doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"].get<int>()];
  EXPECT_EQ(col["componentType"], 5126);
  EXPECT_EQ(col["type"], "VEC4");
}

TEST(GltfWrite, TheDocumentHasWhatTheSpecificationRequires) {
  IndexedMesh quad;
  quad.positions = {{-1, 0, 2}, {1, 0, 2}, {1, 3, 2}, {-1, 3, 5}};
  quad.indices = {0, 1, 2, 3};
  quad.face_sizes = {4};
  quad.normals = {{0, 0, 1}, {1, 0, 0}};
  quad.normal_indices = {0, 0, 0, 1};  // a hard corner: vertex 3 keeps its own normal
  const json doc = json::parse(write_gltf(quad));
  EXPECT_EQ(doc["asset"]["version"], "2.0");
  const json& prim = doc["meshes"][0]["primitives"][0];
  EXPECT_EQ(prim["mode"], 4);
  const json& pos = doc["accessors"][prim["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(pos["min"], json::parse("[-1, 0, 2]"));
  EXPECT_EQ(pos["max"], json::parse("[1, 3, 5]"));
  EXPECT_EQ(pos["count"], 4);
  EXPECT_TRUE(prim["attributes"].contains("NORMAL"));
  EXPECT_FALSE(prim["attributes"].contains("TEXCOORD_0"));
  EXPECT_FALSE(prim["attributes"].contains("COLOR_0"));
  const json& idx = doc["accessors"][prim["indices"].get<int>()];
  EXPECT_EQ(idx["componentType"], 5123);  // u16
  EXPECT_EQ(idx["count"], 6);             // the quad fanned into two triangles
  EXPECT_EQ(doc["buffers"][0]["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0),
            0u);
  const IndexedMesh back = read_gltf(write_gltf(quad), "q");
  EXPECT_EQ(back.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));

  // The binary container: magic, version 2, total length, JSON chunk first.
  const std::string glb = write_glb(quad);
  std::uint32_t header[5];
  ASSERT_GE(glb.size(), sizeof header);
  std::memcpy(header, glb.data(), sizeof header);
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(header[1], 2u);
  EXPECT_EQ(header[2], glb.size());
  EXPECT_EQ(glb.substr(16, 4), "JSON");
}

TEST(GltfWrite, LargeMeshesGetThirtyTwoBitIndices) {
  IndexedMesh strip;
  const std::uint32_t n = 70000;
  for (std::uint32_t i = 0; i < n; ++i)
    strip.positions.push_back({static_cast<float>(i / 2), static_cast<float>(i % 2), 0});
  for (std::uint32_t i = 0; i + 2 < n; ++i) {
    if (i % 2 == 0)
      strip.indices.insert(strip.indices.end(), {i, i + 1, i + 2});
    else
      strip.indices.insert(strip.indices.end(), {i, i + 2, i + 1});
  }
  const json doc = json::parse(write_gltf(strip));
  const int idx = doc["meshes"][0]["primitives"][0]["indices"];
  EXPECT_EQ(doc["accessors"][idx]["componentType"], 5125);  // u32
  const IndexedMesh back = read_gltf(write_glb(strip), "big");
  EXPECT_EQ(back.indices, strip.indices);
  EXPECT_EQ(back.positions.size(), strip.positions.size());
}

TEST(GltfWrite, VerticesNoFaceUsesKeepTheirPositionsAndGetZeroAttributes) {
  IndexedMesh m;
  m.positions = {{5, 6, 7}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {8, 9, 10}};
  m.indices = {1, 2, 3};
  m.texcoords = {{0.25f, 0.5f}};
  m.texcoord_indices = {0, 0, 0};
  const IndexedMesh back = read_gltf(write_gltf(m), "m");
  ASSERT_EQ(back.positions.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_TRUE(same_bits(back.positions[i], m.positions[i])) << i;
  EXPECT_EQ(back.indices, m.indices);
  EXPECT_EQ(back.texcoords[0].x, 0.f);  // isolated: zeros
  EXPECT_EQ(back.texcoords[0].y, 0.f);
  EXPECT_EQ(back.texcoords[2].x, 0.25f);
}

TEST(GltfWrite, AMeshWithoutFacesGivesNoSceneAndBadMeshesAreRefused) {
  IndexedMesh none;
  none.positions = {{1, 2, 3}};
  const IndexedMesh back = read_gltf(write_glb(none), "empty");
  EXPECT_TRUE(back.positions.empty());
  EXPECT_TRUE(back.indices.empty());
  IndexedMesh bad;
  bad.positions = {{0, 0, 0}};
  bad.indices = {0, 0, 5};
  EXPECT_THROW(write_glb(bad), InvalidInputError);
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

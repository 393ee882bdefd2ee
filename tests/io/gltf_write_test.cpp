// The glTF writer (src/io/gltf_write.cpp): round trips through the reader, seams, hard edges,
// colours, the document's required parts and the index width.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "caught.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/properties.h"
#include "hedge/render/render_buffers.h"
#include "io/gltf_test_common.h"
#include "io/io_errors.h"
#include "support/io_checks.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace gltf_test;
using test::data_path;

using test::same_bits;

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
  const std::size_t seams = RenderBuffers(spot, uv_only).seam_splits();
  ASSERT_GT(seams, 0u);
  for (const char* name : {"spot.glb", "spot.gltf"}) {
    const std::string path = (dir / name).string();
    write_mesh(spot, path);
    // The file holds one vertex per render vertex: the engines' split.
    EXPECT_EQ(read_indexed_file(path).positions.size(), spot.n_vertices() + seams) << name;
    SurfaceMesh back = read_mesh(path);
    EXPECT_EQ(back.n_vertices(), spot.n_vertices()) << name;
    EXPECT_EQ(back.n_faces(), spot.n_faces()) << name;
    EXPECT_EQ(RenderBuffers(back, uv_only).seam_splits(), seams) << name;
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

// A mesh with submeshes (a solid fracture piece: outer faces in 0, caps in 2) is one primitive per
// submesh with material N for submesh N, over shared vertex accessors; reading it back gives the
// same vertices, each face with its corners and its submesh, the faces grouped by submesh.
TEST(GltfWrite, SubmeshesArePrimitivesWithTheirMaterialsAndReadBack) {
  IndexedMesh spot = read_obj(read_file(data_path("spot_triangulated.obj")));
  const std::size_t faces = spot.face_count();
  for (std::size_t f = 0; f < faces; ++f) spot.face_submeshes.push_back(f % 3 == 1 ? 2 : 0);
  const json doc = json::parse(write_gltf(spot));
  const json& prims = doc["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 2u);
  ASSERT_EQ(doc["materials"].size(), 3u);  // submesh 1 is unused but keeps its number
  EXPECT_EQ(doc["materials"][2]["name"], "submesh_2");
  EXPECT_EQ(prims[0]["material"], 0);
  EXPECT_EQ(prims[1]["material"], 2);
  EXPECT_EQ(prims[0]["attributes"], prims[1]["attributes"]);
  EXPECT_NE(prims[0]["indices"], prims[1]["indices"]);

  const IndexedMesh plain =
      read_gltf(write_glb(read_obj(read_file(data_path("spot_triangulated.obj")))), "p");
  for (const bool binary : {false, true}) {
    const IndexedMesh back = read_gltf(binary ? write_glb(spot) : write_gltf(spot), "spot");
    // The primitives share their vertices: as many as without submeshes, in the same order.
    ASSERT_EQ(back.positions.size(), plain.positions.size());
    EXPECT_EQ(
        std::memcmp(back.positions.data(), plain.positions.data(), plain.positions.size() * sizeof(Vec3)), 0);
    ASSERT_EQ(back.face_submeshes.size(), faces);
    std::size_t read = 0;
    for (const std::int32_t s : {0, 2})
      for (std::size_t f = 0; f < faces; ++f) {
        if (spot.face_submeshes[f] != s) continue;
        EXPECT_EQ(back.face_submeshes[read], s) << f;
        for (std::size_t k = 0; k < 3; ++k)
          ASSERT_TRUE(
              same_bits(back.positions[back.indices[3 * read + k]], spot.positions[spot.indices[3 * f + k]]))
              << f;
        ++read;
      }
    EXPECT_EQ(read, faces);
  }
  // A file read without materials has no submeshes; out-of-range submeshes are refused by name.
  EXPECT_TRUE(plain.face_submeshes.empty());
  spot.face_submeshes[5] = -1;
  const InvalidInputError e =
      test::caught<InvalidInputError>([&] { write_glb(spot); }, InvalidInputError(""));
  EXPECT_EQ(std::string(e.what()), "indexed mesh: face 5 has submesh -1, outside [0, 65535]");
  spot.face_submeshes.pop_back();
  EXPECT_THROW(write_gltf(spot), InvalidInputError);
}

// The mesh a file with submeshes builds into carries them as "f:submesh".
TEST(GltfWrite, ASurfaceMeshKeepsItsSubmeshesThroughAGlbFile) {
  SurfaceMesh cube = build(read_obj(read_file(data_path("spot_triangulated.obj"))));
  auto submesh = cube.add_face_property<std::int32_t>(kSubmeshProperty);
  for (const Face f : cube.faces()) submesh[f] = static_cast<std::int32_t>(f.idx() % 2);
  const IndexedMesh back = read_gltf(write_glb(to_indexed(cube)), "cube");
  const SurfaceMesh again = build(back, default_build_options(FileFormat::glb));
  EXPECT_TRUE(again.validate().empty());
  const auto read = again.get_face_property<std::int32_t>(kSubmeshProperty);
  ASSERT_TRUE(read);
  std::size_t odd = 0;
  for (const Face f : again.faces()) odd += static_cast<std::size_t>(read[f]);
  std::size_t expected = 0;
  for (const Face f : cube.faces()) expected += static_cast<std::size_t>(submesh[f]);
  EXPECT_EQ(odd, expected);
  EXPECT_GT(odd, 0u);
}

TEST(GltfWrite, RefusesANonFiniteValueBeforeWriting) {
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_gltf(m); });
  test::expect_writer_refuses_non_finite([](const IndexedMesh& m) { return write_glb(m); });
}

}  // namespace
}  // namespace hedge

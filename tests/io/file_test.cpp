#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/core/face_operations.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "io/file_fixture.h"
#include "io/io_errors.h"
#include "test_meshes.h"

namespace hedge {
namespace {

namespace fs = std::filesystem;

using test::catch_io_error;
using test::data_path;
using test::expect_io_error;
using test::FileTest;

TEST(FormatFromPath, ExtensionsAreCaseInsensitive) {
  EXPECT_EQ(format_from_path("a/b/mesh.obj"), FileFormat::obj);
  EXPECT_EQ(format_from_path("MESH.OFF"), FileFormat::off);
  EXPECT_EQ(format_from_path("x.y.Ply"), FileFormat::ply);
  EXPECT_EQ(format_from_path("/abs/part.StL"), FileFormat::stl);
  EXPECT_EQ(format_from_path("mesh.GLTF"), FileFormat::gltf);
  EXPECT_EQ(format_from_path("mesh.Glb"), FileFormat::glb);
  EXPECT_THROW(format_from_path("mesh.fbx"), IoError);
  EXPECT_THROW(format_from_path("dir.obj/mesh"), IoError);
  EXPECT_THROW(format_from_path("obj"), IoError);
  // An empty path says so, rather than blaming an extension.
  try {
    format_from_path("");
    ADD_FAILURE() << "an empty path was accepted";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("the path is empty"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("unknown file extension"), std::string::npos) << e.what();
  }
  try {
    format_from_path("model.3ds");
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), "model.3ds");
    EXPECT_NE(std::string(e.what()).find("unknown file extension"), std::string::npos);
  }
}

TEST(DefaultBuildOptions, RepairEverywhereAndWeldOnlyStlAndGltf) {
  for (FileFormat f : {FileFormat::obj, FileFormat::off, FileFormat::ply, FileFormat::stl, FileFormat::gltf,
                       FileFormat::glb}) {
    const BuildOptions o = default_build_options(f);
    EXPECT_EQ(o.policy, TopologyPolicy::repair);
    const bool welds = f == FileFormat::stl || f == FileFormat::gltf || f == FileFormat::glb;
    EXPECT_EQ(o.weld, welds ? Weld::exact : Weld::none);
  }
}

TEST(ReadIndexed, DispatchesOnTheFormat) {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_indexed(off, FileFormat::off).indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_THROW(read_indexed(off, FileFormat::obj), IoError);
  EXPECT_THROW(read_indexed(off, FileFormat::ply), IoError);
  EXPECT_THROW(read_indexed(off, FileFormat::gltf), IoError);
  IndexedMesh m = read_indexed(off, FileFormat::off);
  for (FileFormat f : {FileFormat::obj, FileFormat::off, FileFormat::ply, FileFormat::stl, FileFormat::gltf,
                       FileFormat::glb})
    EXPECT_EQ(read_indexed(write_indexed(m, f), f).positions, m.positions);
}

TEST_F(FileTest, IndexedFilesInEveryFormat) {
  IndexedMesh m = read_indexed_file(data_path("fandisk_quads.off"));
  // Colours, which only glTF carries, are left out by the other writers.
  m.colors = {{1, 0, 0, 1}, {0, 0, 1, 0.5f}};
  for (std::size_t c = 0; c < m.indices.size(); ++c)
    m.color_indices.push_back(static_cast<std::uint32_t>(c % 2));
  for (const char* ext : {"obj", "off", "ply"}) {
    SCOPED_TRACE(ext);
    const std::string p = path(std::string("m.") + ext);
    write_indexed_file(m, p);
    const IndexedMesh back = read_indexed_file(p);
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.face_sizes, m.face_sizes);
    EXPECT_TRUE(back.color_indices.empty());
  }
  write_indexed_file(m, path("m.stl"));
  const IndexedMesh stl = read_indexed_file(path("m.stl"));
  EXPECT_EQ(stl.face_count(), 2 * m.face_count());  // quads fanned into two triangles
  EXPECT_THROW(write_indexed_file(m, path("m.xyz")), IoError);
  EXPECT_FALSE(fs::exists(path("m.xyz")));
}

TEST_F(FileTest, ErrorsFromFilesNameThePath) {
  put(path("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
  const IoError e = catch_io_error([&] { read_indexed_file(path("bad.obj")); });
  EXPECT_EQ(e.path(), path("bad.obj"));
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(std::string(e.what()), path("bad.obj") + ":3: expected a vertex index after 'f', got 'x'");
}

TEST_F(FileTest, ATruncatedFaceLineIsNamedWithItsLine) {
  // A file cut in the middle of its last face line: "f 3" has one corner.
  const std::string cut = path("cut.obj");
  put(cut, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 3\n");
  // Strict: refused, with the line.
  try {
    read_mesh(cut, BuildOptions{.policy = TopologyPolicy::strict});
    FAIL() << "a one-corner face under the strict policy";
  } catch (const IoError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_EQ(std::string(e.what()),
              cut + ":6: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  }
  // Repair: the face is dropped, and the report says where and why, not only a count.
  BuildReport report;
  const SurfaceMesh m = read_mesh(cut, &report);
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(report.degenerate_faces, 1u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            cut + ":6: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  EXPECT_TRUE(m.validate().empty());

  // The same in OFF (line of the record) and PLY (ascii: line; binary: byte offset of the face).
  const std::string off = path("cut.off");
  put(off, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n2 2 1\n");
  report = {};
  read_mesh(off, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            off + ":8: face 1 has 2 corners; a face needs at least 3 (the file may be truncated)");
  EXPECT_THROW(read_mesh(off, BuildOptions{.policy = TopologyPolicy::strict}), IoError);

  const std::string header =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string ascii = path("cut.ply");
  put(ascii, "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n1 2\n");
  report = {};
  read_mesh(ascii, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            ascii + ":14: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  const std::string binary = path("cut_binary.ply");
  std::string body;
  auto f32 = [&](float v) { body.append(reinterpret_cast<const char*>(&v), 4); };
  auto i32 = [&](std::int32_t v) { body.append(reinterpret_cast<const char*>(&v), 4); };
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) f32(v);
  body += char(3);
  for (int v : {0, 1, 2}) i32(v);
  const std::size_t second_face = body.size();
  body += char(1);
  i32(2);
  const std::string head = "ply\nformat binary_little_endian 1.0\n" + header;
  put(binary, head + body);
  report = {};
  read_mesh(binary, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            binary + " (byte " + std::to_string(head.size() + second_face) +
                "): face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
}

TEST(ReadMesh, BuildsWithTheFormatDefaults) {
  BuildReport report;
  const SurfaceMesh tet = read_mesh(data_path("tet.obj"), &report);
  EXPECT_EQ(tet.n_vertices(), 4u);
  EXPECT_EQ(tet.n_faces(), 4u);
  EXPECT_EQ(report.repairs(), 0u);
  // STL: 60 soup corners welded exactly into the icosahedron's 12 vertices.
  const SurfaceMesh ico = read_mesh(data_path("icosahedron_binary.stl"), &report);
  EXPECT_EQ(ico.n_vertices(), 12u);
  EXPECT_EQ(ico.n_faces(), 20u);
  EXPECT_EQ(report.welded_vertices, 48u);
  // Explicit options override the defaults.
  BuildOptions none;
  none.policy = TopologyPolicy::repair;
  EXPECT_EQ(read_mesh(data_path("icosahedron_binary.stl"), none).n_vertices(), 60u);
  EXPECT_THROW(read_mesh(data_path("hourglass_ico.obj"), BuildOptions{}), TopologyError);
}

TEST(ReadMesh, EveryDataFileLoadsWithRepair) {
  for (const auto& entry : fs::directory_iterator(HEDGE_DATA_DIR)) {
    const std::string p = entry.path().string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    SCOPED_TRACE(p);
    BuildReport report;
    const IndexedMesh input = read_indexed_file(p);
    const SurfaceMesh m = read_mesh(p, &report);
    EXPECT_GT(m.n_faces(), 0u);
    EXPECT_LE(m.n_faces(), input.face_count());
    EXPECT_EQ(m.n_faces() + report.degenerate_faces, input.face_count());
  }
  BuildReport spider;
  read_mesh(data_path("Spider_binary.stl"), &spider);
  EXPECT_GT(spider.repairs(), 0u);
  EXPECT_GT(spider.degenerate_faces, 0u);
}

// Faces as position triples, each rotated to start at its smallest corner, sorted: equal for two
// meshes with the same positions and oriented connectivity, whatever their vertex order.
std::vector<std::array<std::tuple<float, float, float>, 3>> canonical_triangles(const IndexedMesh& m) {
  std::vector<std::array<std::tuple<float, float, float>, 3>> out;
  for (std::size_t t = 0; t < m.face_count(); ++t) {
    std::array<std::tuple<float, float, float>, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.positions[m.indices[3 * t + static_cast<std::size_t>(k)]];
      tri[static_cast<std::size_t>(k)] = {p.x, p.y, p.z};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST_F(FileTest, RoundTripThroughEveryFormatKeepsPositionsAndConnectivity) {
  const std::string start = data_path("spot_triangulated.obj");
  const IndexedMesh original = read_indexed_file(start);
  SurfaceMesh mesh = read_mesh(start);
  for (const char* ext : {"off", "ply", "stl", "obj"}) {
    SCOPED_TRACE(ext);
    const std::string p = path(std::string("step.") + ext);
    write_mesh(mesh, p);
    mesh = read_mesh(p);
    EXPECT_EQ(mesh.n_vertices(), original.positions.size());
    EXPECT_EQ(mesh.n_faces(), original.face_count());
  }
  const IndexedMesh final_mesh = read_indexed_file(path("step.obj"));
  EXPECT_EQ(final_mesh.positions.size(), original.positions.size());
  std::vector<Vec3> a = original.positions, b = final_mesh.positions;
  auto less = [](const Vec3& u, const Vec3& v) { return std::tie(u.x, u.y, u.z) < std::tie(v.x, v.y, v.z); };
  std::sort(a.begin(), a.end(), less);
  std::sort(b.begin(), b.end(), less);
  EXPECT_EQ(a, b);
  EXPECT_TRUE(canonical_triangles(final_mesh) == canonical_triangles(original));
}

TEST_F(FileTest, WriteMeshTriangulatesForStl) {
  const SurfaceMesh m = read_mesh(data_path("spot_control_mesh.obj"));
  write_mesh(m, path("cage.stl"));
  // 4 triangles, 160 quads and 16 pentagons: 4 + 320 + 48 triangles.
  EXPECT_EQ(read_indexed_file(path("cage.stl")).face_count(), 372u);
  write_mesh(m, path("cage.obj"));
  const IndexedMesh obj = read_indexed_file(path("cage.obj"));
  EXPECT_EQ(obj.face_count(), 180u);
  EXPECT_EQ(obj.texcoord_indices.size(), obj.indices.size());
  WriteOptions ascii;
  ascii.binary = false;
  write_mesh(m, path("cage.ply"), ascii);
  EXPECT_EQ(read_file(path("cage.ply")).find("format ascii 1.0"), 4u);
}

// Every real mesh beside the project, defects included, loads in repair mode into a valid mesh,
// and only degenerate faces are dropped. Skipped where the shared meshes are absent.
TEST(ReadMesh, EverySharedMeshRepairsIntoAValidMesh) {
  const fs::path dir = HEDGE_SHARED_MESHES_DIR;
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no shared meshes beside the project";
  std::size_t checked = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const IndexedMesh indexed = read_indexed_file(entry.path().string());
    BuildReport report;
    const SurfaceMesh mesh = read_mesh(entry.path().string(), &report);
    EXPECT_TRUE(mesh.validate().empty());
    EXPECT_EQ(mesh.n_faces() + report.degenerate_faces, indexed.face_count());
    for (Vertex v : mesh.vertices()) ASSERT_TRUE(mesh.is_manifold(v));
    ++checked;
  }
  EXPECT_GE(checked, 20u);
}

TEST_F(FileTest, WriteMeshRefusesANonFinitePositionAndLeavesTheFile) {
  SurfaceMesh m = build(test::cube());
  // Garbage renumbers the exported vertices: the error names the mesh's own vertex.
  ASSERT_TRUE(remove_vertex(m, Vertex(0)));
  m.position(Vertex(6)).z = std::numeric_limits<float>::quiet_NaN();
  for (const char* name : {"a.obj", "a.off", "a.ply", "a.stl", "a.gltf", "a.glb"}) {
    put(path(name), "old");
    const InvalidInputError e =
        test::caught<InvalidInputError>([&] { write_mesh(m, path(name)); }, InvalidInputError(""));
    EXPECT_EQ(std::string(e.what()).rfind("write_mesh: vertex 6 has a non-finite position (", 0), 0u)
        << e.what();
    EXPECT_EQ(read_file(path(name)), "old") << name;
  }
  EXPECT_EQ(listing().size(), 6u);  // no temporary file left
}

}  // namespace
}  // namespace hedge

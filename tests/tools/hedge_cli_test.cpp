// Runs the built hedge CLI as a user would and checks exit codes, output and error messages.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

std::size_t total_repairs(const json& j) {
  std::size_t n = 0;
  for (const char* key : {"degenerate_faces", "repeated_corners", "reoriented_faces", "non_manifold_edges",
                          "non_manifold_vertices", "duplicated_vertices"}) {
    n += j["repairs"][key].get<std::size_t>();
  }
  return n;
}

TEST_F(HedgeCli, InfoJsonHasEveryKeyWithTheTetrahedronsValues) {
  const std::string file = data("tet.obj");
  const json j = run_json({"info", file, "--json"});
  for (const char* key :
       {"file", "vertices", "edges", "faces", "halfedges", "boundary_loops", "components",
        "euler_characteristic", "genus", "is_triangle_mesh", "is_manifold", "valid", "problems", "repairs"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key :
       {"welded_vertices", "degenerate_faces", "repeated_corners", "reoriented_faces", "non_manifold_edges",
        "non_manifold_vertices", "duplicated_vertices", "isolated_vertices"}) {
    ASSERT_TRUE(j["repairs"].contains(key)) << key;
    EXPECT_EQ(j["repairs"][key], 0) << key;
  }
  EXPECT_EQ(j["file"], file);
  EXPECT_EQ(j["vertices"], 4);
  EXPECT_EQ(j["edges"], 6);
  EXPECT_EQ(j["faces"], 4);
  EXPECT_EQ(j["halfedges"], 12);
  EXPECT_EQ(j["boundary_loops"], 0);
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_EQ(j["genus"], 0);
  EXPECT_EQ(j["is_triangle_mesh"], true);
  EXPECT_EQ(j["is_manifold"], true);
  EXPECT_EQ(j["valid"], true);
  EXPECT_TRUE(j["problems"].is_array());
  EXPECT_TRUE(j["problems"].empty());
}

TEST_F(HedgeCli, InfoTextListsTheCounts) {
  const Result r = run({"info", data("tet.obj")});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("vertices"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Euler characteristic"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("repairs"), std::string::npos) << r.out;
}

TEST_F(HedgeCli, InfoOnAPolygonMesh) {
  const json j = run_json({"info", data("spot_control_mesh.obj"), "--json"});
  EXPECT_EQ(j["vertices"], 188);
  EXPECT_EQ(j["faces"], 180);
  EXPECT_EQ(j["is_triangle_mesh"], false);
  EXPECT_EQ(j["boundary_loops"], 0);
  EXPECT_EQ(j["genus"], 0);
  EXPECT_EQ(j["valid"], true);
}

TEST_F(HedgeCli, InfoComputesTheGenus) {
  const json torus = run_json({"info", data("bob_small.ply"), "--json"});
  EXPECT_EQ(torus["euler_characteristic"], 0);
  EXPECT_EQ(torus["genus"], 1);
  const json anchor = run_json({"info", data("anchor.off"), "--json"});
  EXPECT_EQ(anchor["genus"], 4);
}

TEST_F(HedgeCli, GenusIsNullForAnOpenMesh) {
  const json j = run_json({"info", data("degtri_four.off"), "--json"});
  EXPECT_TRUE(j["genus"].is_null());
  EXPECT_GE(j["boundary_loops"], 1);
}

TEST_F(HedgeCli, DefectMeshesReportRepairs) {
  const json cube = run_json({"info", data("cube-minimal-degenerated.obj"), "--json"});
  EXPECT_GT(total_repairs(cube), 0u);
  EXPECT_EQ(cube["valid"], true);
  EXPECT_EQ(cube["is_manifold"], true);

  const json sheets = run_json({"info", data("triple_vierbein.obj"), "--json"});
  EXPECT_GT(sheets["repairs"]["non_manifold_edges"].get<int>(), 0);
  EXPECT_GT(sheets["repairs"]["non_manifold_vertices"].get<int>(), 0);
}

TEST_F(HedgeCli, StlIsWeldedAndCanBeLeftUnwelded) {
  const json welded = run_json({"info", data("icosahedron_binary.stl"), "--json"});
  EXPECT_EQ(welded["vertices"], 12);
  EXPECT_EQ(welded["faces"], 20);
  EXPECT_EQ(welded["genus"], 0);
  const json soup = run_json({"info", data("icosahedron_binary.stl"), "--json", "--weld", "none"});
  EXPECT_EQ(soup["vertices"], 60);
  EXPECT_EQ(soup["components"], 20);
  EXPECT_TRUE(soup["genus"].is_null());
}

TEST_F(HedgeCli, StrictInfoRejectsADefectMesh) {
  expect_data_error({"info", data("cube-minimal-degenerated.obj"), "--strict"},
                    "cube-minimal-degenerated.obj");
}

TEST_F(HedgeCli, ValidateExitCodes) {
  const Result ok = run({"validate", data("tet.obj")});
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("valid"), std::string::npos);

  const json j = run_json({"validate", data("spot_control_mesh.obj"), "--json"});
  EXPECT_EQ(j["valid"], true);
  EXPECT_TRUE(j["problems"].empty());

  const Result strict = run({"validate", data("triple_vierbein.obj"), "--strict"});
  EXPECT_EQ(strict.code, 1);
  EXPECT_NE(strict.out.find("invalid"), std::string::npos) << strict.out;
  EXPECT_NE(strict.out.find("topology error"), std::string::npos) << strict.out;

  const Result strict_json = run({"validate", data("triple_vierbein.obj"), "--strict", "--json"});
  EXPECT_EQ(strict_json.code, 1);
  ASSERT_TRUE(json::accept(strict_json.out)) << strict_json.out;
  const json sj = json::parse(strict_json.out);
  EXPECT_EQ(sj["valid"], false);
  EXPECT_FALSE(sj["problems"].empty());
}

TEST_F(HedgeCli, EveryDataMeshIsValidAfterRepair) {
  for (const auto& entry : fs::directory_iterator(kData)) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    const Result r = run({"validate", entry.path().string()});
    EXPECT_EQ(r.code, 0) << entry.path() << ": " << r.out << r.err;
  }
}

TEST_F(HedgeCli, StressReportsAppliedAndRefusedOperations) {
  const json j =
      run_json({"stress", data("spot_control_mesh.obj"), "--ops", "1500", "--seed", "5", "--json"});
  EXPECT_EQ(j["valid"], true);
  EXPECT_TRUE(j["problems"].empty());
  std::size_t applied = 0, refused = 0;
  for (const auto& [name, n] : j["applied"].items()) applied += n.get<std::size_t>();
  for (const auto& [name, n] : j["refused"].items()) refused += n.get<std::size_t>();
  EXPECT_EQ(applied + refused, 1500u);
  EXPECT_GT(j["applied"]["collapse"].get<std::size_t>(), 0u);
  EXPECT_GT(j["applied"]["split_edge"].get<std::size_t>(), 0u);
  // The same seed gives the same report.
  const json again =
      run_json({"stress", data("spot_control_mesh.obj"), "--ops", "1500", "--seed", "5", "--json"});
  EXPECT_EQ(again["applied"], j["applied"]);
  EXPECT_EQ(again["faces"], j["faces"]);
  const Result text = run({"stress", data("anchor.off"), "--ops", "500"});
  EXPECT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("collapse"), std::string::npos);
  expect_usage_error({"stress", data("anchor.off"), "--ops", "lots"});
}

TEST_F(HedgeCli, RenderBuffersReportsSeamsAndSmallSyncs) {
  const json j = run_json({"render-buffers", data("spot_triangulated.obj"), "--edits", "150", "--json"});
  // spot's UV seams: more render vertices than mesh vertices, one per extra attribute set.
  EXPECT_EQ(j["mesh"]["vertices"], 2930);
  EXPECT_EQ(j["triangles"], 5856);
  EXPECT_GT(j["seam_splits"].get<std::size_t>(), 0u);
  EXPECT_EQ(j["render_vertices"].get<std::size_t>(), 2930u + j["seam_splits"].get<std::size_t>());
  EXPECT_EQ(j["vertex_stride_bytes"], 32);  // position, normal, texcoord
  EXPECT_EQ(j["layout"]["texcoord"], 6);
  EXPECT_EQ(j["full_upload_bytes"].get<std::size_t>(),
            32u * 2930u + 32u * j["seam_splits"].get<std::size_t>() + 4u * 3u * 5856u);
  EXPECT_GT(j["edits"]["applied"].get<std::size_t>(), 100u);
  const double median = j["edits"]["median_bytes"].get<double>();
  EXPECT_GT(median, 0.0);
  EXPECT_LT(median, 1024.0);
  EXPECT_EQ(j["valid"], true);
  const Result text = run({"render-buffers", data("spot_control_mesh.obj"), "--winding", "cw", "--separate"});
  EXPECT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("separate streams"), std::string::npos);
  EXPECT_NE(text.out.find("seam splits"), std::string::npos);
  expect_usage_error({"render-buffers", data("tet.obj"), "--winding", "sideways"});
  expect_data_error({"render-buffers", data("missing.obj")}, "missing.obj");
}

TEST_F(HedgeCli, ConvertWritesAReadableFileInEveryFormat) {
  for (const std::string ext : {"ply", "off", "obj", "stl"}) {
    for (const bool ascii : {false, true}) {
      const fs::path out = tmp("sub/dir/spot." + ext);
      std::vector<std::string> args = {"convert", data("spot_control_mesh.obj"), out.string()};
      if (ascii) args.push_back("--ascii");
      const Result r = run(args);
      ASSERT_EQ(r.code, 0) << ext << ": " << r.err;
      EXPECT_NE(r.out.find("converted"), std::string::npos) << r.out;
      ASSERT_TRUE(fs::exists(out)) << out;

      const json j = run_json({"info", out.string(), "--json"});
      EXPECT_EQ(j["valid"], true) << ext;
      EXPECT_EQ(j["vertices"], 188) << ext;
      EXPECT_EQ(j["genus"], 0) << ext;
      if (ext == "stl") {
        EXPECT_EQ(j["is_triangle_mesh"], true);  // STL holds triangles only
      } else {
        EXPECT_EQ(j["faces"], 180) << ext;
      }
      fs::remove(out);
    }
  }
}

TEST_F(HedgeCli, ConvertReordersForTheVertexCacheAndInfoMeasuresIt) {
  const json before = run_json({"info", data("spot_triangulated.obj"), "--json"});
  const fs::path out = tmp("spot_cache.obj"), spatial = tmp("spot_spatial.obj");
  ASSERT_EQ(run({"convert", data("spot_triangulated.obj"), out.string(), "--reorder", "vertex-cache"}).code,
            0);
  ASSERT_EQ(run({"convert", data("spot_triangulated.obj"), spatial.string(), "--reorder", "spatial"}).code,
            0);
  const json after = run_json({"info", out.string(), "--json"});
  const json after_spatial = run_json({"info", spatial.string(), "--json"});
  for (const char* key : {"vertices", "faces", "genus", "valid"}) {
    EXPECT_EQ(after[key], before[key]) << key;
    EXPECT_EQ(after_spatial[key], before[key]) << key;
  }
  EXPECT_NEAR(after["area"].get<double>(), before["area"].get<double>(), 1e-4 * before["area"].get<double>());
  const double acmr = after["cache_miss_ratio"].get<double>();
  EXPECT_GT(acmr, 0.5);
  EXPECT_LT(acmr, 0.75);
  EXPECT_LT(acmr, after_spatial["cache_miss_ratio"].get<double>());
  EXPECT_LT(acmr, before["cache_miss_ratio"].get<double>());
  expect_usage_error({"convert", data("tet.obj"), tmp("x.obj").string(), "--reorder", "hilbert"});
  EXPECT_FALSE(fs::exists(tmp("x.obj")));
}

TEST_F(HedgeCli, ConvertToGlbAndInfoOnItKeepTheMeshAndItsSeams) {
  const fs::path glb = tmp("out/spot.glb");
  const Result r = run({"convert", data("spot_triangulated.obj"), glb.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(glb)"), std::string::npos) << r.out;
  EXPECT_EQ(read_text(glb).rfind("glTF", 0), 0u);

  const json before = run_json({"info", data("spot_triangulated.obj"), "--json"});
  const json after = run_json({"info", glb.string(), "--json"});
  for (const char* key : {"vertices", "edges", "faces", "boundary_loops", "genus", "valid", "is_manifold"})
    EXPECT_EQ(after[key], before[key]) << key;
  // The file splits vertices at UV seams as engines do; loading welds exactly those copies back.
  const json buffers = run_json({"render-buffers", data("spot_triangulated.obj"), "--edits", "0", "--json"});
  const std::size_t seams = buffers["seam_splits"].get<std::size_t>();
  EXPECT_GT(seams, 0u);
  EXPECT_EQ(after["repairs"]["welded_vertices"].get<std::size_t>(), seams);
  EXPECT_EQ(
      run_json({"render-buffers", glb.string(), "--edits", "0", "--json"})["seam_splits"].get<std::size_t>(),
      seams);

  // .glb -> .gltf -> .obj: the same mesh all the way.
  const fs::path gltf = tmp("spot.gltf"), obj = tmp("spot.obj");
  ASSERT_EQ(run({"convert", glb.string(), gltf.string()}).code, 0);
  ASSERT_EQ(run({"convert", gltf.string(), obj.string()}).code, 0);
  EXPECT_EQ(read_text(gltf).rfind("{", 0), 0u);
  const json last = run_json({"info", obj.string(), "--json"});
  for (const char* key : {"vertices", "faces", "genus"}) EXPECT_EQ(last[key], before[key]) << key;
  EXPECT_NEAR(last["area"].get<double>(), before["area"].get<double>(), 1e-9 * before["area"].get<double>());

  // A malformed file: one error line that names the file and the accessor.
  const fs::path bad = tmp("bad.gltf");
  write_text(
      bad, R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 4}}]}]})");
  expect_data_error({"info", bad.string()}, "bad.gltf");
  const Result e = run({"info", bad.string()});
  EXPECT_NE(e.err.find("accessor 4 does not exist"), std::string::npos) << e.err;
}

TEST_F(HedgeCli, ConvertAsciiPly) {
  const fs::path out = tmp("tet.ply");
  ASSERT_EQ(run({"convert", data("tet.obj"), out.string(), "--ascii"}).code, 0);
  EXPECT_EQ(read_text(out).rfind("ply\nformat ascii", 0), 0u);
  const fs::path bin = tmp("tet-bin.ply");
  ASSERT_EQ(run({"convert", data("tet.obj"), bin.string()}).code, 0);
  EXPECT_EQ(read_text(bin).rfind("ply\nformat binary_little_endian", 0), 0u);
}

TEST_F(HedgeCli, ATruncatedFileIsReportedWithItsLine) {
  const fs::path cut = tmp("cut.obj");
  write_text(cut, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 3");
  const Result r = run({"info", cut.string(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "hedge: warning: " + cut.string() +
                       ":6: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)\n");
  const json j = json::parse(r.out);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["repairs"]["degenerate_faces"], 1);
  EXPECT_EQ(j["faces"], 1);
  // --strict refuses it, naming the line.
  const Result strict = run({"info", cut.string(), "--strict"});
  EXPECT_EQ(strict.code, 1);
  EXPECT_NE(strict.err.find("cut.obj:6: face 1 has 1 corner"), std::string::npos) << strict.err;
  // Other commands warn too, and still do their work.
  const Result conv = run({"convert", cut.string(), tmp("out.ply").string()});
  EXPECT_EQ(conv.code, 0);
  EXPECT_NE(conv.err.find("hedge: warning: "), std::string::npos);
  EXPECT_TRUE(fs::exists(tmp("out.ply")));
}

TEST_F(HedgeCli, MalformedFilesAreDataErrors) {
  const fs::path obj = tmp("broken.obj");
  write_text(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 zz\n");
  expect_data_error({"info", obj.string()}, "broken.obj");
  expect_data_error({"validate", obj.string()}, "broken.obj");
  expect_data_error({"convert", obj.string(), tmp("x.ply").string()}, "broken.obj");
  EXPECT_FALSE(fs::exists(tmp("x.ply")));

  const fs::path range = tmp("out_of_range.obj");
  write_text(range, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expect_data_error({"info", range.string()}, "out_of_range.obj");

  const fs::path off = tmp("truncated.off");
  write_text(off, "OFF\n4 2 0\n0 0 0\n1 0 0\n");
  expect_data_error({"info", off.string(), "--json"}, "truncated.off");

  const fs::path ply = tmp("garbage.ply");
  write_text(ply, std::string("ply\nformat binary_little_endian 1.0\nelement vertex 1000000\n") +
                      "property float x\nproperty float y\nproperty float z\nend_header\n\x01\x02");
  expect_data_error({"info", ply.string()}, "garbage.ply");

  const fs::path stl = tmp("short.stl");
  write_text(stl, std::string(84, '\0').replace(80, 1, "\x05"));
  expect_data_error({"info", stl.string()}, "short.stl");
}

// A glTF from a stranger: no file outside its folder is read, deep JSON and amplifying files are
// refused with a message, and nothing is written.
TEST_F(HedgeCli, HostileGltfFilesAreDataErrors) {
  const std::string head =
      R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
      R"({"bufferView":1,"componentType":5123,"count":30000,"type":"SCALAR"}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":60000}],)";
  auto file = [&](const std::string& name, const std::string& meshes, const std::string& buffers) {
    write_text(tmp(name), head + R"("meshes":)" + meshes + R"(,"buffers":)" + buffers + "}");
    return tmp(name).string();
  };
  const std::string one = R"([{"primitives":[{"attributes":{"POSITION":0}}]}])";
  const std::string passwd =
      file("passwd.gltf", one, R"([{"byteLength":60036,"uri":"../../../../../../../../etc/passwd"}])");
  expect_data_error({"info", passwd},
                    "passwd.gltf: buffer 0: uri '../../../../../../../../etc/passwd' does not name a regular "
                    "file inside the .gltf's folder");
  expect_data_error({"convert", passwd, tmp("out.obj").string()}, "does not name a regular file");
  EXPECT_FALSE(fs::exists(tmp("out.obj")));
  const std::string absolute = file("absolute.gltf", one, R"([{"byteLength":60036,"uri":"/etc/passwd"}])");
  expect_data_error({"info", absolute}, "absolute.gltf: buffer 0: uri is an absolute path");
  const std::string text = file("text.gltf", one, R"([{"byteLength":5,"uri":"data:text/plain,hello"}])");
  expect_data_error({"validate", text},
                    "text.gltf: buffer 0: a data URI must be base64 application/octet-stream");

  // 1,000 primitives on one accessor of 30,000 indices: 30M corners from a 120 KB file.
  std::string prims;
  for (int p = 0; p < 1000; ++p)
    prims += std::string(p ? "," : "") + R"({"attributes":{"POSITION":0},"indices":1})";
  const std::string buffer =
      std::string(R"([{"byteLength":60036,"uri":"data:application/octet-stream;base64,)") +
      std::string(80048, 'A') + R"("}])";
  const std::string shared = file("shared.gltf", R"([{"primitives":[)" + prims + "]}]", buffer);
  expect_data_error({"info", shared},
                    "shared.gltf: its JSON and the meshes its nodes place would take about");
  expect_data_error({"info", shared}, "raise the budget");

  std::string deep =
      head + R"("meshes":)" + one + R"(,"extras":)" + std::string(17000, '[') + std::string(17000, ']') + "}";
  write_text(tmp("deep.gltf"), deep);
  expect_data_error({"info", tmp("deep.gltf").string()},
                    "deep.gltf: malformed glTF: JSON nested deeper than 64 levels");

  const std::string negative =
      file("negative.gltf", R"([{"primitives":[{"attributes":{"POSITION":0},"indices":-5}]}])", buffer);
  expect_data_error({"info", negative},
                    "negative.gltf: mesh 0 primitive 0: indices is -5; it must be 0 or more");

  // A buffer beside the file is read, unless the user turns external buffers off.
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  write_text(tmp("beside.bin"),
             std::string(reinterpret_cast<const char*>(positions), 36) + std::string(60000, '\0'));
  const std::string beside = file("beside.gltf", one, R"([{"byteLength":60036,"uri":"beside.bin"}])");
  const Result r = run({"info", beside, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(json::parse(r.out)["faces"], 1);
  // --max-memory is the read budget too: a small one refuses what the default reads.
  ASSERT_EQ(run({"info", data("two_quads.glb")}).code, 0);
  expect_data_error({"info", data("two_quads.glb"), "--max-memory", "1K"},
                    "two_quads.glb: its JSON would take about");
  expect_data_error({"convert", data("two_quads.glb"), tmp("q.obj").string(), "--max-memory", "1K"},
                    "more than the read budget of 1.0 KiB");
  EXPECT_FALSE(fs::exists(tmp("q.obj")));
  expect_data_error({"info", beside, "--no-external-buffers"},
                    "beside.gltf: buffer 0: its data is in a separate file ('uri'), and reading external "
                    "buffers is turned off");
}

TEST_F(HedgeCli, MissingFileAndUnknownExtensionAreDataErrors) {
  expect_data_error({"info", tmp("missing.obj").string()}, "missing.obj");
  const fs::path xyz = tmp("mesh.xyz");
  write_text(xyz, "1 2 3\n");
  expect_data_error({"info", xyz.string()}, "mesh.xyz");
  expect_data_error({"convert", data("tet.obj"), tmp("out.xyz").string()}, "out.xyz");
  EXPECT_FALSE(fs::exists(tmp("out.xyz")));
}

TEST_F(HedgeCli, UsageErrorsExitWithTwo) {
  expect_usage_error({});
  expect_usage_error({"frobnicate"});
  expect_usage_error({"info"});
  expect_usage_error({"convert", data("tet.obj")});
  expect_usage_error({"info", data("tet.obj"), "--weld", "sometimes"});
  expect_usage_error({"info", data("tet.obj"), "--weld-eps", "-1"});
  expect_usage_error({"info", data("tet.obj"), "--no-such-flag"});
}

TEST_F(HedgeCli, HelpAndVersion) {
  const Result help = run({"--help"});
  EXPECT_EQ(help.code, 0);
  for (const char* command : {"info", "validate", "convert"}) {
    EXPECT_NE(help.out.find(command), std::string::npos) << command;
  }
  const Result sub = run({"info", "--help"});
  EXPECT_EQ(sub.code, 0);
  EXPECT_NE(sub.out.find("--json"), std::string::npos) << sub.out;
  const Result version = run({"--version"});
  EXPECT_EQ(version.code, 0);
  EXPECT_FALSE(version.out.empty());
}

}  // namespace

namespace {

using namespace cli_test;

TEST_F(HedgeCli, InfoReportsAreaVolumeAndBoundingBox) {
  write_text(tmp("box.obj"),
             "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 3\nv 2 0 3\nv 2 1 3\nv 0 1 3\n"
             "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  const json j = run_json({"info", tmp("box.obj").string(), "--json"});
  EXPECT_NEAR(j["area"].get<double>(), 2 * (2 + 6 + 3), 1e-9);
  EXPECT_NEAR(j["volume"].get<double>(), 6, 1e-9);
  EXPECT_EQ(j["bounding_box"]["min"], json::array({0, 0, 0}));
  EXPECT_EQ(j["bounding_box"]["max"], json::array({2, 1, 3}));
  // An open mesh has no volume.
  const json open = run_json({"info", data("three_peaks.off"), "--json"});
  EXPECT_TRUE(open["volume"].is_null());
  EXPECT_GT(open["area"].get<double>(), 0);
  const Result text = run({"info", tmp("box.obj").string()});
  EXPECT_NE(text.out.find("volume"), std::string::npos);
  EXPECT_NE(text.out.find("bounding box"), std::string::npos);
}

}  // namespace

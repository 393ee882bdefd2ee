// hedge fracture --kind solid|auto, run as a user would.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

// Every file of a folder with its bytes, in name order.
std::vector<std::pair<std::string, std::string>> folder(const fs::path& dir) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& e : fs::directory_iterator(dir))
    files.emplace_back(e.path().filename().string(), read_text(e.path()));
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> strike(const fs::path& out, const std::string& material, const std::string& seed) {
  return {"fracture",  data("spot_triangulated.obj"),
          "--solid",   "--impact",
          "0,0,0",     "--tolerance",
          "10",        "--break-radius",
          "0.3",       "--material",
          material,    "--seed",
          seed,        "-o",
          out.string()};
}

// Each piece file is a closed, valid mesh as the summary describes it; the volumes add up to the
// input's; the bonds name pieces or the remaining object, and each piece's bonds cover its caps.
TEST_F(HedgeCli, SolidFractureWritesClosedPiecesAndTheBondGraph) {
  const fs::path out = tmp("broken");
  std::vector<std::string> args = strike(out, "stone", "7");
  args.push_back("--json");
  const json j = run_json(args);
  ASSERT_TRUE(j.contains("pieces")) << j.dump();
  EXPECT_TRUE(j["seconds"].contains("clip"));
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_FALSE(summary.contains("seconds"));
  EXPECT_EQ(summary["kind"], "solid");
  EXPECT_EQ(summary["radius"].get<double>(), 0.3);
  const json& pieces = summary["pieces"];
  const std::size_t n = pieces.size();
  ASSERT_GE(n, 2u);
  EXPECT_LE(n, 7u);
  const json remaining = run_json({"info", (out / "remaining.obj").string(), "--json"});
  EXPECT_TRUE(remaining["valid"].get<bool>());
  EXPECT_TRUE(remaining["is_closed"].get<bool>());
  EXPECT_EQ(remaining["faces"], summary["remaining"]["faces"]);
  EXPECT_GT(summary["remaining"]["inner_faces"].get<int>(), 0);
  double total = summary["remaining"]["volume"].get<double>();
  std::vector<double> bonded(n, 0.0);
  for (const json& b : summary["bonds"]) {
    const std::size_t a = b["a"].get<std::size_t>();
    ASSERT_LT(a, n);
    EXPECT_GT(b["area"].get<double>(), 0);
    bonded[a] += b["area"].get<double>();
    if (b["b"].is_string()) {
      EXPECT_EQ(b["b"], "remaining");
    } else {
      ASSERT_LT(b["b"].get<std::size_t>(), n);
      EXPECT_LT(a, b["b"].get<std::size_t>());
      bonded[b["b"].get<std::size_t>()] += b["area"].get<double>();
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const json& p = pieces[i];
    const json info = run_json({"info", (out / p["file"].get<std::string>()).string(), "--json"});
    EXPECT_TRUE(info["valid"].get<bool>()) << p["file"];
    EXPECT_TRUE(info["is_closed"].get<bool>()) << p["file"];
    EXPECT_EQ(info["faces"], p["faces"]);
    EXPECT_NEAR(info["volume"].get<double>(), p["volume"].get<double>(), 1e-6 * p["volume"].get<double>());
    EXPECT_GT(p["volume"].get<double>(), 0);
    EXPECT_GT(p["inner_faces"].get<int>(), 0);
    // The caps in their own submesh (1: spot has none), as usemtl runs of the OBJ file.
    const std::string obj = read_text(out / p["file"].get<std::string>());
    EXPECT_NE(obj.find("usemtl submesh_1\n"), std::string::npos) << p["file"];
    EXPECT_NE(obj.find("usemtl submesh_0\n"), std::string::npos) << p["file"];
    EXPECT_NEAR(p["mass"]["mass"].get<double>(), p["volume"].get<double>(), 1e-12);  // density 1
    EXPECT_EQ(p["mass"]["principal_axes"].size(), 3u);
    EXPECT_GE(p["hull"]["faces"].get<int>(), 4);
    EXPECT_NEAR(bonded[i], p["cap_area"].get<double>(), 1e-3 * p["cap_area"].get<double>()) << i;
    total += p["volume"].get<double>();
  }
  EXPECT_NEAR(total, summary["input_volume"].get<double>(), 1e-6 * summary["input_volume"].get<double>());
  EXPECT_EQ(folder(out).size(), n + 2);
}

TEST_F(HedgeCli, SolidFractureTwoRunsGiveByteIdenticalFolders) {
  ASSERT_EQ(run(strike(tmp("a"), "glass", "3")).code, 0);
  ASSERT_EQ(run(strike(tmp("b"), "glass", "3")).code, 0);
  const auto a = folder(tmp("a")), b = folder(tmp("b"));
  ASSERT_GE(a.size(), 10u);
  EXPECT_TRUE(a == b);
  // Fewer pieces into the same folder leave no stale piece file.
  ASSERT_EQ(run(strike(tmp("a"), "stone", "3")).code, 0);
  const json summary = json::parse(read_text(tmp("a") / "summary.json"));
  EXPECT_EQ(folder(tmp("a")).size(), summary["pieces"].size() + 2);
  // The same with --format glb: the binary files hold nothing of the run either.
  std::vector<std::string> glb_a = strike(tmp("ga"), "glass", "3"), glb_b = strike(tmp("gb"), "glass", "3");
  glb_a.insert(glb_a.end(), {"--format", "glb"});
  glb_b.insert(glb_b.end(), {"--format", "glb"});
  ASSERT_EQ(run(glb_a).code, 0);
  ASSERT_EQ(run(glb_b).code, 0);
  const auto ga = folder(tmp("ga")), gb = folder(tmp("gb"));
  ASSERT_EQ(ga.size(), a.size());
  EXPECT_EQ(ga.front().first.substr(ga.front().first.size() - 4), ".glb");
  EXPECT_TRUE(ga == gb);
}

// The JSON chunk of a .glb file (after the 12-byte header and the chunk's length and type).
json glb_json(const std::string& glb) {
  EXPECT_EQ(glb.substr(0, 4), "glTF");
  EXPECT_EQ(glb.substr(16, 4), "JSON");
  std::uint32_t length = 0;
  for (int k = 3; k >= 0; --k)
    length = length * 256 + static_cast<unsigned char>(glb[12 + static_cast<std::size_t>(k)]);
  return json::parse(glb.substr(20, length));
}

// --format glb writes each piece as one primitive per submesh: the outer faces with material 0,
// the caps with the inner material 1, as many triangles as the summary's inner faces.
TEST_F(HedgeCli, SolidFracturePiecesAsGlbCarryTheInnerMaterial) {
  const fs::path out = tmp("glb");
  std::vector<std::string> args = strike(out, "stone", "7");
  args.insert(args.end(), {"--format", "glb"});
  ASSERT_EQ(run(args).code, 0);
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_EQ(summary["remaining"]["file"], "remaining.glb");
  ASSERT_GE(summary["pieces"].size(), 2u);
  for (const json& p : summary["pieces"]) {
    const std::string file = p["file"].get<std::string>();
    ASSERT_EQ(file.substr(file.size() - 4), ".glb");
    const json doc = glb_json(read_text(out / file));
    ASSERT_EQ(doc["materials"].size(), 2u) << file;
    EXPECT_EQ(doc["materials"][1]["name"], "submesh_1");
    const json& prims = doc["meshes"][0]["primitives"];
    ASSERT_EQ(prims.size(), 2u) << file;
    EXPECT_EQ(prims[1]["material"], 1);
    EXPECT_EQ(doc["accessors"][prims[1]["indices"].get<int>()]["count"].get<int>(),
              3 * p["inner_faces"].get<int>());
    const json info = run_json({"info", (out / file).string(), "--json"});
    EXPECT_TRUE(info["valid"].get<bool>()) << file;
    EXPECT_TRUE(info["is_closed"].get<bool>()) << file;
    EXPECT_EQ(info["faces"], p["faces"]);
  }
  // An OBJ run into the same folder leaves no .glb of this run behind, and the other way round.
  ASSERT_EQ(run(strike(out, "stone", "7")).code, 0);
  EXPECT_EQ(folder(out).size(), summary["pieces"].size() + 2);
  ASSERT_EQ(run(args).code, 0);
  EXPECT_EQ(folder(out).size(), summary["pieces"].size() + 2);
  expect_usage_error({"fracture", data("spot_triangulated.obj"), "--impact", "0,0,0", "-o", tmp("x").string(),
                      "--format", "stl"});
}

// three_peaks is open at the impact: --kind solid refuses it by name, writing nothing; --kind auto
// says why on stderr and breaks its surface instead.
TEST_F(HedgeCli, SolidFractureOfAnOpenMeshIsRefusedOrFallsBack) {
  const std::vector<std::string> base = {"fracture",   data("three_peaks.off"), "--impact",
                                         "0.1,0.2,10", "--tolerance",           "100",
                                         "-o",         tmp("out").string()};
  std::vector<std::string> solid = base;
  solid.insert(solid.end(), {"--kind", "solid"});
  expect_data_error(solid, "three_peaks.off");
  EXPECT_NE(run(solid).err.find("the mesh is open: edge"), std::string::npos);
  EXPECT_FALSE(fs::exists(tmp("out")));
  std::vector<std::string> automatic = base;
  automatic.insert(automatic.end(), {"--kind", "auto"});
  const Result r = run(automatic);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("surface fracture instead"), std::string::npos) << r.err;
  const json summary = json::parse(read_text(tmp("out") / "summary.json"));
  EXPECT_GE(summary["shards"].size(), 2u);
  EXPECT_NE(summary["solid_refusal"].get<std::string>().find("open"), std::string::npos);
  // The refusal's code too, the enumerator's name as every binding gives it, so a script decides by
  // it and not by the message's words.
  EXPECT_EQ(summary["solid_refusal_code"], "open");
  // A surface fracture asked for records no refusal.
  std::vector<std::string> surface = base;
  surface.back() = tmp("surface").string();
  ASSERT_EQ(run(surface).code, 0);
  const json plain = json::parse(read_text(tmp("surface") / "summary.json"));
  EXPECT_FALSE(plain.contains("solid_refusal"));
  EXPECT_FALSE(plain.contains("solid_refusal_code"));
  // On a closed mesh auto breaks it as a solid.
  std::vector<std::string> spot = strike(tmp("spot"), "stone", "1");
  spot[2] = "--kind=auto";
  ASSERT_EQ(run(spot).code, 0);
  EXPECT_EQ(json::parse(read_text(tmp("spot") / "summary.json"))["kind"], "solid");
}

// "auto" falls back for the input's shape only: an impact off the surface of the open three_peaks is
// an error of the solid fracture, not a surface fracture that fails in turn.
TEST_F(HedgeCli, SolidFractureAutoReportsARefusalThatIsNotAboutShape) {
  const std::vector<std::string> args = {
      "fracture", data("three_peaks.off"), "--impact", "0.1,0.2,50", "--kind", "auto",
      "-o",       tmp("out").string()};
  expect_data_error(args, "three_peaks.off");
  const Result r = run(args);
  EXPECT_NE(r.err.find("cannot be broken as a solid: the impact"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("surface fracture instead"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp("out")));
}

TEST_F(HedgeCli, SolidFractureOptionsAreChecked) {
  std::vector<std::string> a = strike(tmp("x"), "stone", "1");
  a.insert(a.end(), {"--kind", "auto"});  // --solid and --kind together
  expect_usage_error(a);
  std::vector<std::string> b = strike(tmp("x"), "stone", "1");
  b.insert(b.end(), {"--units", "edge_lengths", "--radius", "3"});  // solid sizes: not in edge lengths
  expect_usage_error(b);
  std::vector<std::string> c = strike(tmp("x"), "stone", "1");
  c[2] = "--kind=rubble";
  expect_usage_error(c);
  EXPECT_FALSE(fs::exists(tmp("x")));
}

}  // namespace

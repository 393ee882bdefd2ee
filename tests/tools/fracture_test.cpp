// hedge fracture, run as a user would.
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

TEST_F(HedgeCli, FractureWritesShardsAndASummaryThatDescribesThem) {
  const fs::path out = tmp("broken");
  const json j =
      run_json({"fracture", data("spot_triangulated.obj"), "--impact", "0.0,0.0,0.0", "--tolerance", "10",
                "--material", "glass", "--seed", "4", "-o", out.string(), "--thickness", "0.01", "--json"});
  ASSERT_TRUE(j.contains("shards")) << j.dump();
  ASSERT_TRUE(j.contains("seconds"));
  const json summary = json::parse(read_text(out / "summary.json"));
  EXPECT_FALSE(summary.contains("seconds"));  // no timings in the files
  const std::size_t n = summary["shards"].size();
  EXPECT_GE(n, 20u);
  EXPECT_LE(n, 60u);
  const json remaining = run_json({"info", (out / "remaining.obj").string(), "--json"});
  EXPECT_TRUE(remaining["valid"].get<bool>());
  EXPECT_EQ(remaining["faces"], summary["remaining"]["faces"]);
  for (const json& s : summary["shards"]) {
    const json info = run_json({"info", (out / s["file"].get<std::string>()).string(), "--json"});
    EXPECT_TRUE(info["valid"].get<bool>()) << s["file"];
    EXPECT_EQ(info["faces"], s["faces"]);
    EXPECT_TRUE(s["closed"].get<bool>());
    EXPECT_GT(s["volume"].get<double>(), 0);
    EXPECT_GT(s["mass"]["mass"].get<double>(), 0);
    EXPECT_EQ(s["mass"]["inertia"].size(), 9u);
    EXPECT_GE(s["hull"]["faces"].get<int>(), 4);
  }
  EXPECT_EQ(folder(out).size(), n + 2);
  // The same strike as .glb into the same folder replaces the OBJ files instead of joining them.
  run_json({"fracture", data("spot_triangulated.obj"), "--impact", "0.0,0.0,0.0", "--tolerance", "10",
            "--material", "glass", "--seed", "4", "-o", out.string(), "--thickness", "0.01", "--json",
            "--format", "glb"});
  const auto files = folder(out);
  EXPECT_EQ(files.size(), n + 2);
  for (const auto& [name, text] : files)
    EXPECT_TRUE(name == "summary.json" || name.ends_with(".glb")) << name;
}

// --break-radius puts the material into model units: twice the radius breaks about four times the
// area; a negative radius is refused.
TEST_F(HedgeCli, FractureBreakRadiusIsInModelUnits) {
  double broken[2] = {0, 0};
  const char* radius[2] = {"0.12", "0.24"};
  for (int i = 0; i < 2; ++i) {
    const fs::path out = tmp(std::string("radius_") + radius[i]);
    const json j =
        run_json({"fracture", data("spot_triangulated.obj"), "--impact", "0.0,0.0,0.0", "--tolerance", "10",
                  "--seed", "4", "--break-radius", radius[i], "-o", out.string(), "--json"});
    ASSERT_TRUE(j.contains("shards")) << j.dump();
    EXPECT_EQ(j["break_radius"].get<double>(), std::stod(radius[i]));
    for (const json& s : j["shards"]) broken[i] += s["area"].get<double>();
  }
  EXPECT_GT(broken[1], 2.5 * broken[0]);
  EXPECT_LT(broken[1], 6.0 * broken[0]);
  const Result r = run({"fracture", data("spot_triangulated.obj"), "--impact", "0,0,0", "--tolerance", "10",
                        "--break-radius", "-1", "-o", tmp("bad").string()});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--break-radius"), std::string::npos) << r.err;
}

// The presets' break radius is a fraction of the mesh's diagonal by default; --units and --radius
// set it; open shards weigh as thin shells (--shell-thickness, or a twentieth of the break radius).
TEST_F(HedgeCli, FractureUnitsRadiusAndShellThickness) {
  const std::vector<std::string> base = {"fracture",    data("spot_triangulated.obj"),
                                         "--impact",    "0.0,0.0,0.0",
                                         "--tolerance", "10",
                                         "--seed",      "4",
                                         "--json",      "-o"};
  auto strike = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.push_back(tmp(name).string());
    args.insert(args.end(), extra.begin(), extra.end());
    return run_json(args);
  };
  const json preset = strike("preset", {});
  EXPECT_EQ(preset["units"], "diagonal_fraction");
  EXPECT_EQ(preset["radius"].get<double>(), 0.13);
  const double diagonal = 2.58809;  // of spot's bounding box
  EXPECT_NEAR(preset["break_radius"].get<double>(), 0.13 * diagonal, 1e-4);
  for (const json& s : preset["shards"]) {
    EXPECT_FALSE(s["closed"].get<bool>());
    EXPECT_NEAR(s["shell_thickness"].get<double>(), 0.05 * 0.13 * diagonal, 1e-4);
    EXPECT_GT(s["mass"]["mass"].get<double>(), 0);
    EXPECT_GT(s["mass"]["principal_moments"][0].get<double>(), 0);
  }
  const json model = strike("model", {"--units", "model", "--radius", "0.2", "--shell-thickness", "0.01"});
  EXPECT_EQ(model["units"], "model");
  EXPECT_EQ(model["break_radius"].get<double>(), 0.2);
  for (const json& s : model["shards"]) {
    EXPECT_EQ(s["shell_thickness"].get<double>(), 0.01);
    EXPECT_NEAR(s["volume"].get<double>(), 0.01 * s["area"].get<double>(), 1e-12);
  }
  const Result r = run({"fracture", data("spot_triangulated.obj"), "--impact", "0,0,0", "--tolerance", "10",
                        "--units", "metres", "-o", tmp("bad").string()});
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--units"), std::string::npos) << r.err;
}

TEST_F(HedgeCli, FractureTwoRunsGiveByteIdenticalFolders) {
  const std::vector<std::string> base = {"fracture",    data("three_peaks.off"),
                                         "--impact",    "0.1,0.2,10",
                                         "--tolerance", "100",
                                         "--material",  "wood",
                                         "--seed",      "77"};
  auto args = [&](const fs::path& out) {
    std::vector<std::string> a = base;
    a.insert(a.end(), {"-o", out.string()});
    return a;
  };
  ASSERT_EQ(run(args(tmp("a"))).code, 0);
  ASSERT_EQ(run(args(tmp("b"))).code, 0);
  const auto a = folder(tmp("a")), b = folder(tmp("b"));
  ASSERT_GE(a.size(), 4u);
  EXPECT_TRUE(a == b);
  // Another seed breaks differently; a second run into the same folder leaves no stale shard file.
  std::vector<std::string> other = args(tmp("a"));
  other[9] = "78";
  ASSERT_EQ(run(other).code, 0);
  const auto c = folder(tmp("a"));
  EXPECT_FALSE(c == a);
  const json summary = json::parse(read_text(tmp("a") / "summary.json"));
  EXPECT_EQ(c.size(), summary["shards"].size() + 2);
}

TEST_F(HedgeCli, FractureReadsAMaterialFile) {
  write_text(
      tmp("two.json"),
      R"({"name": "two rings", "rings": [{"points": 3, "spacing": 2}, {"points": 5, "spacing": 2.5, "jitter": 0.2}]})");
  const json j =
      run_json({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                "--material", tmp("two.json").string(), "-o", tmp("out").string(), "--json"});
  EXPECT_EQ(j["material"], "two rings");
  EXPECT_GE(j["shards"].size(), 2u);
  EXPECT_LE(j["shards"].size(), 8u);
  EXPECT_EQ(j["units"], "diagonal_fraction");  // a file's default, with the default radius
  EXPECT_EQ(j["radius"].get<double>(), 0.1);
  write_text(tmp("metres.json"),
             R"({"rings": [{"points": 3, "spacing": 2}], "units": "model", "radius": 4.5})");
  const json m =
      run_json({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                "--material", tmp("metres.json").string(), "-o", tmp("out").string(), "--json"});
  EXPECT_EQ(m["units"], "model");
  EXPECT_EQ(m["break_radius"].get<double>(), 4.5);
}

TEST_F(HedgeCli, FractureBadMaterialFileNamesTheField) {
  write_text(tmp("bad.json"), R"({"rings": [{"points": 3, "spacing": 2}, {"points": 5, "spacing": "far"}]})");
  const Result r = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                        "--material", tmp("bad.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("rings[1].spacing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp("out")));  // nothing written
  write_text(tmp("typo.json"), R"({"rings": [], "grian": [1, 0, 0]})");
  const Result t = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--material",
                        tmp("typo.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(t.code, 1);
  EXPECT_NE(t.err.find("'grian'"), std::string::npos) << t.err;
  // The former "absolute" is refused, saying what replaced it.
  write_text(tmp("old.json"), R"({"rings": [{"points": 3, "spacing": 2}], "absolute": true})");
  const Result a = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--material",
                        tmp("old.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(a.code, 1);
  EXPECT_NE(a.err.find("'absolute' was replaced by units and radius"), std::string::npos) << a.err;
  write_text(tmp("units.json"), R"({"rings": [{"points": 3, "spacing": 2}], "units": "metres"})");
  const Result u = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--material",
                        tmp("units.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(u.code, 1);
  EXPECT_NE(u.err.find("'units' must be"), std::string::npos) << u.err;
  write_text(tmp("broken.json"), R"({"rings": [)");
  expect_data_error({"fracture", data("three_peaks.off"), "--impact", "0,0,0", "--material",
                     tmp("broken.json").string(), "-o", tmp("out").string()},
                    "broken.json");
}

TEST_F(HedgeCli, FractureMaterialFileOutOfRangeNumbersNameTheFile) {
  // Found by fuzz/fuzz_material.cpp: a number beyond a double's range escaped the parser as a JSON
  // library exception, a grain beyond float's range was converted to float (undefined behaviour),
  // and a zero grain with a stretch passed the parser. Each is now a data error naming the file.
  const std::pair<const char*, const char*> cases[] = {
      {R"({"rings": [{"points": 3, "spacing": 1e400}]})", "not valid JSON"},
      {R"({"rings": [{"points": 3, "spacing": 2}], "grain": [1e39, 0, 0], "grain_stretch": 2})", "'grain'"},
      {R"({"rings": [{"points": 3, "spacing": 2}], "grain": [0, 0, 1e-50], "grain_stretch": 2})", "'grain'"},
  };
  for (const auto& [text, what] : cases) {
    write_text(tmp("range.json"), text);
    const Result r = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                          "--material", tmp("range.json").string(), "-o", tmp("out").string()});
    EXPECT_EQ(r.code, 1) << text;
    EXPECT_NE(r.err.find("range.json"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp("out")));
  }
}

TEST_F(HedgeCli, FractureRefusesAMissAndBadArguments) {
  // Far from the surface: a data error, and the output folder is not created.
  const Result r =
      run({"fracture", data("three_peaks.off"), "--impact", "1000,1000,1000", "-o", tmp("out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("tolerance"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp("out")));
  expect_usage_error({"fracture", data("three_peaks.off"), "--impact", "1,2", "-o", tmp("out").string()});
  expect_usage_error({"fracture", data("three_peaks.off"), "--impact", "1,nan,2", "-o", tmp("out").string()});
  expect_usage_error({"fracture", data("three_peaks.off"), "--impact", "1,2,3", "--thickness", "-1", "-o",
                      tmp("out").string()});
  const Result m = run({"fracture", data("three_peaks.off"), "--impact", "1,2,3", "--material", "metal", "-o",
                        tmp("out").string()});
  EXPECT_EQ(m.code, 1);
  EXPECT_NE(m.err.find("glass, stone, wood, ice"), std::string::npos) << m.err;
}

TEST_F(HedgeCli, FractureWorkIsBoundedWhateverTheMaterialFile) {
  // 1000 rings of 100000 points in a 37 KB file ran past 300 s; now refused at once, unchanged.
  std::string rings;
  for (int i = 0; i < 1000; ++i) rings += std::string(i ? "," : "") + R"({"points": 100000, "spacing": 1})";
  write_text(tmp("hostile.json"), R"({"rings": [)" + rings + "]}");
  const Result r = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                        "--material", tmp("hostile.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("more than the limit of 10000 in all rings"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp("out")));
  // 10^6 nested arrays (2 MB) were parsed whole, at 40 times the file's size; now the file is read
  // to its limit only, and deep nesting is refused at level 8 while it is read.
  write_text(tmp("deep.json"), std::string(1000000, '[') + std::string(1000000, ']'));
  const Result d = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--material",
                        tmp("deep.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(d.code, 1);
  EXPECT_NE(d.err.find("a material is at most 1048576 bytes of JSON"), std::string::npos) << d.err;
  write_text(tmp("deep.json"), R"({"rings": [[[[[[[[[[]]]]]]]]]]})");
  const Result n = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--material",
                        tmp("deep.json").string(), "-o", tmp("out").string()});
  EXPECT_EQ(n.code, 1);
  EXPECT_NE(n.err.find("nested deeper than 8 levels"), std::string::npos) << n.err;
  EXPECT_FALSE(fs::exists(tmp("out")));
  // A thickness of 1e30 gave shards of volume 1e86; now bounded by the mesh's diagonal.
  const Result t = run({"fracture", data("three_peaks.off"), "--impact", "0.1,0.2,10", "--tolerance", "100",
                        "--thickness", "1e30", "-o", tmp("out").string()});
  EXPECT_EQ(t.code, 1);
  EXPECT_NE(t.err.find("times the diagonal of the mesh's bounding box"), std::string::npos) << t.err;
  EXPECT_NE(t.err.find("use a thickness of at most"), std::string::npos) << t.err;
  EXPECT_FALSE(fs::exists(tmp("out")));
}

}  // namespace

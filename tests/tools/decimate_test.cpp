// hedge decimate, run as a user would.
#include <cstdlib>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

TEST_F(HedgeCli, DecimateReachesEachKindOfTarget) {
  const fs::path out = tmp("decimated.obj");
  const json before = run_json({"info", data("spot_triangulated.obj"), "--json"});
  const std::size_t v0 = before["vertices"];
  struct Case {
    std::vector<std::string> args;
    const char* count;  // the count the option targets
    std::size_t target;
  };
  const Case cases[] = {
      {{"--ratio", "0.1"}, "vertices", (v0 + 5) / 10},
      {{"--vertices", "500"}, "vertices", 500},
      {{"--faces", "800"}, "faces", 800},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"decimate", data("spot_triangulated.obj"), out.string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const Result r = run(args);
    ASSERT_EQ(r.code, 0) << c.args[0] << ": " << r.err;
    EXPECT_NE(r.out.find("max error"), std::string::npos) << r.out;
    const json after = run_json({"info", out.string(), "--json"});
    const std::size_t achieved = after[c.count].get<std::size_t>();
    EXPECT_LE(achieved, c.target) << c.args[0];
    EXPECT_GE(achieved, c.target * 9 / 10) << c.args[0];
    EXPECT_TRUE(after["valid"].get<bool>());
  }
}

TEST_F(HedgeCli, DecimateStopsAtTheErrorLimitAndPrintsIt) {
  const fs::path out = tmp("decimated.ply");
  const Result r =
      run({"decimate", data("three_peaks.off"), out.string(), "--max-error", "0.001", "--keep-boundary"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::size_t at = r.out.find("max error ");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_LE(std::stod(r.out.substr(at + 10)), 0.001) << r.out;
  const json before = run_json({"info", data("three_peaks.off"), "--json"});
  const json after = run_json({"info", out.string(), "--json"});
  EXPECT_LT(after["vertices"].get<std::size_t>(), before["vertices"].get<std::size_t>());
  EXPECT_TRUE(after["valid"].get<bool>());
}

TEST_F(HedgeCli, DecimateDrawsItsProgressBarWhenAsked) {
  const char* old = std::getenv("HEDGE_PROGRESS");
  const std::string saved = old ? old : "";
  ::setenv("HEDGE_PROGRESS", "always", 1);
  const Result r = run({"decimate", data("spot_triangulated.obj"), tmp("d.obj").string(), "--ratio", "0.2"});
  if (old) {
    ::setenv("HEDGE_PROGRESS", saved.c_str(), 1);
  } else {
    ::unsetenv("HEDGE_PROGRESS");
  }
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("\rdecimate ["), std::string::npos) << r.err;
  EXPECT_NE(r.err.rfind("] 100%"), std::string::npos) << r.err;
}

TEST_F(HedgeCli, DecimateRefusesBadInputWithoutWriting) {
  const fs::path out = tmp("x.obj");
  expect_usage_error({"decimate", data("tet.obj"), out.string()});  // no target
  expect_usage_error({"decimate", data("tet.obj"), out.string(), "--ratio", "0"});
  expect_usage_error({"decimate", data("tet.obj"), out.string(), "--ratio", "1.5"});
  expect_usage_error({"decimate", data("tet.obj"), out.string(), "--ratio", "0.5", "--vertices", "3"});
  expect_usage_error({"decimate", data("tet.obj"), out.string(), "--max-error", "-1"});
  expect_data_error({"decimate", data("spot_control_mesh.obj"), out.string(), "--ratio", "0.5"}, "triangles");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

// hedge smooth, run as a user would.
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

TEST_F(HedgeCli, SmoothWritesASmootherMeshWithTheSameConnectivity) {
  const fs::path out = tmp("smooth.obj");
  for (const char* method : {"uniform", "taubin", "cotangent", "implicit", "cotan"}) {
    const Result r =
        run({"smooth", data("spot_triangulated.obj"), out.string(), "--method", method, "--iterations", "5"});
    ASSERT_EQ(r.code, 0) << method << ": " << r.err;
    EXPECT_NE(r.out.find(method), std::string::npos);
    const json before = run_json({"info", data("spot_triangulated.obj"), "--json"});
    const json after = run_json({"info", out.string(), "--json"});
    EXPECT_EQ(after["vertices"], before["vertices"]) << method;
    EXPECT_EQ(after["faces"], before["faces"]) << method;
    EXPECT_TRUE(after["valid"].get<bool>());
    // Smoothing a closed surface lowers its area.
    EXPECT_LT(after["area"].get<double>(), before["area"].get<double>()) << method;
  }
}

TEST_F(HedgeCli, SmoothRefusesBadInputWithoutWriting) {
  const fs::path out = tmp("x.obj");
  expect_usage_error({"smooth", data("tet.obj"), out.string(), "--method", "gaussian"});
  expect_usage_error({"smooth", data("tet.obj"), out.string(), "--iterations", "-3"});
  expect_data_error({"smooth", data("tet.obj"), out.string(), "--lambda", "2"}, "lambda");
  expect_data_error({"smooth", data("spot_control_mesh.obj"), out.string(), "--method", "cotangent"},
                    "triangles");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

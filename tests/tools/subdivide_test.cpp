// hedge subdivide, run as a user would.
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

// hedge subdivide on tet.obj with `options`, then what hedge info --json says of the file it wrote.
class HedgeSubdivide : public HedgeCli {
 protected:
  json subdivide_tet(const std::string& out_name, const std::vector<std::string>& options) const {
    const fs::path out = tmp(out_name);
    std::vector<std::string> args = {"subdivide", data("tet.obj"), out.string()};
    args.insert(args.end(), options.begin(), options.end());
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return run_json({"info", out.string(), "--json"});
  }
};

TEST_F(HedgeSubdivide, SubdivideMultipliesTheFacesAndKeepsTheMeshValid) {
  const json j = subdivide_tet("sub.ply", {"--scheme", "loop", "--steps", "3"});
  EXPECT_EQ(j["faces"], 256);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_TRUE(j["valid"].get<bool>());
  // Loop shrinks a tetrahedron toward a rounder, smaller body.
  const json before = run_json({"info", data("tet.obj"), "--json"});
  EXPECT_LT(j["volume"].get<double>(), before["volume"].get<double>());

  const json m = subdivide_tet("mid.obj", {"--scheme", "midpoint"});
  EXPECT_EQ(m["faces"], 16);
  EXPECT_NEAR(m["volume"].get<double>(), before["volume"].get<double>(), 1e-6);

  const fs::path split = tmp("split.obj");
  ASSERT_EQ(run({"subdivide", data("spot_control_mesh.obj"), split.string(), "--scheme", "split-faces"}).code,
            0);
  EXPECT_EQ(run_json({"info", split.string(), "--json"})["faces"], 732);

  const fs::path cc = tmp("cc.obj");
  ASSERT_EQ(run({"subdivide", data("spot_control_mesh.obj"), cc.string(), "--scheme", "catmull-clark",
                 "--steps", "2"})
                .code,
            0);
  const json q = run_json({"info", cc.string(), "--json"});
  EXPECT_EQ(q["faces"], 4 * 732);
  EXPECT_TRUE(q["is_quad_mesh"].get<bool>());
  EXPECT_TRUE(q["valid"].get<bool>());
}

TEST_F(HedgeCli, SubdivideRefusesPolygonsForLoopAndBadOptions) {
  const fs::path out = tmp("x.obj");
  expect_data_error({"subdivide", data("spot_control_mesh.obj"), out.string()}, "triangles");
  expect_usage_error({"subdivide", data("tet.obj"), out.string(), "--scheme", "butterfly"});
  expect_usage_error({"subdivide", data("tet.obj"), out.string(), "--steps", "40"});
  expect_data_error({"subdivide", data("tet.obj"), tmp("x.xyz").string()}, "x.xyz");
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(HedgeSubdivide, SubdivideBySqrt3TriplesTheFacesOfTriangles) {
  const json j = subdivide_tet("sqrt3.obj", {"--scheme", "sqrt3", "--steps", "2"});
  EXPECT_EQ(j["faces"], 36);
  EXPECT_EQ(j["vertices"], 20);
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_TRUE(j["valid"].get<bool>());
  const json before = run_json({"info", data("tet.obj"), "--json"});
  EXPECT_LT(j["volume"].get<double>(), before["volume"].get<double>());
  expect_data_error({"subdivide", data("spot_control_mesh.obj"), tmp("q.obj").string(), "--scheme", "sqrt3"},
                    "triangles");
}

}  // namespace

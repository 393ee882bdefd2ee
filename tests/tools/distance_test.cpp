// hedge distance, run as a user would.
#include <cmath>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

//! A unit square of two triangles at height z, as OBJ text.
std::string square(float z) {
  const std::string h = std::to_string(z);
  return "v 0 0 " + h + "\nv 1 0 " + h + "\nv 1 1 " + h + "\nv 0 1 " + h + "\nf 1 2 3\nf 1 3 4\n";
}

TEST_F(HedgeCli, DistanceOfASquareToAShiftedCopyIsTheShift) {
  write_text(tmp("a.obj"), square(0));
  write_text(tmp("b.obj"), square(0.5f));
  const json j =
      run_json({"distance", tmp("a.obj").string(), tmp("b.obj").string(), "--samples", "500", "--json"});
  EXPECT_DOUBLE_EQ(j["hausdorff"].get<double>(), 0.5);
  EXPECT_NEAR(j["mean"].get<double>(), 0.5, 1e-12);
  EXPECT_EQ(j["a_to_b"]["points"].get<std::size_t>(), 504u);
  EXPECT_NEAR(j["hausdorff_over_diagonal_of_a"].get<double>(), 0.5 / std::sqrt(2.0), 1e-9);

  const Result text = run({"distance", tmp("a.obj").string(), tmp("b.obj").string()});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("Hausdorff distance    0.5"), std::string::npos) << text.out;
}

TEST_F(HedgeCli, DistanceOfAMeshToItselfIsZero) {
  const json j =
      run_json({"distance", data("spot_triangulated.obj"), data("spot_triangulated.obj"), "--json"});
  EXPECT_LT(j["hausdorff"].get<double>(), 1e-5);
  EXPECT_GT(j["b_to_a"]["points"].get<std::size_t>(), 100000u);
}

TEST_F(HedgeCli, DistanceRefusesAMeshWithoutFacesAndBadArguments) {
  write_text(tmp("points.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_data_error({"distance", data("tet.obj"), tmp("points.obj").string()}, "points.obj");
  expect_data_error({"distance", data("tet.obj"), tmp("missing.obj").string()}, "missing.obj");
  expect_usage_error({"distance", data("tet.obj")});
  expect_usage_error({"distance", data("tet.obj"), data("tet.obj"), "--samples", "-4"});
}

}  // namespace

// The memory budget of the commands (tools/hedge/memory_budget.cpp): --max-memory SIZE, by
// default the memory available; work estimated past it is refused before it is allocated.
#include <string>
#include <vector>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

//! A data error (exit 1, one line) that holds every one of `parts`.
void expect_budget_refusal(const Result& r, const std::vector<std::string>& parts) {
  EXPECT_EQ(r.code, 1) << r.err;
  const auto err = lines(r.err);
  ASSERT_EQ(err.size(), 1u) << r.err;
  for (const std::string& p : parts)
    EXPECT_NE(err[0].find(p), std::string::npos) << "no '" << p << "' in " << err[0];
}

TEST_F(HedgeCli, SubdivideIsRefusedPastTheBudgetBeforeItAllocates) {
  const fs::path out = tmp("sub.obj");
  // 6 steps of Loop on a tetrahedron: 16384 faces, about 6 MiB with the copy that writing OBJ text
  // makes; 1M cannot hold them, and the message says how many steps can.
  const Result r = run({"subdivide", data("tet.obj"), out.string(), "--steps", "6", "--max-memory", "1M"});
  expect_budget_refusal(r, {"tet.obj", "6 steps of loop on 4 faces", "more than the budget of 1.0 MiB",
                            "--max-memory 1M", "use --steps 4 or fewer (or write a binary format"});
  EXPECT_FALSE(fs::exists(out));
  // The advice holds: 4 steps fit in 1M, and 5 steps do when written as binary PLY.
  ASSERT_EQ(run({"subdivide", data("tet.obj"), out.string(), "--steps", "4", "--max-memory", "1M"}).code, 0);
  EXPECT_EQ(run_json({"info", out.string(), "--json"})["faces"], 1024);
  EXPECT_EQ(run({"subdivide", data("tet.obj"), out.string(), "--steps", "5", "--max-memory", "1M"}).code, 1);
  ASSERT_EQ(
      run({"subdivide", data("tet.obj"), tmp("sub.ply").string(), "--steps", "5", "--max-memory", "1M"}).code,
      0);
  EXPECT_EQ(run_json({"info", tmp("sub.ply").string(), "--json"})["faces"], 4096);
  // Sizes in bytes and with units.
  EXPECT_EQ(
      run({"subdivide", data("tet.obj"), out.string(), "--steps", "6", "--max-memory", "4294967296"}).code,
      0);
  EXPECT_EQ(run({"subdivide", data("tet.obj"), out.string(), "--steps", "6", "--max-memory", "1GiB"}).code,
            0);
  EXPECT_EQ(run({"subdivide", data("tet.obj"), out.string(), "--steps", "5", "--max-memory", "2048K"}).code,
            0);
}

TEST_F(HedgeCli, TheDefaultBudgetIsTheMemoryAvailable) {
  // 8 steps of Loop on spot (5856 triangles): 384 million faces, under 2^31 half-edges but far
  // more memory than this kind of machine has (the estimate is about 100 GiB).
  const fs::path out = tmp("sub.obj");
  const Result r = run({"subdivide", data("spot_triangulated.obj"), out.string(), "--steps", "8"});
  expect_budget_refusal(r, {"8 steps of loop", "the memory available now", "--max-memory SIZE", "or fewer"});
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(HedgeCli, MalformedMemorySizesAreUsageErrors) {
  for (const std::string size : {"0", "-5", "12X", "1.5G", "99999999999999999999", "20000000000T", "M", ""}) {
    SCOPED_TRACE(size);
    const Result r = run({"subdivide", data("tet.obj"), tmp("o.obj").string(), "--max-memory", size});
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("--max-memory"), std::string::npos) << r.err;
  }
}

TEST_F(HedgeCli, RenderDistanceAndRenderBuffersCheckTheirBudget) {
  const std::string in = data("tet.obj");
  // 8192x8192 at 4x4 samples: 67 million samples would need about 2 GiB.
  expect_budget_refusal(run({"render", in, "-o", tmp("p.png").string(), "--size", "8192x8192",
                             "--supersample", "1", "--max-memory", "64M"}),
                        {"a picture of 8192x8192", "--max-memory 64M", "smaller --size"});
  EXPECT_FALSE(fs::exists(tmp("p.png")));
  expect_budget_refusal(run({"distance", in, in, "--samples", "100000000", "--max-memory", "64M"}),
                        {"100000000 samples", "--max-memory 64M", "fewer --samples"});
  expect_budget_refusal(run({"render-buffers", in, "--edits", "10000000", "--max-memory", "1M"}),
                        {"10000000 edits", "fewer --edits"});
  EXPECT_EQ(run({"render-buffers", in, "--edits", "10", "--max-memory", "1M"}).code, 0);
}

TEST_F(HedgeCli, TourSkipsStagesPastTheBudget) {
  const Result r = run({"tour", data("spot_control_mesh.obj"), "--out", tmp("t").string(), "--panel", "64",
                        "--max-memory", "200K"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Catmull-Clark"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("skipped: the result would pass 4000000 faces or 200.0 KiB of memory"),
            std::string::npos)
      << r.out;
}

}  // namespace

// The progress bar of the long commands (tools/hedge/progress_bar.h), run as a user would: only
// on a terminal unless HEDGE_PROGRESS says otherwise.
#include <cstdlib>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

// Sets HEDGE_PROGRESS for the commands this test runs, and restores it after.
class ProgressSetting {
 public:
  explicit ProgressSetting(const char* value) {
    const char* old = std::getenv("HEDGE_PROGRESS");
    had_ = old != nullptr;
    if (had_) old_ = old;
    if (value) {
      ::setenv("HEDGE_PROGRESS", value, 1);
    } else {
      ::unsetenv("HEDGE_PROGRESS");
    }
  }
  ~ProgressSetting() {
    if (had_) {
      ::setenv("HEDGE_PROGRESS", old_.c_str(), 1);
    } else {
      ::unsetenv("HEDGE_PROGRESS");
    }
  }

 private:
  bool had_ = false;
  std::string old_;
};

TEST_F(HedgeCli, ProgressIsDrawnWhenAskedAndEndsAtOneHundredPercent) {
  const ProgressSetting always("always");
  const Result r =
      run({"smooth", data("spot_triangulated.obj"), tmp("s.obj").string(), "--iterations", "20"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("\rsmooth ["), std::string::npos) << r.err;
  // The last update is the whole bar at 100%, and the line is ended.
  const std::string full = "[" + std::string(30, '#') + "] 100%";
  EXPECT_NE(r.err.rfind(full), std::string::npos) << r.err;
  EXPECT_EQ(r.err.back(), '\n');
  EXPECT_EQ(lines(r.err).size(), 1u) << "one line, redrawn in place";
}

TEST_F(HedgeCli, SubdivideReportsItsStepsOnTheBar) {
  const ProgressSetting always("always");
  const Result r = run({"subdivide", data("spot_triangulated.obj"), tmp("s.ply").string(), "--steps", "3"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("\rsubdivide ["), std::string::npos) << r.err;
  EXPECT_NE(r.err.rfind("[" + std::string(30, '#') + "] 100%"), std::string::npos) << r.err;
  EXPECT_EQ(lines(r.err).size(), 1u);
}

TEST_F(HedgeCli, ProgressStaysOutOfFilesAndPipesByDefault) {
  for (const char* setting : {static_cast<const char*>(nullptr), "auto", "never"}) {
    const ProgressSetting s(setting);
    const Result r =
        run({"smooth", data("spot_triangulated.obj"), tmp("s.obj").string(), "--iterations", "20"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << (setting ? setting : "unset");
  }
}

TEST_F(HedgeCli, AnUnknownProgressSettingIsAUsageError) {
  const ProgressSetting bad("sometimes");
  const Result r = run({"smooth", data("tet.obj"), tmp("s.obj").string()});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("HEDGE_PROGRESS must be auto, always or never, got 'sometimes'"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(tmp("s.obj")));
}

TEST_F(HedgeCli, AnErrorAfterTheBarStartsOnALineOfItsOwn) {
  const ProgressSetting always("always");
  // The bar is drawn while smoothing; writing to a folder that is a file then fails.
  write_text(tmp("file"), "x");
  const Result r =
      run({"smooth", data("spot_triangulated.obj"), (tmp("file") / "out.obj").string(), "--iterations", "5"});
  EXPECT_EQ(r.code, 1);
  const auto err = lines(r.err);
  ASSERT_EQ(err.size(), 2u) << r.err;
  EXPECT_EQ(err[1].rfind("hedge: error: ", 0), 0u) << err[1];
}

}  // namespace

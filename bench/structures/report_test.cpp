// The report of the structures benchmark: growth classification and the generated section of
// docs/structures.md. Built and run by bench/structures/run before it measures anything, and by
// CTest in a build with HEDGE_BUILD_BENCH=ON.
#include "report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace hedge::structures {
namespace {

//! A series whose every query of structure 0 costs c * n_t^slope.
std::vector<MeshResult> synthetic_series(double slope) {
  std::vector<MeshResult> series;
  for (std::size_t n = 1000; n <= 1'024'000; n *= 4) {
    MeshResult m;
    m.n_faces = n;
    m.structures[0].ok = true;
    m.structures[0].build_ns = 30.0 * double(n);
    for (QueryTiming& q : m.structures[0].queries) q.ns = 5.0 * std::pow(double(n), slope);
    series.push_back(m);
  }
  return series;
}

TEST(Report, ClassifiesGrowth) {
  const GrowthFit flat = fit_growth(synthetic_series(0.1), 0, 0);
  EXPECT_NEAR(flat.slope, 0.1, 1e-9);
  EXPECT_TRUE(flat.clear);
  EXPECT_EQ(flat.measured, Growth::constant);
  const GrowthFit linear = fit_growth(synthetic_series(1.0), 0, 3);
  EXPECT_NEAR(linear.slope, 1.0, 1e-9);
  EXPECT_EQ(linear.measured, Growth::linear);
  EXPECT_FALSE(fit_growth(synthetic_series(0.6), 0, 0).clear);
  EXPECT_NEAR(fit_growth(synthetic_series(1.0), 0, kQueryCount).slope, 0.0, 1e-9);  // build per triangle
  EXPECT_FALSE(std::isfinite(fit_growth(synthetic_series(1.0), 1, 0).slope));       // structure not built
}

TEST(Report, OneDisturbedSizeDoesNotChangeTheClass) {
  std::vector<MeshResult> series = synthetic_series(0.0);
  series.back().structures[0].queries[0].ns *= 30;  // one sample hit by a busy machine
  EXPECT_EQ(fit_growth(series, 0, 0).measured, Growth::constant);
}

TEST(Report, ReplacesOnlyTheGeneratedSection) {
  const std::string doc = std::string("intro\n") + kBeginMarker + "\nold\n" + kEndMarker + "\noutro\n";
  const std::string out = replace_generated(doc, "new\n");
  EXPECT_EQ(out, std::string("intro\n") + kBeginMarker + "\nnew\n" + kEndMarker + "\noutro\n");
  EXPECT_EQ(replace_generated(out, "new\n"), out);
  EXPECT_THROW(replace_generated("no markers", "x"), std::runtime_error);
}

}  // namespace
}  // namespace hedge::structures

#include <gtest/gtest.h>

#include "hedge/core/build.h"

namespace hedge {
namespace {

TEST(Weld, ExactMergesIdenticalPositionsInFirstSeenOrder) {
  std::vector<Vec3> p = {{1, 2, 3}, {0, 0, 0}, {1, 2, 3}, {-0.0f, 0, 0}, {1, 2, 3.0000005f}};
  std::vector<Vec3> unique;
  auto map = weld_positions(p, Weld::exact, 0, unique);
  EXPECT_EQ(map, (std::vector<Index>{0, 1, 0, 1, 2}));
  EXPECT_EQ(unique.size(), 3u);
  EXPECT_EQ(unique[0], (Vec3{1, 2, 3}));
}

TEST(Weld, EpsilonIsRelativeToTheBoundingBox) {
  // Box diagonal 100: 1e-4 relative is 0.01 absolute.
  std::vector<Vec3> p = {{0, 0, 0}, {100, 0, 0}, {0.005f, 0, 0}, {0.02f, 0, 0}, {99.995f, 0.001f, 0}};
  std::vector<Vec3> unique;
  auto map = weld_positions(p, Weld::epsilon, 1e-4, unique);
  EXPECT_EQ(map, (std::vector<Index>{0, 1, 0, 2, 1}));
  EXPECT_EQ(unique.size(), 3u);
  // Points are matched to kept representatives, never chained through each other.
  std::vector<Vec3> chain = {{0, 0, 0}, {100, 0, 0}, {0.008f, 0, 0}, {0.016f, 0, 0}};
  map = weld_positions(chain, Weld::epsilon, 1e-4, unique);
  EXPECT_EQ(map, (std::vector<Index>{0, 1, 0, 2}));
}

TEST(Weld, NoneAndDegenerateBoxes) {
  std::vector<Vec3> p = {{1, 1, 1}, {1, 1, 1}};
  std::vector<Vec3> unique;
  EXPECT_EQ(weld_positions(p, Weld::none, 0, unique), (std::vector<Index>{0, 1}));
  EXPECT_EQ(unique.size(), 2u);
  // All points equal: the box is empty, so epsilon welding falls back to exact.
  EXPECT_EQ(weld_positions(p, Weld::epsilon, 1e-3, unique), (std::vector<Index>{0, 0}));
  EXPECT_TRUE(weld_positions({}, Weld::epsilon, 1e-3, unique).empty());
}

TEST(Weld, ManyPointsInOneCell) {
  std::vector<Vec3> p;
  for (int i = 0; i < 1000; ++i) p.push_back({float(i % 10) * 1e-9f, 0, 0});
  p.push_back({1, 1, 1});
  std::vector<Vec3> unique;
  auto map = weld_positions(p, Weld::epsilon, 1e-3, unique);
  EXPECT_EQ(unique.size(), 2u);
  EXPECT_EQ(map.back(), 1u);
}

}  // namespace
}  // namespace hedge

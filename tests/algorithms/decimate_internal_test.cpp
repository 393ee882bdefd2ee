// The pieces decimate.cpp keeps apart in decimate_internal.h: the radix sort of the candidates'
// keys (the decimation itself is tested in decimate_test.cpp).
#include "algorithms/decimate_internal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hedge/algorithms/geometry.h"
#include "hedge/core/vec.h"

namespace hedge::detail::decimation {
namespace {

// A candidate's key: a cost's float bits over a half-edge index.
std::uint64_t key(float cost, std::uint32_t halfedge) {
  return std::uint64_t(float_bits(cost)) << 32 | halfedge;
}

// The sort orders by cost alone and is stable: equal costs keep the order they came in (the
// order of the edges), which the decimation's results depend on.
void expect_sorted_like_std(std::vector<std::uint64_t> keys) {
  std::vector<std::uint64_t> expected = keys, scratch;
  std::stable_sort(expected.begin(), expected.end(),
                   [](std::uint64_t a, std::uint64_t b) { return (a >> 32) < (b >> 32); });
  radix_sort(keys, scratch);
  EXPECT_EQ(keys, expected);
}

TEST(DecimateRadixSort, CostsOfManyMagnitudesSortAndEqualCostsKeepTheirOrder) {
  SplitMix64 random(25);
  std::vector<std::uint64_t> keys;
  for (std::uint32_t i = 0; i < 5000; ++i) {
    // Costs from 1e-30 to 1e10, and repeated costs whose half-edges come in no order.
    const float cost = i % 7 == 0 ? 0.5f : static_cast<float>(std::pow(10.0, -30 + 40 * random.uniform()));
    keys.push_back(key(cost, static_cast<std::uint32_t>(random.next() % 100000)));
  }
  keys.push_back(key(0.0f, 3));
  expect_sorted_like_std(keys);
}

// Costs of one binade share their top digit (and costs close together the middle one too): the
// passes that would move nothing are skipped, and the order still comes out right.
TEST(DecimateRadixSort, CostsSharingTheirTopDigitsStillSort) {
  SplitMix64 random(7);
  std::vector<std::uint64_t> same_binade, same_top_two, one_cost;
  for (std::uint32_t i = 0; i < 3000; ++i) {
    same_binade.push_back(key(static_cast<float>(1 + random.uniform()), 2999 - i));
    same_top_two.push_back(key(static_cast<float>(1 + 0x1p-11 * random.uniform()), i * 7 % 3001));
    one_cost.push_back(key(0.25f, static_cast<std::uint32_t>(random.next() >> 40)));
  }
  expect_sorted_like_std(same_binade);
  expect_sorted_like_std(same_top_two);
  expect_sorted_like_std(one_cost);
}

TEST(DecimateRadixSort, EmptyAndSingleKey) {
  expect_sorted_like_std({});
  expect_sorted_like_std({key(1.0f, 4)});
}

}  // namespace
}  // namespace hedge::detail::decimation

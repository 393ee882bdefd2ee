#include "binding/picking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "binding_error.h"

namespace hedge::binding {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(BindingPicking, FinitePointsAndDirectionsPass) {
  EXPECT_EQ(need_finite(Vec3{1, -2, 3}, "origin"), (Vec3{1, -2, 3}));
  EXPECT_EQ(need_direction(Vec3{0, 0, 1e-30f}, "direction"), (Vec3{0, 0, 1e-30f}));
}

TEST(BindingPicking, NonFiniteOrZeroIsRefusedByName) {
  const BindingError nan = error_of([] { need_finite(Vec3{NAN, 0, 0}, "ray_cast: origins[3]"); });
  EXPECT_EQ(nan.status, HEDGE_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(nan.message, "ray_cast: origins[3] (nan, 0, 0) is not finite");
  EXPECT_EQ(error_of([] {
              need_direction(Vec3{0, -kInf, 1}, "direction");
            }).message,
            "direction (0, -inf, 1) is not finite");
  const BindingError zero = error_of([] { need_direction(Vec3{0, -0.0f, 0}, "directions[0]"); });
  EXPECT_EQ(zero.status, HEDGE_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(zero.message, "directions[0] has zero length");
}

}  // namespace
}  // namespace hedge::binding

#include "hedge/core/vec.h"

#include <gtest/gtest.h>

namespace hedge {
namespace {

// Rounds p in place and uses it at once, the shape in which GCC 12 at -O2 dropped the rounding of
// x and y from to_double(to_float(p)) (decimation's placement was written so).
[[gnu::noinline]] double round_and_use(Vec3d& p) {
  p = rounded_to_float(p);
  return p.x * 2 + p.y * 3 + p.z;
}

TEST(Vec, RoundedToFloatRoundsEveryCoordinate) {
  volatile double tenth = 0.1;  // not a constant the compiler could fold
  Vec3d p{tenth, tenth * 3, tenth * 7};
  const double used = round_and_use(p);
  EXPECT_EQ(p.x, double(0.1f));
  EXPECT_EQ(p.y, double(float(0.1 * 3)));
  EXPECT_EQ(p.z, double(float(0.1 * 7)));
  EXPECT_EQ(used, p.x * 2 + p.y * 3 + p.z);
  Vec3d exact{0.5, -2.0, 1024.0};  // already floats: unchanged
  round_and_use(exact);
  EXPECT_EQ(exact.x, 0.5);
  EXPECT_EQ(exact.y, -2.0);
  EXPECT_EQ(exact.z, 1024.0);
}

TEST(Vec, ToFloatAndBackAgreeWithRoundedToFloat) {
  const Vec3d p{1.0 / 3, 2.0 / 3, 1e-3};
  const Vec3 f = to_float(p);
  const Vec3d r = rounded_to_float(p);
  EXPECT_EQ(r.x, double(f.x));
  EXPECT_EQ(r.y, double(f.y));
  EXPECT_EQ(r.z, double(f.z));
}

}  // namespace
}  // namespace hedge

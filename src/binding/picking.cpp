#include "binding/picking.h"

#include <cstdio>

#include "binding/errors.h"

namespace hedge::binding {

Vec3 need_finite(const Vec3& p, const std::string& name) {
  if (!is_finite(p)) {
    char text[96];
    std::snprintf(text, sizeof text, " (%g, %g, %g) is not finite", double(p.x), double(p.y), double(p.z));
    fail(HEDGE_ERROR_INVALID_ARGUMENT, name + text);
  }
  return p;
}

Vec3 need_direction(const Vec3& d, const std::string& name) {
  need_finite(d, name);
  if (d.x == 0 && d.y == 0 && d.z == 0) fail(HEDGE_ERROR_INVALID_ARGUMENT, name + " has zero length");
  return d;
}

}  // namespace hedge::binding

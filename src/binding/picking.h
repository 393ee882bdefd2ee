// The binding core: the checks of what a picking call gets (points, ray origins and directions),
// so that every binding refuses a NaN, an infinity or a zero direction with the same words instead
// of reporting it as "nothing hit".
#pragma once

#include <string>

#include "hedge/core/vec.h"

namespace hedge::binding {

//! `p`, a query point or a ray's origin, if finite. \throw BindingError
//! (HEDGE_ERROR_INVALID_ARGUMENT) "NAME (x, y, z) is not finite" otherwise.
Vec3 need_finite(const Vec3& p, const std::string& name);

//! `d`, a ray's direction, if finite and not zero. \throw BindingError
//! (HEDGE_ERROR_INVALID_ARGUMENT) "NAME (x, y, z) is not finite" or "NAME has zero length".
Vec3 need_direction(const Vec3& d, const std::string& name);

}  // namespace hedge::binding

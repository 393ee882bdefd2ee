// How the algorithms write a number into an error message: nine significant digits, enough to tell
// a float apart from its neighbours, without the noise of a double's seventeen.
#pragma once

#include <cstdio>
#include <string>

namespace hedge::detail {

inline std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace hedge::detail

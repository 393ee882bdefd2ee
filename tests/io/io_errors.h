// Test support for the readers: the IoError a call throws, for checks of its message and place.
#pragma once

#include <gtest/gtest.h>

#include "hedge/error.h"

namespace hedge::test {

//! The IoError f() throws; a test failure (and an empty error) when it throws none.
template <typename F>
IoError catch_io_error(F&& f) {
  try {
    f();
  } catch (const IoError& e) {
    return e;
  }
  ADD_FAILURE() << "no IoError";
  return IoError("", 0, -1, "");
}

}  // namespace hedge::test

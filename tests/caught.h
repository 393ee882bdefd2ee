// Test support: the exception a call throws, kept for checks of what it says.
#pragma once

#include <gtest/gtest.h>

namespace hedge::test {

//! The E that f() throws; a test failure, and `none`, when it throws none.
template <typename E, typename F>
E caught(F&& f, E none) {
  try {
    f();
  } catch (const E& e) {
    return e;
  }
  ADD_FAILURE() << "nothing was thrown";
  return none;
}

}  // namespace hedge::test

// What the tests of the binding core share (edits_test.cpp, handles_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include "binding/errors.h"
#include "caught.h"

namespace hedge::binding {

// The BindingError that body() throws; a test failure (and HEDGE_OK) when it throws none.
template <typename Body>
BindingError error_of(Body&& body) {
  return test::caught<BindingError>(body, {HEDGE_OK, ""});
}

}  // namespace hedge::binding

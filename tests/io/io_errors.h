// Test support for the readers and writers: the IoError a call throws, for checks of its message
// and place.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "caught.h"
#include "hedge/error.h"

namespace hedge::test {

//! The IoError f() throws; a test failure (and an empty error) when it throws none.
template <typename F>
IoError catch_io_error(F&& f) {
  return caught<IoError>(f, IoError("", 0, -1, ""));
}

//! f() throws an IoError whose message holds `what`; the error, for further checks.
template <typename F>
IoError expect_io_error(F&& f, const std::string& what) {
  IoError e = catch_io_error(f);
  EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  return e;
}

}  // namespace hedge::test

// The binding core's error kinds (src/binding/errors.cpp).
#include "binding/errors.h"

#include <gtest/gtest.h>

#include <cctype>
#include <new>
#include <stdexcept>
#include <string>

#include "hedge/error.h"

namespace hedge::binding {
namespace {

// The failure that throwing `thrown` maps to, with its message and refusal copied out.
struct Mapped {
  hedge_status status;
  std::string message, refusal;
};
template <typename Throw>
Mapped map(Throw&& thrown) {
  try {
    thrown();
  } catch (...) {
    const Failure f = current_failure();
    return {f.status, f.message, f.refusal};
  }
  ADD_FAILURE() << "nothing was thrown";
  return {};
}

TEST(BindingErrors, EveryExceptionMapsToOneStatus) {
  EXPECT_EQ(map([] { throw IoError("a.obj", 3, -1, "bad face"); }).status, HEDGE_ERROR_IO);
  EXPECT_EQ(map([] { throw TopologyError("three faces on an edge"); }).status, HEDGE_ERROR_TOPOLOGY);
  EXPECT_EQ(map([] { throw InvalidInputError("NaN"); }).status, HEDGE_ERROR_INVALID_ARGUMENT);
  // A plain hedge::Error is bad input or an illegal request, never a bug.
  const Mapped plain = map([] { throw Error("an illegal request"); });
  EXPECT_EQ(plain.status, HEDGE_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(plain.message, "an illegal request");
  EXPECT_EQ(map([] { throw std::bad_alloc(); }).status, HEDGE_ERROR_OUT_OF_MEMORY);
  EXPECT_EQ(map([] { throw std::length_error("vector too long"); }).status, HEDGE_ERROR_OUT_OF_MEMORY);
  const Mapped bug = map([] { throw std::logic_error("a bug"); });
  EXPECT_EQ(bug.status, HEDGE_ERROR_INTERNAL);
  EXPECT_EQ(bug.message, "a bug");
  EXPECT_EQ(map([] { throw 42; }).status, HEDGE_ERROR_INTERNAL);
  const Mapped busy = map([] { fail(HEDGE_ERROR_BUSY, "busy"); });
  EXPECT_EQ(busy.status, HEDGE_ERROR_BUSY);
  EXPECT_EQ(busy.refusal, "");
}

TEST(BindingErrors, ARefusalCarriesItsReasonApart) {
  const Mapped r = map([] { refuse("flip of edge 3", "the edge is on the boundary"); });
  EXPECT_EQ(r.status, HEDGE_ERROR_REFUSED);
  EXPECT_EQ(r.message, "flip of edge 3 refused: the edge is on the boundary; nothing was changed");
  EXPECT_EQ(r.refusal, "the edge is on the boundary");
  EXPECT_NO_THROW(require_allowed(nullptr, "flip of edge 3"));
  EXPECT_EQ(map([] { require_allowed("why", "what"); }).refusal, "why");
}

TEST(BindingErrors, StatusNamesInCAndJs) {
  EXPECT_STREQ(status_name(HEDGE_ERROR_BAD_HANDLE), "HEDGE_ERROR_BAD_HANDLE");
  EXPECT_STREQ(kind_name(HEDGE_ERROR_BAD_HANDLE), "bad-handle");
  EXPECT_STREQ(kind_name(HEDGE_ERROR_BUFFER_TOO_SMALL), "buffer-too-small");
  EXPECT_STREQ(kind_name(HEDGE_OK), "none");
  EXPECT_STREQ(status_name(-77), "HEDGE_ERROR_UNKNOWN");
  EXPECT_STREQ(kind_name(-77), "internal");
  // The JS name is the C name's tail, lower case, '-' for '_': one list, two spellings.
  for (hedge_status s = HEDGE_ERROR_INVALID_ARGUMENT; s >= HEDGE_ERROR_BUSY; --s) {
    std::string js = kind_name(s);
    for (char& c : js) c = c == '-' ? '_' : char(std::toupper(static_cast<unsigned char>(c)));
    EXPECT_EQ("HEDGE_ERROR_" + js, status_name(s));
  }
}

// The C ABI's refusal names: "HEDGE_REFUSAL_" and the table's name in capitals, for every code.
TEST(BindingErrors, RefusalNamesInC) {
  EXPECT_STREQ(refusal_name(Refusal::none), "HEDGE_REFUSAL_NONE");
  EXPECT_STREQ(refusal_name(Refusal::flip_boundary_edge), "HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE");
  EXPECT_STREQ(refusal_name(static_cast<Refusal>(kRefusalCount)), "HEDGE_REFUSAL_UNKNOWN");
  EXPECT_STREQ(refusal_name(static_cast<Refusal>(-1)), "HEDGE_REFUSAL_UNKNOWN");
  for (const RefusalEntry& r : refusals()) {
    std::string c = r.name;
    for (char& ch : c) ch = char(std::toupper(static_cast<unsigned char>(ch)));
    EXPECT_EQ("HEDGE_REFUSAL_" + c, refusal_name(r.code));
  }
}

}  // namespace
}  // namespace hedge::binding

#include "binding/errors.h"

#include <cctype>
#include <cstdio>
#include <new>
#include <stdexcept>

#include "hedge/error.h"

namespace hedge::binding {

void fail(hedge_status status, std::string message) { throw BindingError{status, std::move(message)}; }

void refuse(const std::string& what, const char* why) {
  throw BindingError{HEDGE_ERROR_REFUSED, what + " refused: " + why + "; nothing was changed", why};
}

Failure current_failure() noexcept {
  try {
    throw;
  } catch (const BindingError& e) {
    return {e.status, e.message.c_str(), e.refusal != nullptr ? e.refusal : ""};
  } catch (const IoError& e) {
    return {HEDGE_ERROR_IO, e.what(), ""};
  } catch (const TopologyError& e) {
    return {HEDGE_ERROR_TOPOLOGY, e.what(), ""};
  } catch (const Error& e) {
    // InvalidInputError, and every other hedge::Error: bad input or an illegal request, never a bug.
    return {HEDGE_ERROR_INVALID_ARGUMENT, e.what(), ""};
  } catch (const std::bad_alloc&) {
    return {HEDGE_ERROR_OUT_OF_MEMORY, "out of memory", ""};
  } catch (const std::length_error& e) {
    return {HEDGE_ERROR_OUT_OF_MEMORY, e.what(), ""};
  } catch (const std::exception& e) {
    return {HEDGE_ERROR_INTERNAL, e.what(), ""};
  } catch (...) {
    return {HEDGE_ERROR_INTERNAL, "unknown internal error", ""};
  }
}

namespace {
struct StatusNames {
  hedge_status status;
  const char* c;
  const char* js;
};
constexpr StatusNames kStatusNames[] = {
    {HEDGE_OK, "HEDGE_OK", "none"},
    {HEDGE_ERROR_INVALID_ARGUMENT, "HEDGE_ERROR_INVALID_ARGUMENT", "invalid-argument"},
    {HEDGE_ERROR_BAD_HANDLE, "HEDGE_ERROR_BAD_HANDLE", "bad-handle"},
    {HEDGE_ERROR_REFUSED, "HEDGE_ERROR_REFUSED", "refused"},
    {HEDGE_ERROR_IO, "HEDGE_ERROR_IO", "io"},
    {HEDGE_ERROR_TOPOLOGY, "HEDGE_ERROR_TOPOLOGY", "topology"},
    {HEDGE_ERROR_OUT_OF_MEMORY, "HEDGE_ERROR_OUT_OF_MEMORY", "out-of-memory"},
    {HEDGE_ERROR_BUFFER_TOO_SMALL, "HEDGE_ERROR_BUFFER_TOO_SMALL", "buffer-too-small"},
    {HEDGE_ERROR_INTERNAL, "HEDGE_ERROR_INTERNAL", "internal"},
    {HEDGE_ERROR_BUSY, "HEDGE_ERROR_BUSY", "busy"},
};
const StatusNames* find(hedge_status status) {
  for (const StatusNames& n : kStatusNames)
    if (n.status == status) return &n;
  return nullptr;
}
}  // namespace

const char* status_name(hedge_status status) noexcept {
  const StatusNames* n = find(status);
  return n != nullptr ? n->c : "HEDGE_ERROR_UNKNOWN";
}

const char* kind_name(hedge_status status) noexcept {
  const StatusNames* n = find(status);
  return n != nullptr ? n->js : "internal";
}

// The C ABI's refusal codes are the library's table (hedge/core/refusal.h), value for value.
static_assert(HEDGE_REFUSAL_COUNT == kRefusalCount,
              "c_api.h's HEDGE_REFUSAL_* and hedge/core/refusal.h differ");
static_assert(HEDGE_REFUSAL_FILL_HOLE_LOOP_TOO_SHORT == static_cast<int>(Refusal::fill_hole_loop_too_short));

const char* refusal_name(Refusal refusal) noexcept {
  // "HEDGE_REFUSAL_" and the table's name in capitals, made once; every name fits in 64 bytes.
  struct Names {
    char text[kRefusalCount][64] = {};
    Names() {
      for (std::int32_t i = 0; i < kRefusalCount; ++i) {
        std::snprintf(text[i], sizeof text[i], "HEDGE_REFUSAL_%s", kRefusals[i].name);
        for (char* c = text[i]; *c != '\0'; ++c)
          *c = static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
      }
    }
  };
  static const Names names;
  const auto i = static_cast<std::int32_t>(refusal);
  return i >= 0 && i < kRefusalCount ? names.text[i] : "HEDGE_REFUSAL_UNKNOWN";
}

}  // namespace hedge::binding

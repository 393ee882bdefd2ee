// The binding core's one list of error kinds. Every binding reports a failed call as a hedge_status
// of the C ABI (include/hedge/c_api.h); the JS API names the same statuses with kind strings
// (HedgeError.kind) and the C# binding with HedgeStatus, one to one. The library's exceptions map
// onto the list here, once:
//   hedge::IoError           HEDGE_ERROR_IO
//   hedge::TopologyError     HEDGE_ERROR_TOPOLOGY
//   hedge::InvalidInputError HEDGE_ERROR_INVALID_ARGUMENT
//   any other hedge::Error   HEDGE_ERROR_INVALID_ARGUMENT: the library throws it for bad input or an
//                            illegal request only (hedge/error.h), never for a bug
//   std::bad_alloc, std::length_error  HEDGE_ERROR_OUT_OF_MEMORY
//   anything else            HEDGE_ERROR_INTERNAL (a bug)
// and a BindingError carries its own status (a bad handle, a refused edit, a busy mesh, ...).
#pragma once

#include <string>

#include "hedge/c_api.h"
#include "hedge/core/refusal.h"

namespace hedge::binding {

//! A failure detected by a binding or the binding core, with the status it maps to. A refused edit
//! (HEDGE_ERROR_REFUSED) also carries the refusal: the library's reason (a static string).
struct BindingError {
  hedge_status status;
  std::string message;
  const char* refusal = nullptr;
};

//! \throw BindingError with this status and message.
[[noreturn]] void fail(hedge_status status, std::string message);
//! \throw BindingError (HEDGE_ERROR_REFUSED) saying "<what> refused: <why>; nothing was changed".
[[noreturn]] void refuse(const std::string& what, const char* why);
//! Refuses `what` (see refuse()) if `why`, an edit's refusal, is not null.
inline void require_allowed(const char* why, const std::string& what) {
  if (why != nullptr) refuse(what, why);
}

//! What a failed call reports. `message` and `refusal` stay valid while the exception is handled.
struct Failure {
  hedge_status status;
  const char* message;
  const char* refusal;  //!< the refusal of a refused edit, "" otherwise
};
//! The failure that the exception being handled maps to (the table at the top of this file). Call
//! it inside a catch block only.
Failure current_failure() noexcept;

//! The status's constant name in the C ABI ("HEDGE_ERROR_BAD_HANDLE"), "HEDGE_ERROR_UNKNOWN" for a
//! value that is none.
const char* status_name(hedge_status status) noexcept;
//! The status's name in the JS API (HedgeError.kind): "invalid-argument", "bad-handle", "refused",
//! "io", "topology", "out-of-memory", "buffer-too-small", "internal", "busy"; "none" for HEDGE_OK.
const char* kind_name(hedge_status status) noexcept;

//! The refusal's constant name in the C ABI ("HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE": the table's name in
//! capitals), "HEDGE_REFUSAL_UNKNOWN" for a value that is none. Static storage.
const char* refusal_name(Refusal refusal) noexcept;

}  // namespace hedge::binding

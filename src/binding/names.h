// The names of the library's enums that bindings and the CLI take as strings, written once, with one
// spelling everywhere (the CLI's --method, the JS API's strings, ...):
//   Subdivision   loop, midpoint, catmull-clark, sqrt3, split-faces (also catmull_clark, split_faces)
//   SmoothMethod  uniform, taubin, cotangent, implicit (also cotan)
//   NormalSource  none, attribute, computed, auto (also automatic)
//   NormalWeighting  area, angle, uniform
//   Ordering      spatial, vertex-cache (also vertex_cache)
// The spellings in parentheses are accepted aliases; name() gives the first. Below them, the build
// options' enums from the C ABI's integers (HEDGE_WELD_*, ...), which the JS API passes too.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/fracture_solid.h"
#include "hedge/algorithms/normals.h"
#include "hedge/algorithms/reorder.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/render/render_buffers.h"

namespace hedge::binding {

//! The value `text` names. \throw InvalidInputError "unknown smoothing method 'x' (uniform, taubin,
//! cotangent, implicit)" for a name that is none.
Subdivision parse_subdivision(std::string_view text);
SmoothMethod parse_smooth_method(std::string_view text);
NormalSource parse_normal_source(std::string_view text);
NormalWeighting parse_normal_weighting(std::string_view text);
Ordering parse_ordering(std::string_view text);

//! The value's name.
const char* name(Subdivision value);
const char* name(SmoothMethod value);
const char* name(NormalSource value);
const char* name(NormalWeighting value);
const char* name(Ordering value);

//! Why decimate() stopped, as every binding says it: "target_reached", "error_bound",
//! "no_legal_collapse" (the enumerators' names). A switch without a default, compiled with
//! -Werror=switch: an enumerator added to DecimateStop without a name here does not build.
const char* name(DecimateStop value);
//! The C ABI's HEDGE_DECIMATE_STOP_* constant of the value (its position in DecimateStop).
std::int32_t constant(DecimateStop value);

//! Why a strike cannot be a solid fracture, as every binding says it: "none", "open",
//! "non_manifold", "bad_option", "bad_impact", "off_surface", "no_face", "bad_radius",
//! "foreign_tree" (the enumerators' names). A switch without a default, as name(DecimateStop).
const char* name(SolidRefusal value);
//! The C ABI's HEDGE_SOLID_REFUSAL_* constant of the value (its position in SolidRefusal).
std::int32_t constant(SolidRefusal value);

//! Every accepted spelling (names first, then aliases), for a command line's list of choices.
std::vector<std::string> subdivision_spellings();
std::vector<std::string> smooth_method_spellings();
std::vector<std::string> normal_source_spellings();

//! Fails with HEDGE_ERROR_INVALID_ARGUMENT: "<what> is <constant>, not a <constants> value".
[[noreturn]] void unknown_constant(const char* what, std::int32_t constant, const char* constants);

//! One C ABI constant and the library's value it stands for.
template <typename E>
struct Constant {
  std::int32_t constant;
  E value;
};
//! The value that `constant` stands for in `table`. \throw BindingError
//! (HEDGE_ERROR_INVALID_ARGUMENT) "<what> is 7, not a <constants> value" if it is none of them.
template <typename E, std::size_t N>
E from_constant(const Constant<E> (&table)[N], std::int32_t constant, const char* what,
                const char* constants) {
  for (const Constant<E>& c : table)
    if (c.constant == constant) return c.value;
  unknown_constant(what, constant, constants);
}

//! The value of a HEDGE_WELD_*, HEDGE_POLICY_* or HEDGE_WINDING_* constant. \throw BindingError
//! (HEDGE_ERROR_INVALID_ARGUMENT) "weld is 7, not a HEDGE_WELD_* value" for another integer.
Weld to_weld(std::int32_t weld);
TopologyPolicy to_policy(std::int32_t policy);
Winding to_winding(std::int32_t winding);

//! The most threads a binding's caller may ask a call for.
inline constexpr std::int64_t kMaxThreadsAsked = 1024;
//! A count of threads as every binding takes it: 0 means every core (max_threads(),
//! hedge/core/threads.h), 1 to kMaxThreadsAsked that many. \throw BindingError
//! (HEDGE_ERROR_INVALID_ARGUMENT) "WHAT must be 0 (every core) to 1024, got N" for another.
unsigned thread_count(std::int64_t threads, const char* what);

}  // namespace hedge::binding

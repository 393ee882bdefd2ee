#include "binding/names.h"

#include <span>

#include "binding/errors.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge::binding {

namespace {

template <typename E>
struct Spelling {
  const char* text;
  E value;
  bool alias;
};

constexpr Spelling<Subdivision> kSubdivision[] = {
    {"loop", Subdivision::loop, false},
    {"midpoint", Subdivision::midpoint, false},
    {"catmull-clark", Subdivision::catmull_clark, false},
    {"sqrt3", Subdivision::sqrt3, false},
    {"split-faces", Subdivision::split_faces, false},
    {"catmull_clark", Subdivision::catmull_clark, true},
    {"split_faces", Subdivision::split_faces, true},
};
constexpr Spelling<SmoothMethod> kSmoothMethod[] = {
    {"uniform", SmoothMethod::uniform, false},     {"taubin", SmoothMethod::taubin, false},
    {"cotangent", SmoothMethod::cotangent, false}, {"implicit", SmoothMethod::implicit, false},
    {"cotan", SmoothMethod::cotangent, true},
};
constexpr Spelling<NormalSource> kNormalSource[] = {
    {"none", NormalSource::none, false},          {"attribute", NormalSource::attribute, false},
    {"computed", NormalSource::computed, false},  {"auto", NormalSource::automatic, false},
    {"automatic", NormalSource::automatic, true},
};
constexpr Spelling<NormalWeighting> kNormalWeighting[] = {
    {"area", NormalWeighting::area, false},
    {"angle", NormalWeighting::angle, false},
    {"uniform", NormalWeighting::uniform, false},
};
constexpr Spelling<Ordering> kOrdering[] = {
    {"spatial", Ordering::spatial, false},
    {"vertex-cache", Ordering::vertex_cache, false},
    {"vertex_cache", Ordering::vertex_cache, true},
};

template <typename E>
E parse(std::span<const Spelling<E>> table, std::string_view text, const char* what) {
  std::string known;
  for (const Spelling<E>& s : table) {
    if (text == s.text) return s.value;
    if (!s.alias) known += std::string(known.empty() ? "" : ", ") + s.text;
  }
  throw InvalidInputError("unknown " + std::string(what) + " '" + std::string(text) + "' (" + known + ")");
}

template <typename E>
const char* name_in(std::span<const Spelling<E>> table, E value) {
  for (const Spelling<E>& s : table)
    if (s.value == value) return s.text;
  return "unknown";
}

template <typename E>
std::vector<std::string> spellings(std::span<const Spelling<E>> table) {
  std::vector<std::string> out;
  for (const Spelling<E>& s : table) out.emplace_back(s.text);
  return out;
}

}  // namespace

Subdivision parse_subdivision(std::string_view text) {
  return parse<Subdivision>(kSubdivision, text, "subdivision scheme");
}
SmoothMethod parse_smooth_method(std::string_view text) {
  return parse<SmoothMethod>(kSmoothMethod, text, "smoothing method");
}
NormalSource parse_normal_source(std::string_view text) {
  return parse<NormalSource>(kNormalSource, text, "normal source");
}
NormalWeighting parse_normal_weighting(std::string_view text) {
  return parse<NormalWeighting>(kNormalWeighting, text, "normal weighting");
}
Ordering parse_ordering(std::string_view text) { return parse<Ordering>(kOrdering, text, "ordering"); }

const char* name(Subdivision value) { return name_in<Subdivision>(kSubdivision, value); }
const char* name(SmoothMethod value) { return name_in<SmoothMethod>(kSmoothMethod, value); }
const char* name(NormalSource value) { return name_in<NormalSource>(kNormalSource, value); }
const char* name(NormalWeighting value) { return name_in<NormalWeighting>(kNormalWeighting, value); }
const char* name(Ordering value) { return name_in<Ordering>(kOrdering, value); }

std::vector<std::string> subdivision_spellings() { return spellings<Subdivision>(kSubdivision); }
std::vector<std::string> smooth_method_spellings() { return spellings<SmoothMethod>(kSmoothMethod); }
std::vector<std::string> normal_source_spellings() { return spellings<NormalSource>(kNormalSource); }

void unknown_constant(const char* what, std::int32_t constant, const char* constants) {
  fail(HEDGE_ERROR_INVALID_ARGUMENT,
       std::string(what) + " is " + std::to_string(constant) + ", not a " + constants + " value");
}

Weld to_weld(std::int32_t weld) {
  static constexpr Constant<Weld> kWelds[] = {
      {HEDGE_WELD_NONE, Weld::none}, {HEDGE_WELD_EXACT, Weld::exact}, {HEDGE_WELD_EPSILON, Weld::epsilon}};
  return from_constant(kWelds, weld, "weld", "HEDGE_WELD_*");
}

TopologyPolicy to_policy(std::int32_t policy) {
  static constexpr Constant<TopologyPolicy> kPolicies[] = {{HEDGE_POLICY_STRICT, TopologyPolicy::strict},
                                                           {HEDGE_POLICY_REPAIR, TopologyPolicy::repair}};
  return from_constant(kPolicies, policy, "policy", "HEDGE_POLICY_*");
}

Winding to_winding(std::int32_t winding) {
  static constexpr Constant<Winding> kWindings[] = {{HEDGE_WINDING_CCW, Winding::ccw},
                                                    {HEDGE_WINDING_CW, Winding::cw}};
  return from_constant(kWindings, winding, "winding", "HEDGE_WINDING_*");
}

unsigned thread_count(std::int64_t threads, const char* what) {
  if (threads < 0 || threads > kMaxThreadsAsked)
    fail(HEDGE_ERROR_INVALID_ARGUMENT, std::string(what) + " must be 0 (every core) to " +
                                           std::to_string(kMaxThreadsAsked) + ", got " +
                                           std::to_string(threads));
  return threads == 0 ? max_threads() : static_cast<unsigned>(threads);
}

const char* name(DecimateStop value) {
  switch (value) {
    case DecimateStop::target_reached:
      return "target_reached";
    case DecimateStop::error_bound:
      return "error_bound";
    case DecimateStop::no_legal_collapse:
      return "no_legal_collapse";
  }
  return "unknown";
}

std::int32_t constant(DecimateStop value) { return static_cast<std::int32_t>(value); }

const char* name(SolidRefusal value) {
  switch (value) {
    case SolidRefusal::none:
      return "none";
    case SolidRefusal::open:
      return "open";
    case SolidRefusal::non_manifold:
      return "non_manifold";
    case SolidRefusal::bad_option:
      return "bad_option";
    case SolidRefusal::bad_impact:
      return "bad_impact";
    case SolidRefusal::off_surface:
      return "off_surface";
    case SolidRefusal::no_face:
      return "no_face";
    case SolidRefusal::bad_radius:
      return "bad_radius";
    case SolidRefusal::foreign_tree:
      return "foreign_tree";
  }
  return "unknown";
}

std::int32_t constant(SolidRefusal value) { return static_cast<std::int32_t>(value); }

}  // namespace hedge::binding

// The name tables of the binding core (src/binding/names.cpp).
#include "binding/names.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "binding/errors.h"
#include "hedge/core/threads.h"
#include "hedge/error.h"

namespace hedge::binding {
namespace {

TEST(BindingNames, OneSpellingEachAndItsAliases) {
  EXPECT_EQ(parse_smooth_method("cotangent"), SmoothMethod::cotangent);
  EXPECT_EQ(parse_smooth_method("cotan"), SmoothMethod::cotangent);
  EXPECT_STREQ(name(SmoothMethod::cotangent), "cotangent");
  EXPECT_EQ(parse_subdivision("catmull-clark"), Subdivision::catmull_clark);
  EXPECT_EQ(parse_subdivision("split_faces"), Subdivision::split_faces);
  EXPECT_STREQ(name(Subdivision::split_faces), "split-faces");
  EXPECT_EQ(parse_normal_source("auto"), NormalSource::automatic);
  EXPECT_STREQ(name(NormalSource::automatic), "auto");
  EXPECT_EQ(parse_normal_weighting("angle"), NormalWeighting::angle);
  EXPECT_STREQ(name(NormalWeighting::uniform), "uniform");
  EXPECT_EQ(parse_ordering("vertex-cache"), Ordering::vertex_cache);
  EXPECT_EQ(parse_ordering("vertex_cache"), Ordering::vertex_cache);
  EXPECT_STREQ(name(Ordering::vertex_cache), "vertex-cache");
  EXPECT_THROW(parse_normal_weighting("cotangent"), InvalidInputError);
  for (const std::string& s : smooth_method_spellings()) EXPECT_NO_THROW(parse_smooth_method(s)) << s;
  for (const std::string& s : subdivision_spellings()) EXPECT_NO_THROW(parse_subdivision(s)) << s;
  const auto methods = smooth_method_spellings();
  EXPECT_NE(std::find(methods.begin(), methods.end(), "cotan"), methods.end());
  try {
    parse_smooth_method("gaussian");
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInputError& e) {
    EXPECT_STREQ(e.what(), "unknown smoothing method 'gaussian' (uniform, taubin, cotangent, implicit)");
  }
}

TEST(BindingNames, TheCAbisConstants) {
  EXPECT_EQ(to_weld(HEDGE_WELD_EPSILON), Weld::epsilon);
  EXPECT_EQ(to_policy(HEDGE_POLICY_STRICT), TopologyPolicy::strict);
  EXPECT_EQ(to_winding(HEDGE_WINDING_CW), Winding::cw);
  try {
    to_weld(7);
    ADD_FAILURE() << "accepted";
  } catch (const BindingError& e) {
    EXPECT_EQ(e.status, HEDGE_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(e.message, "weld is 7, not a HEDGE_WELD_* value");
  }
}

// Every DecimateStop has a name (a new enumerator without one does not build: -Werror=switch), the
// names are distinct, and the C ABI's constants are the enumerators' positions.
TEST(BindingNames, DecimateStopsAllHaveNamesAndConstants) {
  const DecimateStop all[] = {DecimateStop::target_reached, DecimateStop::error_bound,
                              DecimateStop::no_legal_collapse};
  EXPECT_STREQ(name(DecimateStop::target_reached), "target_reached");
  EXPECT_STREQ(name(DecimateStop::error_bound), "error_bound");
  EXPECT_STREQ(name(DecimateStop::no_legal_collapse), "no_legal_collapse");
  for (const DecimateStop a : all) {
    EXPECT_STRNE(name(a), "unknown");
    for (const DecimateStop b : all)
      if (a != b) EXPECT_STRNE(name(a), name(b));
  }
  EXPECT_EQ(constant(DecimateStop::target_reached), HEDGE_DECIMATE_TARGET_REACHED);
  EXPECT_EQ(constant(DecimateStop::error_bound), HEDGE_DECIMATE_ERROR_BOUND);
  EXPECT_EQ(constant(DecimateStop::no_legal_collapse), HEDGE_DECIMATE_NO_LEGAL_COLLAPSE);
}

// Every SolidRefusal has a name and its C ABI constant, as DecimateStop's.
TEST(BindingNames, SolidRefusalsAllHaveNamesAndConstants) {
  const SolidRefusal all[] = {SolidRefusal::none,       SolidRefusal::open,       SolidRefusal::non_manifold,
                              SolidRefusal::bad_option, SolidRefusal::bad_impact, SolidRefusal::off_surface,
                              SolidRefusal::no_face,    SolidRefusal::bad_radius, SolidRefusal::foreign_tree};
  EXPECT_STREQ(name(SolidRefusal::open), "open");
  EXPECT_STREQ(name(SolidRefusal::non_manifold), "non_manifold");
  EXPECT_STREQ(name(SolidRefusal::off_surface), "off_surface");
  for (const SolidRefusal a : all) {
    EXPECT_STRNE(name(a), "unknown");
    for (const SolidRefusal b : all)
      if (a != b) EXPECT_STRNE(name(a), name(b));
  }
  EXPECT_EQ(constant(SolidRefusal::none), HEDGE_SOLID_REFUSAL_NONE);
  EXPECT_EQ(constant(SolidRefusal::open), HEDGE_SOLID_REFUSAL_OPEN);
  EXPECT_EQ(constant(SolidRefusal::non_manifold), HEDGE_SOLID_REFUSAL_NON_MANIFOLD);
  EXPECT_EQ(constant(SolidRefusal::foreign_tree) + 1, HEDGE_SOLID_REFUSAL_COUNT);
}

TEST(BindingNames, ThreadCounts) {
  EXPECT_EQ(thread_count(0, "threads"), max_threads());  // 0: every core
  EXPECT_EQ(thread_count(3, "threads"), 3u);
  EXPECT_EQ(thread_count(kMaxThreadsAsked, "threads"), 1024u);
  for (const std::int64_t bad : {std::int64_t(-1), kMaxThreadsAsked + 1, std::int64_t(1) << 40}) {
    try {
      thread_count(bad, "render: threads");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const BindingError& e) {
      EXPECT_EQ(e.status, HEDGE_ERROR_INVALID_ARGUMENT);
      EXPECT_EQ(e.message, "render: threads must be 0 (every core) to 1024, got " + std::to_string(bad));
    }
  }
}

}  // namespace
}  // namespace hedge::binding

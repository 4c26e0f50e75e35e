// robustness_if_continued: the robustness of a formula were the trace to go on in whatever way
// serves it best. An F the end cut off is no longer violated; what the observed samples decide
// (a G already broken, an F whose whole window was seen) stays violated; negation turns the
// padding against the negated formula.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/spec_horizon.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// x = 0, 1, 2, 3 at t = 0, 1, 2, 3 s.
struct Ramp {
  std::vector<double> time = {0, 1, 2, 3};
  std::vector<double> x = {0, 1, 2, 3};

  SignalSource source() const {
    return SignalSource{time, [this](const SpecTerm&) { return SignalValues{x, false}; }, {}};
  }
};

struct Both {
  double strict = 0;
  double continued = 0;
};

Both judge(const std::string& text) {
  const SourceFile file("--spec", text);
  avunit::FormulaParseResult parsed = avunit::parse_formula(file);
  if (!parsed.formula) {
    ADD_FAILURE() << format_diagnostics(file, parsed.diagnostics);
    return {};
  }
  const Ramp ramp;
  return {
      robustness_signal(*parsed.formula, ramp.source()).front(),
      robustness_if_continued(*parsed.formula, ramp.source(), formula_horizon(*parsed.formula))};
}

TEST(RobustnessIfContinuedTest, AnEventuallyTheEndCutOffIsNoLongerViolated) {
  const Both unbounded = judge("F (x > 5)");
  EXPECT_DOUBLE_EQ(unbounded.strict, -2);
  EXPECT_EQ(unbounded.continued, kInf);
  // F[0:6] at t = 0 reads to 6 s, past the trace's 3 s.
  const Both bounded = judge("F[0:6] (x > 5)");
  EXPECT_DOUBLE_EQ(bounded.strict, -2);
  EXPECT_EQ(bounded.continued, kInf);
}

TEST(RobustnessIfContinuedTest, WhatTheObservedSamplesDecideStays) {
  // The whole window [0, 2] was seen.
  const Both seen = judge("F[0:2] (x > 5)");
  EXPECT_DOUBLE_EQ(seen.strict, -3);
  EXPECT_DOUBLE_EQ(seen.continued, -3);
  // G already broken at t = 3.
  const Both broken = judge("G (x < 2.5)");
  EXPECT_DOUBLE_EQ(broken.strict, -0.5);
  EXPECT_DOUBLE_EQ(broken.continued, -0.5);
  // The G's first windows are whole and violated, whatever the later ones would be.
  const Both nested = judge("G[0:10] F[0:2] (x > 5)");
  EXPECT_DOUBLE_EQ(nested.strict, -3);
  EXPECT_DOUBLE_EQ(nested.continued, -3);
  // A conjunction keeps its decided conjunct.
  const Both conjunction = judge("G (x < 2.5) & F (x > 5)");
  EXPECT_DOUBLE_EQ(conjunction.continued, -0.5);
}

TEST(RobustnessIfContinuedTest, NegationTurnsTheUnseenFutureAgainstWhatItNegates) {
  // ~G (x < 5) is F (x >= 5): not yet, but it may come.
  const Both negated = judge("~G (x < 5)");
  EXPECT_DOUBLE_EQ(negated.strict, -2);
  EXPECT_EQ(negated.continued, kInf);
  // An implication's premise is negated too: (x > 1) -> F (x > 5) at t = 0 holds anyway, and
  // G (x > -1) -> F (x > 5) is open until the end.
  const Both implication = judge("G (x > -1) -> F (x > 5)");
  EXPECT_DOUBLE_EQ(implication.strict, -1);
  EXPECT_EQ(implication.continued, kInf);
}

}  // namespace
}  // namespace scenfuzz

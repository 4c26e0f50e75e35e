// robustness_if_started_later: the robustness of a formula with its first seconds excused, the
// start state a scenario gave the trace rather than what the trace did with it. A G no longer
// counts those samples against the formula; an F still counts what they did for it but is never
// satisfied by them; negation turns the excuse as it turns robustness_if_continued's padding.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/spec_horizon.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kGrace = 2.0;

// `speed` every 0.1 s for 6 s: `fast` until `until` seconds, then `slow`.
struct Speeds {
  std::vector<double> time;
  std::vector<double> speed;

  Speeds(double fast, double until, double slow) {
    for (int i = 0; i <= 60; ++i) {
      time.push_back(0.1 * i);
      speed.push_back(time.back() < until - 1e-9 ? fast : slow);
    }
  }

  SignalSource source() const {
    return SignalSource{time, [this](const SpecTerm&) { return SignalValues{speed, false}; }, {}};
  }
};

struct Both {
  double strict = 0;
  double excused = 0;
};

Both judge(const std::string& text, const Speeds& speeds, double grace = kGrace) {
  const SourceFile file("--spec", text);
  avunit::FormulaParseResult parsed = avunit::parse_formula(file);
  if (!parsed.formula) {
    ADD_FAILURE() << format_diagnostics(file, parsed.diagnostics);
    return {};
  }
  return {robustness_signal(*parsed.formula, speeds.source()).front(),
          robustness_if_started_later(*parsed.formula, speeds.source(), grace)};
}

TEST(RobustnessIfStartedLaterTest, AGBrokenOnlyWithinTheGraceHolds) {
  const Both once_fast = judge("G (speed <= 30)", Speeds(36, 1, 28));
  EXPECT_DOUBLE_EQ(once_fast.strict, -6);
  EXPECT_DOUBLE_EQ(once_fast.excused, 2);
  // Broken up to the last sample of the grace (1.9 s) and from 2 s on not: still excused.
  EXPECT_DOUBLE_EQ(judge("G (speed <= 30)", Speeds(36, 2, 28)).excused, 2);
  // Within the grace even a G that never holds there is +inf: nothing observed counts.
  EXPECT_EQ(judge("G[0:1] (speed <= 30)", Speeds(36, 1, 28)).excused, kInf);
}

TEST(RobustnessIfStartedLaterTest, AViolationThatOutlastsTheGraceStays) {
  const Both long_fast = judge("G (speed <= 30)", Speeds(36, 5, 28));
  EXPECT_DOUBLE_EQ(long_fast.strict, -6);
  EXPECT_DOUBLE_EQ(long_fast.excused, -6);
  // A sample at 2.0 s is observed: the grace is [0, 2).
  EXPECT_DOUBLE_EQ(judge("G (speed <= 30)", Speeds(36, 2.05, 28)).excused, -6);
}

TEST(RobustnessIfStartedLaterTest, NegationTurnsTheExcuseAgainstWhatItNegates) {
  // `~(speed > 30)`: the atom is -inf within the grace, its negation +inf.
  const Both negated = judge("G (~(speed > 30))", Speeds(36, 1, 28));
  EXPECT_DOUBLE_EQ(negated.strict, -6);
  EXPECT_DOUBLE_EQ(negated.excused, 2);
  // `~F` asks for every sample as a G does: excused the same way.
  EXPECT_DOUBLE_EQ(judge("~F (speed > 30)", Speeds(36, 1, 28)).excused, 2);
  // `~G` asks for some sample as an F does: the grace's samples still satisfy it...
  EXPECT_DOUBLE_EQ(judge("~G (speed <= 30)", Speeds(36, 1, 28)).excused, 6);
  // ... but an excused sample cannot: never above 30 after the start, it is violated.
  const Both never_fast_later = judge("~G (speed <= 30)", Speeds(28, 0, 28));
  EXPECT_DOUBLE_EQ(never_fast_later.excused, never_fast_later.strict);
}

TEST(RobustnessIfStartedLaterTest, AnFIsJudgedOnTheGracesSamplesAsTheyAre) {
  // Wholly within the grace and unmet (36 km/h cannot become 10 in a second): still violated,
  // the excused samples do not satisfy it.
  const Both unmet = judge("F[0:1] (speed < 10)", Speeds(36, 1, 28));
  EXPECT_DOUBLE_EQ(unmet.strict, -18);
  EXPECT_DOUBLE_EQ(unmet.excused, -18);
  // Met within the grace: what the samples did for it is real.
  const Both met = judge("F[0:1] (speed < 10)", Speeds(5, 1, 28));
  EXPECT_DOUBLE_EQ(met.strict, 5);
  EXPECT_DOUBLE_EQ(met.excused, 5);
  // An F that is never met stays violated beside a G the grace excuses: excusing the start
  // excuses no F, which a plain +inf within the grace would have satisfied.
  const Both both = judge("G (speed <= 30) & F (speed < 10)", Speeds(36, 1, 28));
  EXPECT_DOUBLE_EQ(both.strict, -18);
  EXPECT_DOUBLE_EQ(both.excused, -18);
  // An obligation under a G that an atom within the grace triggers is excused with it (from 2 s
  // on the trigger is 2 below its threshold).
  const Both triggered = judge("G ((speed > 30) -> F[0:0.5] (speed < 10))", Speeds(36, 1, 28));
  EXPECT_DOUBLE_EQ(triggered.strict, -6);
  EXPECT_DOUBLE_EQ(triggered.excused, 2);
}

TEST(RobustnessIfStartedLaterTest, NoGraceIsTheStrictRobustness) {
  const Both none = judge("G (speed <= 30)", Speeds(36, 1, 28), 0);
  EXPECT_DOUBLE_EQ(none.excused, none.strict);
}

TEST(RobustnessIfStartedLaterTest, BothEndsExcusedTogether) {
  const SourceFile file("--spec", "G (speed <= 30) & F[0:10] (speed < 10)");
  avunit::FormulaParseResult parsed = avunit::parse_formula(file);
  ASSERT_TRUE(parsed.formula);
  const Speeds speeds(36, 1, 28);
  const double horizon = formula_horizon(*parsed.formula);
  // The start alone leaves the F the end cut off; the end alone the G the start broke.
  EXPECT_LT(robustness_if_started_later(*parsed.formula, speeds.source(), kGrace), 0);
  EXPECT_LT(robustness_if_continued(*parsed.formula, speeds.source(), horizon), 0);
  EXPECT_DOUBLE_EQ(robustness_excusing(*parsed.formula, speeds.source(), {kGrace, horizon}), 2);
}

}  // namespace
}  // namespace scenfuzz

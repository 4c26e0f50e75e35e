// Robustness worked out by hand for every operator and its edges (empty windows, windows past the
// trace end or into the past, uneven sampling, X at the last sample, until's p-before-q rule), the
// witness explain_robustness names, and the errors the engine raises. Each case also holds the
// reference evaluator to the same numbers, so the agreement test compares against something
// checked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/spec.hpp"
#include "oracle/robustness.hpp"
#include "tests/oracle/naive_robustness.hpp"

namespace scenfuzz {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Named signals for one test: values per sample, and the names that are discrete (flags,
// enumerations).
struct Signals {
  std::vector<double> time;
  std::map<std::string, std::vector<double>> values;
  std::set<std::string> discrete;

  SignalSource source() const {
    return SignalSource{time,
                        [this](const SpecTerm& term) {
                          auto found = values.find(term.name);
                          if (found == values.end())
                            throw OracleError(term.location, "no signal " + term.name);
                          return SignalValues{found->second, discrete.count(term.name) > 0};
                        },
                        {}};
  }
};

std::vector<double> seconds(std::size_t samples) {
  std::vector<double> time;
  for (std::size_t i = 0; i < samples; ++i) time.push_back(static_cast<double>(i));
  return time;
}

// The formula `text` means; a test failure (and an empty formula) when it does not parse.
std::optional<Formula> parse(const std::string& text) {
  const SourceFile file("--spec", text);
  avunit::FormulaParseResult result = avunit::parse_formula(file);
  if (!result.formula) ADD_FAILURE() << format_diagnostics(file, result.diagnostics);
  return result.formula;
}

bool agree(double a, double b) {
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-9;
}

std::string values_text(const std::vector<double>& values) {
  std::string text;
  for (double value : values) text += " " + std::to_string(value);
  return text;
}

void expect_values(const std::string& what, const std::vector<double>& got,
                   const std::vector<double>& expected) {
  bool same = got.size() == expected.size();
  for (std::size_t i = 0; same && i < got.size(); ++i) same = agree(got[i], expected[i]);
  EXPECT_TRUE(same) << what << "\nexpected:" << values_text(expected)
                    << "\ngot:     " << values_text(got);
}

// The engine and the reference both give `expected` for `text` at every sample.
void expect_robustness(const std::string& text, const Signals& signals,
                       const std::vector<double>& expected) {
  const std::optional<Formula> formula = parse(text);
  if (!formula) return;
  const SignalSource source = signals.source();
  expect_values("engine, " + text, robustness_signal(*formula, source), expected);
  expect_values("reference, " + text, test::naive_robustness(*formula, source), expected);
}

Signals one_signal(std::vector<double> x) {
  Signals signals{seconds(x.size()), {{"x", std::move(x)}}, {}};
  return signals;
}

TEST(RobustnessCases, ComparisonsAreSignedDistances) {
  const Signals signals = one_signal({1, 3, -2});
  expect_robustness("x < 2", signals, {1, -1, 4});
  expect_robustness("x <= 2", signals, {1, -1, 4});
  expect_robustness("x > 2", signals, {-1, 1, -4});
  expect_robustness("x >= 2", signals, {-1, 1, -4});
  expect_robustness("x == 2", signals, {-1, -1, -4});
  expect_robustness("x != 2", signals, {1, 1, 4});
  expect_robustness("x == 3", signals, {-2, 0, -5});
}

TEST(RobustnessCases, ComparisonsOfArithmetic) {
  Signals signals{seconds(3), {{"x", {1, 3, -2}}, {"y", {0.5, 1, 2}}}, {}};
  expect_robustness("x + 1 > y * 2", signals, {1, 2, -5});
  expect_robustness("-x < 3 / 2 - 1", signals, {1.5, 3.5, -1.5});
  expect_robustness("x - y >= 0", signals, {0.5, 2, -4});
}

TEST(RobustnessCases, DiscreteComparisonsAreTrueOrFalse) {
  Signals signals{seconds(3), {{"c", {3, 1, 3}}, {"x", {3, 1, 3}}}, {"c"}};
  expect_robustness("green == green", signals, {1, 1, 1});
  expect_robustness("red == green", signals, {-1, -1, -1});
  expect_robustness("red != green", signals, {1, 1, 1});
  expect_robustness("c == green", signals, {1, -1, 1});
  expect_robustness("c != green", signals, {-1, 1, -1});
  expect_robustness("c < green", signals, {-1, 1, -1});
  expect_robustness("c >= red", signals, {1, 1, 1});
  expect_robustness("~(c == green)", signals, {-1, 1, -1});
  // One side numeric: a signed distance, even against a word or a discrete signal.
  expect_robustness("x == green", signals, {0, -2, 0});
  expect_robustness("c == 1", signals, {-2, 0, -2});
  expect_robustness("x > left", signals, {2, 0, 2});
}

TEST(RobustnessCases, FlagAndDistancePredicates) {
  Signals signals{
      seconds(4),
      {{"hornOn", {0, 1, 2, 0}}, {"f", {-1, 0, 0.5, 0}}, {"stoplineAhead", {5, 2, 0.5, 0}}},
      {"hornOn"}};
  expect_robustness("hornOn", signals, {-1, 1, 1, -1});
  expect_robustness("f", signals, {1, -1, 1, -1});
  expect_robustness("~hornOn", signals, {1, -1, -1, 1});
  expect_robustness("stoplineAhead(2)", signals, {-3, 0, 1.5, 2});
  expect_robustness("~stoplineAhead(2)", signals, {3, 0, -1.5, -2});
}

TEST(RobustnessCases, BooleanOperators) {
  Signals signals{seconds(3), {{"x", {1, -2, 3}}, {"y", {2, -1, -4}}}, {}};
  expect_robustness("~(x > 0)", signals, {-1, 2, -3});
  expect_robustness("x > 0 & y > 0", signals, {1, -2, -4});
  expect_robustness("x > 0 | y > 0", signals, {2, -1, 3});
  expect_robustness("x > 0 -> y > 0", signals, {2, 2, -3});
  expect_robustness("~~(x > 0)", signals, {1, -2, 3});
}

TEST(RobustnessCases, BooleanOperatorsWithInfinities) {
  // F over a window past the end of a 3 s trace is -inf everywhere, G +inf.
  Signals signals{seconds(3), {{"x", {1, -2, 3}}, {"y", {2, -1, -4}}}, {}};
  expect_robustness("F[10:20](x > 0)", signals, {-kInf, -kInf, -kInf});
  expect_robustness("G[10:20](x > 0)", signals, {kInf, kInf, kInf});
  expect_robustness("~F[10:20](x > 0)", signals, {kInf, kInf, kInf});
  expect_robustness("~G[10:20](x > 0)", signals, {-kInf, -kInf, -kInf});
  expect_robustness("G[10:20](x > 0) & y > 0", signals, {2, -1, -4});
  expect_robustness("F[10:20](x > 0) & y > 0", signals, {-kInf, -kInf, -kInf});
  expect_robustness("F[10:20](x > 0) | y > 0", signals, {2, -1, -4});
  expect_robustness("G[10:20](x > 0) | y > 0", signals, {kInf, kInf, kInf});
  expect_robustness("F[10:20](x > 0) -> y > 0", signals, {kInf, kInf, kInf});
  expect_robustness("G[10:20](x > 0) -> y > 0", signals, {2, -1, -4});
  expect_robustness("y > 0 -> F[10:20](x > 0)", signals, {-2, 1, 4});
  expect_robustness("G[10:20](x > 0) & F[10:20](y > 0)", signals, {-kInf, -kInf, -kInf});
}

TEST(RobustnessCases, UnboundedAlwaysAndEventually) {
  const Signals signals = one_signal({3, 1, 2, 5});
  expect_robustness("G(x > 0)", signals, {1, 1, 2, 5});
  expect_robustness("F(x > 0)", signals, {5, 5, 5, 5});
  expect_robustness("F(x < 2)", signals, {1, 1, 0, -3});
  expect_robustness("G(F(x > 2))", signals, {3, 3, 3, 3});
}

TEST(RobustnessCases, BoundedAlwaysAndEventually) {
  const Signals signals = one_signal({3, 1, 2, 5});
  expect_robustness("G[0:1](x > 0)", signals, {1, 1, 2, 5});
  expect_robustness("F[0:1](x > 0)", signals, {3, 2, 5, 5});
  // Windows that start later run off the end: G gives +inf, F -inf there.
  expect_robustness("G[1:2](x > 0)", signals, {1, 2, 5, kInf});
  expect_robustness("F[1:2](x > 0)", signals, {2, 5, 5, -kInf});
  expect_robustness("F[3:3](x > 0)", signals, {5, -kInf, -kInf, -kInf});
  // Reaching past the end: clipped, the same as unbounded.
  expect_robustness("G[0:10](x > 0)", signals, {1, 1, 2, 5});
  expect_robustness("F[0:1000000](x > 0)", signals, {5, 5, 5, 5});
  // Zero width: the sample itself.
  expect_robustness("G[0:0](x > 0)", signals, {3, 1, 2, 5});
  // Between samples: empty everywhere.
  expect_robustness("G[0.25:0.75](x > 0)", signals, {kInf, kInf, kInf, kInf});
}

// `X[a, b] p` (scenest, real LawBreaker files) is read as `F[a, b] p`: p between a and b seconds
// ahead. Not the literal next sample, which on a 1 s trace would never lie in [1, 1.5] only by
// luck of the sampling.
TEST(RobustnessCases, NextWithAnIntervalIsTheShiftedEventually) {
  const Signals signals = one_signal({3, 1, 2, 5});
  expect_robustness("X[1, 1.5](x > 0)", signals, {1, 2, 5, -kInf});
  expect_robustness("X[1:2](x > 0)", signals, {2, 5, 5, -kInf});
  expect_robustness("X[0.25, 0.75](x > 0)", signals, {-kInf, -kInf, -kInf, -kInf});
  expect_robustness("~X[1, 1.5](x > 2)", signals, {1, 0, -3, kInf});
  // On uneven sampling, too: the window, not the next sample.
  Signals uneven{{0, 0.5, 2, 2.2, 5}, {{"x", {4, 2, 3, 1, 6}}}, {}};
  expect_robustness("X[1:2](x > 0)", uneven, {3, 3, -kInf, -kInf, -kInf});
}

TEST(RobustnessCases, NegativeLowerBoundsLookIntoThePast) {
  const Signals signals = one_signal({3, 1, 2, 5});
  expect_robustness("F[-1:0](x > 0)", signals, {3, 3, 2, 5});
  expect_robustness("G[-2:-1](x > 0)", signals, {kInf, 3, 1, 1});
  expect_robustness("G[-10:5](x > 0)", signals, {1, 1, 1, 1});
  expect_robustness("F[-1,1](x < 2)", signals, {1, 1, 1, -0});
}

TEST(RobustnessCases, UnevenSampling) {
  Signals signals{{0, 0.5, 2, 2.2, 5}, {{"x", {4, 2, 3, 1, 6}}}, {}};
  expect_robustness("G[0:1.5](x > 0)", signals, {2, 2, 1, 1, 6});
  expect_robustness("F[1:2](x > 0)", signals, {3, 3, -kInf, -kInf, -kInf});
  expect_robustness("F[-0.5:0](x > 0)", signals, {4, 4, 3, 3, 6});
  expect_robustness("X(x > 0)", signals, {2, 3, 1, 6, kInf});
}

TEST(RobustnessCases, WindowEdgesTolerateRounding) {
  // 3 * 0.1 is 0.30000000000000004: the window [0, 0.3] of sample 0 still holds sample 3.
  Signals signals{{0, 0.1, 0.2, 3 * 0.1}, {{"x", {5, 4, 3, 1}}}, {}};
  expect_robustness("G[0:0.3](x > 0)", signals, {1, 1, 1, 1});
  expect_robustness("F[0.3:0.3](x > 0)", signals, {1, -kInf, -kInf, -kInf});
  expect_robustness("F[0.1:0.1](x > 0)", signals, {4, 3, 1, -kInf});
}

TEST(RobustnessCases, NextIsTheFollowingSample) {
  const Signals signals = one_signal({3, 1, 2});
  expect_robustness("X(x > 0)", signals, {1, 2, kInf});
  expect_robustness("X(X(x > 0))", signals, {2, kInf, kInf});
  expect_robustness("~X(x > 0)", signals, {-1, -2, -kInf});
  expect_robustness("x > 0 & X(x > 0)", signals, {1, 1, 2});
  expect_robustness("X(x > 0)", one_signal({7}), {kInf});
}

TEST(RobustnessCases, UnboundedUntil) {
  Signals signals{seconds(4), {{"x", {1, 2, -1, 3}}, {"y", {-1, -2, 4, -3}}}, {}};
  // At sample 2, q holds there itself although p does not: p need not hold at j.
  expect_robustness("x > 0 U y > 0", signals, {1, 2, 4, -3});
  // p failing at sample 1, before q holds at 2, caps what q can give.
  Signals failing{seconds(4), {{"x", {1, -5, 1, 1}}, {"y", {-9, -9, 3, -9}}}, {}};
  expect_robustness("x > 0 U y > 0", failing, {-5, -5, 3, -9});
}

TEST(RobustnessCases, BoundedUntil) {
  Signals signals{seconds(4), {{"x", {1, 2, -1, 3}}, {"y", {-1, -2, 4, -3}}}, {}};
  expect_robustness("x > 0 U[1:2] y > 0", signals, {1, 2, -3, -kInf});
  expect_robustness("x > 0 U[0:0] y > 0", signals, {-1, -2, 4, -3});
  expect_robustness("x > 0 U[0:100] y > 0", signals, {1, 2, 4, -3});
  // j before i: only q counts there.
  expect_robustness("x > 0 U[-1:-1] y > 0", signals, {-kInf, -1, -2, 4});
}

TEST(RobustnessCases, NestedUntil) {
  Signals signals{
      seconds(4), {{"a", {1, 2, -1, 3}}, {"b", {-1, -2, 4, -3}}, {"c", {-4, 5, -6, 7}}}, {}};
  expect_robustness("(a > 0 U b > 0) U[0:1] c > 0", signals, {1, 5, 4, 7});
}

TEST(RobustnessCases, NestedBoundedOperators) {
  Signals signals{seconds(10),
                  {{"x", {1, 1, 1, 1, 1, 1, 0, 1, 1, 1}}, {"y", {1, 0, 1, 1, 0, 1, 1, 0, 1, 1}}},
                  {}};
  expect_robustness("G[0:5](x > 0.5 & F[0:2](y < 0.1))", signals,
                    {0.1, -0.5, -0.5, -0.9, -0.9, -0.9, -0.9, -0.9, -0.9, -0.9});
}

TEST(RobustnessCases, EmptyTraceHasNoSamples) {
  expect_robustness("G(x > 0)", Signals{{}, {{"x", {}}}, {}}, {});
}

TEST(RobustnessExplain, WitnessIsTheAtomAndSampleOfTheMinimum) {
  const std::string text = "G(x > 0) & G(y > 0)";
  const std::optional<Formula> parsed = parse(text);
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  Signals signals{seconds(5), {{"x", {1, 2, 3, 4, 5}}, {"y", {3, 2, 1, -2, 4}}}, {}};
  const RobustnessWitness witness = explain_robustness(formula, signals.source());
  EXPECT_EQ(witness.robustness, -2);
  ASSERT_NE(witness.atom, nullptr);
  EXPECT_EQ(witness.atom, &formula.operands.at(1).operands.at(0));
  EXPECT_EQ(witness.atom->location.offset, text.find("y > 0"));
  EXPECT_EQ(witness.sample, 3u);
}

TEST(RobustnessExplain, WitnessAtALaterSampleAndThroughNegation) {
  const std::string text = "~F[0:2](x > 0)";
  const std::optional<Formula> parsed = parse(text);
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  const Signals signals = one_signal({9, 1, 3, 2, 8});
  const RobustnessWitness witness = explain_robustness(formula, signals.source(), 1);
  EXPECT_EQ(witness.robustness, -3);
  ASSERT_NE(witness.atom, nullptr);
  EXPECT_EQ(witness.atom->location.offset, text.find("x > 0"));
  EXPECT_EQ(witness.sample, 2u);
}

TEST(RobustnessExplain, WitnessOfUntilIsTheFailingHoldOrTheReachedGoal) {
  const std::string text = "x > 0 U y > 0";
  const std::optional<Formula> parsed = parse(text);
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  Signals failing{seconds(4), {{"x", {1, -5, 1, 1}}, {"y", {-9, -9, 3, -9}}}, {}};
  RobustnessWitness witness = explain_robustness(formula, failing.source());
  EXPECT_EQ(witness.robustness, -5);
  ASSERT_NE(witness.atom, nullptr);
  EXPECT_EQ(witness.atom, &formula.operands.at(0));
  EXPECT_EQ(witness.sample, 1u);
  witness = explain_robustness(formula, failing.source(), 2);
  EXPECT_EQ(witness.robustness, 3);
  EXPECT_EQ(witness.atom, &formula.operands.at(1));
  EXPECT_EQ(witness.sample, 2u);
}

TEST(RobustnessExplain, EmptyWindowHasNoAtom) {
  const std::optional<Formula> parsed = parse("F[10:20](x > 0)");
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  Signals signals{{0, 0.5, 1}, {{"x", {1, 2, 3}}}, {}};
  const RobustnessWitness witness = explain_robustness(formula, signals.source());
  EXPECT_EQ(witness.robustness, -kInf);
  EXPECT_EQ(witness.atom, nullptr);
}

TEST(RobustnessExplain, NextAtTheLastSampleHasNoAtom) {
  const std::optional<Formula> parsed = parse("X(x > 0)");
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  const Signals signals = one_signal({1, 2, 3});
  const RobustnessWitness witness = explain_robustness(formula, signals.source(), 2);
  EXPECT_EQ(witness.robustness, kInf);
  EXPECT_EQ(witness.atom, nullptr);
}

TEST(RobustnessErrors, UnknownSignalIsAnOracleError) {
  const std::string text = "G(x > 0 & w < 1)";
  const std::optional<Formula> parsed = parse(text);
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  const Signals signals = one_signal({1, 2, 3});
  try {
    robustness_signal(formula, signals.source());
    ADD_FAILURE() << "no error for the unknown signal w";
  } catch (const OracleError& error) {
    EXPECT_EQ(error.location().offset, text.find('w'));
  }
  EXPECT_THROW(explain_robustness(formula, signals.source()), OracleError);
}

TEST(RobustnessErrors, NotANumberFromALeafIsAnOracleError) {
  const std::optional<Formula> parsed = parse("F(x > 0)");
  ASSERT_TRUE(parsed);
  const Formula& formula = *parsed;
  const Signals signals = one_signal({1, std::nan(""), 3});
  EXPECT_THROW(robustness_signal(formula, signals.source()), OracleError);
  EXPECT_THROW(explain_robustness(formula, signals.source()), OracleError);
}

}  // namespace
}  // namespace scenfuzz

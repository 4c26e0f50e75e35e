// NloptStrategy driven by hand through propose/observe on synthetic objectives (no simulation):
// every accepted algorithm minimises a shifted sphere, repeats itself for a seed, survives +inf
// results and destruction mid-run, and local methods restart after converging.
#include "fuzz/nlopt_strategy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace scenfuzz {
namespace {

using Objective = std::function<double(const UnitPoint&)>;

std::vector<SearchDimension> cube(std::size_t count) {
  std::vector<SearchDimension> dimensions(count);
  for (std::size_t i = 0; i < count; ++i) dimensions[i].name = "x" + std::to_string(i);
  return dimensions;
}

double shifted_sphere(const UnitPoint& x) {
  const double centre[] = {0.3, 0.7, 0.5};
  double sum = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sum += (x[i] - centre[i % 3]) * (x[i] - centre[i % 3]);
  return sum;
}

bool inside_unit_cube(const UnitPoint& x) {
  return std::all_of(x.begin(), x.end(), [](double c) { return c >= 0.0 && c <= 1.0; });
}

// One propose/observe round: the point proposed and the objective fed back.
UnitPoint step(SearchStrategy& strategy, const Objective& objective) {
  const std::vector<UnitPoint> batch = strategy.propose(4);
  if (batch.size() != 1) {
    ADD_FAILURE() << "expected a batch of one point, got " << batch.size();
    return {};
  }
  const double value = objective(batch.front());
  const Observation observation{batch.front(), value, std::isfinite(value)};
  strategy.observe(std::span(&observation, 1));
  return batch.front();
}

std::vector<UnitPoint> drive(SearchStrategy& strategy, const Objective& objective,
                             std::size_t evaluations) {
  std::vector<UnitPoint> points;
  for (std::size_t i = 0; i < evaluations; ++i) points.push_back(step(strategy, objective));
  return points;
}

bool is_local(const std::string& name) {
  return name.starts_with("LN_") || name.find("AUGLAG") != std::string::npos ||
         name.find("MLSL") != std::string::npos;
}

class EveryAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryAlgorithm, MinimisesShiftedSphere) {
  const std::string name = GetParam();
  const auto dimensions = cube(3);
  NloptStrategy strategy(name, dimensions, 7, 400);
  const std::size_t budget = 400;
  const double tolerance = 1e-6;
  double first = 0;
  double best = std::numeric_limits<double>::infinity();
  std::size_t reached_at = 0;
  for (std::size_t i = 0; i < budget; ++i) {
    const UnitPoint point = step(strategy, shifted_sphere);
    ASSERT_EQ(point.size(), 3u);
    ASSERT_TRUE(inside_unit_cube(point));
    const double value = shifted_sphere(point);
    if (i == 0) first = value;
    best = std::min(best, value);
    if (reached_at == 0 && best < tolerance) reached_at = i + 1;
  }
  EXPECT_DOUBLE_EQ(strategy.best_objective(), best);
  EXPECT_DOUBLE_EQ(shifted_sphere(strategy.best_point()), best);
  const std::string reached =
      reached_at > 0 ? "after " + std::to_string(reached_at) + " evaluations" : "never";
  std::printf("[ sphere   ] %-24s first %.3g best %.3g, below %.0e %s, %zu runs\n", name.c_str(),
              first, best, tolerance, reached.c_str(), strategy.runs());
  if (is_local(name)) {
    EXPECT_LT(best, tolerance) << name;
  } else {
    EXPECT_LT(best, 0.2 * first) << name;
    EXPECT_LT(best, 1e-2) << name;
  }
}

TEST_P(EveryAlgorithm, SameSeedSamePoints) {
  const std::string name = GetParam();
  const auto dimensions = cube(3);
  NloptStrategy first(name, dimensions, 11, 150);
  const std::vector<UnitPoint> alone = drive(first, shifted_sphere, 150);
  // Interleaved with a strategy of another seed on another thread: NLopt's generator is
  // per thread, so neither disturbs the other.
  NloptStrategy again(name, dimensions, 11, 150);
  NloptStrategy other(name, dimensions, 12, 150);
  std::vector<UnitPoint> interleaved;
  for (std::size_t i = 0; i < 150; ++i) {
    interleaved.push_back(step(again, shifted_sphere));
    step(other, shifted_sphere);
  }
  EXPECT_EQ(alone, interleaved) << name;
}

TEST_P(EveryAlgorithm, InfiniteAndNanResultsDoNotBreakIt) {
  const std::string name = GetParam();
  const auto dimensions = cube(3);
  NloptStrategy strategy(name, dimensions, 3, 200);
  std::size_t calls = 0;
  const Objective objective = [&](const UnitPoint& x) {
    ++calls;
    if (calls <= 10) return std::numeric_limits<double>::infinity();  // a start among infeasibles
    if (calls % 7 == 0) return std::numeric_limits<double>::quiet_NaN();
    if (x[0] > 0.6) return std::numeric_limits<double>::infinity();
    return shifted_sphere(x);
  };
  const std::vector<UnitPoint> points = drive(strategy, objective, 200);
  EXPECT_TRUE(std::all_of(points.begin(), points.end(), inside_unit_cube));
  EXPECT_TRUE(std::isfinite(strategy.best_objective()));
}

TEST_P(EveryAlgorithm, DestroyedMidRunReturnsPromptly) {
  const std::string name = GetParam();
  const auto dimensions = cube(3);
  // Budget 0 leaves NLopt without an evaluation limit: only the stop can end the run.
  for (const std::size_t budget : {400u, 0u}) {
    for (const bool outstanding : {false, true}) {
      auto strategy = make_nlopt_strategy(name, dimensions, 5, budget);
      drive(*strategy, shifted_sphere, 5);
      if (outstanding) {
        ASSERT_EQ(strategy->propose(1).size(), 1u);
      }
      const auto start = std::chrono::steady_clock::now();
      strategy.reset();
      const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
      EXPECT_LT(elapsed.count(), 1.0)
          << name << " budget " << budget << (outstanding ? " with" : " without")
          << " a proposal outstanding";
    }
  }
}

TEST_P(EveryAlgorithm, DestroyedBeforeAnyProposal) {
  const auto dimensions = cube(3);
  auto strategy = make_nlopt_strategy(GetParam(), dimensions, 5, 400);
  strategy.reset();
}

std::string parameter_name(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

INSTANTIATE_TEST_SUITE_P(NloptStrategy, EveryAlgorithm,
                         ::testing::ValuesIn(nlopt_algorithm_names()), parameter_name);

TEST(NloptStrategy, LocalMethodRestartsFromNewPointsAfterConverging) {
  const auto dimensions = cube(3);
  NloptStrategy strategy("LN_BOBYQA", dimensions, 9, 400);
  std::vector<std::size_t> run_of_point;
  std::vector<UnitPoint> points;
  for (std::size_t i = 0; i < 400; ++i) {
    points.push_back(step(strategy, shifted_sphere));
    run_of_point.push_back(strategy.runs());
  }
  ASSERT_GT(strategy.runs(), 3u);
  // The first point of each run is its random start: each differs from the last run's.
  std::set<UnitPoint> run_starts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0 || run_of_point[i] != run_of_point[i - 1]) run_starts.insert(points[i]);
  }
  EXPECT_EQ(run_starts.size(),
            std::set<std::size_t>(run_of_point.begin(), run_of_point.end()).size());
  // After converging, a restart moves far from the minimum again.
  const auto first_restart = std::find(run_of_point.begin(), run_of_point.end(), 2u);
  ASSERT_NE(first_restart, run_of_point.end());
  const UnitPoint& restart_point =
      points[static_cast<std::size_t>(first_restart - run_of_point.begin())];
  EXPECT_GT(shifted_sphere(restart_point), 1e-4);
  EXPECT_LT(strategy.best_objective(), 1e-8);
}

TEST(NloptStrategy, KeepsProposingBeyondTheBudget) {
  // Infeasible points do not count against the search loop's budget, so it may ask for more.
  const auto dimensions = cube(3);
  for (const std::string name : {"LN_SBPLX", "GN_ESCH", "GN_DIRECT_L", "GN_AGS"}) {
    NloptStrategy strategy(name, dimensions, 4, 40);
    const std::vector<UnitPoint> points = drive(strategy, shifted_sphere, 300);
    EXPECT_EQ(points.size(), 300u) << name;
  }
}

TEST(NloptStrategy, DeterministicGlobalRestartContinuesWithoutRepeatingPoints) {
  const auto dimensions = cube(3);
  NloptStrategy strategy("GN_DIRECT_L", dimensions, 4, 50);
  const std::vector<UnitPoint> points = drive(strategy, shifted_sphere, 200);
  EXPECT_GT(strategy.runs(), 1u);
  EXPECT_EQ(std::set<UnitPoint>(points.begin(), points.end()).size(), points.size());
}

TEST(NloptStrategy, UnknownAndGradientBasedNamesThrow) {
  const auto dimensions = cube(3);
  for (const std::string name : {"LN_NOPE", "LD_LBFGS", "GD_STOGO", "", "GN_MLSL+LD_LBFGS",
                                 "LN_BOBYQA+LN_SBPLX", "GN_MLSL+GN_ESCH"}) {
    try {
      make_nlopt_strategy(name, dimensions, 1, 10);
      ADD_FAILURE() << "'" << name << "' was accepted";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("LN_BOBYQA"), std::string::npos) << message;
      EXPECT_NE(message.find("GN_ISRES"), std::string::npos) << message;
    }
  }
  try {
    make_nlopt_strategy("LD_LBFGS", dimensions, 1, 10);
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("gradient"), std::string::npos) << error.what();
  }
}

TEST(NloptStrategy, NamesAcceptVariants) {
  const auto dimensions = cube(3);
  for (const std::string name :
       {"ln_bobyqa", "NLOPT_GN_ESCH", "GN_MLSL_LDS+LN_SBPLX", "AUGLAG+LN_COBYLA"}) {
    auto strategy = make_nlopt_strategy(name, dimensions, 2, 100);
    EXPECT_EQ(drive(*strategy, shifted_sphere, 100).size(), 100u) << name;
  }
  const std::vector<std::string> names = nlopt_algorithm_names();
  for (const std::string listed : {"GN_ISRES", "GN_CRS2_LM", "GN_ESCH", "GN_DIRECT", "GN_DIRECT_L",
                                   "GN_MLSL", "GN_MLSL_LDS", "LN_BOBYQA", "LN_COBYLA", "LN_SBPLX",
                                   "LN_NELDERMEAD", "LN_PRAXIS", "LN_NEWUOA_BOUND", "GN_AGS"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), listed), names.end()) << listed;
  }
}

TEST(NloptStrategy, AgsRejectsMoreThanTenDimensions) {
  const auto eleven = cube(11);
  EXPECT_THROW(make_nlopt_strategy("GN_AGS", eleven, 1, 10), std::invalid_argument);
  const auto ten = cube(10);
  auto strategy = make_nlopt_strategy("GN_AGS", ten, 1, 10);
  EXPECT_EQ(drive(*strategy, shifted_sphere, 5).size(), 5u);
}

TEST(NloptStrategy, NoDimensionsProposesTheEmptyPoint) {
  NloptStrategy strategy("LN_BOBYQA", {}, 1, 10);
  for (const UnitPoint& point : drive(strategy, shifted_sphere, 5)) EXPECT_TRUE(point.empty());
}

TEST(NloptStrategy, ProposeTwiceWithoutObserveIsAnError) {
  const auto dimensions = cube(2);
  NloptStrategy strategy("LN_COBYLA", dimensions, 1, 10);
  ASSERT_EQ(strategy.propose(1).size(), 1u);
  EXPECT_THROW(strategy.propose(1), std::logic_error);
}

}  // namespace
}  // namespace scenfuzz

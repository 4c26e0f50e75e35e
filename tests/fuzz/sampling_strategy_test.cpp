// The sampling baselines: a seed fixes their points, batch sizes never change them (which is what
// makes a search independent of the thread count), and Latin hypercube designs stay stratified.
#include "fuzz/sampling_strategy.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "sampler/point_samplers.hpp"

namespace scenfuzz {
namespace {

std::vector<SearchDimension> test_dimensions() {
  return {
      {.name = "ego.init.speed",
       .kind = GeneKind::continuous,
       .choices = 0,
       .group = "ego",
       .series = ""},
      {.name = "npc1.init.heading",
       .kind = GeneKind::angle,
       .choices = 0,
       .group = "npc1",
       .series = ""},
      {.name = "weather.rain",
       .kind = GeneKind::continuous,
       .choices = 0,
       .group = "",
       .series = ""},
      {.name = "npc1.type",
       .kind = GeneKind::discrete,
       .choices = 3,
       .group = "npc1",
       .series = ""},
  };
}

const std::vector<std::string> sampling_names = {"random", "halton", "lhs"};

// Proposes batches of the given sizes, observing every batch as a search would (all points
// judged, objective 1), and returns all points in order.
std::vector<UnitPoint> propose_in_batches(SearchStrategy& strategy,
                                          const std::vector<std::size_t>& batch_sizes) {
  std::vector<UnitPoint> points;
  for (const std::size_t size : batch_sizes) {
    std::vector<UnitPoint> batch = strategy.propose(size);
    EXPECT_EQ(batch.size(), size);
    std::vector<Observation> results;
    for (const UnitPoint& point : batch) {
      results.push_back({.point = point, .objective = 1.0, .judged = true});
    }
    strategy.observe(results);
    points.insert(points.end(), batch.begin(), batch.end());
  }
  return points;
}

std::vector<UnitPoint> points_of(const std::string& name, std::uint64_t seed, std::size_t budget,
                                 const std::vector<std::size_t>& batch_sizes) {
  const std::vector<SearchDimension> dimensions = test_dimensions();
  const auto strategy = make_sampling_strategy(name, dimensions, seed, budget);
  return propose_in_batches(*strategy, batch_sizes);
}

// Whether each of the `points.size()` equal slices of [0, 1) holds exactly one point, in every
// dimension.
bool is_latin_hypercube(const std::vector<UnitPoint>& points) {
  const std::size_t count = points.size();
  for (std::size_t dimension = 0; dimension < points.front().size(); ++dimension) {
    std::vector<double> coordinates;
    for (const UnitPoint& point : points) coordinates.push_back(point[dimension]);
    std::sort(coordinates.begin(), coordinates.end());
    for (std::size_t i = 0; i < count; ++i) {
      const double lower = static_cast<double>(i) / static_cast<double>(count);
      const double upper = static_cast<double>(i + 1) / static_cast<double>(count);
      if (coordinates[i] < lower || coordinates[i] >= upper) return false;
    }
  }
  return true;
}

TEST(SamplingStrategy, ProposesExactlyTheRequestedNumberOfPointsInsideTheCube) {
  for (const std::string& name : sampling_names) {
    // Far past the budget: baselines never end by themselves.
    const std::vector<UnitPoint> points = points_of(name, 1, 10, {1, 7, 30, 2});
    ASSERT_EQ(points.size(), 40u) << name;
    for (const UnitPoint& point : points) {
      ASSERT_EQ(point.size(), test_dimensions().size()) << name;
      for (const double coordinate : point) {
        EXPECT_GE(coordinate, 0.0) << name;
        EXPECT_LT(coordinate, 1.0) << name;
      }
    }
  }
}

TEST(SamplingStrategy, SameSeedGivesTheSamePoints) {
  for (const std::string& name : sampling_names) {
    EXPECT_EQ(points_of(name, 42, 16, {16}), points_of(name, 42, 16, {16})) << name;
    EXPECT_NE(points_of(name, 42, 16, {16}), points_of(name, 43, 16, {16})) << name;
  }
}

TEST(SamplingStrategy, BatchSizesDoNotChangeTheSequence) {
  for (const std::string& name : sampling_names) {
    EXPECT_EQ(points_of(name, 7, 100, {3, 5}), points_of(name, 7, 100, {8})) << name;
    // Across the end of a Latin hypercube design too: designs of 5 points.
    const std::vector<UnitPoint> whole = points_of(name, 7, 5, {12});
    EXPECT_EQ(points_of(name, 7, 5, {3, 5, 4}), whole) << name;
    EXPECT_EQ(points_of(name, 7, 5, {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}), whole) << name;
  }
}

TEST(SamplingStrategy, HaltonFollowsTheSequenceInIndexOrder) {
  const std::vector<UnitPoint> points = points_of("halton", 9, 20, {20});
  const HaltonSequence sequence(test_dimensions().size(), 9);
  for (std::uint64_t k = 0; k < points.size(); ++k) EXPECT_EQ(points[k], sequence.point(k));
}

TEST(SamplingStrategy, RandomDrawsUniformPointsFromTheSeed) {
  const std::vector<UnitPoint> points = points_of("random", 9, 20, {20});
  Random random(9);
  for (const UnitPoint& point : points) {
    EXPECT_EQ(point, uniform_point(test_dimensions().size(), random));
  }
}

TEST(SamplingStrategy, LatinHypercubeStratifiesEveryDesignOfBudgetPoints) {
  constexpr std::size_t budget = 25;
  const std::vector<UnitPoint> points = points_of("lhs", 3, budget, {10, 10, 10, 20});
  ASSERT_EQ(points.size(), 2 * budget);
  const std::vector<UnitPoint> first(points.begin(), points.begin() + budget);
  const std::vector<UnitPoint> second(points.begin() + budget, points.end());
  EXPECT_TRUE(is_latin_hypercube(first));
  EXPECT_TRUE(is_latin_hypercube(second));
  EXPECT_NE(first, second);
}

TEST(SamplingStrategy, LatinHypercubeWithNoBudgetStillProposes) {
  EXPECT_EQ(points_of("lhs", 3, 0, {4}).size(), 4u);
}

TEST(SamplingStrategy, WorksWithoutDimensions) {
  for (const std::string& name : sampling_names) {
    const auto strategy = make_sampling_strategy(name, {}, 1, 10);
    const std::vector<UnitPoint> points = strategy->propose(3);
    ASSERT_EQ(points.size(), 3u) << name;
    for (const UnitPoint& point : points) EXPECT_TRUE(point.empty()) << name;
  }
}

TEST(SamplingStrategy, RejectsAnUnknownName) {
  const std::vector<SearchDimension> dimensions = test_dimensions();
  EXPECT_THROW(make_sampling_strategy("sobol", dimensions, 1, 10), std::invalid_argument);
  EXPECT_THROW(make_sampling_strategy("ga", dimensions, 1, 10), std::invalid_argument);
}

}  // namespace
}  // namespace scenfuzz

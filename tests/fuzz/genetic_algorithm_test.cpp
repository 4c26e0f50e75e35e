// The genetic algorithm on synthetic objectives, driven by hand through propose/observe:
// determinism, independence from batch splitting, speed against uniform random search, batches
// of two points or more (descents side by side, topped up with children), and the behaviour of
// each gene kind, the actor swap, refinement of the best point, (mu + lambda) survival, held
// runs of signal segments, restarts and infeasible points.
#include "fuzz/genetic_algorithm.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "sampler/random.hpp"

namespace scenfuzz {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

using Objective = std::function<double(const UnitPoint&)>;

std::vector<SearchDimension> continuous_dimensions(std::size_t count) {
  std::vector<SearchDimension> dimensions(count);
  for (std::size_t i = 0; i < count; ++i) dimensions[i].name = "x" + std::to_string(i);
  return dimensions;
}

// Dimensions of every kind, some grouped into actors.
std::vector<SearchDimension> mixed_dimensions() {
  return {{"ego.speed", GeneKind::continuous, 0, "ego", ""},
          {"ego.heading", GeneKind::angle, 0, "ego", ""},
          {"npc1.speed", GeneKind::continuous, 0, "npc1", ""},
          {"npc1.type", GeneKind::discrete, 3, "npc1", ""},
          {"npc1.lane", GeneKind::discrete, 5, "npc1", ""},
          {"weather", GeneKind::discrete, 4, "", ""},
          {"friction", GeneKind::continuous, 0, "", ""}};
}

Observation judged(const UnitPoint& point, double objective) { return {point, objective, true}; }

// Proposes and observes until `evaluations` points were evaluated, asking for batch_size(call)
// points at the call-th proposal; returns every point in the order proposed.
std::vector<UnitPoint> drive(SearchStrategy& strategy, const Objective& objective,
                             std::size_t evaluations,
                             const std::function<std::size_t(std::size_t)>& batch_size) {
  std::vector<UnitPoint> points;
  for (std::size_t call = 0; points.size() < evaluations; ++call) {
    const std::vector<UnitPoint> batch =
        strategy.propose(std::min(batch_size(call), evaluations - points.size()));
    if (batch.empty()) break;
    std::vector<Observation> results;
    for (const UnitPoint& point : batch) {
      results.push_back(judged(point, objective(point)));
      points.push_back(point);
    }
    strategy.observe(results);
  }
  return points;
}

std::size_t batches_of(std::size_t) { return 8; }

double sum_objective(const UnitPoint& point) {
  double sum = 0;
  for (const double coordinate : point) sum += coordinate;
  return sum;
}

double distance(const UnitPoint& a, const UnitPoint& b) {
  double squares = 0;
  for (std::size_t i = 0; i < a.size(); ++i) squares += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(squares);
}

// One whole generation: the population's size (or, after the first, minus the elites).
std::vector<UnitPoint> next_generation(GeneticAlgorithm& algorithm, const Objective& objective) {
  const std::vector<UnitPoint> batch = algorithm.propose(1000);
  std::vector<Observation> results;
  for (const UnitPoint& point : batch) results.push_back(judged(point, objective(point)));
  algorithm.observe(results);
  return batch;
}

TEST(GeneticAlgorithm, SameSeedGivesTheSamePoints) {
  const auto dimensions = mixed_dimensions();
  const auto first = make_genetic_algorithm(dimensions, 42, 400);
  const auto second = make_genetic_algorithm(dimensions, 42, 400);
  const auto other = make_genetic_algorithm(dimensions, 43, 400);
  const auto points = drive(*first, sum_objective, 400, batches_of);
  ASSERT_EQ(points.size(), 400u);
  EXPECT_EQ(points, drive(*second, sum_objective, 400, batches_of));
  EXPECT_NE(points, drive(*other, sum_objective, 400, batches_of));
  for (const UnitPoint& point : points) {
    ASSERT_EQ(point.size(), dimensions.size());
    for (const double coordinate : point) {
      EXPECT_GE(coordinate, 0.0);
      EXPECT_LE(coordinate, 1.0);
    }
  }
}

TEST(GeneticAlgorithm, BatchSplittingDoesNotChangeThePoints) {
  const auto dimensions = mixed_dimensions();
  const auto whole = make_genetic_algorithm(dimensions, 7, 500);
  const auto three_then_five = make_genetic_algorithm(dimensions, 7, 500);
  const auto one_by_one = make_genetic_algorithm(dimensions, 7, 500);
  const auto points = drive(*whole, sum_objective, 500, [](std::size_t) { return 1000; });
  EXPECT_EQ(points, drive(*three_then_five, sum_objective, 500,
                          [](std::size_t call) { return call % 2 == 0 ? 3u : 5u; }));
  EXPECT_EQ(points, drive(*one_by_one, sum_objective, 500, [](std::size_t) { return 1; }));
}

// Evaluations until the first negative objective (`cap` when there is none).
std::size_t evaluations_to_finding(SearchStrategy& strategy, const Objective& objective,
                                   std::size_t cap) {
  std::size_t evaluations = 0;
  while (evaluations < cap) {
    const std::vector<UnitPoint> batch = strategy.propose(8);
    std::vector<Observation> results;
    for (const UnitPoint& point : batch) {
      const double value = objective(point);
      ++evaluations;
      if (value < 0) return evaluations;
      results.push_back(judged(point, value));
    }
    strategy.observe(results);
  }
  return cap;
}

std::size_t median(std::vector<std::size_t> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

TEST(GeneticAlgorithm, FindsASmallBallSoonerThanUniformRandomSearch) {
  const UnitPoint centre = {0.8, 0.2, 0.6, 0.4, 0.9, 0.1};
  const Objective ball = [&](const UnitPoint& point) { return distance(point, centre) - 0.15; };
  const auto dimensions = continuous_dimensions(centre.size());
  constexpr std::size_t cap = 200000;
  std::vector<std::size_t> genetic;
  std::vector<std::size_t> uniform;
  for (std::uint64_t seed = 1; seed <= 11; ++seed) {
    const auto algorithm = make_genetic_algorithm(dimensions, seed, 2000);
    genetic.push_back(evaluations_to_finding(*algorithm, ball, cap));
    Random random(seed);
    std::size_t evaluations = 0;
    while (evaluations < cap) {
      ++evaluations;
      if (ball(uniform_point(centre.size(), random)) < 0) break;
    }
    uniform.push_back(evaluations);
  }
  std::cout << "evaluations to the first finding, median over 11 seeds: genetic algorithm "
            << median(genetic) << ", uniform random " << median(uniform) << "\n";
  ::testing::Test::RecordProperty("genetic_median", std::to_string(median(genetic)));
  ::testing::Test::RecordProperty("random_median", std::to_string(median(uniform)));
  EXPECT_LT(median(genetic), median(uniform));
}

TEST(GeneticAlgorithm, TheTwoDescentsRunSideBySide) {
  // On a plateau the descent from the best point improves on nothing after its start.
  const Objective plateau = [](const UnitPoint&) { return 1.0; };
  GeneticAlgorithm algorithm(continuous_dimensions(4), 21, 500);
  const std::vector<UnitPoint> first = next_generation(algorithm, plateau);
  EXPECT_EQ(first.size(), 4u);  // max(4, d) points start the search while descents run
  EXPECT_EQ(algorithm.status().local_runs, 2u);
  // One point of each in every round: from the best point (the first of equal values), which
  // is not simulated again, its simplex's first step along the first axis; and the random
  // descent's start.
  const std::vector<UnitPoint> round = next_generation(algorithm, plateau);
  ASSERT_EQ(round.size(), 2u);
  for (std::size_t axis = 1; axis < 4; ++axis) EXPECT_EQ(round[0][axis], first[0][axis]);
  EXPECT_NE(round[0][0], first[0][0]);
  EXPECT_EQ(std::count(first.begin(), first.end(), round[1]), 0);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(next_generation(algorithm, plateau).size(), 2u);
}

TEST(GeneticAlgorithm, NoDescentStartsFromAViolation) {
  GeneticAlgorithm algorithm(continuous_dimensions(4), 23, 500);
  const std::vector<UnitPoint> first =
      next_generation(algorithm, [](const UnitPoint& point) { return point[0] - 0.5; });
  // Some point of the Latin hypercube violates: only the random descent runs.
  EXPECT_EQ(algorithm.status().local_runs, 1u);
  // Its start, topped up with a child bred from the population.
  const std::vector<UnitPoint> round = algorithm.propose(16);
  ASSERT_EQ(round.size(), 2u);
  EXPECT_EQ(std::count(first.begin(), first.end(), round[0]), 0);
  EXPECT_EQ(std::count(first.begin(), first.end(), round[1]), 0);
  // The child joins the population as soon as it is observed.
  algorithm.observe(std::vector<Observation>{judged(round[0], 3.0), judged(round[1], -7.0)});
  EXPECT_EQ(algorithm.status().best_objective, -7.0);
  EXPECT_EQ(algorithm.status().best_point, round[1]);
}

// Sizes of the batches of a search driven with batches of up to 16 points (the search loop's).
std::vector<std::size_t> batch_sizes(GeneticAlgorithm& algorithm, const Objective& objective,
                                     std::size_t evaluations) {
  std::vector<std::size_t> sizes;
  for (std::size_t done = 0; done < evaluations;) {
    const std::vector<UnitPoint> batch = algorithm.propose(16);
    std::vector<Observation> results;
    for (const UnitPoint& point : batch) results.push_back(judged(point, objective(point)));
    algorithm.observe(results);
    sizes.push_back(batch.size());
    done += batch.size();
  }
  return sizes;
}

TEST(GeneticAlgorithm, EveryBatchHoldsAtLeastTwoPoints) {
  // A descent asks for one point at a time; a batch of one would leave all workers but one idle.
  const UnitPoint centre = {0.8, 0.2, 0.6, 0.4, 0.9, 0.1};
  const Objective ball = [&](const UnitPoint& point) { return distance(point, centre) - 0.05; };
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    GeneticAlgorithm algorithm(continuous_dimensions(centre.size()), seed, 1000);
    const std::vector<std::size_t> sizes = batch_sizes(algorithm, ball, 1000);
    EXPECT_GT(algorithm.status().local_runs, 4u);
    EXPECT_EQ(std::count(sizes.begin(), sizes.end(), 1u), 0) << "seed " << seed;
  }
  // Without the children, a descent left alone runs one point at a time.
  GeneticAlgorithmOptions alone;
  alone.descent_round_points = 1;
  GeneticAlgorithm algorithm(continuous_dimensions(centre.size()), 1, 1000, alone);
  const std::vector<std::size_t> sizes = batch_sizes(algorithm, ball, 1000);
  EXPECT_GT(std::count(sizes.begin(), sizes.end(), 1u), 0);
}

TEST(GeneticAlgorithm, BeyondTheDimensionLimitTheGenerationsRunAlone) {
  GeneticAlgorithm algorithm(continuous_dimensions(40), 25, 1500);
  EXPECT_EQ(next_generation(algorithm, sum_objective).size(), algorithm.status().population);
  EXPECT_EQ(next_generation(algorithm, sum_objective).size(), 8u);
  EXPECT_EQ(algorithm.status().local_runs, 0u);
}

TEST(GeneticAlgorithm, DescentsReachASmoothViolationSoonerThanTheGenerationsAlone) {
  // A ball in 6 dimensions whose distance guides the way: what the descents are for.
  const UnitPoint centre = {0.8, 0.2, 0.6, 0.4, 0.9, 0.1};
  const Objective ball = [&](const UnitPoint& point) { return distance(point, centre) - 0.15; };
  const auto dimensions = continuous_dimensions(centre.size());
  GeneticAlgorithmOptions alone;
  alone.local_search = false;
  std::vector<std::size_t> with_descents;
  std::vector<std::size_t> without;
  for (std::uint64_t seed = 1; seed <= 11; ++seed) {
    GeneticAlgorithm descending(dimensions, seed, 5000);
    GeneticAlgorithm plain(dimensions, seed, 5000, alone);
    with_descents.push_back(evaluations_to_finding(descending, ball, 5000));
    without.push_back(evaluations_to_finding(plain, ball, 5000));
  }
  std::cout << "evaluations to the first finding, median over 11 seeds: with descents "
            << median(with_descents) << ", generations alone " << median(without) << "\n";
  EXPECT_LT(median(with_descents), median(without));
}

TEST(GeneticAlgorithm, DiscreteGenesSitInTheMiddleOfACellAndEveryChoiceAppears) {
  const auto dimensions = mixed_dimensions();
  const auto algorithm = make_genetic_algorithm(dimensions, 3, 300);
  const auto points = drive(*algorithm, sum_objective, 300, batches_of);
  for (std::size_t gene = 0; gene < dimensions.size(); ++gene) {
    if (dimensions[gene].kind != GeneKind::discrete) continue;
    const auto choices = static_cast<double>(dimensions[gene].choices);
    std::set<double> seen;
    for (const UnitPoint& point : points) {
      const double cell = point[gene] * choices - 0.5;
      EXPECT_EQ(cell, std::round(cell)) << dimensions[gene].name << " at " << point[gene];
      seen.insert(std::round(cell));
    }
    EXPECT_EQ(seen.size(), dimensions[gene].choices) << dimensions[gene].name;
  }
}

TEST(GeneticAlgorithm, BlendingTakesEachDiscreteChoiceFromAParent) {
  // With many choices, a child's choice that is neither parent's would be seen at once.
  const std::vector<SearchDimension> dimensions = {{"x", GeneKind::continuous, 0, "", ""},
                                                   {"lane", GeneKind::discrete, 997, "", ""}};
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.crossover_probability = 1.0;
  options.mutation_rate = 0.0;
  GeneticAlgorithm algorithm(dimensions, 19, 400, options);
  const auto parents = next_generation(algorithm, sum_objective);
  std::set<double> parent_choices;
  for (const UnitPoint& parent : parents) parent_choices.insert(parent[1]);
  // Every child is a blend: with a continuous gene, breeding never gives only duplicates here,
  // so no uniform point stands in for a child.
  for (const UnitPoint& child : next_generation(algorithm, sum_objective)) {
    EXPECT_TRUE(parent_choices.contains(child[1])) << child[1];
  }
}

// How many of the last points lie within 0.1 past the upper end of [0, 1), i.e. in [0, 0.1).
std::size_t wrapped_points(GeneKind kind, std::uint64_t seed) {
  std::vector<SearchDimension> dimensions = continuous_dimensions(2);
  dimensions[0].kind = kind;
  // The target sits just below 1: on the circle its neighbourhood continues at 0.
  const Objective near_target = [kind](const UnitPoint& point) {
    const double gap = std::abs(point[0] - 0.97);
    return (kind == GeneKind::angle ? std::min(gap, 1.0 - gap) : gap) + 0.1 * point[1];
  };
  const auto algorithm = make_genetic_algorithm(dimensions, seed, 1000);
  const auto points = drive(*algorithm, near_target, 1000, batches_of);
  std::size_t count = 0;
  for (std::size_t i = 500; i < points.size(); ++i) {
    EXPECT_GE(points[i][0], 0.0);
    EXPECT_LT(points[i][0], kind == GeneKind::angle ? 1.0 : 1.0 + 1e-12);
    if (points[i][0] < 0.1) ++count;
  }
  return count;
}

TEST(GeneticAlgorithm, AngleGenesWrapAroundInsteadOfStoppingAtTheBound) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const std::size_t angle = wrapped_points(GeneKind::angle, seed);
    const std::size_t continuous = wrapped_points(GeneKind::continuous, seed);
    EXPECT_GT(angle, 50u) << "seed " << seed;
    EXPECT_GT(angle, 4 * continuous) << "seed " << seed;
  }
}

TEST(GeneticAlgorithm, ActorSwapExchangesExactlyTheGenesOfOneGroup) {
  const auto dimensions = mixed_dimensions();
  const std::vector<std::set<std::size_t>> groups = {{0, 1}, {2, 3, 4}};
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.crossover_probability = 1.0;
  options.actor_swap_probability = 1.0;
  options.mutation_rate = 0.0;
  options.refinement_fraction = 0.0;
  GeneticAlgorithm algorithm(dimensions, 11, 400, options);
  const auto parents = next_generation(algorithm, sum_objective);
  const auto children = next_generation(algorithm, sum_objective);
  ASSERT_FALSE(children.empty());

  // A child is one parent with one group's genes taken from another parent, and nothing else.
  const auto is_swap_child = [&](const UnitPoint& child) {
    for (const UnitPoint& base : parents) {
      for (const UnitPoint& donor : parents) {
        if (&donor == &base) continue;
        for (const auto& group : groups) {
          bool matches = true;
          for (std::size_t gene = 0; gene < child.size(); ++gene) {
            matches = matches && child[gene] == (group.contains(gene) ? donor : base)[gene];
          }
          if (matches) return true;
        }
      }
    }
    return false;
  };
  std::size_t swapped = 0;
  for (const UnitPoint& child : children) {
    // A child that shares no continuous gene with any parent is a uniform point, drawn when
    // breeding gave only duplicates.
    bool shares_continuous = false;
    for (const UnitPoint& parent : parents) {
      shares_continuous = shares_continuous || child[0] == parent[0] || child[2] == parent[2] ||
                          child[6] == parent[6];
    }
    if (!shares_continuous) continue;
    EXPECT_TRUE(is_swap_child(child)) << "a child differs from its parents outside one group";
    ++swapped;
  }
  EXPECT_GE(swapped, children.size() / 2);
}

TEST(GeneticAlgorithm, LaterGenerationsHaveTheOffspringCount) {
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.offspring = 5;
  GeneticAlgorithm algorithm(continuous_dimensions(4), 3, 1000, options);
  EXPECT_EQ(next_generation(algorithm, sum_objective).size(), algorithm.status().population);
  for (int generation = 0; generation < 5; ++generation)
    EXPECT_EQ(next_generation(algorithm, sum_objective).size(), 5u);
}

TEST(GeneticAlgorithm, RefinementChildrenSurroundTheBestPointAtSeveralScales) {
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.refinement_fraction = 1.0;
  options.offspring = 40;
  GeneticAlgorithm algorithm(continuous_dimensions(5), 21, 1000, options);
  next_generation(algorithm, sum_objective);
  const UnitPoint best = algorithm.status().best_point;
  std::vector<double> distances;
  for (const UnitPoint& child : next_generation(algorithm, sum_objective))
    distances.push_back(distance(child, best));
  std::sort(distances.begin(), distances.end());
  ASSERT_EQ(distances.size(), 40u);
  // Steps are Gaussian on each of 5 genes with a scale from 0.01 to 0.2: the nearest children
  // are within a few hundredths, none is far (a blend or a fresh point would be).
  EXPECT_GT(distances.front(), 0.0);
  EXPECT_LT(distances[3], 0.1);
  EXPECT_LT(distances.back(), 1.0);
  EXPECT_GT(distances.back() / distances.front(), 5.0);
}

TEST(GeneticAlgorithm, TheBestPointSurvivesChildrenThatAreAllWorse) {
  // (mu + lambda): parents compete with their children, so a first-generation point that no
  // child beats is still the centre of refinement generations later.
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.refinement_fraction = 1.0;
  options.elites = 0;
  options.stagnation_simulations = 0;
  GeneticAlgorithm algorithm(continuous_dimensions(3), 8, 1000, options);
  std::size_t evaluated = 0;
  const Objective first_is_best = [&](const UnitPoint&) {
    return evaluated++ == 0 ? -1.0 : 1.0 + static_cast<double>(evaluated);
  };
  const UnitPoint first = next_generation(algorithm, first_is_best).front();
  std::vector<double> distances;
  for (int generation = 0; generation < 10; ++generation) {
    for (const UnitPoint& child : next_generation(algorithm, first_is_best))
      distances.push_back(distance(child, first));
  }
  // Refinement around a drifting centre (the best child of the last generation) would wander
  // off by about a step per generation; around `first` the typical child stays within a step.
  std::sort(distances.begin(), distances.end());
  EXPECT_LT(distances[distances.size() / 2], 0.12);
  EXPECT_LT(distances[distances.size() * 9 / 10], 0.35);
  EXPECT_EQ(algorithm.status().best_point, first);
}

// Two signals of 6 segments each, then one gene outside any signal.
std::vector<SearchDimension> signal_dimensions() {
  std::vector<SearchDimension> dimensions;
  for (const std::string signal : {"throttle", "brake"})
    for (int k = 0; k < 6; ++k)
      dimensions.push_back({signal + "_" + std::to_string(k), GeneKind::continuous, 0, "", signal});
  dimensions.push_back({"friction", GeneKind::continuous, 0, "", ""});
  return dimensions;
}

// The longest run of equal consecutive values among genes [first, first + count).
std::size_t longest_run(const UnitPoint& point, std::size_t first, std::size_t count) {
  std::size_t longest = 1;
  std::size_t run = 1;
  for (std::size_t gene = first + 1; gene < first + count; ++gene) {
    run = point[gene] == point[gene - 1] ? run + 1 : 1;
    longest = std::max(longest, run);
  }
  return longest;
}

TEST(GeneticAlgorithm, HoldSetsARunOfOneSignalsSegmentsToOneValue) {
  GeneticAlgorithmOptions options;
  options.local_search = false;  // the generations alone, without descents between them
  options.hold_probability = 1.0;
  options.refinement_fraction = 0.0;
  options.crossover_probability = 0.0;
  options.mutation_rate = 0.0;
  options.offspring = 30;
  GeneticAlgorithm algorithm(signal_dimensions(), 17, 1000, options);
  const auto parents = next_generation(algorithm, sum_objective);
  std::size_t extremes = 0;
  for (const UnitPoint& child : next_generation(algorithm, sum_objective)) {
    // A held child is a parent with one run of one signal replaced: the other signal and the
    // free gene are a parent's.
    const bool throttle_held = longest_run(child, 0, 6) >= 2;
    const bool brake_held = longest_run(child, 6, 6) >= 2;
    EXPECT_TRUE(throttle_held || brake_held);
    bool from_a_parent = false;
    for (const UnitPoint& parent : parents) {
      bool same = child[12] == parent[12];
      for (std::size_t gene = throttle_held ? 6 : 0; gene < (throttle_held ? 12u : 6u); ++gene)
        same = same && child[gene] == parent[gene];
      from_a_parent = from_a_parent || same;
    }
    EXPECT_TRUE(from_a_parent);
    for (const double value : child) extremes += value == 0.0 || value == 1.0 ? 1 : 0;
  }
  EXPECT_GT(extremes, 0u);
}

TEST(GeneticAlgorithm, WithoutSignalsNothingIsHeld) {
  GeneticAlgorithmOptions options;
  options.hold_probability = 1.0;
  options.refinement_fraction = 0.0;
  options.crossover_probability = 0.0;
  options.mutation_rate = 0.0;
  GeneticAlgorithm algorithm(continuous_dimensions(6), 17, 1000, options);
  const auto parents = next_generation(algorithm, sum_objective);
  // No crossover and no mutation: children are copies of parents, which duplicates reject,
  // so every child is a fresh uniform point; none has equal neighbouring genes.
  for (const UnitPoint& child : next_generation(algorithm, sum_objective))
    EXPECT_EQ(longest_run(child, 0, 6), 1u);
}

// Whether every one of the points' coordinates falls in its own slice of [0, 1).
bool is_latin_hypercube(const std::vector<UnitPoint>& points) {
  const auto count = static_cast<double>(points.size());
  for (std::size_t gene = 0; gene < points.front().size(); ++gene) {
    std::set<std::size_t> slices;
    for (const UnitPoint& point : points) {
      slices.insert(static_cast<std::size_t>(std::floor(point[gene] * count)));
    }
    if (slices.size() != points.size()) return false;
  }
  return true;
}

TEST(GeneticAlgorithm, ConstantObjectiveStagnatesAndRestartsWithAFreshDesign) {
  GeneticAlgorithmOptions options;
  options.local_search = false;         // the generations alone, without descents between them
  options.stagnation_simulations = 24;  // three generations of 8
  GeneticAlgorithm algorithm(continuous_dimensions(4), 5, 1000, options);
  const Objective constant = [](const UnitPoint&) { return 1.0; };
  EXPECT_TRUE(is_latin_hypercube(next_generation(algorithm, constant)));
  // The first generation is progress (from nothing to 1.0); three more without any follow.
  for (int generation = 0; generation < 3; ++generation) {
    EXPECT_EQ(algorithm.status().restarts, 0u);
    EXPECT_FALSE(is_latin_hypercube(next_generation(algorithm, constant)));
  }
  EXPECT_EQ(algorithm.status().restarts, 1u);
  const auto restart = next_generation(algorithm, constant);
  EXPECT_EQ(restart.size(), algorithm.status().population - 2);
  EXPECT_TRUE(is_latin_hypercube(restart));
}

TEST(GeneticAlgorithm, StagnationCountsSimulationsNotGenerations) {
  // On a plateau in 16 dimensions each generation's descents take about 70 simulations until
  // their patience ends them: twelve such generations would outlast a budget of 500, about a
  // hundred simulations do not.
  GeneticAlgorithm algorithm(continuous_dimensions(16), 6, 500);
  drive(
      algorithm, [](const UnitPoint&) { return 1.0; }, 500, batches_of);
  EXPECT_LT(algorithm.status().generations, 12u);
  EXPECT_GE(algorithm.status().restarts, 2u);
}

TEST(GeneticAlgorithm, RestartAfterConvergencePlacesPointsFarFromTheOldPopulation) {
  const UnitPoint centre = {0.3, 0.3, 0.3};
  const Objective bowl = [&](const UnitPoint& point) { return distance(point, centre); };
  GeneticAlgorithmOptions options;
  options.stagnation_simulations = 40;
  options.improvement_tolerance = 0.01;
  GeneticAlgorithm algorithm(continuous_dimensions(3), 9, 2000, options);
  double spread_before = infinity;
  for (int generation = 0; generation < 200 && algorithm.status().restarts == 0; ++generation) {
    spread_before = 0;
    for (const UnitPoint& point : next_generation(algorithm, bowl)) {
      spread_before = std::max(spread_before, distance(point, centre));
    }
  }
  ASSERT_EQ(algorithm.status().restarts, 1u);
  double spread_after = 0;
  for (const UnitPoint& point : next_generation(algorithm, bowl)) {
    spread_after = std::max(spread_after, distance(point, centre));
  }
  EXPECT_LT(spread_before, 0.4);
  EXPECT_GT(spread_after, 0.6);
}

TEST(GeneticAlgorithm, InfiniteObservationsNeverBecomeTheBest) {
  const auto dimensions = continuous_dimensions(3);
  GeneticAlgorithm algorithm(dimensions, 13, 600);
  for (std::size_t evaluations = 0; evaluations < 400;) {
    const std::vector<UnitPoint> batch = algorithm.propose(1000);
    evaluations += batch.size();
    std::vector<Observation> results;
    for (const UnitPoint& point : batch) {
      // The lower-left region is infeasible, unjudged or absurd, though the objective says it
      // would be best there.
      const double objective = point[0] + point[1];
      if (point[0] < 0.4) {
        results.push_back({point, -5.0, false});
      } else if (point[1] < 0.2) {
        results.push_back(judged(point, std::numeric_limits<double>::quiet_NaN()));
      } else {
        results.push_back(judged(point, objective));
      }
    }
    algorithm.observe(results);
  }
  const GeneticAlgorithmStatus& status = algorithm.status();
  ASSERT_FALSE(status.best_point.empty());
  EXPECT_TRUE(std::isfinite(status.best_objective));
  EXPECT_GE(status.best_point[0], 0.4);
  EXPECT_GE(status.best_point[1], 0.2);
  EXPECT_NEAR(status.best_objective, 0.6, 0.05);
}

TEST(GeneticAlgorithm, OnlyInfeasiblePointsLeaveNoBestAndTheSearchGoesOn) {
  GeneticAlgorithmOptions options;
  options.stagnation_simulations = 16;
  GeneticAlgorithm algorithm(continuous_dimensions(2), 17, 400, options);
  const auto points = drive(
      algorithm, [](const UnitPoint&) { return infinity; }, 400, batches_of);
  EXPECT_EQ(points.size(), 400u);
  EXPECT_TRUE(algorithm.status().best_point.empty());
  EXPECT_EQ(algorithm.status().best_objective, infinity);
  EXPECT_GT(algorithm.status().restarts, 0u);
}

TEST(GeneticAlgorithm, PopulationFollowsDimensionsAndBudget) {
  EXPECT_EQ(GeneticAlgorithm(continuous_dimensions(2), 1, 1000).status().population, 10u);
  EXPECT_EQ(GeneticAlgorithm(continuous_dimensions(8), 1, 1000).status().population, 20u);
  EXPECT_EQ(GeneticAlgorithm(continuous_dimensions(40), 1, 1000).status().population, 50u);
  EXPECT_EQ(GeneticAlgorithm(continuous_dimensions(8), 1, 48).status().population, 12u);
  EXPECT_EQ(GeneticAlgorithm(continuous_dimensions(8), 1, 8).status().population, 4u);
}

TEST(GeneticAlgorithm, AnEmptySpaceIsOnePoint) {
  GeneticAlgorithm algorithm({}, 1, 100);
  const auto points = drive(algorithm, sum_objective, 100, batches_of);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_TRUE(points.front().empty());
}

TEST(GeneticAlgorithm, DiscreteDimensionWithoutChoicesIsRejected) {
  const std::vector<SearchDimension> dimensions = {{"lane", GeneKind::discrete, 0, "", ""}};
  EXPECT_THROW(GeneticAlgorithm(dimensions, 1, 100), std::invalid_argument);
}

}  // namespace
}  // namespace scenfuzz

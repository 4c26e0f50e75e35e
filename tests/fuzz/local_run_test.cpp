// The local descent (COBYLA replayed from its told values): it walks down a smooth objective,
// repeats itself exactly, counts the points since it last improved, ends on a plateau after its
// patience, survives infinities and NaN, and refuses to be driven out of order.
#include "fuzz/local_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

namespace scenfuzz {
namespace {

using Objective = std::function<double(const UnitPoint&)>;

// Drives `run` to its end (or `cap` points); returns the points in the order asked.
std::vector<UnitPoint> descend(LocalRun& run, const Objective& objective, std::size_t cap = 500) {
  std::vector<UnitPoint> points;
  while (points.size() < cap) {
    const std::optional<UnitPoint> point = run.next_point();
    if (!point) break;
    points.push_back(*point);
    run.tell(objective(*point));
  }
  return points;
}

double distance_to(const UnitPoint& point, const UnitPoint& target) {
  double squares = 0;
  for (std::size_t i = 0; i < point.size(); ++i)
    squares += (point[i] - target[i]) * (point[i] - target[i]);
  return std::sqrt(squares);
}

TEST(LocalRun, WalksDownASmoothObjectiveInAFewPoints) {
  const UnitPoint target = {0.8, 0.15, 0.6, 0.35};
  const Objective cone = [&](const UnitPoint& point) { return distance_to(point, target); };
  LocalRun run({0.2, 0.9, 0.1, 0.7});
  const std::vector<UnitPoint> points = descend(run, cone);
  ASSERT_FALSE(points.empty());
  EXPECT_TRUE(run.ended());
  EXPECT_EQ(points.front(), (UnitPoint{0.2, 0.9, 0.1, 0.7}));  // the start comes first
  double best = std::numeric_limits<double>::infinity();
  std::size_t reached = 0;
  for (std::size_t i = 0; i < points.size() && reached == 0; ++i) {
    best = std::min(best, cone(points[i]));
    if (best < 0.05) reached = i + 1;
  }
  EXPECT_GT(reached, 0u) << "best " << best << " after " << points.size() << " points";
  EXPECT_LE(reached, 60u);
  for (const UnitPoint& point : points)
    for (const double coordinate : point) {
      EXPECT_GE(coordinate, 0.0);
      EXPECT_LE(coordinate, 1.0);
    }
}

TEST(LocalRun, TheSameValuesGiveTheSamePoints) {
  const Objective slope = [](const UnitPoint& point) { return point[0] - 2 * point[1] + point[2]; };
  LocalRun first({0.5, 0.5, 0.5});
  LocalRun second({0.5, 0.5, 0.5});
  const std::vector<UnitPoint> points = descend(first, slope);
  EXPECT_GT(points.size(), 4u);
  EXPECT_EQ(points, descend(second, slope));
}

TEST(LocalRun, EndsOnAPlateauOnceItsPatienceIsSpent) {
  LocalRunOptions options;
  options.patience = 6;
  LocalRun run({0.3, 0.6, 0.4, 0.5, 0.2}, options);
  const std::vector<UnitPoint> points = descend(run, [](const UnitPoint&) { return 1.27; });
  // The start improves on nothing; six more points that do not improve end the run.
  EXPECT_EQ(points.size(), 7u);
  EXPECT_TRUE(run.ended());
  EXPECT_FALSE(run.next_point());
}

TEST(LocalRun, CountsThePointsSinceItsBestLastImproved) {
  LocalRun run({0.5, 0.5});
  // Improvements by less than `improvement` (2 cm) do not count as improving.
  const std::vector<double> values = {1.0, 0.99, 0.9, 0.895, 0.95, 0.5};
  const std::vector<std::size_t> expected = {0, 1, 0, 1, 2, 0};
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_TRUE(run.next_point());
    run.tell(values[i]);
    EXPECT_EQ(run.points_without_improvement(), expected[i]) << "after value " << values[i];
  }
}

TEST(LocalRun, AStartAlreadyEvaluatedIsNotAskedForAgain) {
  const UnitPoint start = {0.3, 0.6, 0.4};
  const Objective sum = [](const UnitPoint& point) { return point[0] + point[1] + point[2]; };
  LocalRun fresh(start);
  const std::vector<UnitPoint> asked = descend(fresh, sum);
  LocalRun known(start, sum(start));
  const std::vector<UnitPoint> skipping = descend(known, sum);
  ASSERT_GT(asked.size(), 2u);
  EXPECT_EQ(asked.front(), start);
  // The same course without its first point.
  EXPECT_EQ(skipping, std::vector<UnitPoint>(asked.begin() + 1, asked.end()));
}

TEST(LocalRun, InfinitiesAndNaNAreWorseThanAnyValue) {
  // Infeasible (infinite) left of 0.5 and NaN near the top; the descent must still go down.
  const Objective objective = [](const UnitPoint& point) {
    if (point[0] < 0.5) return std::numeric_limits<double>::infinity();
    if (point[1] > 0.9) return std::numeric_limits<double>::quiet_NaN();
    return point[0] + point[1];
  };
  LocalRun run({0.9, 0.8});
  const std::vector<UnitPoint> points = descend(run, objective);
  double best = std::numeric_limits<double>::infinity();
  for (const UnitPoint& point : points) {
    const double value = objective(point);
    if (!std::isnan(value)) best = std::min(best, value);
  }
  EXPECT_LT(best, 1.0);
  EXPECT_TRUE(run.ended());
}

TEST(LocalRun, MustBeToldBeforeAskingAgain) {
  LocalRun run({0.5, 0.5});
  ASSERT_TRUE(run.next_point());
  EXPECT_THROW(run.next_point(), std::logic_error);
  run.tell(1.0);
  EXPECT_NO_THROW(run.next_point());
  LocalRun fresh({0.5});
  EXPECT_THROW(fresh.tell(1.0), std::logic_error);
}

TEST(LocalRun, StopsAfterItsMaximumOfPoints) {
  LocalRunOptions options;
  options.max_points = 5;
  LocalRun run({0.1, 0.1}, options);
  // Steadily falling: patience alone would never end it soon.
  const std::vector<UnitPoint> points =
      descend(run, [](const UnitPoint& point) { return -point[0] - point[1]; });
  EXPECT_EQ(points.size(), 5u);
}

}  // namespace
}  // namespace scenfuzz

// StartPointStrategy: the start point leads the first batch, the inner strategy gets exactly the
// results of its own points, and it ends when the inner strategy ends.
#include "fuzz/start_point_strategy.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace scenfuzz {
namespace {

// Proposes 1-D points 0.1, 0.2, ... up to `total`, and records what it was told.
class CountingStrategy : public SearchStrategy {
 public:
  explicit CountingStrategy(std::size_t total, std::vector<double>& observed)
      : total_(total), observed_(observed) {}
  std::vector<UnitPoint> propose(std::size_t limit) override {
    std::vector<UnitPoint> points;
    while (points.size() < limit && proposed_ < total_)
      points.push_back({0.1 * static_cast<double>(++proposed_)});
    return points;
  }
  void observe(std::span<const Observation> results) override {
    for (const Observation& result : results) observed_.push_back(result.point[0]);
  }

 private:
  std::size_t total_;
  std::size_t proposed_ = 0;
  std::vector<double>& observed_;
};

std::vector<Observation> observations(const std::vector<UnitPoint>& points) {
  std::vector<Observation> results;
  for (const UnitPoint& point : points) results.push_back({point, 1.0, true});
  return results;
}

TEST(StartPointStrategy, TheStartLeadsAndTheInnerStrategySeesOnlyItsOwnPoints) {
  std::vector<double> observed;
  StartPointStrategy strategy({0.5}, std::make_unique<CountingStrategy>(3, observed));
  const std::vector<UnitPoint> first = strategy.propose(2);
  ASSERT_EQ(first, (std::vector<UnitPoint>{{0.5}, {0.1}}));
  strategy.observe(observations(first));
  EXPECT_EQ(observed, (std::vector<double>{0.1}));
  const std::vector<UnitPoint> second = strategy.propose(4);
  ASSERT_EQ(second.size(), 2u);
  strategy.observe(observations(second));
  EXPECT_EQ(observed.size(), 3u);
  EXPECT_TRUE(strategy.propose(4).empty());
}

TEST(StartPointStrategy, ABatchOfOneIsTheStartAlone) {
  std::vector<double> observed;
  StartPointStrategy strategy({0.5, 0.25}, std::make_unique<CountingStrategy>(2, observed));
  const std::vector<UnitPoint> first = strategy.propose(1);
  ASSERT_EQ(first, (std::vector<UnitPoint>{{0.5, 0.25}}));
  strategy.observe(observations(first));
  EXPECT_TRUE(observed.empty());
  EXPECT_EQ(strategy.propose(1), (std::vector<UnitPoint>{{0.1}}));
}

}  // namespace
}  // namespace scenfuzz

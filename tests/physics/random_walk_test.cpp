// Seeded random walks for pedestrians: bounded, reproducible, long enough.
#include "physics/actors/random_walk.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace scenfuzz {
namespace {

TEST(RandomWalk, StaysWithinItsRadius) {
  const MapPose start{{100, -20}, 0.5};
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    Polyline path = random_walk_path(start, 1.4, 120, 10, seed);
    for (const MapPoint& point : path.points())
      ASSERT_LE(distance(point, start.position), 10 + 1e-9) << seed;
  }
}

TEST(RandomWalk, IsLongEnoughWithLegsOfTwoToFiveSeconds) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    Polyline path = random_walk_path({{0, 0}, 0}, 1.2, 60, 25, seed);
    EXPECT_GE(path.length(), 1.2 * 60);
    EXPECT_LT(path.length(), 1.2 * 60 + 1.2 * 5 + 1e-9);
    for (std::size_t i = 0; i < path.segment_count(); ++i) {
      double leg = path.arc_lengths()[i + 1] - path.arc_lengths()[i];
      EXPECT_LE(leg, 1.2 * 5 + 1e-9);
    }
  }
  // The first leg sets off along the start heading.
  Polyline path = random_walk_path({{0, 0}, 1}, 1, 30, 50, 7);
  EXPECT_NEAR(path.heading_at(0), 1, 1e-12);
  EXPECT_GE(path.arc_lengths()[1], 2 - 1e-9);
}

TEST(RandomWalk, SameSeedSamePathDifferentSeedDifferentPath) {
  const MapPose start{{5, 5}, 2};
  Polyline first = random_walk_path(start, 1.5, 90, 15, 42);
  Polyline again = random_walk_path(start, 1.5, 90, 15, 42);
  Polyline other = random_walk_path(start, 1.5, 90, 15, 43);
  EXPECT_EQ(first.points(), again.points());
  EXPECT_NE(first.points(), other.points());
}

TEST(RandomWalk, SmallRadiusStillWalksItsLength) {
  Polyline path = random_walk_path({{0, 0}, 0}, 1.4, 100, 1, 3);
  EXPECT_GE(path.length(), 140);
  for (const MapPoint& point : path.points()) EXPECT_LE(distance(point, {0, 0}), 1 + 1e-9);
}

TEST(RandomWalk, RejectsBadArguments) {
  EXPECT_THROW(random_walk_path({}, 0, 10, 5, 1), std::invalid_argument);
  EXPECT_THROW(random_walk_path({}, 1, -1, 5, 1), std::invalid_argument);
  EXPECT_THROW(random_walk_path({}, 1, 10, 0, 1), std::invalid_argument);
  EXPECT_THROW(random_walk_path({}, 1, 1e12, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace scenfuzz

// lines_cross rejects segment pairs by boxes (the other line's, its runs', each segment's) before
// the cross products: its answer must be that of testing every pair, on seeded random wiggly
// lines of a few to hundreds of segments (finely sampled junction lanes), crossing or not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

double cross(MapPoint o, MapPoint a, MapPoint b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The definition: some segment of one properly crosses some segment of the other.
bool every_pair_cross(const Polyline& first, const Polyline& second) {
  const auto& p = first.points();
  const auto& q = second.points();
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    for (std::size_t j = 0; j + 1 < q.size(); ++j) {
      const double d1 = cross(q[j], q[j + 1], p[i]), d2 = cross(q[j], q[j + 1], p[i + 1]);
      const double d3 = cross(p[i], p[i + 1], q[j]), d4 = cross(p[i], p[i + 1], q[j + 1]);
      if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0))) return true;
    }
  return false;
}

// A random walk of `segments` steps of about `step` m from `start`, turning a little each step.
Polyline wiggly_line(std::mt19937_64& random, MapPoint start, std::size_t segments, double step) {
  std::uniform_real_distribution<double> turn(-0.4, 0.4), unit(0, 1);
  double heading = unit(random) * 2 * std::numbers::pi;
  std::vector<MapPoint> points{start};
  for (std::size_t k = 0; k < segments; ++k) {
    heading += turn(random);
    const double length = step * (0.5 + unit(random));
    points.push_back({points.back().x + length * std::cos(heading),
                      points.back().y + length * std::sin(heading)});
  }
  return Polyline(points);
}

TEST(LinesCrossTest, AgreesWithTestingEveryPairOfSegments) {
  std::mt19937_64 random(21);
  std::uniform_real_distribution<double> place(-30, 30);
  std::uniform_int_distribution<std::size_t> size(1, 300);
  int crossing = 0, apart = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = size(random), m = size(random);
    const Polyline a =
        wiggly_line(random, {place(random), place(random)}, n, 60.0 / static_cast<double>(n));
    const Polyline b =
        wiggly_line(random, {place(random), place(random)}, m, 60.0 / static_cast<double>(m));
    const bool expected = every_pair_cross(a, b);
    ASSERT_EQ(lines_cross(a, b), expected) << "trial " << trial << ": " << n << " x " << m;
    ASSERT_EQ(lines_cross(b, a), expected) << "trial " << trial;
    (expected ? crossing : apart) += 1;
  }
  // Both answers must have been asked for many times.
  EXPECT_GT(crossing, 100);
  EXPECT_GT(apart, 100);
}

TEST(LinesCrossTest, AgreesWithTestingEveryPairOnTheCrossroadsJunctionLanes) {
  const RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  int pairs = 0;
  for (const Lane& first : map.lanes()) {
    if (!first.junction) continue;
    for (const Lane& second : map.lanes()) {
      if (!second.junction || &first == &second) continue;
      EXPECT_EQ(lines_cross(first.centre_line, second.centre_line),
                every_pair_cross(first.centre_line, second.centre_line))
          << first.id << " x " << second.id;
      ++pairs;
    }
  }
  EXPECT_GT(pairs, 50);
}

}  // namespace
}  // namespace scenfuzz

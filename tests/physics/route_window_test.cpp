// RouteTracker::window walks from its last answer for the same `behind` (a cache of a const
// query): its windows must be exactly those of two binary searches (Polyline::segment_at), for
// any sequence of progress, windows asked with repeated, new, long and short extents, and more
// `behind` values than it keeps hints for.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "physics/ego/route_tracker.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/map_source.hpp"

namespace scenfuzz {
namespace {

TEST(RouteTracker, WindowsFromHintsAreTheBinarySearchedOnes) {
  RoadMap map = load_map("crossroads", MapSearchPath{});
  std::optional<LaneRoute> route =
      find_route(map, LanePosition{*map.find_lane("west_in_1"), 100, 0},
                 LanePosition{*map.find_lane("north_out_1"), 50, 0});
  ASSERT_TRUE(route);
  RouteTracker tracker(map, *route, {}, 13.9);
  const Polyline& path = tracker.path();
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const double behinds[] = {0, 5, 30, 12.5};  // one more than the hints kept
  int windows = 0;
  for (double progress = 0; progress < tracker.length() + 5; progress += 0.3 + 2 * unit(random)) {
    tracker.update(path.point_at(progress));
    for (int ask = 0; ask < 4; ++ask) {
      const double behind = behinds[random() % 4];
      // Mostly like the driver's (60 m and on with speed), now and then far longer or none.
      const double ahead = unit(random) < 0.8 ? 60 + 60 * unit(random) : 400 * unit(random);
      const PathWindow window = tracker.window(behind, ahead);
      const double p = tracker.progress();
      ASSERT_EQ(window.first, path.segment_at(std::max(0.0, p - behind))) << progress;
      ASSERT_EQ(window.last, path.segment_at(std::min(tracker.length(), p + ahead))) << progress;
      ++windows;
    }
  }
  EXPECT_GT(windows, 300);
}

}  // namespace
}  // namespace scenfuzz

// Giving way at a stop or yield sign (physics/ego/priority_traffic.hpp) on the built-in T-junction:
// the ego turning right out of the side road (south_in_0 into south_east_0) gives way to traffic
// from its left that merges into its lane, not to traffic on the far half of the road.
#include "physics/ego/priority_traffic.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {
namespace {

class PriorityTrafficTest : public ::testing::Test {
 protected:
  PriorityTrafficTest()
      : map_(build_road_map(generate_builtin_map("t_junction", {}))),
        conflicts_(conflicting_lanes(map_, lane("south_east_0"))) {}

  LaneIndex lane(const char* id) const { return *map_.find_lane(id); }

  // A car `before_end` metres before the end of lane `id`, along it, at `speed`.
  WorldObject car_on(const char* id, double before_end, double speed) const {
    const Lane& l = map_.lane(lane(id));
    const double s = l.length() - before_end;
    const MapPoint p = l.centre_line.point_at(s);
    WorldObject car;
    car.id = 1;
    car.kind = TraceActorKind::vehicle;
    car.x = p.x;
    car.y = p.y;
    car.heading = l.centre_line.heading_at(s);
    car.speed = speed;
    car.length = 4.6;
    car.width = 1.9;
    return car;
  }

  bool must_wait(const WorldObject& car) const {
    const MapPoint ego = map_.lane(lane("south_in_0")).centre_line.points().back();
    return priority_traffic(map_, conflicts_, std::vector<WorldObject>{car}, ego);
  }

  RoadMap map_;
  std::vector<LaneIndex> conflicts_;
};

TEST_F(PriorityTrafficTest, ACarFromTheLeftWithinTheCriticalGapIsGivenWay) {
  ASSERT_FALSE(conflicts_.empty());
  // 31 m from the junction at 6 m/s: 5.2 s, less than 6.5 s (the corpus finding: the ego moved
  // off after its stop and was hit merging in front of it).
  EXPECT_TRUE(must_wait(car_on("west_in_0", 31, 6)));
  // 80 m at 6 m/s, 13 s away: the ego goes.
  EXPECT_FALSE(must_wait(car_on("west_in_0", 80, 6)));
  // Standing at the line: first come, first go.
  EXPECT_FALSE(must_wait(car_on("west_in_0", 10, 0)));
}

TEST_F(PriorityTrafficTest, ACarInsideTheJunctionOnACrossingLaneIsGivenWay) {
  EXPECT_TRUE(must_wait(car_on("west_east_0", 5, 0.5)));
}

TEST_F(PriorityTrafficTest, TrafficOnTheFarHalfDoesNotHoldARightTurn) {
  // East-bound traffic merges into the right turn's lane; west-bound traffic never meets it.
  EXPECT_FALSE(must_wait(car_on("east_in_0", 20, 10)));
}

}  // namespace
}  // namespace scenfuzz

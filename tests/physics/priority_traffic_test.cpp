// Giving way at a stop or yield sign (physics/ego/priority_traffic.hpp) on the built-in T-junction:
// the ego turning right out of the side road (south_in_0 into south_east_0) gives way to traffic
// from its left that merges into its lane, not to traffic on the far half of the road.
#include "physics/ego/priority_traffic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
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
        conflicts_(conflicting_lanes(map_, lane("south_east_0"))) {
    const std::vector<LaneIndex> own{lane("south_east_0")};
    points_ = conflict_points(map_, own, conflicts_);
  }

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
    return priority_traffic(map_, points_, std::vector<WorldObject>{car}, ego);
  }

  RoadMap map_;
  std::vector<LaneIndex> conflicts_;
  std::vector<ConflictPoint> points_;
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

TEST_F(PriorityTrafficTest, ACarInTheJunctionIsGivenWayUntilItIsPastTheEgosPath) {
  // On the through lane, before the point where the right turn joins it: given way.
  const double length = map_.lane(lane("west_east_0")).length();
  EXPECT_TRUE(must_wait(car_on("west_east_0", length - 1, 5)));
  // Past it, by more than a car's length: gone.
  const MapPoint end = map_.lane(lane("south_east_0")).centre_line.points().back();
  const double join = map_.lane(lane("west_east_0")).centre_line.project(end).s;
  ASSERT_LT(join + 6, length + 20);  // the join may lie on the next lane: then past the end
  if (join + 6 < length) {
    EXPECT_FALSE(must_wait(car_on("west_east_0", length - join - 6, 5)));
  } else {
    EXPECT_FALSE(must_wait(car_on("east_out_0", map_.lane(lane("east_out_0")).length() - 10, 5)));
  }
}

// A car on the ring `line` at `s` (taken round the ring), heading along it at `speed`.
WorldObject car_on_ring(const Polyline& line, double s, double speed) {
  const double length = line.length();
  s = std::fmod(s + length, length);
  WorldObject car;
  car.id = 1;
  car.kind = TraceActorKind::vehicle;
  const MapPoint p = line.point_at(s);
  car.x = p.x;
  car.y = p.y;
  car.heading = line.heading_at(s);
  car.speed = speed;
  car.length = 4.6;
  car.width = 1.9;
  return car;
}

// The roundabout's ring is one lane running round into itself: a car on it is given way only while
// it comes round towards the ego's entry, not once it has gone by (it waited for the whole ring).
TEST(PriorityTrafficRingTest, ACarOnTheRingIsGivenWayOnlyComingRoundToTheEntry) {
  const RoadMap map = build_road_map(generate_builtin_map("roundabout", {}));
  const LaneIndex entry = *map.find_lane("south_entry");
  const LaneIndex ring = *map.find_lane("ring_0");
  const std::vector<LaneIndex> conflicts = conflicting_lanes(map, entry);
  const std::vector<LaneIndex> own{entry};
  const std::vector<ConflictPoint> points = conflict_points(map, own, conflicts);
  double join = -1;
  for (const ConflictPoint& point : points)
    if (point.lane == ring) join = point.s;
  ASSERT_GE(join, 0);
  const Polyline& line = map.lane(ring).centre_line;
  auto car_at = [&](double s) { return std::vector<WorldObject>{car_on_ring(line, s, 6)}; };
  const MapPoint ego = map.lane(entry).centre_line.points().front();
  EXPECT_TRUE(priority_traffic(map, points, car_at(join - 20), ego));   // 3.3 s away
  EXPECT_FALSE(priority_traffic(map, points, car_at(join + 20), ego));  // gone by
  EXPECT_FALSE(priority_traffic(map, points, car_at(join - 50), ego));  // 8.3 s away
}

// The ego's whole way through the roundabout (entry, the ring twice as the route crosses its
// start, exit): the ring meets it only where the entry joins it. Paired with itself or with the
// exit that leaves it, the ring gave points on the ego's own way round, and the ego waited at its
// entry for a car driving away ahead of it (corpus finding roundabout_entry 001: 17 s at the line
// for a car 60 m round the ring); the other entries share the ring as successor but never meet it.
TEST(PriorityTrafficRingTest, TheEgosWayRoundMeetsTheRingOnlyWhereItsEntryJoins) {
  const RoadMap map = build_road_map(generate_builtin_map("roundabout", {}));
  const LaneIndex ring = *map.find_lane("ring_0");
  const std::vector<LaneIndex> own{*map.find_lane("south_entry"), ring, ring,
                                   *map.find_lane("north_exit")};
  std::vector<LaneIndex> conflicts;
  for (LaneIndex lane : own) {
    std::vector<LaneIndex> more = conflicting_lanes(map, lane);
    conflicts.insert(conflicts.end(), more.begin(), more.end());
  }
  std::sort(conflicts.begin(), conflicts.end());
  conflicts.erase(std::unique(conflicts.begin(), conflicts.end()), conflicts.end());
  ASSERT_TRUE(std::binary_search(conflicts.begin(), conflicts.end(), ring));
  const std::vector<ConflictPoint> points = conflict_points(map, own, conflicts);
  const Polyline& line = map.lane(ring).centre_line;
  const double join = line.project(map.lane(own[0]).centre_line.points().back()).s;
  std::vector<double> on_ring;
  for (const ConflictPoint& point : points) {
    if (point.lane == ring) on_ring.push_back(point.s);
    const std::string& id = map.lane(point.lane).id;
    EXPECT_TRUE(id.find("_entry") == std::string::npos || id == "south_entry")
        << "a point on " << id << " at " << point.s;
  }
  ASSERT_EQ(on_ring.size(), 1u);
  EXPECT_NEAR(on_ring[0], join, 1e-6);

  const double length = line.length();
  const MapPoint ego = map.lane(own[0]).centre_line.points().front();
  auto holds = [&](double s) {
    return priority_traffic(map, points, std::vector<WorldObject>{car_on_ring(line, s, 5)}, ego);
  };
  EXPECT_TRUE(holds(join - 20));   // 4 s from the join
  EXPECT_FALSE(holds(join + 30));  // ahead of the ego on its way round: a lead
  EXPECT_FALSE(holds(join - 60));  // 12 s away

  // Inside the junction (crossing_inside): a car on the ring holds the ego only within the reach
  // it is given, coming round to the join, or on it.
  const double reach = 4.6 + 5 * 5.0;
  EXPECT_TRUE(
      short_of_conflict(map, points, ring, std::fmod(join - 10 + length, length), 4.6, reach));
  EXPECT_TRUE(short_of_conflict(map, points, ring, join + 2, 4.6, reach));
  EXPECT_FALSE(
      short_of_conflict(map, points, ring, std::fmod(join - 60 + length, length), 4.6, reach));
  EXPECT_FALSE(short_of_conflict(map, points, ring, std::fmod(join + 30, length), 4.6, reach));
}

TEST_F(PriorityTrafficTest, TrafficOnTheFarHalfDoesNotHoldARightTurn) {
  // East-bound traffic merges into the right turn's lane; west-bound traffic never meets it.
  EXPECT_FALSE(must_wait(car_on("east_in_0", 20, 10)));
}

}  // namespace
}  // namespace scenfuzz

// The responsibility oracle at junctions no light decides, on hand-built traces
// (tests/oracle/hand_traces.hpp): priority to the right where neither approach has a light or a
// sign, a turning ego hit in its side by a car going straight, and a yield sign at a roundabout's
// entry whatever the angle at which the two meet.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "oracle/responsibility.hpp"
#include "physics/map/builtin_maps.hpp"
#include "tests/oracle/hand_traces.hpp"

namespace scenfuzz {
namespace {

using test::along_lanes;
using test::Distance;
using test::end_at_contact;
using test::judge;
using test::kCarLength;
using test::Motion;
using test::move;
using test::State;
using test::steady;
using test::stopping_at;
using test::two_actor_trace;

// The built-in crossroads without its lights: a junction no light or sign controls.
RoadMap uncontrolled_crossroads() {
  MapDescription description = generate_builtin_map("crossroads", {});
  description.traffic_lights.clear();
  return build_road_map(description);
}

const Lane& lane_named(const RoadMap& map, const std::string& id) {
  return map.lane(*map.find_lane(id));
}

// Straight through the junction: from `arm` in to the opposite arm out, on lane 1, starting
// `before` metres before the junction.
std::vector<std::string> straight_through(const std::string& from, const std::string& to) {
  return {from + "_in_1", from + "_" + to + "_1", to + "_out_1"};
}

// How far along `lanes` (from `s0` on the first) the centre comes nearest to `point`, to 1 cm.
double distance_to(const RoadMap& map, const std::vector<std::string>& lanes, double s0,
                   MapPoint point) {
  double best = 0;
  double nearest = 1e9;
  for (double d = 0; d < 300; d += 0.01) {
    const MapPoint p = test::along(map, lanes, s0, d);
    const double gap = std::hypot(p.x - point.x, p.y - point.y);
    if (gap < nearest) {
      nearest = gap;
      best = d;
    }
  }
  return best;
}

// Where the centre lines of two straight connectors cross.
MapPoint crossing_of(const RoadMap& map, const std::string& a, const std::string& b) {
  const MapPoint a0 = lane_named(map, a).centre_line.point_at(0);
  const MapPoint b0 = lane_named(map, b).centre_line.point_at(0);
  // One runs north-south (x fixed), the other west-east (y fixed).
  return std::abs(a0.x - lane_named(map, a).centre_line.point_at(5).x) < 1e-6
             ? MapPoint{a0.x, b0.y}
             : MapPoint{b0.x, a0.y};
}

constexpr double kBefore = 30;  // m before the junction where the straight runs start

double start_s(const RoadMap& map, const std::vector<std::string>& lanes) {
  return lane_named(map, lanes.front()).length() - kBefore;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

// ---- priority to the right ----

// The ego northwards from the south, the car westwards from the east (on the ego's right), both
// at 10 m/s; the car's centre crosses the ego's line `lead` seconds before the ego's centre would.
// With a lead of 0.45 s the ego's front meets the car's flank behind its centre.
Trace ego_north_car_west(const RoadMap& map, double lead, Distance ego_distance) {
  Trace trace = two_actor_trace(12);
  const std::vector<std::string> ego = straight_through("south", "north");
  const std::vector<std::string> car = straight_through("east", "west");
  const MapPoint cross = crossing_of(map, ego[1], car[1]);
  const double ego_to = distance_to(map, ego, start_s(map, ego), cross);
  const double car_to = distance_to(map, car, start_s(map, car), cross);
  double ego_at = 0;  // when the ego's centre reaches the crossing
  while (ego_distance(ego_at) < ego_to && ego_at < 11) ego_at += 1e-3;
  const double car_at = ego_at - lead;
  move(trace, map, trace.actors[0], along_lanes(map, ego, start_s(map, ego), ego_distance));
  move(trace, map, trace.actors[1], along_lanes(map, car, start_s(map, car), [=](double t) {
         return car_to + 10 * (t - car_at);
       }));
  return trace;
}

TEST(JunctionResponsibilityTest, TheTestsUncontrolledCrossroadsHasNoLightOrSign) {
  const RoadMap map = uncontrolled_crossroads();
  EXPECT_TRUE(map.traffic_lights().empty());
  EXPECT_TRUE(map.signs().empty());
  for (const Lane& lane : map.lanes())
    for (const LaneFeature& feature : lane.features)
      EXPECT_EQ(feature.kind, FeatureKind::crosswalk) << lane.id;
}

TEST(JunctionResponsibilityTest, EgoCrossingInFrontOfACarFromItsRightIsAtFault) {
  const RoadMap map = uncontrolled_crossroads();
  Trace trace = ego_north_car_west(map, 0.45, steady(10));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason,
            "did not give way to a car coming from its right at a junction without lights or "
            "signs: drove into it, in its path from 0.5 s before impact");
}

TEST(JunctionResponsibilityTest, ACarFromTheEgosLeftCrossingInFrontOfItIsAtFault) {
  const RoadMap map = uncontrolled_crossroads();
  // Roles swapped: the ego westwards from the east, the car northwards from the south (on the
  // ego's left) crossing just in front of it.
  Trace trace = ego_north_car_west(map, 0.45, steady(10));
  std::swap(trace.actors[0], trace.actors[1]);
  std::swap(trace.actors[0].name, trace.actors[1].name);
  std::swap(trace.actors[0].kind, trace.actors[1].kind);
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason,
            "the other did not give way to the ego coming from its right at a junction without "
            "lights or signs: drove into the ego, in its path from 0.5 s before impact");
}

TEST(JunctionResponsibilityTest, ACarFromTheRightThatCouldHaveStoppedAndDidNotSharesIt) {
  const RoadMap map = uncontrolled_crossroads();
  // The ego creeps into the junction and stops with its front in the car's lane; the car, from
  // the ego's right at 10 m/s, is 40 m away then (within its RSS safe distance of 63 m, but room
  // to stop at 4 m/s^2 after its 2 s response time) and never brakes.
  const std::vector<std::string> ego = straight_through("south", "north");
  const std::vector<std::string> car = straight_through("east", "west");
  const MapPoint cross = crossing_of(map, ego[1], car[1]);
  const double ego_to = distance_to(map, ego, start_s(map, ego), cross);
  // Its centre 1.5 m before the car's centre line: its front 0.8 m across it.
  const Distance ego_distance = stopping_at(6, 3, ego_to - 1.5);
  double rest = 0;
  while (ego_distance(rest + 0.01) > ego_distance(rest) + 1e-9) rest += 0.01;
  Trace trace = two_actor_trace(20);
  move(trace, map, trace.actors[0], along_lanes(map, ego, start_s(map, ego), ego_distance));
  const double car_to = distance_to(map, car, start_s(map, car), cross);
  // At the ego's rest the car's front is 40 m from the ego's near side.
  const double car_at_rest = car_to - 40 - kCarLength / 2 - 1.85 / 2;
  move(trace, map, trace.actors[1], along_lanes(map, car, start_s(map, car), [=](double t) {
         return car_at_rest + 10 * (t - rest);
       }));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::shared) << r.reason;
  EXPECT_TRUE(starts_with(r.reason,
                          "did not give way to a car coming from its right at a junction without "
                          "lights or signs: stopped in its path "))
      << r.reason;
  EXPECT_NE(r.reason.find(", and the other did not brake at 4 m/s^2"), std::string::npos)
      << r.reason;
}

TEST(JunctionResponsibilityTest, PriorityToTheRightIsNotTheRuleWhereLightsAre) {
  // The same crossing on the signalised crossroads, both lights green (no colours in the trace):
  // the car from the right came into the ego's path too close for it to stop.
  const RoadMap map = test::builtin("crossroads");
  Trace trace = ego_north_car_west(map, 0.45, steady(10));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.find("from its right"), std::string::npos) << r.reason;
}

// ---- a turning ego hit in its side ----

// The ego turns left from the south (south_in_1, south_west_1, west_out_1) at 5 m/s across the
// eastbound lanes; a car going straight eastwards on west_in_0 (y = -5.25) at 10 m/s, `gap`
// metres from the ego when the ego's body comes into its lane, never brakes and runs into the
// ego's left side.
Trace turning_ego_hit_in_its_side(const RoadMap& map, double gap) {
  Trace trace = two_actor_trace(16);
  const std::vector<std::string> turn = {"south_in_1", "south_west_1", "west_out_1"};
  const Motion ego = along_lanes(map, turn, lane_named(map, "south_in_1").length() - 20, steady(5));
  constexpr double kLaneY = -5.25;
  double t_in = 0;
  for (;; t_in += 1e-3) {
    const State s = ego(t_in);
    const double h = std::atan2(s.vy, s.vx);
    const double reach = kCarLength / 2 * std::abs(std::sin(h)) + 1.85 / 2 * std::abs(std::cos(h));
    if (s.y + reach >= kLaneY - 1.75) break;
  }
  move(trace, map, trace.actors[0], ego);
  const double x_at_in = ego(t_in).x - gap - kCarLength;
  move(trace, map, trace.actors[1], [=](double t) {
    return State{x_at_in + 10 * (t - t_in), kLaneY, 10, 0};
  });
  return trace;
}

TEST(JunctionResponsibilityTest, EgoTurningAcrossACarGoingStraightTooCloseIsAtFault) {
  const RoadMap map = test::builtin("crossroads");
  Trace trace = turning_ego_hit_in_its_side(map, 15);
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_GT(r.triage.impact_angle, 30) << "a side impact, not one along the road";
  EXPECT_LT(r.triage.impact_angle, 150) << "a side impact, not one along the road";
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_TRUE(starts_with(r.reason, "left the car no room to stop: came into its path "))
      << r.reason;
}

// The same ego turning left, and a car behind it in south_in_1 going straight on at 10 m/s
// that never brakes and runs into its rear as it turns away: a rear-end in the lanes both
// followed (the ego ahead the whole way), not a side impact the ego caused by turning.
TEST(JunctionResponsibilityTest, ACarGoingStraightIntoTheRearOfATurningEgoIsAtFault) {
  const RoadMap map = test::builtin("crossroads");
  Trace trace = two_actor_trace(16);
  const double s0 = lane_named(map, "south_in_1").length() - 20;
  move(trace, map, trace.actors[0],
       along_lanes(map, {"south_in_1", "south_west_1", "west_out_1"}, s0, steady(5)));
  // 30 m behind (centre to centre), 5 m/s faster: it reaches the ego in the junction.
  move(trace, map, trace.actors[1],
       along_lanes(map, straight_through("south", "north"), s0 - 30, steady(10)));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_TRUE(starts_with(r.reason, "hit from behind by a car")) << r.reason;
}

// ---- a roundabout's yield sign ----

// Along lanes each entered at an arc length of its own: (lane, s at which it is joined).
MapPoint along_joined(const RoadMap& map, const std::vector<std::pair<std::string, double>>& lanes,
                      double s0, double d) {
  double s = s0 + d;
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const Lane& lane = lane_named(map, lanes[i].first);
    const double from = i == 0 ? 0 : lanes[i].second;
    if (s + from <= lane.length() || i + 1 == lanes.size())
      return lane.centre_line.point_at(s + from);
    s -= lane.length() - from;
  }
  return {};
}

Motion along_joined_lanes(const RoadMap& map, std::vector<std::pair<std::string, double>> lanes,
                          double s0, Distance distance) {
  return [=, &map](double t) {
    constexpr double h = 1e-4;
    const MapPoint p = along_joined(map, lanes, s0, distance(t));
    const MapPoint a = along_joined(map, lanes, s0, distance(std::max(0.0, t - h)));
    const MapPoint b = along_joined(map, lanes, s0, distance(t + h));
    const double span = t + h - std::max(0.0, t - h);
    return State{p.x, p.y, (b.x - a.x) / span, (b.y - a.y) / span};
  };
}

// The ego from the south past yield_south into the ring; the car on ring_0 at `car_speed`,
// `behind` metres (centre to centre, along the ring) behind the point where the ego joins it when
// the ego's centre gets there.
struct RoundaboutEntry {
  RoadMap map = test::builtin("roundabout");
  Motion ego;
  Motion car;
  double join_time = 0;
};

RoundaboutEntry roundabout_entry(double behind, Distance ego_distance, double car_speed) {
  RoundaboutEntry entry;
  const RoadMap& map = entry.map;
  const Lane& entry_lane = lane_named(map, "south_entry");
  const double join = lane_named(map, "ring_0")
                          .centre_line.project(entry_lane.centre_line.point_at(entry_lane.length()))
                          .s;
  const double s0 = lane_named(map, "south_in_0").length() - 20;
  entry.ego = along_joined_lanes(map, {{"south_in_0", 0}, {"south_entry", 0}, {"ring_0", join}}, s0,
                                 ego_distance);
  while (ego_distance(entry.join_time) < 20 + entry_lane.length()) entry.join_time += 1e-3;
  const double t_join = entry.join_time;
  entry.car = along_joined_lanes(
      map, {{"ring_0", 0}}, 0, [=](double t) { return join - behind + car_speed * (t - t_join); });
  return entry;
}

TEST(JunctionResponsibilityTest, EgoEnteringARoundaboutJustInFrontOfACarOnTheRingIsAtFault) {
  // The ego enters at 3 m/s 6 m (centre to centre) in front of the car on the ring at 9 m/s,
  // which hits its rear at a shallow angle, the ego already on the ring (as in a search of
  // corpora/avunit/roundabout_entry.avu, 29 degrees there): it did not give way at the yield sign.
  const RoundaboutEntry entry = roundabout_entry(6, steady(3), 9);
  Trace trace = two_actor_trace(12);
  move(trace, entry.map, trace.actors[0], entry.ego);
  move(trace, entry.map, trace.actors[1], entry.car);
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, entry.map);
  EXPECT_LT(r.triage.impact_angle, 30) << "along the ring";
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_TRUE(starts_with(r.reason,
                          "did not give way at the yield sign yield_south to traffic with "
                          "priority: came into its path "))
      << r.reason;
}

TEST(JunctionResponsibilityTest, EgoThatEnteredTheRingWithRoomAndStoppedIsNotAtFault) {
  // The car 70 m behind when the ego joins (beyond its safe distance, about 50 m); the ego stops
  // 10 m into the ring and the car, never braking, runs into it.
  const RoundaboutEntry entry = roundabout_entry(
      70,
      [](double t) {
        const double cruise = 20 + 8.4 + 10 - 4.0 * 4.0 / (2 * 2);  // to the start of its braking
        if (t * 4 <= cruise) return 4 * t;
        const double tb = std::min(t - cruise / 4, 2.0);
        return cruise + 4 * tb - tb * tb;
      },
      8);
  Trace trace = two_actor_trace(25);
  move(trace, entry.map, trace.actors[0], entry.ego);
  move(trace, entry.map, trace.actors[1], entry.car);
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, entry.map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.find("did not give way"), std::string::npos) << r.reason;
}

}  // namespace
}  // namespace scenfuzz

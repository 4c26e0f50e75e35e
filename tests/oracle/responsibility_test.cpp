// The responsibility oracle on traces built by hand on built-in maps
// (tests/oracle/hand_traces.hpp): who is to blame for a collision with the ego, why in words, and
// the triage numbers.
#include "oracle/responsibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "oracle/ego_phase.hpp"
#include "oracle/failure_mode.hpp"
#include "oracle/implausible_motion.hpp"
#include "oracle/judge.hpp"
#include "oracle/rss_distances.hpp"
#include "physics/map/lane_queries.hpp"
#include "tests/oracle/hand_traces.hpp"

namespace scenfuzz {
namespace {

using test::along;
using test::along_lanes;
using test::builtin;
using test::Distance;
using test::end_at_contact;
using test::judge;
using test::kCarLength;
using test::kCarWidth;
using test::Motion;
using test::move;
using test::State;
using test::steady;
using test::stopping_at;
using test::two_actor_trace;

// The crossroads' lights as its plan shows them (north-south green 0-25 s, east-west red 0-30 s).
void add_crossroads_lights(Trace& trace) {
  for (const char* id : {"light_north", "light_south"}) {
    TraceLight light{id, {}};
    for (double t : trace.time)
      light.colour.push_back(t < 25   ? SignalColour::green
                             : t < 28 ? SignalColour::yellow
                                      : SignalColour::red);
    trace.lights.push_back(light);
  }
  for (const char* id : {"light_east", "light_west"})
    trace.lights.push_back(
        {id, std::vector<SignalColour>(trace.sample_count(), SignalColour::red)});
}

Motion cruise_east(double x0, double y, double speed) {
  return [=](double t) { return State{x0 + speed * t, y, speed, 0}; };
}

Motion standing(double x, double y) {
  return [=](double) { return State{x, y, 0, 0}; };
}

// Along +x from x0 at v0; from `from` braking at `decel` to a stop.
Motion braking_east(double x0, double y, double v0, double from, double decel) {
  return [=](double t) {
    if (t <= from) return State{x0 + v0 * t, y, v0, 0};
    const double tb = std::min(t - from, v0 / decel);
    return State{x0 + v0 * from + v0 * tb - decel * tb * tb / 2, y, v0 - decel * tb, 0};
  };
}

// Along +x at `speed` from x0, moving sideways from y0 by `shift` (sign: direction) from `from`:
// lateral acceleration `a` up to `v_lat`, then steady.
Motion sidestep_east(double x0, double y0, double speed, double from, double a, double v_lat,
                     double shift) {
  return [=](double t) {
    const double dir = shift >= 0 ? 1 : -1;
    double lateral = 0;
    double v = 0;
    if (t > from) {
      const double ramp = v_lat / a;
      const double u = t - from;
      if (u <= ramp) {
        lateral = a * u * u / 2;
        v = a * u;
      } else {
        lateral = a * ramp * ramp / 2 + v_lat * (u - ramp);
        v = v_lat;
      }
      if (lateral >= std::abs(shift)) {
        lateral = std::abs(shift);
        v = 0;
      }
    }
    return State{x0 + speed * t, y0 + dir * lateral, speed, dir * v};
  };
}

// On `straight`, east_1 runs along y = -1.75 and east_0 along y = -5.25.
constexpr double kEast1 = -1.75;
constexpr double kEast0 = -5.25;

TEST(ResponsibilityTest, EgoStoppedAtARedLightAndRearEndedIsNotAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(10);
  add_crossroads_lights(trace);
  // west_in_1 along y = -1.75 eastwards, its stop line at x = -16; the ego's front 0.5 m before.
  const double ego_x = -16.5 - kCarLength / 2;
  move(trace, map, trace.actors[0], standing(ego_x, -1.75));
  move(trace, map, trace.actors[1], cruise_east(ego_x - 60, -1.75, 10));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other);
  EXPECT_EQ(r.reason, "hit from behind while stopped at a red light");
  EXPECT_TRUE(r.triage.ego_stationary);
  EXPECT_NEAR(r.triage.relative_speed, 10, 1e-9);
  EXPECT_NEAR(r.triage.impact_angle, 0, 1e-9);
  EXPECT_FALSE(r.triage.entry) << "the ego was hit from behind: nothing came into its path";
}

TEST(ResponsibilityTest, EgoRearEndingACarThatBrakesGentlyAfterASafeGapIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(20);
  // 55 m apart at 15 m/s: more than RSS's 45.5 m, so the gap is safe until the lead brakes.
  const double gap = 55 + kCarLength;
  ASSERT_GT(55, rss_safe_longitudinal_same(15, 15, 1, RssParameters{}));
  move(trace, map, trace.actors[0], cruise_east(10, kEast1, 15));
  move(trace, map, trace.actors[1], braking_east(10 + gap, kEast1, 15, 2, 3));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("ran into a car: braked at 0 m/s^2 where RSS owes 4 m/s^2", 0), 0u)
      << r.reason;
  EXPECT_NEAR(r.triage.ego_speed, 15, 1e-9);
  EXPECT_FALSE(r.triage.ego_stationary);
  ASSERT_TRUE(r.triage.entry);
  EXPECT_TRUE(r.triage.entry->from_start) << "the car ahead was in the ego's lane all along";
}

TEST(ResponsibilityTest, ACarRearEndingTheEgoThatBrakesGentlyIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(20);
  // The npc 90 m behind at 15 m/s (RSS's safe distance with rho 2 s is 83.4 m), never braking;
  // the ego brakes at 1 m/s^2 from 2 s, well within RSS's 8 m/s^2, and is still moving at impact.
  ASSERT_LT(rss_safe_longitudinal_same(15, 15, 2, RssParameters{}), 90);
  move(trace, map, trace.actors[0], braking_east(100 + kCarLength, kEast1, 15, 2, 1));
  move(trace, map, trace.actors[1], cruise_east(10, kEast1, 15));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason, "hit from behind by a car that braked at 0 m/s^2 where RSS owes 4 m/s^2");
  EXPECT_FALSE(r.danger_began);  // a danger along the lane: the phase is read at impact
  EXPECT_FALSE(r.triage.ego_stationary);
  EXPECT_FALSE(r.triage.ego_braking_at_limit);
}

TEST(ResponsibilityTest, ACutterEnteringTheEgosLaneJustBeforeImpactIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(12);
  move(trace, map, trace.actors[0], cruise_east(10, kEast1, 12));
  // Ahead on east_0 at 10 m/s; from 2.5 s it moves left into east_1.
  move(trace, map, trace.actors[1], sidestep_east(24.7, kEast0, 10, 2.5, 1.5, 1.5, 3.5));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason,
            "the car entered the ego's lane 1.1 s before impact, less than the ego's stopping "
            "time at 8 m/s^2 (1.5 s)");
  ASSERT_TRUE(r.triage.entry);
  EXPECT_FALSE(r.triage.entry->from_start);
  EXPECT_NEAR(trace.time.back() - r.triage.entry->time, 1.1, 0.05);
  EXPECT_GT(r.triage.entry->gap, 0);
  EXPECT_NEAR(r.triage.entry->closing_speed, 2, 0.1);
  EXPECT_NEAR(r.triage.entry->time_to_collision,
              r.triage.entry->gap / r.triage.entry->closing_speed, 1e-9);
  EXPECT_NEAR(r.triage.entry->required_deceleration, 4 / (2 * r.triage.entry->gap), 0.2);
}

// West-bound along y = 1.75 (west_1) from x0 at v0; from `from` braking at `decel` to a stop.
Motion braking_west(double x0, double v0, double from, double decel) {
  return [=](double t) {
    const State east = braking_east(-x0, 1.75, v0, from, decel)(t);
    return State{-east.x, east.y, -east.vx, 0};
  };
}

// East-bound at `speed` from x0 on east_1, pulling out into west_1 from `from` over `over` seconds
// (a half-cosine, as a driver steers).
Motion pulling_out_east(double x0, double speed, double from, double over) {
  return [=](double t) {
    const double u = std::clamp((t - from) / over, 0.0, 1.0);
    const double rate =
        u > 0 && u < 1 ? 1.75 * std::numbers::pi / over * std::sin(std::numbers::pi * u) : 0;
    return State{x0 + speed * t, kEast1 + 1.75 * (1 - std::cos(std::numbers::pi * u)), speed, rate};
  };
}

// An overtaker pulls out of east_1 into the ego's west_1 and comes at it head-on; the ego, in its
// own lane, brakes to a stop 1 s before the impact. The overtaker brought its path to the ego: the
// ego did not stop in its way.
TEST(ResponsibilityTest, EgoStoppedInItsOwnLaneAndHitByAnOvertakerIsNotAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10);
  move(trace, map, trace.actors[0], braking_west(200, 8, 2, 3), std::numbers::pi);
  move(trace, map, trace.actors[1], pulling_out_east(100, 12, 1, 3));
  end_at_contact(trace);
  ASSERT_LT(trace.actors[0].speed.back(), 0.01) << "the ego stands at the impact";
  ASSERT_GT(trace.time.back(), 5.5) << "the ego stood for a while";
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.find("no room to stop"), std::string::npos) << r.reason;
}

TEST(ResponsibilityTest, EgoChangingLaneIntoACarAlongsideIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10);
  move(trace, map, trace.actors[0], sidestep_east(10, kEast1, 10, 1, 1, 1, -3.5));
  move(trace, map, trace.actors[1], cruise_east(12, kEast0, 10));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason, "changed lane into a car alongside");
}

TEST(ResponsibilityTest, EgoChangingLaneInFrontOfAFasterCarSaysHowFarAheadItWas) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10);
  // The ego at 10 m/s moves from east_1 into east_0 15.4 m ahead of a car there at 16 m/s.
  move(trace, map, trace.actors[0], sidestep_east(30, kEast1, 10, 0.5, 1, 1, -3.5));
  move(trace, map, trace.actors[1], cruise_east(10, kEast0, 16));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("changed lane ", 0), 0u) << r.reason;
  EXPECT_NE(r.reason.find(" m in front of a car "), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find("alongside"), std::string::npos) << r.reason;
}

TEST(ResponsibilityTest, ACarThatNeverBrakesLongAfterTheEgoChangedLaneInFrontSharesIt) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(20);
  // The ego at 12 m/s moves into east_0 25 m ahead of a car there at 14 m/s, finishing after
  // 4 s; the car closes at 2 m/s for another 6 s without ever braking.
  move(trace, map, trace.actors[0], sidestep_east(35, kEast1, 12, 0.5, 1, 1, -3.5));
  move(trace, map, trace.actors[1], cruise_east(10, kEast0, 14));
  end_at_contact(trace);
  ASSERT_GT(trace.time.back(), 9.0);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::shared) << r.reason;
  EXPECT_EQ(r.reason.rfind("changed lane ", 0), 0u) << r.reason;
  EXPECT_NE(r.reason.find("hit from behind by a car that braked at 0 m/s^2"), std::string::npos)
      << r.reason;
  // The failure is the lane change, seconds before the impact in the lane: its phase is read
  // when the danger began, so a run whose impact comes sooner is the same mode.
  ASSERT_TRUE(r.danger_began);
  EXPECT_LT(trace.time[*r.danger_began], 4.0);
  EXPECT_EQ(ego_phase_at(trace, map, *r.danger_began), EgoPhase::leaving_lane);
  EXPECT_EQ(ego_phase_at(trace, map, trace.sample_count() - 1), EgoPhase::in_lane);
  SpecVerdict verdict;
  verdict.name = kNoCollisionSpec;
  verdict.robustness = -0.5;
  verdict.time = trace.time.back();
  EXPECT_EQ(describe_failure(trace, map, verdict).phase, EgoPhase::in_lane);
  EXPECT_EQ(describe_failure(trace, map, verdict, r.danger_began).phase, EgoPhase::leaving_lane);
}

TEST(ResponsibilityTest, BothChangingLaneIntoEachOtherShareIt) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10);
  move(trace, map, trace.actors[0], sidestep_east(10, kEast1, 10, 1, 1, 1, -3.5));
  move(trace, map, trace.actors[1], sidestep_east(12, kEast0, 10, 1, 1, 1, 3.5));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::shared) << r.reason;
  EXPECT_EQ(r.reason, "changed lane into a car alongside, and the car moved sideways into the ego");
  EXPECT_TRUE(ego_responsible(r.responsibility));
}

TEST(ResponsibilityTest, EgoRunningARedLightIntoCrossingTrafficIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(8);
  add_crossroads_lights(trace);
  // The ego eastwards on west_in_1 (red), the npc northwards on south_in_1 (green); their paths
  // cross at (1.75, -1.75), the ego there at 3 s, the npc 0.2 s later.
  move(trace, map, trace.actors[0], cruise_east(1.75 - 36, -1.75, 12));
  move(trace, map, trace.actors[1], [](double t) {
    return State{1.75, -1.75 - 10 * 3.2 + 10 * t, 0, 10};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("ran a red light (light_west) ", 0), 0u) << r.reason;
  EXPECT_NEAR(r.triage.impact_angle, 90, 1e-9);
}

TEST(ResponsibilityTest, ARedLightRunnerHittingTheEgoIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(8);
  add_crossroads_lights(trace);
  // Now the npc comes from the west on red, the ego from the south on green, just ahead of it.
  move(trace, map, trace.actors[1], cruise_east(1.75 - 36, -1.75, 12));
  move(trace, map, trace.actors[0], [](double t) {
    return State{1.75, -1.75 - 10 * 2.8 + 10 * t, 0, 10};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.rfind("the other ran a red light (light_west) ", 0), 0u) << r.reason;
}

TEST(ResponsibilityTest, APedestrianWalkingIntoTheSideOfAStationaryEgoIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::pedestrian);
  move(trace, map, trace.actors[0], standing(50, kEast1));
  move(trace, map, trace.actors[1], [](double t) { return State{50, -8 + 1.4 * t, 0, 1.4}; });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason, "a pedestrian walked into the right of the stopped ego");
}

TEST(ResponsibilityTest, APedestrianRunningIntoTheFrontCornerOfAMovingEgoIsNamedByTheSideHit) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::pedestrian);
  // A child runs north out of east_0 at 3 m/s into the front corner of an ego passing at 5 m/s in
  // east_1: in the ego's path for less than 0.1 s before the contact.
  move(trace, map, trace.actors[0], cruise_east(0, kEast1, 5));
  move(trace, map, trace.actors[1], [](double t) { return State{7.9, -6 + 3 * t, 0, 3}; });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason, "a pedestrian walked into the front of the moving ego");
}

TEST(ResponsibilityTest, EgoHittingAPedestrianItHadRoomToStopForIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::pedestrian);
  // The pedestrian is in the ego's lane from 1 s, 40 m ahead of an ego at 10 m/s that never
  // brakes (RSS's safe distance: 34.5 m).
  move(trace, map, trace.actors[0], cruise_east(0, kEast1, 10));
  move(trace, map, trace.actors[1], [](double t) {
    const double y = std::min(-4.5 + 2 * t, -1.75);
    return State{60, y, 0, y < -1.75 ? 2.0 : 0.0};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("hit a pedestrian that entered its path", 0), 0u) << r.reason;
}

TEST(ResponsibilityTest, APedestrianSteppingInTooCloseAndAnEgoThatNeverBrakesShareIt) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::pedestrian);
  // The pedestrian walks from east_0 into east_1 at 0.5 m/s about 50 m ahead of the ego at
  // 15 m/s (less than its safe distance); the ego never brakes in the 3.5 s it has.
  move(trace, map, trace.actors[0], cruise_east(0, kEast1, 15));
  move(trace, map, trace.actors[1], [](double t) { return State{100, -5 + 0.5 * t, 0, 0.5}; });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::shared) << r.reason;
  EXPECT_NE(r.reason.find(", and the ego did not brake at 4 m/s^2"), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find("the ego the ego"), std::string::npos) << r.reason;
}

TEST(ResponsibilityTest, DrivingIntoAnObstacleIsTheEgos) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::obstacle);
  move(trace, map, trace.actors[0], cruise_east(0, kEast1, 10));
  move(trace, map, trace.actors[1], standing(40, kEast1));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego);
  EXPECT_EQ(r.reason, "drove into a stationary obstacle (npc)");
}

TEST(ResponsibilityTest, EveryCollisionOfTheEgoIsJudgedAndOthersAreNot) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10, TraceActorKind::obstacle);
  move(trace, map, trace.actors[0], cruise_east(0, kEast1, 10));
  move(trace, map, trace.actors[1], standing(40, kEast1));
  end_at_contact(trace);
  trace.collisions.push_back({trace.time.back(), 1, 2, {}, BodySide::front, BodySide::rear});
  const std::vector<CollisionResponsibility> all =
      ego_collision_responsibilities(trace, map, RssParameters{});
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].collision, 0u);
  EXPECT_EQ(all[0].other, 1u);
}

TEST(ResponsibilityTest, TheCollisionOracleCountsOnlyCollisionsTheEgoIsResponsibleFor) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(10);
  add_crossroads_lights(trace);
  const double ego_x = -16.5 - kCarLength / 2;
  move(trace, map, trace.actors[0], standing(ego_x, -1.75));
  move(trace, map, trace.actors[1], cruise_east(ego_x - 60, -1.75, 10));
  end_at_contact(trace);
  const ScenarioTemplate no_specs;
  const SourceFile file("inline.avu", "");
  const std::vector<SpecVerdict> excused = judge_trace(no_specs, {}, trace, map, file);
  ASSERT_EQ(excused.size(), 1u);
  EXPECT_FALSE(excused[0].violated()) << "rear-ended at a red light: not the ego's fault";
  EXPECT_GE(excused[0].robustness, 0);
  EXPECT_LT(excused[0].robustness, 0.6) << "the clearance just before the contact";
  EXPECT_EQ(excused[0].atom_text,
            "the ego and npc (not counted: a collision not the ego's fault with npc)");
  JudgeOptions all;
  all.all_collisions = true;
  const std::vector<SpecVerdict> counted = judge_trace(no_specs, {}, trace, map, file, all);
  EXPECT_TRUE(counted[0].violated());
  EXPECT_EQ(counted[0].atom_text, "the ego and npc");
}

// ---- priority at a junction: the crossroads, the ego turning left from the south ----

// The ego's left turn: 20 m before the end of south_in_1, through south_west_1 into west_out_1.
const std::vector<std::string> kLeftTurn = {"south_in_1", "south_west_1", "west_out_1"};
constexpr double kBeforeJunction = 20;

Motion ego_turning_left(const RoadMap& map, Distance distance) {
  const double s0 = map.lane(*map.find_lane("south_in_1")).length() - kBeforeJunction;
  return along_lanes(map, kLeftTurn, s0, distance);
}

// When the ego, moving by `distance`, has its centre on x (first time, to 1 ms).
double time_at_x(const RoadMap& map, const Distance& distance, double x) {
  const Motion ego = ego_turning_left(map, distance);
  for (double t = 0; t < 30; t += 1e-3)
    if (ego(t).x <= x) return t;
  return 30;
}

// Oncoming southwards on north_in_1 and straight through (x = -1.75) at `speed`, its front at
// y_front at time `at`.
Motion oncoming(double speed, double y_front, double at) {
  return [=](double t) {
    return State{-1.75, y_front + kCarLength / 2 + speed * (at - t), 0, -speed};
  };
}

// Lights with light_south (the ego's) and light_north (the oncoming's) in the given colours, the
// crossing road red.
void add_lights(Trace& trace, SignalColour south, SignalColour north) {
  trace.lights.push_back({"light_south", std::vector<SignalColour>(trace.sample_count(), south)});
  trace.lights.push_back({"light_north", std::vector<SignalColour>(trace.sample_count(), north)});
  for (const char* id : {"light_east", "light_west"})
    trace.lights.push_back(
        {id, std::vector<SignalColour>(trace.sample_count(), SignalColour::red)});
}

// As `oncoming`, but braking at `decel` from time `from` on.
Motion oncoming_braking(double speed, double y_front, double at, double from, double decel) {
  const auto driven = [=](double t) {
    if (t <= from) return speed * t;
    const double tb = std::min(t - from, speed / decel);
    return speed * from + speed * tb - decel * tb * tb / 2;
  };
  return [=](double t) {
    const double v = t <= from ? speed : std::max(0.0, speed - decel * (t - from));
    return State{-1.75, y_front + kCarLength / 2 + driven(at) - driven(t), 0, -v};
  };
}

bool says_zero_seconds(const std::string& reason) {
  return reason.find(" 0 s before impact") != std::string::npos;
}

TEST(ResponsibilityTest, EgoTurningLeftIntoAnOncomingCarGoingStraightIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(12);
  add_lights(trace, SignalColour::green, SignalColour::green);
  const Distance ego = steady(6);
  const double t = time_at_x(map, ego, -1.75);
  move(trace, map, trace.actors[0], ego_turning_left(map, ego));
  move(trace, map, trace.actors[1], oncoming(12, ego_turning_left(map, ego)(t).y, t));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("turned left without giving way to an oncoming car going straight: "
                           "came into its path ",
                           0),
            0u)
      << r.reason;
  EXPECT_FALSE(says_zero_seconds(r.reason)) << r.reason;
}

// How far the ego's left turn at the crossroads runs until its centre is 0.5 m into the oncoming
// lane (x = -1.25), to the centimetre.
double distance_into_oncoming_lane(const RoadMap& map) {
  const Motion turning = ego_turning_left(map, steady(1));
  for (double d = 0;; d += 0.01)
    if (turning(d).x <= -1.25) return d;
}

TEST(ResponsibilityTest, EgoStoppingInTheOncomingLaneMidTurnJustBeforeACarComesIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(20);
  add_lights(trace, SignalColour::green, SignalColour::green);
  // The ego stops with its centre 0.5 m into the oncoming lane; the car, braking at 4 m/s^2 from
  // 1 s before, hits it 1.5 s later.
  const double stop_at = distance_into_oncoming_lane(map);
  const Distance ego = stopping_at(6, 3, stop_at);
  const double rest = time_at_x(map, ego, -1.25 + 1e-6);
  const Motion ego_motion = ego_turning_left(map, ego);
  move(trace, map, trace.actors[0], ego_motion);
  move(trace, map, trace.actors[1],
       oncoming_braking(12, ego_motion(rest + 1.5).y + 2, rest + 1.5, rest - 1, 4));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_TRUE(r.triage.ego_stationary);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_NE(r.reason.find("stopped in its path "), std::string::npos) << r.reason;
  EXPECT_EQ(r.reason.find("while stopped"), std::string::npos) << r.reason;
}

TEST(ResponsibilityTest, EgoStoppedInTheOncomingLaneLongBeforeACarRamsItIsNotAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(30);
  add_lights(trace, SignalColour::green, SignalColour::green);
  const double stop_at = distance_into_oncoming_lane(map);
  const Distance ego = stopping_at(6, 3, stop_at);
  const Motion ego_motion = ego_turning_left(map, ego);
  // Standing from about 6 s; the car arrives at 25 s, 200 m away then: room to stop.
  move(trace, map, trace.actors[0], ego_motion);
  move(trace, map, trace.actors[1], oncoming(10, ego_motion(25).y + 2, 25));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
}

TEST(ResponsibilityTest, EgoWaitingBeforeTheJunctionAndHitIsNotAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(10);
  add_lights(trace, SignalColour::green, SignalColour::green);
  // The ego stands on south_in_1 1 m before its stop line (y = -16); a car cutting the corner
  // from the north-west drives into its front.
  const double ego_y = -17 - kCarLength / 2;
  move(trace, map, trace.actors[0], standing(1.75, ego_y), std::numbers::pi / 2);
  move(trace, map, trace.actors[1], [=](double t) {
    return State{1.75 - 8 + 1 * t, ego_y + kCarLength + 40 - 5 * t, 1, -5};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.rfind("hit on its front", 0), 0u) << r.reason;
}

TEST(ResponsibilityTest, AnOncomingCarRunningARedLightIntoTheTurningEgoIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(12);
  add_lights(trace, SignalColour::green, SignalColour::red);
  const Distance ego = steady(6);
  const double t = time_at_x(map, ego, -1.75);
  move(trace, map, trace.actors[0], ego_turning_left(map, ego));
  move(trace, map, trace.actors[1], oncoming(12, ego_turning_left(map, ego)(t).y, t));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.rfind("the other ran a red light (light_north) ", 0), 0u) << r.reason;
}

TEST(ResponsibilityTest, EgoTurningRightIntoAPedestrianOnTheCrosswalkIsAtFault) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(20, TraceActorKind::pedestrian);
  add_lights(trace, SignalColour::green, SignalColour::green);
  // The ego turns right from south_in_0 into east_out_0 (y = -5.25) at 5 m/s; a pedestrian walks
  // north along x = 13 across crosswalk_east (x 11 to 15, y -10 to 10) and meets its front.
  const double s0 = map.lane(*map.find_lane("south_in_0")).length() - kBeforeJunction;
  const Motion ego = along_lanes(map, {"south_in_0", "south_east_0", "east_out_0"}, s0, steady(5));
  double t = 0;
  while (ego(t).x < 13 - kCarLength / 2 - 0.3) t += 1e-3;
  move(trace, map, trace.actors[0], ego);
  move(trace, map, trace.actors[1], [=](double u) {
    return State{13, -5.25 - 0.5 + 1.4 * (u - t), 0, 1.4};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason.rfind("turned right into a pedestrian on the crosswalk crosswalk_east without "
                           "giving way: it was on the crosswalk ",
                           0),
            0u)
      << r.reason;
}

// `distance` along `lanes` from `s0`, `offset(t)` to the left of the centre line.
Motion offset_along_lanes(const RoadMap& map, std::vector<std::string> lanes, double s0,
                          Distance distance, std::function<double(double)> offset) {
  const auto at = [=, &map](double t) {
    const double d = distance(t);
    // The direction of a chord 1 m long: smooth across the polyline's vertices.
    const MapPoint p = along(map, lanes, s0, d);
    const MapPoint back = along(map, lanes, s0, d - 0.5);
    const MapPoint q = along(map, lanes, s0, d + 0.5);
    const double h = std::atan2(q.y - back.y, q.x - back.x);
    return MapPoint{p.x - std::sin(h) * offset(t), p.y + std::cos(h) * offset(t)};
  };
  return [=](double t) {
    constexpr double h = 1e-4;
    const MapPoint p = at(t);
    const MapPoint a = at(std::max(0.0, t - h));
    const MapPoint b = at(t + h);
    const double span = t + h - std::max(0.0, t - h);
    return State{p.x, p.y, (b.x - a.x) / span, (b.y - a.y) / span};
  };
}

TEST(ResponsibilityTest, EgoDriftingIntoACarAlongsideInATurnHasNotChangedLane) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(10);
  add_lights(trace, SignalColour::green, SignalColour::green);
  // Both round the left turn south_west_1 at 5 m/s, the car 3 m inside the ego; from 0.5 s the
  // ego drifts left at up to 1 m/s.
  const std::vector<std::string> turn = {"south_west_1", "west_out_1"};
  move(trace, map, trace.actors[0], offset_along_lanes(map, turn, 0, steady(5), [](double t) {
         const double u = std::max(0.0, t - 0.5);
         return u < 0.5 ? u * u : 0.25 + (u - 0.5);
       }));
  move(trace, map, trace.actors[1],
       offset_along_lanes(map, turn, 0, steady(5), [](double) { return 3.0; }));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
  EXPECT_EQ(r.reason, "turned left into a car alongside");
}

TEST(ResponsibilityTest, ACarHittingTheEgosSideIsNeverSaidToEnterItsPathAtImpact) {
  const RoadMap map = builtin("crossroads");
  Trace trace = two_actor_trace(8);
  add_lights(trace, SignalColour::green, SignalColour::green);
  for (TraceLight& light : trace.lights)
    std::fill(light.colour.begin(), light.colour.end(), SignalColour::green);
  // The ego eastwards through the junction at 10 m/s, its centre at x = 0 at 3 s; a car
  // northwards at 5 m/s meets its right side there, 1 m ahead of its centre.
  move(trace, map, trace.actors[0], cruise_east(-30, -1.75, 10));
  const double y_contact = -1.75 - kCarWidth / 2 - kCarLength / 2 - 0.01;
  move(trace, map, trace.actors[1], [=](double t) {
    return State{1, y_contact + 5 * (t - 3), 0, 5};
  });
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_FALSE(says_zero_seconds(r.reason)) << r.reason;
  EXPECT_EQ(r.reason.find("the car entered the ego's path"), std::string::npos) << r.reason;
  EXPECT_FALSE(r.triage.entry) << "touching the ego's flank at impact is no entry into its path";
}

// A car ahead that stops harder than any car can (20 m/s^2) just before the ego runs into it: the
// ego could not have anticipated it, so the collision is the other's, with the reason.
TEST(ResponsibilityTest, ACarThatMovedAsNoCarCanJustBeforeImpactIsAtFault) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(10);
  move(trace, map, trace.actors[0], cruise_east(10, kEast1, 12));
  move(trace, map, trace.actors[1], braking_east(10 + 20 + kCarLength, kEast1, 12, 2, 20));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  EXPECT_EQ(r.responsibility, Responsibility::other) << r.reason;
  EXPECT_EQ(r.reason.rfind("the car moved as no road user can: accelerating or braking harder "
                           "than its class can",
                           0),
            0u)
      << r.reason;
}

// The same impossible stop long before the ego arrives (it then stood still for seconds): the ego
// had all that time to see a standing car, so running into it stays the ego's fault.
TEST(ResponsibilityTest, MotionAsNoCarCanLongBeforeImpactDoesNotExcuseTheEgo) {
  const RoadMap map = builtin("straight");
  Trace trace = two_actor_trace(14);
  move(trace, map, trace.actors[0], cruise_east(10, kEast1, 12));
  move(trace, map, trace.actors[1], braking_east(10 + 140, kEast1, 10, 0.5, 20));
  end_at_contact(trace);
  const CollisionResponsibility r = judge(trace, map);
  ASSERT_GT(trace.collisions.at(0).time, 0.5 + kImplausibleMotionWindow + 1);
  EXPECT_EQ(r.responsibility, Responsibility::ego) << r.reason;
}

TEST(RssParametersTest, DefaultsAreAdRssLibsAndNamesOverrideThem) {
  const RssParameters defaults;
  EXPECT_EQ(defaults.response_time_ego, 1);
  EXPECT_EQ(defaults.response_time_other, 2);
  EXPECT_EQ(defaults.accel_max, 3.5);
  EXPECT_EQ(defaults.brake_min, 4);
  EXPECT_EQ(defaults.brake_max, 8);
  EXPECT_EQ(defaults.brake_min_correct, 3);
  EXPECT_EQ(defaults.lateral_accel_max, 0.2);
  EXPECT_EQ(defaults.lateral_brake_min, 0.8);
  EXPECT_EQ(defaults.lateral_fluctuation_margin, 0.1);
  const RssParametersOrError parsed =
      parse_rss_parameters({"brake_min=3", "response_time_ego=0.5"});
  ASSERT_TRUE(parsed.parameters) << parsed.error;
  EXPECT_EQ(parsed.parameters->brake_min, 3);
  EXPECT_EQ(parsed.parameters->response_time_ego, 0.5);
  EXPECT_EQ(parse_rss_parameters({"brake_mid=3"}).error,
            "'brake_mid' is not an RSS parameter (one of response_time_ego, response_time_other, "
            "accel_max, brake_min, brake_max, brake_min_correct, lateral_accel_max, "
            "lateral_brake_min, lateral_fluctuation_margin)");
  EXPECT_EQ(parse_rss_parameters({"brake_min=0"}).error,
            "'brake_min=0': the value must be a number > 0");
  EXPECT_EQ(parse_rss_parameters({"brake_min"}).error, "'brake_min' is not NAME=VALUE");
  EXPECT_TRUE(parse_rss_parameters({"lateral_fluctuation_margin=0"}).parameters);
}

TEST(RssDistancesTest, SafeDistancesAreThePapers) {
  const RssParameters rss;
  // 10 m/s behind 10 m/s, rho 1: 10 + 1.75 + 13.5^2/8 - 100/16.
  EXPECT_NEAR(rss_safe_longitudinal_same(10, 10, 1, rss), 10 + 1.75 + 13.5 * 13.5 / 8 - 6.25,
              1e-12);
  EXPECT_EQ(rss_safe_longitudinal_same(0, 30, 1, rss), 0) << "never negative";
  // Neither moving sideways: the margin plus what each may drift within its response time.
  const double drift_ego = 0.5 * 0.2 * 1 + 0.2 * 0.2 / 1.6;
  const double drift_other = 0.5 * 0.2 * 4 + 0.4 * 0.4 / 1.6;
  EXPECT_NEAR(rss_safe_lateral(0, 1, 0, 2, rss), 0.1 + drift_ego + drift_other, 1e-12);
  // Moving apart fast enough: only the margin.
  EXPECT_NEAR(rss_safe_lateral(-3, 1, -3, 2, rss), 0.1, 1e-12);
}

}  // namespace
}  // namespace scenfuzz

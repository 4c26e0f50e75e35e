// Avoidability on traces built by hand: a crossing seen coming three seconds ahead is avoidable
// by braking; a car that darts out, one that rear-ends a standing ego and one that keeps coming
// head-on at a braking ego are not.
#include "oracle/collision_avoidability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "physics/trace/trace_footprint.hpp"
#include "tests/oracle/trace_fixtures.hpp"

namespace scenfuzz {
namespace {

using test::empty_trace;
using test::still_actor;

constexpr double kCarLength = 4.6, kCarWidth = 1.85;
constexpr double kNorth = std::numbers::pi / 2;

// A car whose centre is at place(t) with `heading`, its speed the rate it moves there.
TraceActor car(const Trace& trace, const std::string& name, TraceActorKind kind,
               const std::function<MapPoint(double)>& place, double heading) {
  TraceActor actor =
      still_actor(trace, name, kind, BodyShape::box, kCarLength, kCarWidth, 0, 0, heading);
  for (std::size_t i = 0; i < trace.sample_count(); ++i) {
    const MapPoint p = place(trace.time[i]), q = place(trace.time[i] + trace.dt);
    actor.x[i] = p.x;
    actor.y[i] = p.y;
    actor.speed[i] = std::hypot(q.x - p.x, q.y - p.y) / trace.dt;
  }
  return actor;
}

using Path = std::function<MapPoint(double)>;

// Records the ego's first contact with actor 1, as the simulation would, and returns its index.
std::size_t record_first_contact(Trace& trace) {
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (signed_distance(footprint_at(trace, kEgo, i), footprint_at(trace, 1, i)) <= 0) {
      trace.collisions.push_back({trace.time[i], kEgo, 1, {trace.actors[1].x[i], 0}});
      return trace.collisions.size() - 1;
    }
  ADD_FAILURE() << "the hand-made trace has no contact";
  return 0;
}

// The ego and car1 driving `ego` and `other` for `seconds`, sampled every 0.1 s, with their first
// contact recorded as collision 0.
Trace meeting(double seconds, const Path& ego, double ego_heading, const Path& other,
              double other_heading) {
  Trace trace = empty_trace(static_cast<std::size_t>(std::lround(seconds * 10)) + 1, 0.1);
  trace.actors.push_back(car(trace, "ego", TraceActorKind::ego, ego, ego_heading));
  trace.actors.push_back(car(trace, "car1", TraceActorKind::vehicle, other, other_heading));
  record_first_contact(trace);
  return trace;
}

MapPoint east_at_15(double t) { return {15 * t, 0}; }

// The ego east along y = 0 at 15 m/s from x = 0; car1 north along x = 60 at 12.5 m/s, level with
// the ego's lane at 4 s, and on beyond it (as a replay that ignores the impact goes on).
Trace crossing() {
  return meeting(
      8, east_at_15, 0,
      [](double t) {
        return MapPoint{60, -50 + 12.5 * t};
      },
      kNorth);
}

TEST(CollisionAvoidability, ACrossingSeenThreeSecondsAheadIsAvoidableByBraking) {
  const Trace trace = crossing();
  const double impact = trace.collisions[0].time;
  const Avoidability a = collision_avoidability(trace, 0, RssParameters{});
  EXPECT_TRUE(a.avoidable) << a.reason;
  // Both carry on at constant speed: the conflict shows kConflictHorizon before the impact.
  EXPECT_NEAR(a.conflict_time, impact - kConflictHorizon, 0.11);
  EXPECT_DOUBLE_EQ(a.brake_time, a.conflict_time + 1.0);
  EXPECT_GT(a.clearance, 0);
  EXPECT_GT(a.stop_short, 5);
  EXPECT_NE(a.reason.find("stays"), std::string::npos) << a.reason;
}

TEST(CollisionAvoidability, ASlowerResponseThanTheWarningMakesTheSameCrossingUnavoidable) {
  RssParameters slow;
  slow.response_time_ego = 3.5;
  const Avoidability a = collision_avoidability(crossing(), 0, slow);
  EXPECT_FALSE(a.avoidable);
  EXPECT_EQ(a.clearance, 0);
  EXPECT_NE(a.reason.find("response time"), std::string::npos) << a.reason;
}

TEST(CollisionAvoidability, ACarDartingOutHalfASecondAheadIsUnavoidable) {
  // Standing at the kerb until 3.5 s, then across the ego's lane at 12 m/s.
  const Trace trace = meeting(
      8, east_at_15, 0,
      [](double t) {
        return MapPoint{60, -6 + (t < 3.5 ? 0.0 : 12 * (t - 3.5))};
      },
      kNorth);
  const Avoidability a = collision_avoidability(trace, 0, RssParameters{});
  EXPECT_FALSE(a.avoidable);
  EXPECT_GE(a.conflict_time, 3.35);
  EXPECT_NE(a.reason.find("response time"), std::string::npos) << a.reason;
}

TEST(CollisionAvoidability, BrakingCannotSaveAStandingEgoFromACarBehind) {
  const Trace trace = meeting(
      6,
      [](double) {
        return MapPoint{0, 0};
      },
      0,
      [](double t) {
        return MapPoint{-60 + 15 * t, 0};
      },
      0);
  const Avoidability a = collision_avoidability(trace, 0, RssParameters{});
  EXPECT_FALSE(a.avoidable);
  EXPECT_NE(a.reason.find("still meets"), std::string::npos) << a.reason;
  EXPECT_EQ(a.stop_short, 0);
}

TEST(CollisionAvoidability, BrakingCannotSaveTheEgoFromACarThatKeepsComingHeadOn) {
  const Trace trace = meeting(
      8,
      [](double t) {
        return MapPoint{10 * t, 0};
      },
      0,
      [](double t) {
        return MapPoint{120 - 15 * t, 0};
      },
      std::numbers::pi);
  const Avoidability a = collision_avoidability(trace, 0, RssParameters{});
  EXPECT_FALSE(a.avoidable);
  EXPECT_NE(a.reason.find("still meets"), std::string::npos) << a.reason;
  // It did brake to a stop short of the impact: the other came on regardless.
  EXPECT_GT(a.stop_short, 0);
}

}  // namespace
}  // namespace scenfuzz

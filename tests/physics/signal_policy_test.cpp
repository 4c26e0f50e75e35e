// The law-abiding driver's signal rules as plain functions: the weather's lights, brake lights,
// the high beam dipped for vehicles ahead and oncoming, hazard lights after an emergency stop or a
// collision, a short horn in an emergency, the indicators' notice before a manoeuvre and during an
// overtaking plan, and the signal names traces use.
#include "physics/ego/signal_policy.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "map_fixtures.hpp"
#include "physics/actors/vehicle_signal_names.hpp"
#include "physics/ego/ego_indicators.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/simulation/plugin_observation.hpp"

namespace scenfuzz {
namespace {

namespace sig = vehicle_signal;

SignalWeather weather_of(Conditions conditions) { return signal_weather(conditions, {}); }

bool has(VehicleSignals signals, VehicleSignals bit) { return (signals & bit) != 0; }

TEST(SignalPolicyTest, LowBeamsFromDuskToDawnNotAtNoon) {
  EXPECT_FALSE(
      has(weather_signals(weather_of({.darkness = darkness_at(12 * 3600)})), sig::low_beam));
  EXPECT_TRUE(
      has(weather_signals(weather_of({.darkness = darkness_at(23 * 3600)})), sig::low_beam));
  EXPECT_TRUE(
      has(weather_signals(weather_of({.darkness = darkness_at(18.5 * 3600)})), sig::low_beam));
}

TEST(SignalPolicyTest, FogLightsAndLowBeamsInFogWipersInRainAndSnow) {
  const VehicleSignals fog = weather_signals(weather_of({.fog = 0.5}));  // 58 m visibility
  EXPECT_TRUE(has(fog, sig::fog_lights));
  EXPECT_TRUE(has(fog, sig::low_beam));
  EXPECT_FALSE(has(fog, sig::wipers));
  const VehicleSignals thin = weather_signals(weather_of({.fog = 0.1}));  // 124 m
  EXPECT_FALSE(has(thin, sig::fog_lights));
  const VehicleSignals rain = weather_signals(weather_of({.rain = 0.5}));
  EXPECT_TRUE(has(rain, sig::wipers));
  EXPECT_FALSE(has(rain, sig::fog_lights));
  EXPECT_FALSE(has(rain, sig::low_beam));
  EXPECT_TRUE(has(weather_signals(weather_of({.snow = 0.3})), sig::wipers));
  EXPECT_EQ(weather_signals(weather_of({})), 0);
}

TEST(SignalPolicyTest, BrakeLightsWhenDeceleratingOrHeldStanding) {
  EXPECT_EQ(brake_lights(-0.6, 10, true), sig::brake_lights);
  EXPECT_EQ(brake_lights(-0.4, 10, true), 0);
  EXPECT_EQ(brake_lights(0, 0, true), sig::brake_lights);
  EXPECT_EQ(brake_lights(0, 0, false), 0) << "parked";
}

WorldObject vehicle_at(double x, double y, double heading) {
  WorldObject object;
  object.id = 1;
  object.x = x;
  object.y = y;
  object.heading = heading;
  object.length = 4.5;
  object.width = 1.8;
  return object;
}

TEST(SignalPolicyTest, HighBeamOnlyAtNightWithNoVehicleNearAheadOrOncoming) {
  const KinematicState ego{};  // at the origin heading east
  const SignalWeather night = weather_of({.darkness = 1});
  EXPECT_TRUE(high_beam_allowed(ego, {}, night));
  EXPECT_FALSE(high_beam_allowed(ego, {}, weather_of({})));
  EXPECT_FALSE(high_beam_allowed(ego, {}, weather_of({.fog = 0.5, .darkness = 1})));
  const std::vector<WorldObject> oncoming_near{vehicle_at(140, 3.5, 3.14159)};
  const std::vector<WorldObject> oncoming_far{vehicle_at(160, 3.5, 3.14159)};
  const std::vector<WorldObject> ahead_near{vehicle_at(90, 0, 0)};
  const std::vector<WorldObject> ahead_far{vehicle_at(110, 0, 0)};
  const std::vector<WorldObject> behind{vehicle_at(-20, 0, 0)};
  EXPECT_FALSE(high_beam_allowed(ego, oncoming_near, night));
  EXPECT_TRUE(high_beam_allowed(ego, oncoming_far, night));
  EXPECT_FALSE(high_beam_allowed(ego, ahead_near, night));
  EXPECT_TRUE(high_beam_allowed(ego, ahead_far, night));
  EXPECT_TRUE(high_beam_allowed(ego, behind, night));
}

EgoSignalInput moving(double time, double speed, double acceleration, bool emergency) {
  EgoSignalInput input;
  input.time = time;
  input.ego.speed = speed;
  input.acceleration = acceleration;
  input.emergency = emergency;
  return input;
}

TEST(SignalPolicyTest, HazardLightsAfterAnEmergencyStopUntilItDrivesOn) {
  const SignalWeather day = weather_of({});
  SignalMemory memory;
  EXPECT_FALSE(has(ego_signals(moving(0, 10, 0, false), day, memory), sig::hazard_lights));
  const VehicleSignals braking = ego_signals(moving(1, 10, -8, true), day, memory);
  EXPECT_TRUE(has(braking, sig::horn)) << "an object about to be in its path at speed";
  EXPECT_TRUE(has(braking, sig::brake_lights));
  EXPECT_FALSE(has(braking, sig::hazard_lights));
  // The time-to-collision test lapses as it slows; the brake goes on.
  EXPECT_FALSE(has(ego_signals(moving(1.5, 5, -8, false), day, memory), sig::horn))
      << "the horn sounds briefly";
  EXPECT_TRUE(has(ego_signals(moving(2.5, 0, -8, false), day, memory), sig::hazard_lights));
  EXPECT_TRUE(has(ego_signals(moving(8, 1, 1, false), day, memory), sig::hazard_lights));
  EXPECT_FALSE(has(ego_signals(moving(9, 3, 1, false), day, memory), sig::hazard_lights));
}

TEST(SignalPolicyTest, NoHazardLightsAfterAnOrdinaryStop) {
  SignalMemory memory;
  const SignalWeather day = weather_of({});
  ego_signals(moving(0, 5, -2, false), day, memory);
  const VehicleSignals stopped = ego_signals(moving(2, 0, -2, false), day, memory);
  EXPECT_FALSE(has(stopped, sig::hazard_lights));
  EXPECT_FALSE(has(stopped, sig::horn));
  EXPECT_TRUE(has(stopped, sig::brake_lights));
}

TEST(SignalPolicyTest, HazardLightsWhenStandingAfterACollisionReplaceTheIndicator) {
  SignalMemory memory;
  EgoSignalInput input = moving(3, 0, 0, false);
  input.collided = true;
  input.indicator = sig::left_indicator;
  const VehicleSignals signals = ego_signals(input, weather_of({}), memory);
  EXPECT_TRUE(has(signals, sig::hazard_lights));
  EXPECT_FALSE(has(signals, sig::left_indicator));
}

TEST(SignalPolicyTest, IndicatesFromThreeSecondsOrThirtyMetresBeforeUntilTheEnd) {
  const std::vector<IndicationStretch> stretches{{100, 130, sig::right_indicator},
                                                 {200, 220, sig::left_indicator}};
  IndicationCursor cursor;
  EXPECT_EQ(indicator_at(stretches, 60, 5, cursor), 0);  // 40 m before, 30 m notice
  EXPECT_EQ(indicator_at(stretches, 71, 5, cursor), sig::right_indicator);
  EXPECT_EQ(indicator_at(stretches, 129, 5, cursor), sig::right_indicator);
  EXPECT_EQ(indicator_at(stretches, 131, 20, cursor), 0);  // 69 m before, 60 m notice at 20 m/s
  EXPECT_EQ(indicator_at(stretches, 141, 20, cursor), sig::left_indicator);
  EXPECT_EQ(indicator_at(stretches, 221, 20, cursor), 0);
}

// law57 asks for the indicator wherever the oracle's `direction` says left, from 100 m before
// the junction (measured from the front bumper): a slow car must not wait for its 30 m notice.
TEST(SignalPolicyTest, AJunctionTurnIndicatesFromItsLeastNotice) {
  const std::vector<IndicationStretch> stretches{{200, 230, sig::left_indicator, kTurnNotice}};
  IndicationCursor cursor;
  EXPECT_EQ(indicator_at(stretches, 200 - kTurnNotice - 1, 2, cursor), 0);
  EXPECT_EQ(indicator_at(stretches, 200 - kTurnNotice + 1, 2, cursor), sig::left_indicator);
  EXPECT_EQ(indicator_at(stretches, 231, 2, cursor), 0);
}

TEST(SignalPolicyTest, AnIndicatorOnStaysOnWhenTheVehicleSlows) {
  const std::vector<IndicationStretch> stretches{{300, 330, sig::left_indicator}};
  IndicationCursor cursor;
  EXPECT_EQ(indicator_at(stretches, 100, 20, cursor), 0);  // far: quiet until 90 m before
  EXPECT_EQ(indicator_at(stretches, 245, 20, cursor), sig::left_indicator);  // 60 m notice
  EXPECT_EQ(indicator_at(stretches, 255, 2, cursor), sig::left_indicator)
      << "slowed for the turn: a 30 m notice now, but it stays on";
  EXPECT_EQ(indicator_at(stretches, 331, 5, cursor), 0);
}

LaneIndex lane_named(const RoadMap& map, const std::string& id) {
  for (LaneIndex k = 0; k < map.lanes().size(); ++k)
    if (map.lane(k).id == id) return k;
  ADD_FAILURE() << "no lane " << id;
  return 0;
}

TEST(RouteIndicationsTest, ALaneChangeLeftAndALeftTurnThroughAJunction) {
  const RoadMap map = build_road_map(test::two_lane_road());
  const LaneRoute turning{{{lane_named(map, "a"), 0, 100},
                           {lane_named(map, "a_next"), 0, 50},
                           {lane_named(map, "turn"), 0, 50}},
                          200,
                          0};
  const auto turn = route_indications(map, turning.segments, lane_change_stretches(map, turning));
  ASSERT_EQ(turn.size(), 1u);
  EXPECT_DOUBLE_EQ(turn[0].begin, 150);
  EXPECT_DOUBLE_EQ(turn[0].end, 200);
  EXPECT_EQ(turn[0].indicator, sig::left_indicator);

  const LaneRoute changing{
      {{lane_named(map, "a"), 0, 60}, {lane_named(map, "b"), 60, 100}}, 100, 1};
  const auto change =
      route_indications(map, changing.segments, lane_change_stretches(map, changing));
  ASSERT_EQ(change.size(), 1u);
  EXPECT_EQ(change[0].indicator, sig::left_indicator);
  EXPECT_LT(change[0].begin, change[0].end);

  const LaneRoute straight{
      {{lane_named(map, "b"), 0, 100}, {lane_named(map, "b_next"), 0, 50}}, 150, 0};
  EXPECT_TRUE(
      route_indications(map, straight.segments, lane_change_stretches(map, straight)).empty());
}

// Through a roundabout only the exit is indicated, from about the exit before: going straight on
// (south to north) it indicated right from 110 m before the entry all the way round.
TEST(RouteIndicationsTest, ARoundaboutIndicatesOnlyItsExit) {
  const RoadMap map = build_road_map(generate_builtin_map("roundabout", {}));
  for (const char* out : {"north_out_0", "west_out_0", "east_out_0"}) {
    const auto route = find_route(map, LanePosition{lane_named(map, "south_in_0"), 10, 0},
                                  LanePosition{lane_named(map, out), 20, 0});
    ASSERT_TRUE(route) << out;
    const auto stretches =
        route_indications(map, route->segments, lane_change_stretches(map, *route));
    ASSERT_EQ(stretches.size(), 1u) << out;
    // The route distance where it leaves the ring: the start of the exit connector.
    double exit_start = 0, ring_end = 0;
    for (const RouteSegment& segment : route->segments) {
      const std::string& id = map.lane(segment.lane).id;
      if (id.find("_exit") != std::string::npos) break;
      exit_start += segment.s_end - segment.s_begin;
      if (id == "ring_0") ring_end = exit_start;
    }
    EXPECT_DOUBLE_EQ(stretches[0].begin, exit_start) << out;
    EXPECT_DOUBLE_EQ(stretches[0].begin, ring_end) << out;
    EXPECT_EQ(stretches[0].indicator, sig::right_indicator) << out;
    EXPECT_EQ(stretches[0].least_notice, 0) << out;
    // Off on the way in (40 m before the entry, at 10 m/s); on 25 m before the exit (the first
    // exit's notice reaches back over the entry, as a right turn's should).
    IndicationCursor cursor;
    EXPECT_EQ(look_for_indication(stretches, 60, 10, cursor, IndicationNotice{}), 0) << out;
    IndicationCursor later;
    EXPECT_EQ(look_for_indication(stretches, exit_start - 25, 6, later, IndicationNotice{}),
              sig::right_indicator)
        << out;
  }
}

TEST(SignalPolicyTest, OvertakingIndicatesOutThenBack) {
  OvertakePlan plan;
  plan.active = true;
  plan.offset = 3.5;
  plan.out_begin = 10;
  plan.out_end = 40;
  EXPECT_EQ(overtake_indicator(plan, 20), sig::left_indicator);
  EXPECT_EQ(overtake_indicator(plan, 60), 0) << "level with what it passes";
  plan.back_begin = 80;
  plan.back_end = 110;
  EXPECT_EQ(overtake_indicator(plan, 90), sig::right_indicator);
  plan.active = false;
  EXPECT_EQ(overtake_indicator(plan, 90), 0);
}

TEST(SignalPolicyTest, SignalNamesRoundTrip) {
  EXPECT_EQ(vehicle_signal_list(0), "");
  EXPECT_EQ(vehicle_signal_list(sig::left_indicator | sig::low_beam), "left_indicator|low_beam");
  EXPECT_EQ(vehicle_signal_name(sig::brake_lights), "brake_lights");
  EXPECT_EQ(vehicle_signal_name(3), "");
  for (VehicleSignals s = 0; s <= sig::all; ++s)
    ASSERT_EQ(parse_vehicle_signal_list(vehicle_signal_list(s)), s);
  EXPECT_FALSE(parse_vehicle_signal_list("left_indicator|"));
  EXPECT_FALSE(parse_vehicle_signal_list("blinker"));
}

TEST(SignalPolicyTest, TheObservationCarriesPerceivedVehiclesSignalsOnly) {
  const RoadMap map = build_road_map(test::two_lane_road());
  RouteTracker route(map, {}, {}, 13.9);
  std::vector<WorldObject> seen{vehicle_at(20, 0, 0), vehicle_at(40, 0, 0)};
  seen[0].signals = sig::left_indicator | sig::brake_lights;
  seen[1].id = 2;
  seen[1].kind = TraceActorKind::pedestrian;
  seen[1].signals = sig::horn;  // nonsense for a pedestrian: not passed on
  scenfuzz_observation observation{};
  observation.object_signals[5] = 99;  // left over from an earlier step
  fill_observation(route, KinematicState{}, 0, seen, {}, false, observation);
  ASSERT_EQ(observation.object_count, 2u);
  EXPECT_EQ(observation.object_signals[0],
            SCENFUZZ_SIGNAL_LEFT_INDICATOR | SCENFUZZ_SIGNAL_BRAKE_LIGHTS);
  EXPECT_EQ(observation.object_signals[1], 0u);
  EXPECT_EQ(observation.object_signals[5], 0u);
}

}  // namespace
}  // namespace scenfuzz

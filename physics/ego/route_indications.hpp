// Where a vehicle following a lane route shows its indicators: the stretches of its route where
// it changes lane or turns at a junction, each with the indicator it asks for, and which
// indicator is on at a point of the route. A law-abiding driver indicates from a notice before
// the manoeuvre (3 s of travel or 30 m, whichever is longer; before a junction turn at least
// kTurnNotice) until it ends. Shared by the ego
// (signal_policy.hpp) and the lane-following NPCs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "physics/actors/trajectory.hpp"
#include "physics/actors/vehicle_signals.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// A manoeuvre on a route, in route distance (the arc length of the route's path).
struct IndicationStretch {
  double begin = 0;
  double end = 0;
  VehicleSignals indicator = 0;  // vehicle_signal::left_indicator or right_indicator
  double least_notice = 0;       // m: the notice is at least this, whatever the speed
};

// A junction turn's least notice (m before the junction's entry, from the vehicle's centre):
// Apollo's planner signals a turn when the junction begins within 100 m of the front bumper,
// which is where the oracle's `direction` turns left or right (docs/oracle.md) and law57 asks
// for the indicator; 10 m more covers half the length of the longest vehicle.
inline constexpr double kTurnNotice = 110;

// How long before a manoeuvre the indicator goes on: the longer of the two.
struct IndicationNotice {
  double distance = 30;  // m
  double time = 3;       // s of travel at the current speed
};

// The route's lane changes (`lane_changes`, as lane_change_stretches gives them) and its turns
// through junctions (a junction lane's turn, or where the map gives none, its heading turning by
// more than 30 degrees), sorted by begin. A U-turn indicates left. Through a roundabout only the
// exit is indicated, from the notice before the lane leaving the ring: nothing on the way in,
// whichever exit is taken, as right-hand traffic rules have it (left-hand: the exit's side too).
std::vector<IndicationStretch> route_indications(const RoadMap& map,
                                                 std::span<const RouteSegment> segments,
                                                 std::span<const LaneChangeStretch> lane_changes);

// Which way a junction lane turns: left_indicator, right_indicator, or 0 straight on.
VehicleSignals junction_lane_indicator(const RoadMap& map, LaneIndex lane);

// Remembers the first stretch that has not ended, so that a vehicle moving on along its route
// looks at one or two stretches a step; whether its indicator is on for it (once on, it stays
// on until the stretch ends, even if the vehicle slows and the notice shrinks); and up to where
// nothing can be on (the next stretch is farther than its notice at any speed a vehicle has).
struct IndicationCursor {
  std::size_t next = 0;
  bool on = false;
  double quiet_until = -1e300;
};

// The fastest any vehicle drives (m/s), for IndicationCursor::quiet_until.
inline constexpr double kFastestVehicle = 70;

// Looks at the stretches (indicator_at, when not quiet).
VehicleSignals look_for_indication(std::span<const IndicationStretch> stretches, double progress,
                                   double speed, IndicationCursor& cursor,
                                   const IndicationNotice& notice);

// The indicator on at route distance `progress` driving at `speed`: the first stretch not yet
// ended, from its notice before it (at the speed when it came on) to its end; 0 when none.
// `progress` must not go backwards between calls with the same cursor.
inline VehicleSignals indicator_at(std::span<const IndicationStretch> stretches, double progress,
                                   double speed, IndicationCursor& cursor,
                                   const IndicationNotice& notice = {}) {
  if (progress < cursor.quiet_until) return 0;  // most steps of most vehicles
  return look_for_indication(stretches, progress, speed, cursor, notice);
}

}  // namespace scenfuzz

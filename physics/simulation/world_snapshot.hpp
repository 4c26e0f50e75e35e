// The world at one step as manoeuvre triggers and manoeuvre phases see it: every actor's true
// state and lane (by actor id, the ego first, as in the trace), the lights, the clock. Views into
// the simulation loop's own arrays, valid for that step only.
#pragma once

#include <cstdint>
#include <span>

#include "physics/actors/kinematics.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/actor_grid.hpp"
#include "physics/simulation/lane_occupancy.hpp"
#include "physics/simulation/lane_tracker.hpp"
#include "physics/simulation/observed_manoeuvre.hpp"
#include "physics/simulation/predicted_points.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct WorldSnapshot {
  const RoadMap* map = nullptr;
  double time = 0;                                // s since the start
  std::span<const KinematicState> states;         // by actor id
  std::span<const LaneFix> lanes;                 // by actor id
  std::span<const ObservedManoeuvre> manoeuvres;  // by actor id
  std::span<const double> lengths;                // body length by actor id
  std::span<const SignalColour> lights;           // by index into RoadMap::traffic_lights()
  // When each actor's first manoeuvre phase began (s), NaN while it has not (or it has none).
  std::span<const double> sequence_starts;
  bool collided = false;                  // some collision happened at or before `time`
  std::span<const double> widths;         // body width by actor id
  std::span<const TraceActorKind> kinds;  // by actor id
  // By actor id, 1 while the actor is on the map (TraceActor::present_from/until); empty when
  // every actor is, as without background traffic. An absent actor's state is a parked pose that
  // nobody may see.
  std::span<const std::uint8_t> present;
  // Where each actor will be within prediction_time, and the cosines and sines of their headings,
  // for the lane followers' scans; null when not computed (followers then compute their own).
  const PointPredictor* predictions = nullptr;
  double prediction_time = 0;  // s
  // The actors' positions and predicted points on a grid, for the lane followers' scans; null
  // when not built (followers then look at every actor).
  const ActorGrid* grid = nullptr;
  // The actors by the lanes they occupy, for the lane followers' scans; null when not built.
  const LaneOccupancy* occupancy = nullptr;
  // By actor id, when each vehicle arrived at the junction it is at (JunctionArrivals), NaN at
  // none; empty when not computed (followers then order nobody by arrival).
  std::span<const double> junction_arrivals;
};

inline bool present_in(const WorldSnapshot& world, std::uint32_t actor) {
  return world.present.empty() || world.present[actor] != 0;
}

}  // namespace scenfuzz

// How fast a driver may go on what it can see: never faster than it can stop, after its reaction
// time, within its sight distance (the range at which its perception finds vehicles and
// pedestrians in the scenario's weather and light). Fog at night shrinks that range to tens of
// metres, and with it the speed (docs/simulation.md, "The reference driver").
#pragma once

#include "physics/ego/perception.hpp"

namespace scenfuzz {

struct SightSettings {
  // s from something coming into range to braking: perception's latency (0.1 s), the first
  // detections near the range's edge, where misses are likely, and the decision; about the 0.67 s
  // thinking time of the UK Highway Code's stopping distances.
  double reaction_time = 0.75;
  // m/s^2 it plans to stop with; 0: its vehicle's maximum. Full braking, as the Highway Code's
  // stopping distances assume, keeps the limit above 29 m/s in clear daylight (perception's
  // 80 m pedestrian range), so that clear-weather driving is unchanged; planning with the
  // comfortable 2.5 m/s^2 would cap clear daylight at 17.7 m/s.
  double deceleration = 0;
  double margin = 1.0;  // m left between the front bumper and what it stopped for
  // m between the centre of an object at the edge of the range and its nearest point: small, so
  // that a pedestrian or a short obstacle is covered too (cars are longer).
  double object_extent = 0.5;
  double minimum_speed = 1.5;  // m/s: with almost no sight a driver still creeps on
};

// m covered while reacting and then braking at `deceleration` (> 0) from `speed` to a stop.
double stopping_distance(double speed, double reaction_time, double deceleration);

// The greatest speed whose stopping distance is at most `distance` (0 for distance <= 0): the
// positive root of v t + v^2 / (2 b) = d.
double speed_to_stop_within(double distance, double reaction_time, double deceleration);

// The sight distance: the shorter of perception's vehicle and pedestrian ranges (the driver must
// stop for either).
double sight_distance(const PerceptionSettings& sensing);

// The speed limit the sight distance sets for a driver whose front bumper is `front_overhang`
// ahead of its centre (perception measures ranges from the centre) and who brakes at
// `deceleration`: it stops `margin` short of an object that comes into range dead ahead.
double sight_speed(const PerceptionSettings& sensing, double front_overhang, double deceleration,
                   const SightSettings& settings = {});

}  // namespace scenfuzz

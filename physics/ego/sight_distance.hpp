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
  // The poorer the sight, the more margin a careful driver keeps: it plans to stop with a
  // deceleration from the comfortable one (sight nearly gone) to its vehicle's maximum (its
  // clear-daylight sight), b = comfortable + (maximum - comfortable) f^2, f the fraction of its
  // clear sight it still has. Clear daylight keeps full braking, so the limit stays above 29 m/s
  // there (perception's 80 m pedestrian range) and clear-weather driving is unchanged; at night
  // in rain (25 m) it plans with about 3 m/s^2 and drives at about 9 m/s, not 13.6.
  double comfortable_deceleration = 2.5;  // m/s^2
  double clear_sight = 80;                // m: sight_distance of perception's default settings
  double margin = 1.0;                    // m left between the front bumper and what it stopped for
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

// The deceleration a driver whose vehicle brakes at most at `max_deceleration` plans to stop
// with at this sight (the rule above).
double planned_deceleration(const PerceptionSettings& sensing, double max_deceleration,
                            const SightSettings& settings = {});

// The speed limit the sight distance sets for a driver whose front bumper is `front_overhang`
// ahead of its centre (perception measures ranges from the centre) and whose vehicle brakes at
// most at `max_deceleration`: planning with planned_deceleration, it stops `margin` short of an
// object that comes into range dead ahead.
double sight_speed(const PerceptionSettings& sensing, double front_overhang,
                   double max_deceleration, const SightSettings& settings = {});

}  // namespace scenfuzz

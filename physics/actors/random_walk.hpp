// A pedestrian's wandering: a seeded random walk of straight legs that stays near where it began,
// for pedestrians a scenario places without a route.
#pragma once

#include <cstdint>

#include "physics/map/map_point.hpp"
#include "physics/map/polyline.hpp"

namespace scenfuzz {

// From `start` (heading first along start.heading), legs of 2 to 5 s of walking at `speed`, each
// turning up to 60 degrees either way from the last; a leg that would leave the disc of `radius`
// around the start turns back towards it instead and is cut short at the disc's edge. At least
// speed * duration metres long. The same arguments give the same path on every platform.
// Throws std::invalid_argument unless speed, duration and radius are positive and finite (and
// the walk would need fewer than a million legs).
Polyline random_walk_path(MapPose start, double speed, double duration, double radius,
                          std::uint64_t seed);

}  // namespace scenfuzz

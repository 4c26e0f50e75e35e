// scenest's `streetLightOn` on a simulated trace. LawBreaker means "the road is lit" (law58 asks
// for high beams at night only where it is not) but records the constant 0; no map we read marks
// street lighting either, so we derive it from what the maps do say: a town street (its lane's
// speed limit is at most kLitStreetSpeedLimit) has street lights, and they are on between dusk
// and dawn, when the simulation's darkness is above 0. docs/oracle.md compares the two.
// Private to the oracle.
#pragma once

#include <vector>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// m/s: 60 km/h, the fastest town streets; roads built for more are highways and rural roads.
inline constexpr double kLitStreetSpeedLimit = 60 / 3.6;

// Whether a street lamp lights the ego at each sample (1 or 0), for a run that starts at
// `start_time_of_day` (s since midnight).
std::vector<double> street_lights_on(const Trace& trace, const RoadMap& map,
                                     double start_time_of_day);

}  // namespace scenfuzz

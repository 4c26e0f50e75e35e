// What a plugin driver is told: its configuration at the start of a run, and each step's
// observation in the C ABI's plain structs (physics/ego/ego_plugin.h).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "physics/ego/ego_plugin.h"
#include "physics/ego/perception.hpp"
#include "physics/ego/route_tracker.hpp"
#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {

scenfuzz_ego_config plugin_config(const SimulationSetup& setup, double dt, std::uint64_t seed);

// Fills `observation` for time t: the ego's state, the perceived objects nearest first, the route
// ahead every 2 m, the distance to the target, the next traffic light and stop sign.
void fill_observation(const RouteTracker& route, const KinematicState& ego, double t,
                      std::span<const WorldObject> perceived, std::span<const SignalColour> lights,
                      bool has_target, scenfuzz_observation& observation);

}  // namespace scenfuzz

// A cheap check before any simulation: bodies that already overlap at t = 0. Such a point of the
// search space is infeasible (the scenario would start in a collision), and the search rejects
// it without spending a simulation on it.
#pragma once

#include <optional>
#include <string>

#include "physics/simulation/scenario_setup.hpp"

namespace scenfuzz {

// The first overlapping pair, as "npc1 overlaps ego at t = 0 (by 0.8 m)", or nullopt. Every pair
// of the ego, the vehicles, the pedestrians and the obstacles counts, except obstacle with
// obstacle (scenery may be piled up). Touching is not overlapping.
std::optional<std::string> initial_overlap(const SimulationSetup& setup);

}  // namespace scenfuzz

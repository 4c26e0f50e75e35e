// Internal to outline_map.cpp: fixed-time traffic lights on a drawn road network's junction
// (outline_map.hpp, rule 10). Each road through the junction gets one light, `<light>_<road>`,
// over its lanes coming in, with a stop line where they end at the junction; the two roads take
// turns as the built-in crossroads' two directions do (signal_plans.hpp), the light's road
// showing `colour` at the start of that phase.
#pragma once

#include <string>
#include <vector>

#include "physics/map/map_description.hpp"
#include "physics/map/outline_connectors.hpp"

namespace scenfuzz::outline {

// Adds the lights of junction `arms` to `map` (whose lanes the arms name). `road` must be one of
// the arms' roads.
void add_signals(MapDescription& map, const std::string& light, const std::string& road,
                 SignalColour colour, const std::vector<JunctionArm>& arms);

}  // namespace scenfuzz::outline

// A reconstruction written as a concrete AVUnit scenario: the accident's map, its trees, and each
// vehicle's reconstructed run. The ego (the victim, or the vehicle --ego names) starts as it did
// and is sent where it was going (past the scene, in the lane it crashed in), to be driven by the
// system under test; every other vehicle replays its reconstructed path as waypoints, scripted, so
// that `scenfuzz run` of the file puts a driver in the ego's place in the accident: the regression
// test AC3R and SoVAR make of a report.
#pragma once

#include <string>

#include "lang/scenario.hpp"
#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// The replay of `trace`, a run of `accident` (an accident description's template at a point) on
// `map`.
ScenarioTemplate replay_scenario(const ScenarioTemplate& accident, const Trace& trace,
                                 const RoadMap& map);

// The map the accident template names, with its parameters, as AVUnit's `load` names a
// parametrised built-in map ("crossroads?lanes=1&lane_width=3.5").
std::string map_with_parameters(const MapReference& map);

}  // namespace scenfuzz

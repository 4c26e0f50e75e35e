// scenfuzz's extensions of the traffic slot of CreateScenario (docs/avunit.md, "Extensions"):
// `NPCBehaviour(scripted | reactive)`, how the scenario's NPCs drive,
// `Flow("source_lane", rate, speed[, "destination_lane"])`, background traffic, and
// `TrafficLight("light_id", colour)`, a map light's colour at the start. The elaborator
// evaluates the file; these functions check the calls and build the IR pieces.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lang/avunit/item.hpp"
#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

// One vehicle a second per lane: a denser "flow" is not traffic but a wall of cars.
inline constexpr double kMostVehiclesPerHour = 3600.0;

// The behaviour `NPCBehaviour(...)` names, from its unevaluated call (its argument is a word, not
// a variable), or nullopt after reporting an error.
std::optional<NpcBehaviour> elaborate_npc_behaviour(const Syntax& call, Diagnostics& diagnostics);

// The setting `TrafficLight("light_id", red | yellow | green)` makes, from its unevaluated call
// (the colour is a word, quoted or not, not a variable), or nullopt after reporting an error.
// Whether the map has the light is checked when the scenario is set up for simulation.
std::optional<TrafficLightSetting> elaborate_traffic_light(const Syntax& call,
                                                           Diagnostics& diagnostics);

// The flow `Flow(...)` describes, from its evaluated arguments; `parameters` are the search
// parameters so far (the bounds a rate or speed drawn from a range can reach). Unnamed: the
// elaborator names it. Nullopt after reporting an error.
std::optional<TrafficFlow> elaborate_flow(const Syntax& call, const std::vector<Item>& arguments,
                                          std::span<const Parameter> parameters,
                                          Diagnostics& diagnostics);

// "reactive" or "scripted", as NPCBehaviour(...) takes it.
std::string npc_behaviour_word(NpcBehaviour behaviour);

}  // namespace scenfuzz::avunit

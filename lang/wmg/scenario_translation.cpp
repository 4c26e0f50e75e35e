// The translation's shared state, its top level, and parse(): level detection and the level-1
// route through level1_to_level2.
#include "lang/wmg/scenario_translation.hpp"

#include <optional>

#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/level1_parser.hpp"
#include "lang/wmg/level1_to_level2.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz::wmg {

Value Translation::number(const NumberRange& range, const std::string& name,
                          const std::string& unit, double divisor, ParameterKind kind) {
  Value value = constant_value(range.low, range.location);
  if (range.is_range) {
    Parameter parameter;
    parameter.name = name;
    parameter.kind = kind;
    parameter.lower = range.low;
    parameter.upper = range.high;
    parameter.unit = unit;
    parameter.location = range.location;
    scenario.parameters.push_back(parameter);
    value = parameter_value(static_cast<int>(scenario.parameters.size() - 1), range.location);
  }
  if (divisor == 1.0) return value;
  return binary_value(ValueOp::divide, value, constant_value(divisor), range.location);
}

std::optional<std::string> Translation::lane_id(const LaneName& lane) {
  const std::string written = lane.road.name + "." + lane.lane.name;
  auto road = roads.find(lane.road.name);
  if (road == roads.end()) {
    diagnostics.error(lane.location, "unknown lane '" + written + "': road '" + lane.road.name +
                                         "' is not in the scenery");
    return std::nullopt;
  }
  const std::string& name = lane.lane.name;
  // Pavements (P1, ...) are not lanes of the built-in maps: an actor on one stands at the kerb-side
  // lane, and its lateral offset says how far beyond it. Level 1 does not list them with a road's
  // lanes, so they need no declaration.
  if (name.starts_with("P")) return road->second.lane_prefix + "0";
  if (!road->second.declared.contains(written)) {
    diagnostics.error(lane.location, "unknown lane '" + written + "': road '" + lane.road.name +
                                         "' does not list it in its Number of lanes");
    return std::nullopt;
  }
  if (auto id = road->second.ids.find(written); id != road->second.ids.end()) return id->second;
  int number = 0;
  for (char c : name.substr(1)) number = number * 10 + (c - '0');
  if (number < 1 || number > road->second.traffic_lanes) {
    diagnostics.error(lane.location, "unknown lane '" + written + "': the map of road '" +
                                         lane.road.name + "' has " +
                                         std::to_string(road->second.traffic_lanes) +
                                         " lane(s) in this direction");
    return std::nullopt;
  }
  return road->second.lane_prefix + std::to_string(number - 1);
}

std::vector<std::string> RoadLanes::map_lanes() const {
  std::vector<std::string> lanes;
  for (int k = 0; k < traffic_lanes; ++k) lanes.push_back(lane_prefix + std::to_string(k));
  if (lane_prefix.ends_with("_in_")) {
    const std::string out = lane_prefix.substr(0, lane_prefix.size() - 3) + "out_";
    for (int k = 0; k < traffic_lanes; ++k) lanes.push_back(out + std::to_string(k));
  }
  return lanes;
}

bool Translation::check_actor(const Identifier& actor) {
  if (actors.contains(actor.name)) return true;
  diagnostics.error(actor.location,
                    "actor '" + actor.name + "' is referenced but not initialised in INITIAL");
  return false;
}

std::string sector_text(RelativeLocation location) {
  switch (location) {
    case RelativeLocation::front: return "F";
    case RelativeLocation::front_side_right: return "FSR";
    case RelativeLocation::side_right: return "SR";
    case RelativeLocation::rear_side_right: return "RSR";
    case RelativeLocation::rear: return "R";
    case RelativeLocation::rear_side_left: return "RSL";
    case RelativeLocation::side_left: return "SL";
    case RelativeLocation::front_side_left: return "FSL";
  }
  return "F";
}

ScenarioTemplate translate_level2(const Level2File& file, Diagnostics& diagnostics) {
  Translation translation(diagnostics);
  translation.scenario.language = SourceLanguage::wmg_sdl;
  translation.scenario.has_scenario = true;
  translation.scenario.scenario_name = file.scenery.id.name;
  if (file.header.npc_behaviour)
    translation.scenario.npc_behaviour =
        file.header.npc_behaviour->value == NpcBehaviourWord::scripted ? NpcBehaviour::scripted
                                                                       : NpcBehaviour::reactive;
  translate_scenery(file.scenery, file.dynamics.initialisation, translation);
  // Lanes and actors the dynamics name are checked against the scenery; with no usable map, the
  // same lane would be reported at every use.
  if (!diagnostics.has_errors()) {
    translate_dynamics(file.dynamics, translation);
    choose_first_green(file.dynamics, translation);
    choose_ego_exit(file.scenery, file.dynamics, translation);
  }
  translate_environment(file.environment, translation);
  if (file.traffic && !diagnostics.has_errors()) translate_traffic(*file.traffic, translation);
  return std::move(translation.scenario);
}

namespace {

// The level-2 tree a file stands for, or nullopt after errors.
std::optional<Level2File> level2_tree(const SourceFile& file, Diagnostics& diagnostics) {
  if (detect_wmg_level(file) == 2) {
    Level2ParseResult parsed = parse_level2(file);
    diagnostics = std::move(parsed.diagnostics);
    return std::move(parsed.file);
  }
  Level1ParseResult parsed = parse_level1(file);
  diagnostics = std::move(parsed.diagnostics);
  if (!parsed.file) return std::nullopt;
  return level1_to_level2(*parsed.file, diagnostics);
}

}  // namespace

ParseResult parse(const SourceFile& file) {
  ParseResult result;
  result.scenario.language = SourceLanguage::wmg_sdl;
  std::optional<Level2File> tree = level2_tree(file, result.diagnostics);
  if (!tree || result.diagnostics.has_errors()) return result;
  result.scenario = translate_level2(*tree, result.diagnostics);
  return result;
}

Level2Text level2_text(const SourceFile& file) {
  Level2Text result;
  std::optional<Level2File> tree = level2_tree(file, result.diagnostics);
  if (tree && !result.diagnostics.has_errors()) result.text = print_level2(*tree);
  return result;
}

}  // namespace scenfuzz::wmg

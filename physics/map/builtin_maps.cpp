// The registry of built-in maps: each map's parameters with defaults and ranges, checking of the
// values a caller gives, and dispatch to the map's generator. The defaults reproduce the maps
// fixed in corpora/README.md.
#include "physics/map/builtin_maps.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "physics/map/builtin_geometry.hpp"
#include "physics/map/road_map.hpp"
#include "physics/map/signal_plans.hpp"

namespace scenfuzz {

namespace {

using Generator = MapDescription (*)(const builtin::MapParameters&);

struct RegisteredMap {
  BuiltinMapInfo info;
  Generator generate = nullptr;
};

// Shared parameters, so that the same name means the same thing on every map.
MapParameterInfo lanes_parameter(double upper, std::string description) {
  return {"lanes", 2, 1, upper, "", std::move(description)};
}
MapParameterInfo lane_width_parameter() {
  return {"lane_width", 3.5, 2.5, 5, "m", "width of every lane"};
}
MapParameterInfo speed_limit_parameter(std::string name, double default_value,
                                       std::string description) {
  return {std::move(name), default_value, 1, 70, "m/s", std::move(description)};
}
MapParameterInfo crosswalks_parameter() {
  return {"crosswalks", 1, 0, 1, "", "1: a crosswalk across every arm, 0: none"};
}
// Below 45 degrees the roads run side by side for longer than the junction is wide: a fork, which
// these generators do not build.
MapParameterInfo junction_angle_parameter(std::string crossing_road) {
  return {"angle",
          90,
          45,
          135,
          "deg",
          "angle from the west arm counter-clockwise to the south arm: where the " +
              std::move(crossing_road) + " meets the main road"};
}

std::vector<RegisteredMap> make_registry() {
  std::vector<RegisteredMap> maps;
  maps.push_back({{"straight",
                   "a straight road along +x, lanes east_k (and west_k when two-way)",
                   {lanes_parameter(6, "lanes in each direction"),
                    lane_width_parameter(),
                    {"length", 500, 10, 10000, "m", "length of the road"},
                    {"two_way", 1, 0, 1, "", "1: west-bound lanes too, 0: east-bound only"},
                    speed_limit_parameter("speed_limit", 22.2, "speed limit of every lane")}},
                  builtin::generate_straight});
  maps.push_back(
      {{"curve",
        "a two-way road: a straight, a circular bend, a straight; lanes fwd_k and bwd_k",
        {{"radius", 100, 20, 10000, "m", "radius of the bend's reference line (the centre line)"},
         {"angle", 90, -180, 180, "deg", "how far the road turns; positive bends left"},
         {"straight_before", 100, 0, 5000, "m", "straight before the bend"},
         {"straight_after", 100, 0, 5000, "m", "straight after the bend"},
         lanes_parameter(6, "lanes in each direction"),
         lane_width_parameter(),
         speed_limit_parameter("speed_limit", 22.2, "speed limit of every lane")}},
       builtin::generate_curve});
  maps.push_back({{"t_junction",
                   "main road west-east, side road from the south with a stop sign",
                   {lanes_parameter(4, "lanes in each direction on every arm"),
                    lane_width_parameter(),
                    {"arm_length", 150, 20, 2000, "m", "length of every arm lane"},
                    junction_angle_parameter("side road"),
                    speed_limit_parameter("speed_limit", 13.9, "speed limit of every lane"),
                    crosswalks_parameter()}},
                  builtin::generate_t_junction});
  maps.push_back({{"crossroads",
                   "four arms at a signalised junction with crosswalks and pedestrian signals",
                   {lanes_parameter(4, "lanes in each direction on every arm"),
                    lane_width_parameter(),
                    {"arm_length", 150, 20, 2000, "m", "length of every arm lane"},
                    junction_angle_parameter("crossing road"),
                    speed_limit_parameter("speed_limit", 13.9, "speed limit of every lane"),
                    {"green", kDefaultGreen, 5, 120, "s", "green time of each direction"},
                    {"yellow", kDefaultYellow, 1, 10, "s", "yellow time of each direction"},
                    {"all_red", kDefaultAllRed, 0, 10, "s",
                     "all signals red between one direction's yellow and the "
                     "other's green"},
                    {"east_west_first", 0, 0, 1, "",
                     "1: the west and east arms have the first green, 0: the south and north "
                     "arms"},
                    crosswalks_parameter()}},
                  builtin::generate_crossroads});
  maps.push_back(
      {{"roundabout",
        "a single-lane ring with four two-way arms, yield signs at the entries",
        {{"ring_radius", 20, 5, 100, "m",
          "radius of the ring lane's centre line: 5 for a mini roundabout, 100 for a large one"},
         {"entry_angle", 15, 15, 30, "deg",
          "an entry joins the ring this far after its arm's axis, an exit leaves this far before; "
          "on a small ring further (up to 42), so that their curves stay drivable"},
         {"arm_length", 100, 20, 2000, "m", "length of every arm lane"},
         lane_width_parameter(),
         speed_limit_parameter("speed_limit", 13.9, "speed limit on the arms"),
         speed_limit_parameter("ring_speed_limit", 8.3,
                               "speed limit on the ring, entries and exits")}},
       builtin::generate_roundabout});
  maps.push_back(
      {{"merge",
        "an on-ramp and acceleration lane joining a one-way main road",
        {lanes_parameter(5, "lanes of the main road"),
         lane_width_parameter(),
         {"approach_length", 200, 10, 5000, "m", "main road before the acceleration lane"},
         {"accel_length", 150, 20, 1000, "m", "length of the acceleration lane"},
         {"after_length", 150, 0, 5000, "m", "main road after the acceleration lane ends"},
         {"ramp_length", 100, 0, 2000, "m", "straight part of the ramp before its bend"},
         {"ramp_radius", 200, 30, 2000, "m", "radius of the bend into the acceleration lane"},
         {"merge_angle", 15, 3, 60, "deg", "angle between the ramp and the main road"},
         speed_limit_parameter("speed_limit", 22.2,
                               "speed limit on the main road and the acceleration lane"),
         speed_limit_parameter("ramp_speed_limit", 16.7, "speed limit on the ramp")}},
       builtin::generate_merge});
  return maps;
}

const std::vector<RegisteredMap>& registry() {
  static const std::vector<RegisteredMap> maps = make_registry();
  return maps;
}

const RegisteredMap* find_map(std::string_view name) {
  for (const RegisteredMap& map : registry())
    if (map.info.name == name) return &map;
  return nullptr;
}

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

// Counts and flags have no unit (see MapParameterInfo); a flag is a count from 0 to 1.
bool is_whole_number_parameter(const MapParameterInfo& parameter) { return parameter.unit.empty(); }
bool is_flag(const MapParameterInfo& parameter) {
  return is_whole_number_parameter(parameter) && parameter.lower == 0 && parameter.upper == 1;
}

std::string range_of(const MapParameterInfo& parameter) {
  std::string range = format_number(parameter.lower) + ".." + format_number(parameter.upper);
  return parameter.unit.empty() ? range : range + " " + parameter.unit;
}

std::string accepted_values(const MapParameterInfo& parameter) {
  if (is_flag(parameter)) return "0 or 1";
  if (is_whole_number_parameter(parameter)) return "whole number " + range_of(parameter);
  return range_of(parameter);
}

std::string accepted_parameters(const BuiltinMapInfo& map) {
  std::string text = "'" + map.name + "' accepts";
  const char* separator = " ";
  for (const MapParameterInfo& parameter : map.parameters) {
    text += separator + parameter.name + " (" + accepted_values(parameter) + ", default " +
            format_number(parameter.default_value) + ")";
    separator = ", ";
  }
  return text;
}

[[noreturn]] void reject_parameter(const BuiltinMapInfo& map, const std::string& problem) {
  throw MapError("built-in map '" + map.name + "': " + problem + "; " + accepted_parameters(map));
}

void check_value(const BuiltinMapInfo& map, const MapParameterInfo& parameter, double value) {
  const std::string name = "parameter '" + parameter.name + "'";
  if (std::isnan(value)) reject_parameter(map, name + " is not a number");
  const std::string given = name + " = " + format_number(value);
  bool in_range = value >= parameter.lower && value <= parameter.upper;
  bool whole = value == std::round(value);
  if (is_flag(parameter) && !(in_range && whole)) reject_parameter(map, given + " must be 0 or 1");
  if (!in_range) reject_parameter(map, given + " is outside its range " + range_of(parameter));
  if (is_whole_number_parameter(parameter) && !whole)
    reject_parameter(map, given + " must be a whole number");
}

std::string known_map_names() {
  std::string names;
  for (const RegisteredMap& map : registry()) names += (names.empty() ? "" : ", ") + map.info.name;
  return names;
}

// "curved" (the map's old name) and the like: a known name that the unknown one extends or cuts.
std::string suggestion_for(std::string_view unknown) {
  for (const RegisteredMap& map : registry()) {
    std::string_view known = map.info.name;
    if (unknown.size() > 2 && (known.starts_with(unknown) || unknown.starts_with(known)))
      return " (did you mean '" + map.info.name + "'?)";
  }
  return "";
}

}  // namespace

const std::vector<BuiltinMapInfo>& builtin_maps() {
  static const std::vector<BuiltinMapInfo> infos = [] {
    std::vector<BuiltinMapInfo> result;
    for (const RegisteredMap& map : registry()) result.push_back(map.info);
    return result;
  }();
  return infos;
}

bool is_builtin_map(std::string_view name) { return find_map(name) != nullptr; }

MapDescription generate_builtin_map(std::string_view name,
                                    const std::vector<MapParameterValue>& parameters) {
  const RegisteredMap* map = find_map(name);
  if (!map)
    throw MapError("unknown built-in map '" + std::string(name) + "'" + suggestion_for(name) +
                   "; the built-in maps are " + known_map_names());
  builtin::MapParameters resolved;
  resolved.map = map->info.name;
  for (const MapParameterInfo& parameter : map->info.parameters)
    resolved.values.push_back({parameter.name, parameter.default_value});
  for (const MapParameterValue& given : parameters) {
    auto known = std::find_if(
        map->info.parameters.begin(), map->info.parameters.end(),
        [&given](const MapParameterInfo& parameter) { return parameter.name == given.name; });
    if (known == map->info.parameters.end())
      reject_parameter(map->info, "unknown parameter '" + given.name + "'");
    check_value(map->info, *known, given.value);
    auto slot = static_cast<std::size_t>(known - map->info.parameters.begin());
    resolved.values[slot].value = given.value;
  }
  return map->generate(resolved);
}

}  // namespace scenfuzz

// Where a scenario's map comes from. A map name is one of
//   - a built-in map, optionally with parameters: "crossroads", "straight?lanes=3&length=400";
//   - a path to an Apollo map file (base_map.bin or base_map.txt), or to a folder holding one;
//   - the name of an Apollo map folder on the map search path: "san_francisco" is
//     <dir>/san_francisco/base_map.bin (or .txt) for the first <dir> that has it.
// The search path is the --map-path folders in order, then SCENFUZZ_MAP_PATH (folders separated
// by ':'), then the repository's corpora/maps.
// A scenario that draws its roads (CH-Scenario outlines) gets outline_map.hpp's lanes instead.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/scenario.hpp"
#include "physics/map/builtin_maps.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct MapSearchPath {
  std::vector<std::filesystem::path> directories;
};

// `command_line` first, then SCENFUZZ_MAP_PATH, then corpora/maps.
MapSearchPath map_search_path(std::vector<std::filesystem::path> command_line);

// A built-in map name split from its parameters: "straight?lanes=3" -> straight, {lanes: 3}.
struct BuiltinMapRequest {
  std::string name;
  std::vector<MapParameterValue> parameters;
};
// Throws MapError for a malformed parameter list (missing '=', a value that is not a number).
BuiltinMapRequest parse_builtin_map_request(std::string_view text);

// Apollo's display name of a map as its folder name: "San Francisco" -> "san_francisco" (Dreamview
// shows folder names in title case with spaces; LawBreaker files write those). Lower case, and
// spaces and '-' to '_', leading and trailing spaces dropped.
std::string normalised_map_name(std::string_view name);

// The file an Apollo map name or path stands for; throws MapError listing where it looked. A bare
// name that is no folder is tried again normalised, so the folder used is in the returned path.
std::filesystem::path resolve_map_file(std::string_view name, const MapSearchPath& search_path);

// The map description a name stands for. `extra_parameters` (a scenario's map parameters)
// override those in the name; they are an error for an Apollo map.
MapDescription describe_map(std::string_view name, const MapSearchPath& search_path,
                            const std::vector<MapParameterValue>& extra_parameters = {});

RoadMap load_map(std::string_view name, const MapSearchPath& search_path,
                 const std::vector<MapParameterValue>& extra_parameters = {});

// A scenario's map with its map parameters evaluated at a point of the search space.
RoadMap load_scenario_map(const MapReference& reference, const MapSearchPath& search_path,
                          std::span<const double> parameter_values);

}  // namespace scenfuzz

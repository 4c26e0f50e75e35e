// The built-in parametric maps: straight, curve, t_junction, crossroads, roundabout, merge.
// Each is a pure function of its parameters, so a map can be part of a search space (WMG SDL
// scenery, AVUnit map parameters). Lane ids and geometry are the contract in corpora/README.md.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "physics/map/map_description.hpp"

namespace scenfuzz {

struct MapParameterValue {
  std::string name;
  double value = 0;
};

// A parameter a built-in map accepts, with its default and the closed range it must lie in.
struct MapParameterInfo {
  std::string name;
  double default_value = 0;
  double lower = 0;
  double upper = 0;
  std::string unit;  // "m", "deg", "s", "" for counts and flags
  std::string description;
};

struct BuiltinMapInfo {
  std::string name;
  std::string description;
  std::vector<MapParameterInfo> parameters;
};

const std::vector<BuiltinMapInfo>& builtin_maps();
bool is_builtin_map(std::string_view name);

// Generates the map. Parameters not given take their defaults; an unknown name, an unknown
// parameter, a value outside its range or a non-integer count throws MapError saying which and
// what is accepted. Later values of the same parameter override earlier ones.
MapDescription generate_builtin_map(std::string_view name,
                                    const std::vector<MapParameterValue>& parameters);

}  // namespace scenfuzz

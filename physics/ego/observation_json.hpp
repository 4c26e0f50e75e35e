// An ego plugin's observation as a compact JSON object, for a finding about a plugin that failed:
// the last thing the plugin was handed is what a reader needs to reproduce the failure.
#pragma once

#include <string>

#include "physics/ego/ego_plugin.h"

namespace scenfuzz {

// {"ego": {"time", "x", "y", "heading", "speed", "acceleration", "yaw_rate", "steering_angle"},
//  "objects": [{"id", "kind", "x", "y", "heading", "speed", "length", "width"}],
//  "route": [{"x", "y", "heading", "speed_limit"}], "distance_to_target", "light",
//  "light_distance", "stop_sign_distance"}: only the object_count objects and route_point_count
// points the observation holds; kinds and lights by name ("vehicle", "red", "none"); non-finite
// numbers (no target, no light, no sign) as null. One line, no spaces.
std::string observation_json(const scenfuzz_observation& observation);

}  // namespace scenfuzz

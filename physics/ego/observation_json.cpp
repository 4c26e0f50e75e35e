// An ego plugin's observation written as JSON with nlohmann-json.
#include "physics/ego/observation_json.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace scenfuzz {
namespace {

using nlohmann::json;

// JSON has no infinity or NaN; null says "none" (no target, no light ahead).
json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

// By name, so that a reader needs no header; a value outside the enum stays a number.
json object_kind(std::uint32_t kind) {
  switch (kind) {
    case SCENFUZZ_OBJECT_VEHICLE: return "vehicle";
    case SCENFUZZ_OBJECT_PEDESTRIAN: return "pedestrian";
    case SCENFUZZ_OBJECT_OBSTACLE: return "obstacle";
    default: return kind;
  }
}

json light_name(std::int32_t light) {
  switch (light) {
    case SCENFUZZ_LIGHT_NONE: return "none";
    case SCENFUZZ_LIGHT_RED: return "red";
    case SCENFUZZ_LIGHT_YELLOW: return "yellow";
    case SCENFUZZ_LIGHT_GREEN: return "green";
    default: return light;
  }
}

json ego_json(const scenfuzz_ego_state& ego) {
  return {{"time", number(ego.time)},
          {"x", number(ego.x)},
          {"y", number(ego.y)},
          {"heading", number(ego.heading)},
          {"speed", number(ego.speed)},
          {"acceleration", number(ego.acceleration)},
          {"yaw_rate", number(ego.yaw_rate)},
          {"steering_angle", number(ego.steering_angle)}};
}

json objects_json(const scenfuzz_observation& observation) {
  json objects = json::array();
  const auto count = std::min<std::uint32_t>(observation.object_count, SCENFUZZ_MAX_OBJECTS);
  for (std::uint32_t i = 0; i < count; ++i) {
    const scenfuzz_object& object = observation.objects[i];
    objects.push_back({{"id", object.id},
                       {"kind", object_kind(object.kind)},
                       {"x", number(object.x)},
                       {"y", number(object.y)},
                       {"heading", number(object.heading)},
                       {"speed", number(object.speed)},
                       {"length", number(object.length)},
                       {"width", number(object.width)}});
  }
  return objects;
}

json route_json(const scenfuzz_observation& observation) {
  json route = json::array();
  const auto count = std::min<std::uint32_t>(observation.route_point_count, SCENFUZZ_ROUTE_POINTS);
  for (std::uint32_t i = 0; i < count; ++i) {
    const scenfuzz_route_point& point = observation.route[i];
    route.push_back({{"x", number(point.x)},
                     {"y", number(point.y)},
                     {"heading", number(point.heading)},
                     {"speed_limit", number(point.speed_limit)}});
  }
  return route;
}

}  // namespace

std::string observation_json(const scenfuzz_observation& observation) {
  const json document = {{"ego", ego_json(observation.ego)},
                         {"objects", objects_json(observation)},
                         {"route", route_json(observation)},
                         {"distance_to_target", number(observation.distance_to_target)},
                         {"light", light_name(observation.light)},
                         {"light_distance", number(observation.light_distance)},
                         {"stop_sign_distance", number(observation.stop_sign_distance)}};
  return document.dump();
}

}  // namespace scenfuzz

// Checks on a scenario's evaluated values, and the messages that say what is wrong with them.
#include "physics/simulation/scenario_checks.hpp"

#include <cmath>
#include <cstdio>

#include "lang/number_format.hpp"
#include "physics/actors/road_friction.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/simulation/simulation_limits.hpp"

namespace scenfuzz {
namespace {

// "(100000, -5.25)": to the centimetre, without exponents.
std::string point_text(MapPoint point) {
  char text[80];
  std::snprintf(text, sizeof text, "(%.10g, %.10g)", std::round(point.x * 100) / 100,
                std::round(point.y * 100) / 100);
  return text;
}

// "(x, y), 141 km from the nearest lane 'east_0'" or "(x, y), on lane 'east_0'".
std::string placed_text(const RoadMap& map, MapPoint point, const LaneProjection& lane) {
  const std::string id = "'" + map.lane(lane.lane).id + "'";
  if (lane.inside) return point_text(point) + ", on lane " + id;
  return point_text(point) + ", " + distance_text(lane.distance) + " from the nearest lane " + id;
}

}  // namespace

std::string distance_text(double metres) {
  if (metres < 1000) return format_number(std::round(metres * 10) / 10) + " m";
  const double kilometres = metres / 1000;
  // Whole kilometres from 100 km on: a tenth of a kilometre is noise at that distance.
  const double rounded =
      kilometres >= 100 ? std::round(kilometres) : std::round(kilometres * 10) / 10;
  return format_number(rounded) + " km";
}

bool check_speed(double speed, bool pedestrian, const std::string& who, const SourceLocation& where,
                 Diagnostics& diagnostics) {
  const double max_speed = pedestrian ? kMaxPedestrianSpeed : kMaxVehicleSpeed;
  if (!std::isfinite(speed) || speed < 0) {
    diagnostics.error(where, "a speed must be a finite number >= 0, not " + format_number(speed));
    return false;
  }
  if (speed > max_speed) {
    diagnostics.error(where, who + "'s speed of " + format_number(speed) + " m/s is beyond any " +
                                 (pedestrian ? "pedestrian" : "vehicle") + " (at most " +
                                 format_number(max_speed) + " m/s)");
    return false;
  }
  return true;
}

bool check_position(MapPoint position, const SourceLocation& where, Diagnostics& diagnostics) {
  for (double coordinate : {position.x, position.y}) {
    if (std::isfinite(coordinate) && std::abs(coordinate) <= kMaxCoordinate) continue;
    diagnostics.error(where, "the position's coordinate " + format_number(coordinate) +
                                 " m lies beyond any map (coordinates are at most " +
                                 distance_text(kMaxCoordinate) + " from the map's origin)");
    return false;
  }
  return true;
}

bool check_duration(double duration, const SourceLocation& where, Diagnostics& diagnostics) {
  if (std::isfinite(duration) && duration <= kMaxScenarioDuration) return true;
  diagnostics.error(where, "the scenario's duration of " + format_number(duration) +
                               " s is beyond the longest the simulation runs (" +
                               format_number(kMaxScenarioDuration) + " s)");
  return false;
}

bool check_road_friction(double friction, const SourceLocation& where, Diagnostics& diagnostics) {
  if (is_road_friction(friction)) return true;
  diagnostics.error(where,
                    "the road's friction must be a number in (0, 1] (a share of dry "
                    "asphalt's grip), not " +
                        format_number(friction));
  return false;
}

void warn_if_far_from_lanes(const RoadMap& map, MapPoint start, const SourceLocation& where,
                            Diagnostics& diagnostics) {
  const auto lane = project_to_lane(map, start);
  if (!lane || lane->distance <= kFarFromLanes) return;
  diagnostics.warning(where, "the ego's initial position is " + distance_text(lane->distance) +
                                 " from the nearest lane ('" + map.lane(lane->lane).id +
                                 "'): it will be simulated driving off the map");
}

void report_empty_ego_route(const RoadMap& map, MapPoint start, MapPoint target,
                            const SourceLocation& where, Diagnostics& diagnostics) {
  const auto from = project_to_lane(map, start);
  const auto to = project_to_lane(map, target);
  std::string why;
  if (from && to && !from->inside && !to->inside) {
    why = "its initial position " + placed_text(map, start, *from) + ", and its target " +
          placed_text(map, target, *to) +
          ", are both off the map and lead to the same place on the lanes";
  } else if (from && to) {
    why = "its target " + placed_text(map, target, *to) + " is where it starts " +
          placed_text(map, start, *from);
  } else {
    why = "map '" + map.name() + "' has no lanes";
  }
  diagnostics.error(where, "the ego's route to its target has no length: " + why);
}

}  // namespace scenfuzz

// place_position: from the IR's positions to map poses.
#include "physics/map/scenario_position.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "lang/number_format.hpp"
#include "physics/map/utm.hpp"

namespace scenfuzz {

namespace {

// "lane_2" < "lane_10": ids compared by their text before the trailing digits, then by number.
bool natural_less(const std::string& a, const std::string& b) {
  auto split = [](const std::string& id) {
    std::size_t digits = id.find_last_not_of("0123456789") + 1;
    std::string number = id.substr(digits);
    return std::tuple(id.substr(0, digits), number.size(), number);
  };
  return split(a) < split(b);
}

// "its lanes are lane_0 .. lane_1523": where a missing lane's id would have to fall. A lane id
// from a newer release of a map is the usual cause, and the range shows it.
std::string lane_range(const RoadMap& map) {
  if (map.lanes().empty()) return "it has no lanes";
  auto [first, last] =
      std::minmax_element(map.lanes().begin(), map.lanes().end(),
                          [](const Lane& a, const Lane& b) { return natural_less(a.id, b.id); });
  return "its lanes are " + first->id + " .. " + last->id + ", " +
         std::to_string(map.lanes().size()) + " lanes";
}

std::optional<PlacedPosition> place_on_lane(const RoadMap& map, const Position& position,
                                            std::span<const double> values,
                                            Diagnostics& diagnostics) {
  const double written_s = evaluate(position.s, values);
  const std::optional<LaneStation> station = map.find_lane_station(position.lane, written_s);
  if (!station) {
    diagnostics.error(position.location, "lane '" + position.lane + "' is not in map '" +
                                             map.name() + "' (" + lane_range(map) + ")");
    return std::nullopt;
  }
  const double s = station->s;
  double lateral = position.lateral ? evaluate(*position.lateral, values) : 0.0;
  auto pose = clamped_lane_pose(map, station->lane, s, lateral);
  if (!pose) {
    diagnostics.error(position.location, "the position on lane '" + position.lane +
                                             "' is not a finite number (s = " + format_number(s) +
                                             ", lateral = " + format_number(lateral) + ")");
    return std::nullopt;
  }
  return PlacedPosition{pose->pose, station->lane, pose->overshoot};
}

std::optional<PlacedPosition> place_coordinate(const RoadMap& map, const Position& position,
                                               std::span<const double> values,
                                               const std::optional<MapPose>& ego,
                                               Diagnostics& diagnostics) {
  double x = evaluate(position.x, values);
  double y = evaluate(position.y, values);
  if (!std::isfinite(x) || !std::isfinite(y)) {
    diagnostics.error(position.location, "the coordinate (" + format_number(x) + ", " +
                                             format_number(y) + ") is not a finite point");
    return std::nullopt;
  }
  PlacedPosition placed;
  switch (position.frame) {
    case Frame::enu: placed.pose.position = {x, y}; break;
    case Frame::wgs84: {
      auto projection = parse_projection(map.projection());
      if (!projection) {
        diagnostics.error(position.location,
                          map.projection().empty()
                              ? "a WGS84 position needs a geo-referenced map; map '" + map.name() +
                                    "' has no projection"
                              : "map '" + map.name() + "' has projection '" + map.projection() +
                                    "', which scenfuzz cannot use (UTM or transverse Mercator "
                                    "on WGS84 only)");
        return std::nullopt;
      }
      if (std::abs(y) > 90) {
        diagnostics.error(position.location,
                          "a WGS84 position is (longitude, latitude); latitude " +
                              format_number(y) + " is outside [-90, 90]");
        return std::nullopt;
      }
      placed.pose.position = project(*projection, GeoPoint{y, x});
      break;
    }
    case Frame::imu: {
      if (!ego) {
        diagnostics.error(position.location,
                          "an IMU position is relative to the ego's initial pose, which is not "
                          "known here (the ego's own position cannot be IMU)");
        return std::nullopt;
      }
      // IMU: x to the ego's right, y forward.
      double forward_x = std::cos(ego->heading), forward_y = std::sin(ego->heading);
      placed.pose.position = {ego->position.x + y * forward_x + x * forward_y,
                              ego->position.y + y * forward_y - x * forward_x};
      placed.pose.heading = ego->heading;
      break;
    }
  }
  return placed;
}

}  // namespace

std::optional<PlacedPosition> place_position(const RoadMap& map, const Position& position,
                                             std::span<const double> values,
                                             const std::optional<MapPose>& ego,
                                             Diagnostics& diagnostics) {
  switch (position.kind) {
    case PositionKind::lane: return place_on_lane(map, position, values, diagnostics);
    case PositionKind::coordinate: return place_coordinate(map, position, values, ego, diagnostics);
    case PositionKind::relative: return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace scenfuzz

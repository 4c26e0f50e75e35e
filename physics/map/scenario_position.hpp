// Where a scenario's position lies on its map: lane positions (`"lane" -> s`, clamped as Apollo
// does), ENU coordinates, WGS84 coordinates projected with the map header's projection, and IMU
// coordinates relative to the ego's initial pose. Relative positions (WMG SDL) need the other
// actors' states and are placed by the simulation.
#pragma once

#include <optional>
#include <span>

#include "lang/diagnostic.hpp"
#include "lang/position.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

struct PlacedPosition {
  MapPose pose;                   // heading: the lane's direction for a lane position, else 0
  std::optional<LaneIndex> lane;  // for a lane position
  double overshoot = 0;           // how far a lane position's s lay outside its lane
};

// Places `position` with the search parameters at `values`. Problems the user must fix (an
// unknown lane, WGS84 on a map without a projection, a non-finite value) are reported to
// `diagnostics` at the position's location, and give nullopt. An IMU position needs `ego`.
std::optional<PlacedPosition> place_position(const RoadMap& map, const Position& position,
                                             std::span<const double> values,
                                             const std::optional<MapPose>& ego,
                                             Diagnostics& diagnostics);

}  // namespace scenfuzz

// What the road-outline tests (outline_map_test, outline_junctions_test) ask of a description:
// a lane by id, and the error describe_outline_map throws.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "physics/map/outline_map.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz::test {

// Fails the test (through the exception GoogleTest reports) when the lane is missing.
inline const LaneDescription& lane_of(const MapDescription& map, std::string_view id) {
  for (const LaneDescription& lane : map.lanes)
    if (lane.id == id) return lane;
  throw std::runtime_error("the map has no lane '" + std::string(id) + "'");
}

// The message describe_outline_map throws for these roads and signals, or "no error".
inline std::string outline_error(const std::vector<RoadOutlineGeometry>& roads,
                                 const std::vector<OutlineSignal>& signals = {}) {
  try {
    describe_outline_map("blank", roads, signals);
  } catch (const MapError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace scenfuzz::test

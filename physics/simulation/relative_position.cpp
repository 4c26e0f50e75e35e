#include "physics/simulation/relative_position.hpp"

#include <cctype>
#include <cmath>

#include "lang/number_format.hpp"

namespace scenfuzz {
namespace {

enum class SectorSide { none, left, right };

// SL, FSL, RSL lie beside the reference on its left; SR, FSR, RSR on its right.
SectorSide sector_side(const std::string& sector) {
  std::string upper;
  for (char c : sector) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (upper == "SL" || upper == "FSL" || upper == "RSL") return SectorSide::left;
  if (upper == "SR" || upper == "FSR" || upper == "RSR") return SectorSide::right;
  return SectorSide::none;
}

}  // namespace

std::optional<MapPose> place_relative(const RoadMap& map, const Position& position,
                                      std::span<const double> values, const MapPose& reference,
                                      const std::string& actor, Diagnostics& diagnostics) {
  auto reference_lane = project_to_lane(map, reference.position, reference.heading);
  if (!reference_lane) {
    diagnostics.error(position.location, actor + " is placed relative to " + position.reference +
                                             ", which stands on no lane of map '" + map.name() +
                                             "'");
    return std::nullopt;
  }
  LaneIndex lane = reference_lane->lane;
  if (!position.lane.empty()) {
    auto written = map.find_lane(position.lane);
    if (!written) {
      diagnostics.error(position.location, "unknown lane '" + position.lane + "' for " + actor +
                                               " on map '" + map.name() + "'");
      return std::nullopt;
    }
    lane = *written;
  } else {
    const Lane& own = map.lane(lane);
    SectorSide side = sector_side(position.relative_location);
    if (side == SectorSide::left && !own.left_forward_neighbours.empty())
      lane = own.left_forward_neighbours.front();
    if (side == SectorSide::right && !own.right_forward_neighbours.empty())
      lane = own.right_forward_neighbours.front();
  }
  // The reference's lane position carried over to the actor's lane: the same arc length, which
  // for lanes of one road (they start together) is the place beside the reference, and for a
  // lane of another arm of a junction the same distance from where the arms begin.
  const double reference_s = reference_lane->s;
  const double offset = evaluate(position.s, values);
  const double lateral = position.lateral ? evaluate(*position.lateral, values) : 0.0;
  if (!std::isfinite(offset) || !std::isfinite(lateral)) {
    diagnostics.error(position.location,
                      actor + "'s offsets from " + position.reference + " are not finite numbers");
    return std::nullopt;
  }
  const double s = reference_s + offset;
  const double length = map.lane(lane).length();
  if (s < 0 || s > length) {
    diagnostics.error(position.location, actor + "'s position, " + format_number(offset) +
                                             " m along the lane from " + position.reference +
                                             ", falls off lane '" + map.lane(lane).id +
                                             "': s = " + format_number(s) + " m on a lane " +
                                             format_number(length) + " m long");
    return std::nullopt;
  }
  return lane_pose_at(map, lane, s, lateral);
}

}  // namespace scenfuzz

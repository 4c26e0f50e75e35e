// WMG SDL relative placement: the reference's lane position carried to the written lane, and a
// pedestrian moved to the side of its road that its sector names.
#include "physics/simulation/relative_position.hpp"

#include <algorithm>
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

// Metres `point` lies to the left of `reference` (negative: to its right).
double left_of(const MapPose& reference, MapPoint point) {
  return -(point.x - reference.position.x) * std::sin(reference.heading) +
         (point.y - reference.position.y) * std::cos(reference.heading);
}

// Every lane of the road through `lane`: its neighbours on either side, either way, and theirs.
std::vector<LaneIndex> road_cross_section(const RoadMap& map, LaneIndex lane) {
  std::vector<LaneIndex> lanes{lane};
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const Lane& current = map.lane(lanes[i]);
    for (const auto* side : {&current.left_forward_neighbours, &current.right_forward_neighbours,
                             &current.left_reverse_neighbours, &current.right_reverse_neighbours})
      for (LaneIndex neighbour : *side)
        if (std::find(lanes.begin(), lanes.end(), neighbour) == lanes.end())
          lanes.push_back(neighbour);
  }
  return lanes;
}

// A pedestrian stands on the side of its road that its sector names, as the reference sees it:
// beyond the outermost lane on that side by its lateral offset (on the pavement there), level
// with `along` (its place on the lane written). A reference on another arm of a junction sees
// that arm's lanes the other way round, so the lane written cannot say the side by itself.
std::optional<MapPose> on_named_side(const RoadMap& map, LaneIndex written, MapPoint along,
                                     double lateral, const MapPose& reference, SectorSide side) {
  const double sign = side == SectorSide::left ? 1 : -1;
  std::optional<LaneIndex> outermost;
  double outermost_left = 0, outermost_s = 0;
  for (LaneIndex lane : road_cross_section(map, written)) {
    const Polyline& centre = map.lane(lane).centre_line;
    const double s = centre.project(along).s;
    const double left = sign * left_of(reference, centre.point_at(s));
    if (!outermost || left > outermost_left) {
      outermost = lane;
      outermost_left = left;
      outermost_s = s;
    }
  }
  const double heading = map.lane(*outermost).centre_line.heading_at(outermost_s);
  // The lane's own left points to the named side when it runs the reference's way round.
  const double facing = std::cos(heading - reference.heading) >= 0 ? 1 : -1;
  return lane_pose_at(map, *outermost, outermost_s, sign * facing * std::abs(lateral));
}

bool enters_junction(const RoadMap& map, LaneIndex lane) {
  const Lane& own = map.lane(lane);
  return !own.junction && !own.successors.empty() &&
         std::all_of(own.successors.begin(), own.successors.end(),
                     [&](LaneIndex next) { return map.lane(next).junction.has_value(); });
}

bool leaves_junction(const RoadMap& map, LaneIndex lane) {
  const Lane& own = map.lane(lane);
  return !own.junction && !own.predecessors.empty() &&
         std::all_of(own.predecessors.begin(), own.predecessors.end(),
                     [&](LaneIndex previous) { return map.lane(previous).junction.has_value(); });
}

// The actor's arc length on `actor`, `offset` ahead of the reference's lane position (see the
// caller).
double lane_s_for(const RoadMap& map, const LaneProjection& reference, LaneIndex actor,
                  double offset) {
  if (enters_junction(map, reference.lane) && leaves_junction(map, actor))
    return map.lane(reference.lane).length() - reference.s - offset;
  return reference.s + offset;
}

}  // namespace

std::optional<MapPose> place_relative(const RoadMap& map, const Position& position,
                                      std::span<const double> values, const MapPose& reference,
                                      bool pedestrian, const std::string& actor,
                                      Diagnostics& diagnostics) {
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
    const SectorSide side = sector_side(position.relative_location);
    if (side == SectorSide::left && !own.left_forward_neighbours.empty())
      lane = own.left_forward_neighbours.front();
    if (side == SectorSide::right && !own.right_forward_neighbours.empty())
      lane = own.right_forward_neighbours.front();
  }
  const double offset = evaluate(position.s, values);
  const double lateral = position.lateral ? evaluate(*position.lateral, values) : 0.0;
  if (!std::isfinite(offset) || !std::isfinite(lateral)) {
    diagnostics.error(position.location,
                      actor + "'s offsets from " + position.reference + " are not finite numbers");
    return std::nullopt;
  }
  // The reference's lane position carried over to the actor's lane: the same arc length, which
  // for lanes of one road (they start together) is the place beside the reference, and for a
  // lane of another arm of a junction the same distance from where the arms begin. A lane
  // leading out of the junction the reference drives into counts from the junction: the same
  // distance from it (beside the reference on its own road's oncoming lane, as far past the
  // junction as the reference is before it on another arm's).
  const double s = lane_s_for(map, *reference_lane, lane, offset);
  const double length = map.lane(lane).length();
  if (s < 0 || s > length) {
    diagnostics.error(position.location, actor + "'s position, " + format_number(offset) +
                                             " m along the lane from " + position.reference +
                                             ", falls off lane '" + map.lane(lane).id +
                                             "': s = " + format_number(s) + " m on a lane " +
                                             format_number(length) + " m long");
    return std::nullopt;
  }
  std::optional<MapPose> pose = lane_pose_at(map, lane, s, lateral);
  const SectorSide side = sector_side(position.relative_location);
  if (pedestrian && pose && side != SectorSide::none &&
      (left_of(reference, pose->position) > 0) != (side == SectorSide::left))
    pose = on_named_side(map, lane, pose->position, lateral, reference, side);
  return pose;
}

}  // namespace scenfuzz

// The indication stretches of a lane route and the indicator at a point of it
// (route_indications.hpp).
#include "physics/ego/route_indications.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/map/junction_stretch.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {
namespace {

// rad a junction lane without a turn attribute must turn through to count as a turn: a
// junction's straight connectors bend a little where the roads meet at an angle.
constexpr double kTurnAngle = 0.5236;  // 30 degrees

bool contains(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

// Which side `to` lies on as seen from `from`: a lane change's indicator.
VehicleSignals lane_change_indicator(const RoadMap& map, LaneIndex from, LaneIndex to) {
  const Lane& lane = map.lane(from);
  if (contains(lane.left_forward_neighbours, to) || contains(lane.left_reverse_neighbours, to))
    return vehicle_signal::left_indicator;
  if (contains(lane.right_forward_neighbours, to) || contains(lane.right_reverse_neighbours, to))
    return vehicle_signal::right_indicator;
  // Not linked as neighbours: by which side of from's centre line to's centre lies.
  const Polyline& line = map.lane(to).centre_line;
  const MapPoint middle = line.point_at(line.length() / 2);
  const PolylineProjection on = lane.centre_line.project(middle);
  return on.lateral >= 0 ? vehicle_signal::left_indicator : vehicle_signal::right_indicator;
}

// The route segment of the stretch that leaves a roundabout's ring (a lane running round into
// itself) the route drives along; nullopt when the stretch has no ring, or ends on it.
std::optional<std::size_t> roundabout_exit(const RoadMap& map,
                                           std::span<const RouteSegment> segments,
                                           const JunctionStretch& stretch) {
  std::optional<std::size_t> ring;
  for (std::size_t k = stretch.first; k <= stretch.last; ++k)
    if (runs_into_itself(map, segments[k].lane)) ring = k;
  if (!ring || *ring + 1 > stretch.last) return std::nullopt;
  return *ring + 1;
}

}  // namespace

VehicleSignals junction_lane_indicator(const RoadMap& map, LaneIndex lane) {
  const Lane& junction_lane = map.lane(lane);
  switch (junction_lane.turn) {
    case LaneTurn::left:
    case LaneTurn::u_turn: return vehicle_signal::left_indicator;
    case LaneTurn::right: return vehicle_signal::right_indicator;
    case LaneTurn::none: break;
  }
  const Polyline& line = junction_lane.centre_line;
  if (line.length() <= 0) return 0;
  const double turned = angle_difference(line.heading_at(line.length()), line.heading_at(0));
  if (turned > kTurnAngle) return vehicle_signal::left_indicator;
  if (turned < -kTurnAngle) return vehicle_signal::right_indicator;
  return 0;
}

std::vector<IndicationStretch> route_indications(const RoadMap& map,
                                                 std::span<const RouteSegment> segments,
                                                 std::span<const LaneChangeStretch> lane_changes) {
  std::vector<IndicationStretch> stretches;
  for (const LaneChangeStretch& change : lane_changes)
    stretches.push_back(
        {change.begin, change.end, lane_change_indicator(map, change.from, change.to)});
  std::vector<double> starts;
  double route_s = 0;
  for (const RouteSegment& segment : segments) {
    starts.push_back(route_s);
    route_s += segment.s_end - segment.s_begin;
  }
  for (double from = 0;;) {
    auto stretch = junction_stretch_ahead(map, segments, starts, from);
    if (!stretch) break;
    from = stretch->exit;
    if (auto exit = roundabout_exit(map, segments, *stretch)) {
      // Round a roundabout: no indicator on the way in, the exit's from the usual notice before
      // it (about the exit before), whichever exit is taken.
      const VehicleSignals indicator = junction_lane_indicator(map, segments[*exit].lane);
      if (indicator != 0) stretches.push_back({starts[*exit], stretch->exit, indicator, 0});
      continue;
    }
    VehicleSignals indicator = 0;
    for (std::size_t k = stretch->first; k <= stretch->last && indicator == 0; ++k)
      indicator = junction_lane_indicator(map, segments[k].lane);
    if (indicator != 0)
      stretches.push_back({stretch->entry, stretch->exit, indicator, kTurnNotice});
  }
  std::sort(
      stretches.begin(), stretches.end(),
      [](const IndicationStretch& a, const IndicationStretch& b) { return a.begin < b.begin; });
  return stretches;
}

VehicleSignals look_for_indication(std::span<const IndicationStretch> stretches, double progress,
                                   double speed, IndicationCursor& cursor,
                                   const IndicationNotice& notice) {
  while (cursor.next < stretches.size() && stretches[cursor.next].end <= progress) {
    ++cursor.next;
    cursor.on = false;
  }
  if (cursor.next >= stretches.size()) {
    cursor.quiet_until = 1e300;
    return 0;
  }
  const IndicationStretch& stretch = stretches[cursor.next];
  if (cursor.on) return stretch.indicator;
  const double lead =
      std::max({notice.distance, notice.time * std::abs(speed), stretch.least_notice});
  if (progress >= stretch.begin - lead) {
    cursor.on = true;
    return stretch.indicator;
  }
  cursor.quiet_until = stretch.begin - std::max({notice.distance, notice.time * kFastestVehicle,
                                                 stretch.least_notice});
  return 0;
}

}  // namespace scenfuzz

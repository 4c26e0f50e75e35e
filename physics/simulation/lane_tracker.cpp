// Lane tracking: the previous lane's nearby segments first, the whole map only when the actor
// has left that lane.
#include "physics/simulation/lane_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace scenfuzz {
namespace {

constexpr std::size_t kSearchSegments = 3;  // on either side of the previous one
// An actor off every lane is looked up again after moving at least this far, however near a lane.
constexpr double kOffLaneRecheck = 0.25;

}  // namespace

double widest_half_lane(const RoadMap& map) {
  double widest = 0;
  for (const Lane& lane : map.lanes())
    for (const auto* side : {&lane.left_width, &lane.right_width})
      for (const WidthSample& sample : *side) widest = std::max(widest, sample.width);
  return widest;
}

LaneFix LaneTracker::update(const RoadMap& map, MapPoint point, double heading) {
  if (lane_ >= 0) {
    const auto lane = static_cast<LaneIndex>(lane_);
    const Polyline& centre = map.lane(lane).centre_line;
    std::size_t first = segment_ > kSearchSegments ? segment_ - kSearchSegments : 0;
    std::size_t last = std::min(segment_ + kSearchSegments, centre.segment_count() - 1);
    PolylineProjection best = centre.project_to_segment(point, first);
    for (std::size_t segment = first + 1; segment <= last; ++segment) {
      PolylineProjection candidate = centre.project_to_segment(point, segment);
      if (candidate.distance < best.distance) best = candidate;
    }
    // Nearest at the edge of the window: it may lie further along; look at the whole lane.
    bool at_window_edge = (best.segment == first && first > 0) ||
                          (best.segment == last && last + 1 < centre.segment_count());
    if (at_window_edge) best = centre.project(point);
    // Beyond an end of the lane, the nearest point is the end point and lies off the normal.
    bool beside = best.distance <= std::abs(best.lateral) + 1e-9;
    double width = best.lateral >= 0 ? lane_left_width_at(map, lane, best.s)
                                     : lane_right_width_at(map, lane, best.s);
    if (beside && std::abs(best.lateral) <= width) {
      segment_ = best.segment;
      return {lane_, best.s};
    }
  }
  if (off_lanes_ && distance(point, off_lanes_at_) < off_lanes_reach_) return {};
  // Most off-lane actors are pedestrians on pavements: the nearest centre line alone (several
  // times cheaper than the heading-aware query) says whether they are on any lane at all.
  auto nearest = project_to_lane(map, point);
  auto projection = nearest && nearest->inside ? project_to_lane(map, point, heading) : nearest;
  if (!projection || !projection->inside) {
    lane_ = -1;
    off_lanes_ = true;
    off_lanes_at_ = point;
    double nearest_centre = nearest ? nearest->distance : 0;
    off_lanes_reach_ = std::max(kOffLaneRecheck, nearest_centre - widest_half_lane_);
    return {};
  }
  off_lanes_ = false;
  lane_ = static_cast<std::int32_t>(projection->lane);
  segment_ = map.lane(projection->lane).centre_line.segment_at(projection->s);
  return {lane_, projection->s};
}

}  // namespace scenfuzz

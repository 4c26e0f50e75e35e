// Lane tracking: the previous lane's nearby segments first, the whole map only when the actor
// has left that lane.
#include "physics/simulation/lane_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace scenfuzz {
namespace {

constexpr std::size_t kSearchSegments = 3;  // on either side of the previous one

}  // namespace

LaneFix LaneTracker::update(const RoadMap& map, MapPoint point, double heading) {
  if (lane_ >= 0) {
    const Lane& lane = map.lane(static_cast<LaneIndex>(lane_));
    const Polyline& centre = lane.centre_line;
    std::size_t first = segment_ > kSearchSegments ? segment_ - kSearchSegments : 0;
    std::size_t last = std::min(segment_ + kSearchSegments, centre.segment_count() - 1);
    PolylineProjection best = centre.project_to_segment(point, first);
    std::size_t best_segment = first;
    for (std::size_t segment = first + 1; segment <= last; ++segment) {
      PolylineProjection candidate = centre.project_to_segment(point, segment);
      if (candidate.distance < best.distance) {
        best = candidate;
        best_segment = segment;
      }
    }
    bool interior = best.s > 0 && best.s < lane.length() &&
                    (best_segment > first || first == 0) &&
                    (best_segment < last || last == centre.segment_count() - 1);
    double width = best.lateral >= 0 ? lane_left_width_at(map, static_cast<LaneIndex>(lane_), best.s)
                                     : lane_right_width_at(map, static_cast<LaneIndex>(lane_), best.s);
    if (interior && std::abs(best.lateral) <= width) {
      segment_ = best_segment;
      return {lane_, best.s};
    }
  }
  auto projection = project_to_lane(map, point, heading);
  if (!projection || !projection->inside) {
    lane_ = -1;
    return {};
  }
  lane_ = static_cast<std::int32_t>(projection->lane);
  segment_ = map.lane(projection->lane).centre_line.segment_at(projection->s);
  return {lane_, projection->s};
}

}  // namespace scenfuzz

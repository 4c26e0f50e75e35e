// Lane tracking: the previous lane's nearby segments first, the whole map only when the actor
// has left that lane.
#include "physics/simulation/lane_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace scenfuzz {
namespace {

constexpr std::size_t kSearchSegments = 3;  // on either side of the previous one
// An actor off every lane is looked up again after moving at least this far, however near a lane.
constexpr double kOffLaneRecheck = 0.25;

}  // namespace

namespace {

// What looking for a point on one lane found.
struct LaneLook {
  std::optional<LaneFix> fix;  // within the lane's width, beside its centre line
  std::size_t segment = 0;     // of the nearest point
  bool past_end = false;       // the point lies beyond the lane's end
};

// Far more than project_to_segment's rounding (about 1e-14 m at a map's scale): a segment whose
// bounding box is farther than a known distance plus this is surely not nearer.
constexpr double kPruneMargin = 1e-9;

// Whether segment k of `line` is surely farther from `point` than `distance`: the distance to its
// bounding box bounds the distance to it from below, and costs no division and no square root.
bool surely_farther(const Polyline& line, std::size_t k, MapPoint point, double distance) {
  const MapPoint& a = line.points()[k];
  const MapPoint& b = line.points()[k + 1];
  // Nested two-argument maxima: std::max of an initializer list compiles to a loop here.
  const double dx =
      std::max(std::max(std::min(a.x, b.x) - point.x, 0.0), point.x - std::max(a.x, b.x));
  const double dy =
      std::max(std::max(std::min(a.y, b.y) - point.y, 0.0), point.y - std::max(a.y, b.y));
  const double bound = distance + kPruneMargin;
  return dx * dx + dy * dy > bound * bound;
}

// The nearest segment among first..last, the first of them on a tie. Segments surely farther
// than one already projected are skipped: they are not the nearest, so skipping them cannot change
// which one is, and the segment the actor was on last step is usually still the nearest. Starting
// from that one, the best so far is simply compared with each candidate (distance, then index).
PolylineProjection nearest_in_window(const Polyline& centre, std::size_t first, std::size_t last,
                                     std::size_t hint, MapPoint point) {
  PolylineProjection best = centre.project_to_segment(point, hint);
  // Not a number (a point that is not one): every comparison fails, and the first segment of the
  // window is the answer, as in a scan from it that keeps the first.
  if (best.distance != best.distance)
    return first == hint ? best : centre.project_to_segment(point, first);
  for (std::size_t k = first; k <= last; ++k) {
    if (k == hint || surely_farther(centre, k, point, best.distance)) continue;
    const PolylineProjection candidate = centre.project_to_segment(point, k);
    if (candidate.distance < best.distance ||
        (candidate.distance == best.distance && k < best.segment))
      best = candidate;
  }
  return best;
}

// Far above width_at's rounding (an interpolation between two samples lies within a few ulps of
// the nearer one's range), far below anything that matters.
constexpr double kWidthMargin = 1e-9;

// Looks for `point` on `lane` among the segments around `segment` (the whole lane when the
// nearest is at the edge of that window). `narrowest`, when given, holds the lane's narrowest
// width on each side (left, right): a point nearer the centre line than that is within the width
// wherever it is along the lane, and the width need not be looked up.
LaneLook look_on(const RoadMap& map, LaneIndex lane, std::size_t segment, MapPoint point,
                 const std::pair<double, double>* narrowest = nullptr) {
  const Polyline& centre = map.lane(lane).centre_line;
  std::size_t first = segment > kSearchSegments ? segment - kSearchSegments : 0;
  std::size_t last = std::min(segment + kSearchSegments, centre.segment_count() - 1);
  PolylineProjection best = nearest_in_window(centre, first, last, std::min(segment, last), point);
  bool at_window_edge = (best.segment == first && first > 0) ||
                        (best.segment == last && last + 1 < centre.segment_count());
  if (at_window_edge) best = centre.project(point);
  // Beyond an end of the lane, the nearest point is the end point and lies off the normal.
  bool beside = best.distance <= std::abs(best.lateral) + 1e-9;
  LaneLook look;
  look.segment = best.segment;
  look.past_end = !beside && best.s >= centre.length() - 1e-9;
  if (!beside) return look;
  if (narrowest != nullptr &&
      std::abs(best.lateral) <=
          (best.lateral >= 0 ? narrowest->first : narrowest->second) - kWidthMargin) {
    look.fix = LaneFix{static_cast<std::int32_t>(lane), best.s};
    return look;
  }
  double width = best.lateral >= 0 ? lane_left_width_at(map, lane, best.s)
                                   : lane_right_width_at(map, lane, best.s);
  if (std::abs(best.lateral) <= width) look.fix = LaneFix{static_cast<std::int32_t>(lane), best.s};
  return look;
}

}  // namespace

LaneFix LaneTracker::update(const RoadMap& map, MapPoint point, double heading) {
  if (lane_ >= 0) {
    const auto lane = static_cast<LaneIndex>(lane_);
    if (!segment_known_) {
      segment_ = map.lane(lane).centre_line.segment_at(assumed_s_);
      segment_known_ = true;
    }
    const std::pair<double, double> narrowest{map.lane(lane).narrowest_left_width,
                                              map.lane(lane).narrowest_right_width};
    LaneLook here = look_on(map, lane, segment_, point, &narrowest);
    if (here.fix) {
      segment_ = here.segment;
      return *here.fix;
    }
    // Driven off the end: almost always onto a successor. Among those that contain the point
    // (a junction's connectors overlap where they begin), the one heading most like the actor.
    if (here.past_end) {
      std::optional<LaneLook> chosen;
      double chosen_difference = 0;
      for (LaneIndex successor : map.lane(lane).successors) {
        LaneLook there = look_on(map, successor, 0, point);
        if (!there.fix) continue;
        double difference = std::abs(
            angle_difference(heading, map.lane(successor).centre_line.heading_at(there.fix->s)));
        if (!chosen || difference < chosen_difference - 1e-9) {
          chosen = there;
          chosen_difference = difference;
        }
      }
      if (chosen) {
        lane_ = chosen->fix->lane;
        segment_ = chosen->segment;
        return *chosen->fix;
      }
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

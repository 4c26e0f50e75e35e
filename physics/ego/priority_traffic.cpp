// Priority traffic at a stop or yield sign (priority_traffic.hpp): each moving vehicle near the
// ego is found on its lane, and followed along it and the lanes ahead of it (a few successors, as
// far as it drives within the critical gap) to where the ego's path meets them.
#include "physics/ego/priority_traffic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "physics/map/lane_queries.hpp"

namespace scenfuzz {
namespace {

constexpr int kLanesAhead = 4;  // successors followed from the vehicle's own lane

// Whether traffic on `lane` gives way itself: a stop or yield sign on it or on a lane leading into
// it (another minor approach, another roundabout entry). It has no priority over the ego.
bool yields(const RoadMap& map, LaneIndex lane) {
  auto signed_lane = [&](LaneIndex l) {
    for (const LaneFeature& feature : map.lane(l).features)
      if (feature.kind == FeatureKind::stop_sign || feature.kind == FeatureKind::yield_sign)
        return true;
    return false;
  };
  if (signed_lane(lane)) return true;
  const Lane& here = map.lane(lane);
  return std::any_of(here.predecessors.begin(), here.predecessors.end(),
                     [&](LaneIndex before) { return before != lane && signed_lane(before); });
}

// Metres the vehicle at `s` on `lane` has to drive to `point` on the same lane (negative: past it).
double ahead_on_lane(const RoadMap& map, LaneIndex lane, double s, double point,
                     double body_length) {
  double ahead = point - s;
  if (ahead < -body_length && runs_into_itself(map, lane)) ahead += map.lane(lane).length();
  return ahead;
}

// Metres along the lanes from `s` on `lane` to the start of the nearest following lane with a
// conflict point, within `reach`, or infinity.
double distance_to_point(const RoadMap& map, std::span<const ConflictPoint> points, LaneIndex lane,
                         double s, double reach) {
  double best = std::numeric_limits<double>::infinity();
  struct Step {
    LaneIndex lane;
    double to_end;  // m from the vehicle to this lane's end
    int depth;
  };
  std::vector<Step> open{{lane, map.lane(lane).length() - s, 0}};
  while (!open.empty()) {
    const Step step = open.back();
    open.pop_back();
    if (step.to_end >= best || step.to_end > reach) continue;
    for (LaneIndex next : map.lane(step.lane).successors) {
      if (next == step.lane || yields(map, next)) continue;
      // To the start of the conflicting lane, not to the point on it: a vehicle coming into the
      // junction behind the ego's merge still catches up with an ego that pulls out slowly.
      bool found = false;
      for (const ConflictPoint& point : points)
        if (point.lane == next) {
          best = std::min(best, step.to_end);
          found = true;
        }
      if (!found && step.depth + 1 < kLanesAhead)
        open.push_back({next, step.to_end + map.lane(next).length(), step.depth + 1});
    }
  }
  return best;
}

}  // namespace

bool short_of_conflict(const RoadMap& map, std::span<const ConflictPoint> points, LaneIndex lane,
                       double s, double length, double reach) {
  bool any = false;
  const bool ring = runs_into_itself(map, lane);
  for (const ConflictPoint& point : points) {
    if (point.lane != lane) continue;
    any = true;
    const double ahead = ahead_on_lane(map, lane, s, point.s, length);
    if (ahead >= -length && (!ring || ahead <= reach)) return true;
  }
  return !any;
}

bool priority_traffic(const RoadMap& map, std::span<const ConflictPoint> points,
                      std::span<const WorldObject> objects, MapPoint ego,
                      const PriorityTrafficSettings& settings) {
  if (points.empty()) return false;
  for (const WorldObject& object : objects) {
    if (object.kind != TraceActorKind::vehicle) continue;  // cyclists are vehicles here
    const double dx = object.x - ego.x, dy = object.y - ego.y;
    if (dx * dx + dy * dy > settings.watch * settings.watch) continue;
    const auto on = project_to_lane(map, {object.x, object.y}, object.heading);
    if (!on || !on->inside) continue;
    // One standing or crawling, at its own line or on the point, is first come, first go: what
    // stands in the ego's path stops it anyway (its object constraints), and waiting on it could
    // last for ever.
    if (object.speed < settings.moving_speed || object.reversing) continue;
    if (yields(map, on->lane)) continue;
    const double reach = settings.critical_gap * object.speed;
    for (const ConflictPoint& point : points) {
      if (point.lane != on->lane) continue;
      const double ahead = ahead_on_lane(map, on->lane, on->s, point.s, object.length);
      // On the point (within its length either side), or coming and soon there.
      if (std::abs(ahead) <= object.length || (ahead > 0 && ahead < reach)) return true;
    }
    if (distance_to_point(map, points, on->lane, on->s, reach) < reach) return true;
  }
  return false;
}

}  // namespace scenfuzz

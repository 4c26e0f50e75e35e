// Priority traffic at a stop or yield sign (priority_traffic.hpp): each vehicle near the ego is
// found on its lane, and followed along the lanes ahead of it (a few successors, as far as it
// drives within the critical gap) to where they first meet a lane of the conflict set.
#include "physics/ego/priority_traffic.hpp"

#include <algorithm>
#include <limits>

#include "physics/map/lane_queries.hpp"

namespace scenfuzz {
namespace {

constexpr int kLanesAhead = 4;  // successors followed from the vehicle's own lane

bool conflicting(const std::vector<LaneIndex>& conflicts, LaneIndex lane) {
  return std::binary_search(conflicts.begin(), conflicts.end(), lane);
}

// Metres along the lanes from `s` on `lane` to the start of the nearest lane in `conflicts`
// within `reach`, or infinity.
double distance_to_conflict(const RoadMap& map, const std::vector<LaneIndex>& conflicts,
                            LaneIndex lane, double s, double reach) {
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
      if (conflicting(conflicts, next)) {
        best = std::min(best, step.to_end);
      } else if (step.depth + 1 < kLanesAhead) {
        open.push_back({next, step.to_end + map.lane(next).length(), step.depth + 1});
      }
    }
  }
  return best;
}

}  // namespace

bool priority_traffic(const RoadMap& map, const std::vector<LaneIndex>& conflicts,
                      std::span<const WorldObject> objects, MapPoint ego,
                      const PriorityTrafficSettings& settings) {
  if (conflicts.empty()) return false;
  for (const WorldObject& object : objects) {
    if (object.kind != TraceActorKind::vehicle) continue;  // cyclists are vehicles here
    const double dx = object.x - ego.x, dy = object.y - ego.y;
    if (dx * dx + dy * dy > settings.watch * settings.watch) continue;
    const auto on = project_to_lane(map, {object.x, object.y}, object.heading);
    if (!on || !on->inside) continue;
    if (conflicting(conflicts, on->lane)) return true;  // in the junction, across the ego's way
    if (object.speed < settings.moving_speed || object.reversing) continue;
    const double reach = settings.critical_gap * object.speed;
    if (distance_to_conflict(map, conflicts, on->lane, on->s, reach) < reach) return true;
  }
  return false;
}

}  // namespace scenfuzz

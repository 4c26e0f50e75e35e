// Walking the lanes ahead (see lanes_ahead.hpp).
#include "physics/simulation/lanes_ahead.hpp"

#include <algorithm>

#include "physics/map/lane_route.hpp"

namespace scenfuzz {
namespace {

constexpr double kMinimumLookahead = 40;   // m
constexpr double kLookaheadTime = 6;       // s of travel
constexpr std::size_t kMaximumLanes = 64;  // lanes walked ahead, for rings of tiny lanes

}  // namespace

std::vector<LaneAhead> lanes_ahead(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                                   double reach, bool& dead_end) {
  std::vector<LaneAhead> lanes{{at.lane, -at.s}};
  dead_end = false;
  while (lanes.size() < kMaximumLanes) {
    const LaneAhead& last = lanes.back();
    double end = last.offset + map.lane(last.lane).length();
    if (end > reach) break;
    LaneIndex next = next_lane(last.lane);
    if (next == last.lane) {
      dead_end = true;
      break;
    }
    LinkPoints link = link_points(map, last.lane, next);
    lanes.push_back({next, last.offset + link.exit_s - link.entry_s});
  }
  return lanes;
}

double lane_lookahead(double speed) { return std::max(kMinimumLookahead, speed * kLookaheadTime); }

}  // namespace scenfuzz

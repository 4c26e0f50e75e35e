// The junction priority rule for manoeuvre phases (see phase_junction.hpp).
#include "physics/simulation/phase_junction.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/map/lane_conflicts.hpp"
#include "physics/simulation/lane_cruise.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kNever = std::numeric_limits<double>::quiet_NaN();
constexpr double kGiveWayTime = 4.0;    // s: oncoming traffic arriving sooner is given way to
constexpr double kPatience = 5.0;       // s standing held before it goes on carefully
constexpr double kStandingSpeed = 0.1;  // m/s
constexpr double kComingSpeed = 1.0;    // m/s: slower, an oncoming vehicle is waiting, not coming

bool is_vehicle(const WorldSnapshot& world, std::uint32_t k) {
  return world.kinds[k] == TraceActorKind::vehicle || world.kinds[k] == TraceActorKind::ego;
}

bool meets(const RoadMap& map, LaneIndex mine, LaneIndex other) {
  const std::vector<ConflictPoint>& points = map.junction_conflict_points(mine);
  return std::any_of(points.begin(), points.end(),
                     [&](const ConflictPoint& point) { return point.lane == other; });
}

// Whether a red light stops the traffic of lane `lane` at its end.
bool red_at_end(const WorldSnapshot& world, LaneIndex lane) {
  for (const LaneFeature& feature : world.map->lane(lane).features)
    if (feature.kind == FeatureKind::traffic_light && feature.index < world.lights.size() &&
        world.lights[feature.index] == SignalColour::red)
      return true;
  return false;
}

// Whether actor k, on an approach lane, comes into a lane that meets `mine` and is not a left
// turn within the give-way time.
bool oncoming_into(const WorldSnapshot& world, std::uint32_t k, LaneIndex mine) {
  const RoadMap& map = *world.map;
  const auto lane = static_cast<LaneIndex>(world.lanes[k].lane);
  const double speed = world.states[k].speed;
  if (map.lane(lane).junction || speed < kComingSpeed || red_at_end(world, lane)) return false;
  const double to_end = map.lane(lane).length() - world.lanes[k].s - world.lengths[k] / 2;
  if (to_end > speed * kGiveWayTime) return false;
  const std::vector<LaneIndex>& conflicts = map.junction_conflicts(mine);
  for (LaneIndex next : map.lane(lane).successors)
    if (map.lane(next).turn != LaneTurn::left &&
        std::find(conflicts.begin(), conflicts.end(), next) != conflicts.end() &&
        meets(map, mine, next))
      return true;
  return false;
}

// Who has the way over junction lane `mine`: someone inside, someone oncoming.
struct Priority {
  bool inside = false;
  bool oncoming = false;
};

Priority priority_over(const WorldSnapshot& world, std::uint32_t self, LaneIndex mine) {
  const RoadMap& map = *world.map;
  const std::vector<LaneIndex>& conflicts = map.junction_conflicts(mine);
  const bool turning_left = map.lane(mine).turn == LaneTurn::left;
  Priority priority;
  for (std::uint32_t k = 0; k < world.states.size(); ++k) {
    if (k == self || world.lanes[k].lane < 0 || !present_in(world, k) || !is_vehicle(world, k))
      continue;
    const auto lane = static_cast<LaneIndex>(world.lanes[k].lane);
    if (std::find(conflicts.begin(), conflicts.end(), lane) != conflicts.end() &&
        meets(map, mine, lane))
      priority.inside = true;
    if (turning_left && oncoming_into(world, k, mine)) priority.oncoming = true;
  }
  return priority;
}

// Over the junction lanes from `entry` on, as far as they are in the same junction.
Priority priority_over_stretch(const WorldSnapshot& world, std::uint32_t self,
                               const std::vector<LaneAhead>& lanes,
                               std::vector<LaneAhead>::const_iterator entry) {
  const RoadMap& map = *world.map;
  Priority priority;
  for (auto lane = entry;
       lane != lanes.end() && map.lane(lane->lane).junction == map.lane(entry->lane).junction;
       ++lane) {
    const Priority on = priority_over(world, self, lane->lane);
    priority.inside = priority.inside || on.inside;
    priority.oncoming = priority.oncoming || on.oncoming;
  }
  return priority;
}

}  // namespace

double junction_entry_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                            const NextLane& next_lane, const ActorClass& body, JunctionWait& wait) {
  const RoadMap& map = *world.map;
  const double v = world.states[self].speed;
  bool dead_end = false;
  const std::vector<LaneAhead> lanes = lanes_ahead(map, at, next_lane, lane_lookahead(v), dead_end);
  auto entry = std::find_if(lanes.begin(), lanes.end(),
                            [&](const LaneAhead& lane) { return map.lane(lane.lane).junction; });
  // Inside a junction (or with none ahead) nobody is given way to.
  if (entry == lanes.begin() || entry == lanes.end() || entry->lane == wait.released) {
    wait.held_since = kNever;
    return kInfinity;
  }
  const double gap = entry->offset - body.length / 2;
  if (gap < v * v / (2 * body.max_deceleration)) return kInfinity;  // committed
  const Priority priority = priority_over_stretch(world, self, lanes, entry);
  // Patience breaks a standstill behind someone inside who does not leave; oncoming traffic
  // always passes, and the gap a left turn waits for comes.
  if (!priority.inside || priority.oncoming) wait.held_since = kNever;
  if (!priority.inside && !priority.oncoming) return kInfinity;
  if (priority.inside && !priority.oncoming) {
    if (v < kStandingSpeed && std::isnan(wait.held_since)) wait.held_since = world.time;
    if (world.time - wait.held_since >= kPatience) {
      wait.released = entry->lane;
      wait.held_since = kNever;
      return kInfinity;
    }
  }
  return stop_line_limit(v, gap, body);
}

}  // namespace scenfuzz

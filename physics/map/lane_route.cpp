// A* over the lane graph, and the road furniture ahead on a route.
//
// The search state is a lane entered at some s. Following a successor enters the next lane at
// s = 0 (or where it joins a ring part-way); a lane change enters a forward neighbour beside the
// entry point (the route changes lane where it entered, which fixes the sequence of lanes; where
// exactly to change is the driver's choice). Costs are metres: the distance driven plus a fixed
// cost per lane change. The heuristic, the straight-line distance to the target, never
// overestimates, so the first goal taken is the cheapest route.
#include "physics/map/lane_route.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace scenfuzz {

namespace {

enum class Entry { start, successor, lane_change, goal };

struct SearchState {
  LaneIndex lane = 0;
  double entry_s = 0;
  double cost = 0;  // from the start to the entry point
  Entry entry = Entry::start;
  std::size_t parent = 0;
  double parent_exit_s = 0;  // where the route left the parent's lane
};

struct Queued {
  double priority = 0;
  std::size_t state = 0;

  bool operator>(const Queued& other) const {
    // Equal priorities pop in insertion order, so routes do not depend on heap internals.
    return priority > other.priority || (priority == other.priority && state > other.state);
  }
};

// An entry already expanded on a lane.
struct Expanded {
  double entry_s;
  double cost;
};

// Whether expanding `state` can find nothing the expanded entries of its lane have not. An entry
// that entered no later and reaches this entry point no more expensively did all this one could.
// A lane change lands beside where it left, at an s of its own; were such entries compared
// exactly, changing back and forth would creep along a road, each time at a new s, and the search
// would grow without useful bound. So a lane-change entry must also reach the lane's end more
// cheaply than every earlier entry (its goal, if on this lane, has already been pushed).
bool dominated(const std::vector<Expanded>& expanded, const SearchState& state) {
  for (const Expanded& earlier : expanded) {
    if (earlier.entry_s <= state.entry_s &&
        earlier.cost + (state.entry_s - earlier.entry_s) <= state.cost)
      return true;
    if (state.entry == Entry::lane_change &&
        earlier.cost - earlier.entry_s <= state.cost - state.entry_s)
      return true;
  }
  return false;
}

LaneRoute reconstruct(const std::vector<SearchState>& states, std::size_t goal) {
  std::vector<std::size_t> chain;
  for (std::size_t state = goal;; state = states[state].parent) {
    chain.push_back(state);
    if (states[state].entry == Entry::start) break;
  }
  std::reverse(chain.begin(), chain.end());
  LaneRoute route;
  // chain: start, ..., the state on the target lane, the goal marker.
  for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
    const SearchState& state = states[chain[i]];
    const SearchState& next = states[chain[i + 1]];
    route.segments.push_back({state.lane, state.entry_s, next.parent_exit_s});
    route.length += next.parent_exit_s - state.entry_s;
    if (next.entry == Entry::lane_change) ++route.lane_changes;
  }
  return route;
}

}  // namespace

std::optional<LaneRoute> find_route(const RoadMap& map, LanePosition from, LanePosition to,
                                    const RouteOptions& options) {
  if (from.lane >= map.lanes().size() || to.lane >= map.lanes().size()) return std::nullopt;
  from.s = std::clamp(from.s, 0.0, map.lane(from.lane).length());
  to.s = std::clamp(to.s, 0.0, map.lane(to.lane).length());

  const MapPoint target = map.lane(to.lane).centre_line.point_at(to.s);
  auto heuristic = [&](LaneIndex lane, double s) {
    return distance(map.lane(lane).centre_line.point_at(s), target);
  };
  std::vector<SearchState> states;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<>> open;
  auto push = [&](SearchState state, double priority) {
    states.push_back(state);
    open.push({priority, states.size() - 1});
  };
  std::vector<std::vector<Expanded>> expanded(map.lanes().size());

  push({from.lane, from.s, 0, Entry::start, 0, 0}, heuristic(from.lane, from.s));
  while (!open.empty()) {
    Queued top = open.top();
    open.pop();
    const SearchState state = states[top.state];
    if (state.entry == Entry::goal) return reconstruct(states, top.state);

    const Lane& lane = map.lane(state.lane);
    if (state.lane == to.lane && to.s >= state.entry_s) {
      double cost = state.cost + (to.s - state.entry_s);
      push({state.lane, to.s, cost, Entry::goal, top.state, to.s}, cost);
    }
    if (dominated(expanded[state.lane], state)) continue;
    expanded[state.lane].push_back({state.entry_s, state.cost});

    for (LaneIndex successor : lane.successors) {
      LinkPoints link = link_points(map, state.lane, successor);
      if (link.exit_s < state.entry_s) continue;  // the branch is behind us on this lane
      double cost = state.cost + (link.exit_s - state.entry_s);
      push({successor, link.entry_s, cost, Entry::successor, top.state, link.exit_s},
           cost + heuristic(successor, link.entry_s));
    }
    if (!options.allow_lane_changes) continue;
    MapPoint here = lane.centre_line.point_at(state.entry_s);
    for (const auto* neighbours : {&lane.left_forward_neighbours, &lane.right_forward_neighbours}) {
      for (LaneIndex neighbour : *neighbours) {
        if (!lane_change_allowed(map, state.lane, neighbour)) continue;
        PolylineProjection beside = map.lane(neighbour).centre_line.project(here);
        double cost = state.cost + beside.distance + options.lane_change_cost;
        push({neighbour, beside.s, cost, Entry::lane_change, top.state, state.entry_s},
             cost + heuristic(neighbour, beside.s));
      }
    }
  }
  return std::nullopt;
}

std::optional<LaneRoute> find_route(const RoadMap& map, MapPose from, MapPose to,
                                    const RouteOptions& options) {
  auto start = project_to_lane(map, from.position, from.heading);
  auto target = project_to_lane(map, to.position, to.heading);
  if (!start || !target) return std::nullopt;
  return find_route(map, LanePosition{start->lane, start->s, start->lateral},
                    LanePosition{target->lane, target->s, target->lateral}, options);
}

std::optional<FeatureAhead> next_feature_ahead(const RoadMap& map, const LaneRoute& route,
                                               double route_distance,
                                               std::optional<FeatureKind> kind) {
  double segment_start = 0;  // route distance at the start of the segment
  for (const RouteSegment& segment : route.segments) {
    for (const LaneFeature& feature : map.lane(segment.lane).features) {
      if (kind && feature.kind != *kind) continue;
      if (feature.s_begin < segment.s_begin || feature.s_begin > segment.s_end) continue;
      double at = segment_start + (feature.s_begin - segment.s_begin);
      if (at < route_distance) continue;
      return FeatureAhead{feature.kind, feature.index, segment.lane, feature.s_begin,
                          at - route_distance};
    }
    segment_start += segment.s_end - segment.s_begin;
  }
  return std::nullopt;
}

LinkPoints link_points(const RoadMap& map, LaneIndex from, LaneIndex to) {
  const Polyline& from_line = map.lane(from).centre_line;
  const Polyline& to_line = map.lane(to).centre_line;
  const MapPoint from_end = from_line.points().back();
  const MapPoint to_start = to_line.points().front();
  LinkPoints link{from_line.length(), 0};
  if (distance(from_end, to_start) <= kJointTolerance) return link;
  PolylineProjection exit = from_line.project(to_start);
  if (exit.distance <= kJointTolerance) {
    link.exit_s = exit.s;  // `to` branches off part-way along `from`
    return link;
  }
  PolylineProjection entry = to_line.project(from_end);
  if (entry.distance <= kJointTolerance) link.entry_s = entry.s;  // `from` joins `to` part-way
  return link;
}

LaneRoute defer_lane_changes(const RoadMap& map, LaneRoute route, double distance) {
  auto& segments = route.segments;
  for (std::size_t k = 0; k + 1 < segments.size(); ++k) {
    RouteSegment& leaving = segments[k];
    RouteSegment& entering = segments[k + 1];
    const Lane& lane = map.lane(leaving.lane);
    auto beside = [&](const std::vector<LaneIndex>& neighbours) {
      return std::find(neighbours.begin(), neighbours.end(), entering.lane) != neighbours.end();
    };
    if (!beside(lane.left_forward_neighbours) && !beside(lane.right_forward_neighbours)) continue;
    // Keep a metre of the entered lane, so the segment after the change is not empty.
    double shift =
        std::min({distance - (leaving.s_end - leaving.s_begin), lane.length() - leaving.s_end,
                  entering.s_end - entering.s_begin - 1.0});
    if (shift <= 0) continue;
    leaving.s_end += shift;
    entering.s_begin += shift;
  }
  return route;
}

}  // namespace scenfuzz

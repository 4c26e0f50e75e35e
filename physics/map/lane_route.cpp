// A* over the lane graph, and the road furniture ahead on a route.
//
// The search state is a lane entered at some s. Following a successor enters the next lane at
// s = 0; a lane change enters a forward neighbour beside the entry point (the route changes lane
// where it entered, which fixes the sequence of lanes; where exactly to change is the driver's
// choice). Costs are metres: the distance driven plus a fixed cost per lane change. The heuristic,
// the straight-line distance to the target, never overestimates, so the first goal taken is the
// cheapest route.
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
};

struct Queued {
  double priority = 0;
  std::size_t state = 0;

  bool operator>(const Queued& other) const {
    // Equal priorities pop in insertion order, so routes do not depend on heap internals.
    return priority > other.priority || (priority == other.priority && state > other.state);
  }
};

LaneRoute reconstruct(const std::vector<SearchState>& states, std::size_t goal, double goal_s,
                      const RoadMap& map) {
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
    double s_end = next.entry == Entry::successor     ? map.lane(state.lane).length()
                   : next.entry == Entry::lane_change ? state.entry_s
                                                      : goal_s;
    route.segments.push_back({state.lane, state.entry_s, s_end});
    route.length += s_end - state.entry_s;
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
  if (from.lane == to.lane && to.s >= from.s) {
    LaneRoute route;
    route.segments.push_back({from.lane, from.s, to.s});
    route.length = to.s - from.s;
    return route;
  }

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
  // The cheapest cost yet of reaching each lane's end: a later entry that cannot beat it is
  // dominated (except for reaching the target, which is checked before pruning).
  std::vector<double> best_end_cost(map.lanes().size(), std::numeric_limits<double>::infinity());

  push({from.lane, from.s, 0, Entry::start, 0}, heuristic(from.lane, from.s));
  while (!open.empty()) {
    Queued top = open.top();
    open.pop();
    const SearchState state = states[top.state];
    if (state.entry == Entry::goal) return reconstruct(states, top.state, to.s, map);

    const Lane& lane = map.lane(state.lane);
    if (state.lane == to.lane && to.s >= state.entry_s) {
      double cost = state.cost + (to.s - state.entry_s);
      push({state.lane, to.s, cost, Entry::goal, top.state}, cost);
    }
    double end_cost = state.cost + (lane.length() - state.entry_s);
    if (end_cost >= best_end_cost[state.lane]) continue;
    best_end_cost[state.lane] = end_cost;

    for (LaneIndex successor : lane.successors)
      push({successor, 0, end_cost, Entry::successor, top.state},
           end_cost + heuristic(successor, 0));
    if (!options.allow_lane_changes) continue;
    MapPoint here = lane.centre_line.point_at(state.entry_s);
    for (const auto* neighbours : {&lane.left_forward_neighbours, &lane.right_forward_neighbours}) {
      for (LaneIndex neighbour : *neighbours) {
        if (!lane_change_allowed(map, state.lane, neighbour)) continue;
        PolylineProjection beside = map.lane(neighbour).centre_line.project(here);
        double cost = state.cost + beside.distance + options.lane_change_cost;
        push({neighbour, beside.s, cost, Entry::lane_change, top.state},
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

}  // namespace scenfuzz

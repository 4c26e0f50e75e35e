// The ego's manoeuvres from the lanes it drives on. A turn is read from the map's lane turn
// types (or, on a map without them, from how far a junction lane bends); a lane change from the
// trace's lane column moving to a neighbour, stretched over the samples where the ego is off
// its lane's centre line towards the other lane.
#include "oracle/law_manoeuvre.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/map/lane_route.hpp"
#include "physics/map/scenario_position.hpp"

namespace scenfuzz {

namespace {

// Apollo's planner switches the turn signal on this far before a turn (its turn_signal_distance).
constexpr double kTurnSignalDistance = 100;  // m
// A junction lane that bends more than this turns (maps without turn types).
constexpr double kTurnAngle = std::numbers::pi / 6;
// Further than this from its lane's centre line towards the next lane, the ego is changing lane;
// the reference driver keeps well within it when it keeps its lane.
constexpr double kLaneChangeOffset = 0.3;  // m
constexpr double kTurnAroundAngle = 3 * std::numbers::pi / 4;
// Past the end of a run the way ahead is followed this many lanes at most (short lanes).
constexpr std::size_t kMaxLanesBeyondRun = 64;
// A vehicle drives the ego's way when its heading is within this of the ego's.
constexpr double kSameWay = std::numbers::pi / 4;

bool contains(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

bool is_successor(const RoadMap& map, LaneIndex from, LaneIndex to) {
  return contains(map.lane(from).successors, to);
}

double segment_heading(const Polyline& line, std::size_t segment) {
  return line.heading_at(line.arc_lengths()[segment]);
}

// How far the heading turns (left positive) driving a centre line from s = from to s = to; to <
// from goes round a closed ring through its start.
double heading_change(const Polyline& line, double from, double to) {
  if (to < from)
    return heading_change(line, from, line.length()) +
           angle_difference(line.heading_at(0), line.heading_at(line.length())) +
           heading_change(line, 0, to);
  double change = 0;
  const std::size_t last = line.segment_at(to);
  for (std::size_t k = line.segment_at(from); k < last; ++k)
    change += angle_difference(segment_heading(line, k + 1), segment_heading(line, k));
  return change;
}

// Metres driven on a lane from s = from to s = to, round a ring when to < from.
double driven_length(const Lane& lane, double from, double to) {
  return to >= from ? to - from : lane.length() - from + to;
}

// Which way lanes turn: the map's turn types, or on a map that gives no junction lane one (the
// built-in roundabout), the heading change along the junction lane.
class LaneTurns {
 public:
  explicit LaneTurns(const RoadMap& map) : map_(map) {
    typed_ = std::any_of(map.lanes().begin(), map.lanes().end(), [](const Lane& lane) {
      return lane.junction && lane.turn != LaneTurn::none;
    });
  }

  LaneTurn turn(LaneIndex index, double s_from, double s_to) const {
    const Lane& lane = map_.lane(index);
    if (typed_ || !lane.junction) return lane.turn;
    const double change = heading_change(lane.centre_line, s_from, s_to);
    if (change > kTurnAngle) return LaneTurn::left;
    if (change < -kTurnAngle) return LaneTurn::right;
    return LaneTurn::none;
  }

  LaneTurn turn(LaneIndex index) const { return turn(index, 0, map_.lane(index).length()); }

 private:
  const RoadMap& map_;
  bool typed_ = false;
};

// Apollo's planner signals left for a U-turn, as for a left turn.
double signal_code(LaneTurn turn) {
  switch (turn) {
    case LaneTurn::none: return kForward;
    case LaneTurn::left: return kLeft;
    case LaneTurn::right: return kRight;
    case LaneTurn::u_turn: return kLeft;
  }
  return kForward;
}

struct Run {
  const Trace& trace;
  const RoadMap& map;
  const LaneVisits& visits;
  const LaneTurns& turns;
  std::optional<LaneRoute> rest;  // from the ego's last place on the lanes to its target
};

// Where the ego's path enters the lane of visit k: the link's entry point when it came off the
// previous lane's end, else where the ego first was on it.
double entry_s(const Run& run, std::size_t k) {
  const std::vector<LaneIndex>& lanes = run.visits.lanes;
  if (k > 0 && is_successor(run.map, lanes[k - 1], lanes[k]))
    return link_points(run.map, lanes[k - 1], lanes[k]).entry_s;
  return run.trace.actors[kEgo].s[run.visits.first_sample[k]];
}

// Where it leaves that lane: onto a successor at the link, sideways where it last was on it, or
// (the run ends on it) at its end.
double exit_s(const Run& run, std::size_t k) {
  const std::vector<LaneIndex>& lanes = run.visits.lanes;
  if (k + 1 >= lanes.size()) return run.map.lane(lanes[k]).length();
  if (is_successor(run.map, lanes[k], lanes[k + 1]))
    return link_points(run.map, lanes[k], lanes[k + 1]).exit_s;
  return run.trace.actors[kEgo].s[run.visits.last_sample[k]];
}

// The turn of route segment k, a junction lane, or of the last of the segments after it in the
// same junction (a roundabout's entry, ring and exit): the lane by which the route leaves.
double route_passage_turn(const Run& run, std::size_t k) {
  const std::vector<RouteSegment>& segments = run.rest->segments;
  const std::optional<std::uint32_t> junction = run.map.lane(segments[k].lane).junction;
  while (k + 1 < segments.size() && run.map.lane(segments[k + 1].lane).junction == junction) ++k;
  return signal_code(run.turns.turn(segments[k].lane, segments[k].s_begin, segments[k].s_end));
}

// Past the lanes the run shows: the ego's route to its target, or without one along successors
// while the way is unambiguous, to the first junction, whose lanes must then all turn the same
// way for the turn to be known. `distance` reaches the end of the last lane of the run.
double turn_beyond_run(const Run& run, double distance) {
  if (run.rest) {
    const std::vector<RouteSegment>& segments = run.rest->segments;
    for (std::size_t k = 1; k < segments.size() && distance <= kTurnSignalDistance; ++k) {
      if (run.map.lane(segments[k].lane).junction) return route_passage_turn(run, k);
      distance += segments[k].s_end - segments[k].s_begin;
    }
    return kForward;
  }
  LaneIndex current = run.visits.lanes.back();
  for (std::size_t step = 0; step < kMaxLanesBeyondRun && distance <= kTurnSignalDistance; ++step) {
    const std::vector<LaneIndex>& successors = run.map.lane(current).successors;
    if (successors.empty()) return kForward;
    if (run.map.lane(successors.front()).junction) {
      const double first = signal_code(run.turns.turn(successors.front()));
      for (LaneIndex successor : successors)
        if (!run.map.lane(successor).junction || signal_code(run.turns.turn(successor)) != first)
          return kForward;
      return first;
    }
    if (successors.size() > 1) return kForward;
    current = successors.front();
    distance += run.map.lane(current).length();
  }
  return kForward;
}

// The turn of the passage through the junction the ego enters at visit k: of the junction lane
// it leaves the junction by. Junction lanes overlap and the lane column can move from one to
// another (from the straight-on lane to the left turn that begins beside it), so that is the
// last of the consecutive visits in the junction; where the run ends in the junction, the last
// junction lane of its route on.
double passage_turn(const Run& run, std::size_t k) {
  const std::vector<LaneIndex>& lanes = run.visits.lanes;
  const std::optional<std::uint32_t> junction = run.map.lane(lanes[k]).junction;
  while (k + 1 < lanes.size() && run.map.lane(lanes[k + 1]).junction == junction) ++k;
  if (k + 1 == lanes.size() && run.rest && run.rest->segments.size() > 1 &&
      run.map.lane(run.rest->segments[1].lane).junction == junction)
    return route_passage_turn(run, 1);
  return signal_code(run.turns.turn(lanes[k], entry_s(run, k), exit_s(run, k)));
}

// The turn of the junction the ego is in, or of the next one on its path when that begins within
// kTurnSignalDistance of its front bumper.
double turn_ahead(const Run& run, std::size_t i) {
  const std::optional<std::size_t> visit = run.visits.visit_at[i];
  if (!visit) return kForward;
  const std::vector<LaneIndex>& lanes = run.visits.lanes;
  const TraceActor& ego = run.trace.actors[kEgo];
  const Lane& lane = run.map.lane(lanes[*visit]);
  if (lane.junction) return passage_turn(run, *visit);
  double distance = driven_length(lane, ego.s[i], exit_s(run, *visit)) - ego.length / 2;
  for (std::size_t k = *visit + 1; k < lanes.size(); ++k) {
    if (distance > kTurnSignalDistance) return kForward;
    const Lane& next = run.map.lane(lanes[k]);
    if (next.junction) return passage_turn(run, k);
    distance += driven_length(next, entry_s(run, k), exit_s(run, k));
  }
  return turn_beyond_run(run, distance);
}

// kLeft or kRight when `to` is the left or right forward neighbour of `from`, else kForward.
double neighbour_side(const RoadMap& map, LaneIndex from, LaneIndex to) {
  const Lane& a = map.lane(from);
  const Lane& b = map.lane(to);
  if (contains(a.left_forward_neighbours, to) || contains(b.right_forward_neighbours, from))
    return kLeft;
  if (contains(a.right_forward_neighbours, to) || contains(b.left_forward_neighbours, from))
    return kRight;
  return kForward;
}

// The ego's centre's offset from its lane's centre line at sample i, left positive.
double lateral_offset(const Trace& trace, const RoadMap& map, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  const auto lane = static_cast<LaneIndex>(ego.lane[i]);
  const double s = std::clamp(ego.s[i], 0.0, map.lane(lane).length());
  const MapPose pose = *lane_pose_at(map, lane, s);
  return -std::sin(pose.heading) * (ego.x[i] - pose.position.x) +
         std::cos(pose.heading) * (ego.y[i] - pose.position.y);
}

// Marks each lane change: from where the ego leaves its old lane's centre line towards the new
// lane to where it is back on the new lane's centre line.
void mark_lane_changes(const Trace& trace, const RoadMap& map, const LaneVisits& visits,
                       EgoManoeuvre& manoeuvre) {
  const TraceActor& ego = trace.actors[kEgo];
  for (std::size_t k = 0; k + 1 < visits.lanes.size(); ++k) {
    const LaneIndex from = visits.lanes[k], to = visits.lanes[k + 1];
    const double side = neighbour_side(map, from, to);
    if (side == kForward) continue;
    const double toward = side == kLeft ? 1 : -1;
    auto on = [&](std::size_t i, LaneIndex lane) {
      return ego.lane[i] == static_cast<std::int32_t>(lane);
    };
    std::size_t start = visits.last_sample[k];
    while (start > visits.first_sample[k] && on(start - 1, from) &&
           toward * lateral_offset(trace, map, start - 1) > kLaneChangeOffset)
      --start;
    std::size_t end = visits.first_sample[k + 1];
    while (end < visits.last_sample[k + 1] && on(end + 1, to) &&
           -toward * lateral_offset(trace, map, end + 1) > kLaneChangeOffset)
      ++end;
    for (std::size_t i = start; i <= end; ++i) {
      manoeuvre.direction[i] = side;
      manoeuvre.lane_changing[i] = 1;
    }
  }
}

// Where another vehicle is along the ego's heading: its footprint wholly ahead of the ego's,
// wholly behind, or beside (overlapping along); `near`: it drives the ego's way within
// kOvertakeBeside across.
enum class Along { behind, beside, ahead };
struct Relative {
  Along along = Along::ahead;
  bool near = false;
};

Relative relative_to_ego(const TraceActor& ego, const TraceActor& other, std::size_t i) {
  const double cos_h = std::cos(ego.heading[i]), sin_h = std::sin(ego.heading[i]);
  const double dx = other.x[i] - ego.x[i], dy = other.y[i] - ego.y[i];
  const double forward = dx * cos_h + dy * sin_h;
  const double across = -dx * sin_h + dy * cos_h;
  const double reach = (ego.length + other.length) / 2;
  Relative relative;
  relative.along = forward >= reach    ? Along::ahead
                   : forward <= -reach ? Along::behind
                                       : Along::beside;
  relative.near = std::abs(across) <= kOvertakeBeside &&
                  std::abs(angle_difference(other.heading[i], ego.heading[i])) < kSameWay;
  return relative;
}

// Samples [first, last] of one pass of a vehicle.
struct Pass {
  std::size_t first = 0, last = 0;
};

// Whether `other` was ahead of the ego in the ego's lane at sample i: the same lane, or one that
// follows it (a lane ends where a road is split into lanes).
bool ahead_in_lane(const RoadMap& map, const TraceActor& ego, const TraceActor& other,
                   std::size_t i) {
  if (!present_at(other, i) || ego.lane[i] < 0 || other.lane[i] < 0) return false;
  const auto mine = static_cast<LaneIndex>(ego.lane[i]);
  const auto theirs = static_cast<LaneIndex>(other.lane[i]);
  return (mine == theirs || is_successor(map, mine, theirs)) &&
         relative_to_ego(ego, other, i).along == Along::ahead;
}

// The lane change out that leads into a pass: walking back from `first` while the vehicle stays
// near and ahead (the ego following it), the first sample of the first lane change met, when
// the vehicle was ahead in the ego's lane as it began. nullopt otherwise: the ego passes a
// vehicle in another lane without leaving its own for it, which is no overtaking.
std::optional<std::size_t> start_of_pass(const Trace& trace, const RoadMap& map,
                                         const TraceActor& other, const EgoManoeuvre& manoeuvre,
                                         std::size_t first) {
  const TraceActor& ego = trace.actors[kEgo];
  for (std::size_t k = first + 1; k-- > 0;) {
    if (manoeuvre.lane_changing[k]) {
      while (k > 0 && manoeuvre.lane_changing[k - 1]) --k;
      if (ahead_in_lane(map, ego, other, k)) return k;
      return std::nullopt;
    }
    if (k == first) continue;  // beside: the pass itself
    const Relative relative = relative_to_ego(ego, other, k);
    if (!present_at(other, k) || relative.along != Along::ahead || !relative.near) break;
  }
  return std::nullopt;
}

// The lane change back after a pass, found the same way forward while the vehicle is behind.
std::size_t end_of_pass(const Trace& trace, const TraceActor& other, const EgoManoeuvre& manoeuvre,
                        std::size_t last) {
  const TraceActor& ego = trace.actors[kEgo];
  for (std::size_t k = last + 1; k < trace.sample_count(); ++k) {
    if (manoeuvre.lane_changing[k]) {
      while (k + 1 < trace.sample_count() && manoeuvre.lane_changing[k + 1]) ++k;
      return k;
    }
    const Relative relative = relative_to_ego(ego, other, k);
    if (!present_at(other, k) || relative.along != Along::behind || !relative.near) break;
  }
  return last;
}

// The passes of `other`: runs of samples where it is near and beside the ego, entered with it
// ahead and left with it behind (or at the end of the run).
std::vector<Pass> passes_of(const Trace& trace, const TraceActor& other) {
  const TraceActor& ego = trace.actors[kEgo];
  const std::size_t count = trace.sample_count();
  auto beside = [&](std::size_t i) {
    const Relative relative = relative_to_ego(ego, other, i);
    return present_at(other, i) && relative.near && relative.along == Along::beside;
  };
  auto is = [&](std::size_t i, Along along) {
    return present_at(other, i) && relative_to_ego(ego, other, i).along == along &&
           std::abs(angle_difference(other.heading[i], ego.heading[i])) < kSameWay;
  };
  std::vector<Pass> passes;
  for (std::size_t i = 0; i < count; ++i) {
    if (!beside(i)) continue;
    std::size_t last = i;
    while (last + 1 < count && beside(last + 1)) ++last;
    const bool from_behind = i > 0 && is(i - 1, Along::ahead);
    const bool left_in_front = last + 1 == count || is(last + 1, Along::behind);
    if (from_behind && left_in_front) passes.push_back({i, last});
    i = last;
  }
  return passes;
}

}  // namespace

LaneVisits lane_visits(const TraceActor& actor) {
  LaneVisits visits;
  visits.visit_at.resize(actor.lane.size());
  for (std::size_t i = 0; i < actor.lane.size(); ++i) {
    if (actor.lane[i] < 0) continue;
    const auto lane = static_cast<LaneIndex>(actor.lane[i]);
    if (visits.lanes.empty() || visits.lanes.back() != lane) {
      visits.lanes.push_back(lane);
      visits.first_sample.push_back(i);
      visits.last_sample.push_back(i);
    }
    visits.last_sample.back() = i;
    visits.visit_at[i] = visits.lanes.size() - 1;
  }
  return visits;
}

std::optional<LanePosition> ego_target(const ScenarioTemplate& scenario,
                                       std::span<const double> parameters, const Trace& trace,
                                       const RoadMap& map) {
  if (!scenario.ego.target || trace.sample_count() == 0) return std::nullopt;
  const TraceActor& ego = trace.actors[kEgo];
  const MapPose start{{ego.x[0], ego.y[0]}, ego.heading[0]};
  Diagnostics ignored;  // a target that cannot be placed leaves the way ahead to the map
  const std::optional<PlacedPosition> placed =
      place_position(map, scenario.ego.target->position, parameters, start, ignored);
  if (!placed) return std::nullopt;
  if (placed->lane)
    return LanePosition{*placed->lane,
                        map.lane(*placed->lane).centre_line.project(placed->pose.position).s, 0};
  const std::optional<LaneProjection> nearest = project_to_lane(map, placed->pose.position);
  if (!nearest) return std::nullopt;
  return LanePosition{nearest->lane, nearest->s, 0};
}

EgoManoeuvre ego_manoeuvre(const Trace& trace, const RoadMap& map,
                           const std::optional<LanePosition>& target) {
  const std::size_t count = trace.sample_count();
  const TraceActor& ego = trace.actors[kEgo];
  const LaneVisits visits = lane_visits(ego);
  const LaneTurns turns(map);
  Run run{trace, map, visits, turns, std::nullopt};
  if (target && !visits.lanes.empty()) {
    const LaneIndex last = visits.lanes.back();
    const double s = std::clamp(ego.s[visits.last_sample.back()], 0.0, map.lane(last).length());
    run.rest = find_route(map, LanePosition{last, s, 0}, *target);
  }
  EgoManoeuvre manoeuvre{std::vector<double>(count), std::vector<std::uint8_t>(count)};
  for (std::size_t i = 0; i < count; ++i) manoeuvre.direction[i] = turn_ahead(run, i);
  mark_lane_changes(trace, map, visits, manoeuvre);
  return manoeuvre;
}

std::vector<double> turning_around(const Trace& trace, const EgoManoeuvre& manoeuvre) {
  const TraceActor& ego = trace.actors[kEgo];
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (manoeuvre.direction[i] == kForward) continue;
    for (std::size_t j = i + 1;
         j < values.size() && trace.time[j] - trace.time[i] <= kTurnAroundWindow; ++j)
      if (std::abs(angle_difference(ego.heading[j], ego.heading[i])) > kTurnAroundAngle) {
        values[i] = 1;
        break;
      }
  }
  return values;
}

std::vector<double> overtaking(const Trace& trace, const RoadMap& map,
                               const EgoManoeuvre& manoeuvre) {
  std::vector<double> values(trace.sample_count());
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    const TraceActor& other = trace.actors[k];
    if (other.kind != TraceActorKind::vehicle) continue;
    for (const Pass& pass : passes_of(trace, other)) {
      const std::optional<std::size_t> first =
          start_of_pass(trace, map, other, manoeuvre, pass.first);
      if (!first) continue;
      const std::size_t last = end_of_pass(trace, other, manoeuvre, pass.last);
      for (std::size_t i = *first; i <= last; ++i) values[i] = 1;
    }
  }
  return values;
}

std::vector<double> current_lane_direction(const Trace& trace, const RoadMap& map) {
  // LawBreaker's coding of the manoeuvres a lane allows.
  constexpr double kForwardOnly = 0, kLeftOnly = 1, kRightOnly = 2, kUTurnOnly = 3;
  constexpr double kForwardOrLeft = 4, kForwardOrRight = 5, kAnyWay = 6, kLeftOrRight = 7;
  const LaneTurns turns(map);
  auto code = [&](LaneIndex index) {
    const Lane& lane = map.lane(index);
    if (lane.junction) {
      const LaneTurn turn = turns.turn(index);
      return turn == LaneTurn::u_turn ? kUTurnOnly : signal_code(turn);
    }
    bool forward = lane.successors.empty(), left = false, right = false, u_turn = false;
    for (LaneIndex successor : lane.successors) {
      if (!map.lane(successor).junction) {
        forward = true;
        continue;
      }
      switch (turns.turn(successor)) {
        case LaneTurn::none: forward = true; break;
        case LaneTurn::left: left = true; break;
        case LaneTurn::right: right = true; break;
        case LaneTurn::u_turn: u_turn = true; break;
      }
    }
    if (u_turn && !forward && !left && !right) return kUTurnOnly;
    left = left || u_turn;  // a U-turn leaves from the lane a left turn does
    if (forward)
      return left && right ? kAnyWay
             : left        ? kForwardOrLeft
             : right       ? kForwardOrRight
                           : kForwardOnly;
    return left && right ? kLeftOrRight : left ? kLeftOnly : kRightOnly;
  };
  const TraceActor& ego = trace.actors[kEgo];
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i)
    if (ego.lane[i] >= 0) values[i] = code(static_cast<LaneIndex>(ego.lane[i]));
  return values;
}

}  // namespace scenfuzz

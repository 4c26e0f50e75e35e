// Failure-mode signatures read from a trace and the map (see failure_mode.hpp for the rules).
#include "oracle/failure_mode.hpp"

#include <algorithm>
#include <cmath>

#include "physics/actors/actor_class.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/polygon.hpp"

namespace scenfuzz {
namespace {

std::size_t window_samples(const Trace& trace, double seconds) {
  return static_cast<std::size_t>(std::lround(seconds / trace.dt));
}

std::optional<LaneIndex> lane_at(const TraceActor& actor, std::size_t i) {
  if (actor.lane[i] < 0) return std::nullopt;
  return static_cast<LaneIndex>(actor.lane[i]);
}

bool contains(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

bool forward_neighbours(const RoadMap& map, LaneIndex a, LaneIndex b) {
  const Lane& lane = map.lane(a);
  return contains(lane.left_forward_neighbours, b) || contains(lane.right_forward_neighbours, b);
}

bool stopped_between(const TraceActor& ego, std::size_t from, std::size_t to) {
  for (std::size_t j = from; j < to; ++j)
    if (ego.speed[j] < kEgoStoppedSpeed) return true;
  return false;
}

bool changing_lane(const Trace& trace, const RoadMap& map, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  const std::optional<LaneIndex> here = lane_at(ego, i);
  if (!here) return false;
  const std::size_t w = window_samples(trace, kLaneChangeWindow);
  const std::size_t from = i > w ? i - w : 0;
  const std::size_t to = std::min(trace.sample_count(), i + w + 1);
  for (std::size_t j = from; j < to; ++j) {
    const std::optional<LaneIndex> there = lane_at(ego, j);
    if (there && *there != *here && forward_neighbours(map, *here, *there)) return true;
  }
  return false;
}

std::optional<EgoActivity> turning(const RoadMap& map, const TraceActor& ego, std::size_t i) {
  const std::optional<LaneIndex> lane = lane_at(ego, i);
  if (!lane || !map.lane(*lane).junction) return std::nullopt;
  switch (map.lane(*lane).turn) {
    case LaneTurn::left: return EgoActivity::turning_left;
    case LaneTurn::right: return EgoActivity::turning_right;
    case LaneTurn::u_turn: return EgoActivity::turning_around;
    case LaneTurn::none: return std::nullopt;
  }
  return std::nullopt;
}

// The nearest other present road user whose centre lies ahead of the ego within its lane's width
// (2 m either side of the ego's heading line) and within max(10 m, 3 s at the ego's speed).
std::optional<ActorId> followed_road_user(const Trace& trace, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  const double c = std::cos(ego.heading[i]), s = std::sin(ego.heading[i]);
  double reach = std::max(10.0, 3 * ego.speed[i]);
  std::optional<ActorId> followed;
  for (ActorId id = 1; id < trace.actors.size(); ++id) {
    const TraceActor& other = trace.actors[id];
    if (other.kind == TraceActorKind::obstacle || !present_at(other, i)) continue;
    const double dx = other.x[i] - ego.x[i], dy = other.y[i] - ego.y[i];
    const double along = dx * c + dy * s, across = -dx * s + dy * c;
    if (along > 0 && along < reach && std::abs(across) < 2) reach = along, followed = id;
  }
  return followed;
}

bool following(const Trace& trace, std::size_t i) {
  return followed_road_user(trace, i).has_value();
}

// On a roundabout: on its ring (a lane that is its own successor), or on a lane into or out of it.
bool on_roundabout(const RoadMap& map, LaneIndex index) {
  const Lane& lane = map.lane(index);
  auto ring = [&](LaneIndex other) { return runs_into_itself(map, other); };
  return ring(index) || std::any_of(lane.successors.begin(), lane.successors.end(), ring) ||
         std::any_of(lane.predecessors.begin(), lane.predecessors.end(), ring);
}

// An acceleration lane: it ends (no successor) beside a lane that goes on past its end.
bool ending_beside_another(const RoadMap& map, const Lane& lane) {
  if (!lane.successors.empty() || lane.centre_line.points().empty()) return false;
  const MapPoint end = lane.centre_line.points().back();
  auto goes_on = [&](LaneIndex neighbour) {
    const Lane& other = map.lane(neighbour);
    return !other.successors.empty() ||
           other.length() - other.centre_line.project(end).s > kMergeLookahead;
  };
  return std::any_of(lane.left_forward_neighbours.begin(), lane.left_forward_neighbours.end(),
                     goes_on) ||
         std::any_of(lane.right_forward_neighbours.begin(), lane.right_forward_neighbours.end(),
                     goes_on);
}

// Two or more lanes outside junctions run into this one (a slip road joining, two becoming one).
bool joined_by_two(const RoadMap& map, LaneIndex index) {
  const Lane& lane = map.lane(index);
  if (lane.junction) return false;
  return std::count_if(lane.predecessors.begin(), lane.predecessors.end(),
                       [&](LaneIndex p) { return !map.lane(p).junction; }) >= 2;
}

// ending_beside_another, looked up in `memo` or worked out once.
bool acceleration_lane(const RoadMap& map, LaneIndex index, RoadFeatureMemo& memo) {
  if (memo.acceleration_lane.empty()) memo.acceleration_lane.assign(map.lanes().size(), -1);
  signed char& known = memo.acceleration_lane[index];
  if (known < 0) known = ending_beside_another(map, map.lane(index)) ? 1 : 0;
  return known == 1;
}

// Merging: on or beside an acceleration lane (within a lane width of its centre line), on a lane
// two lanes run into, or within kMergeLookahead before one.
bool merges(const RoadMap& map, LaneIndex index, double s, MapPoint p, RoadFeatureMemo& memo) {
  const Lane& lane = map.lane(index);
  std::vector<LaneIndex> here = {index};
  here.insert(here.end(), lane.left_forward_neighbours.begin(), lane.left_forward_neighbours.end());
  here.insert(here.end(), lane.right_forward_neighbours.begin(),
              lane.right_forward_neighbours.end());
  for (LaneIndex near : here) {
    const Lane& candidate = map.lane(near);
    if (acceleration_lane(map, near, memo) && candidate.centre_line.project(p).distance < 4)
      return true;
  }
  if (joined_by_two(map, index)) return true;
  if (lane.length() - s > kMergeLookahead) return false;
  return std::any_of(lane.successors.begin(), lane.successors.end(),
                     [&](LaneIndex next) { return joined_by_two(map, next); });
}

}  // namespace

std::string_view ego_activity_name(EgoActivity activity) {
  switch (activity) {
    case EgoActivity::reversing: return "reversing";
    case EgoActivity::stopped: return "stopped";
    case EgoActivity::pulling_out: return "pulling out";
    case EgoActivity::changing_lane: return "changing lane";
    case EgoActivity::turning_left: return "turning left";
    case EgoActivity::turning_right: return "turning right";
    case EgoActivity::turning_around: return "turning around";
    case EgoActivity::following: return "following";
    case EgoActivity::cruising: return "cruising";
  }
  return "cruising";
}

std::string_view road_feature_name(RoadFeature feature) {
  switch (feature) {
    case RoadFeature::roundabout: return "roundabout";
    case RoadFeature::junction: return "junction";
    case RoadFeature::crosswalk: return "crosswalk";
    case RoadFeature::merge: return "merge";
    case RoadFeature::straight: return "straight";
  }
  return "straight";
}

std::string_view failure_event_name(FailureEvent event) {
  switch (event) {
    case FailureEvent::collision: return "collision";
    case FailureEvent::stuck: return "stuck";
    case FailureEvent::near_miss: return "near miss";
    case FailureEvent::rule: return "rule";
  }
  return "rule";
}

std::string_view contact_direction_name(ContactDirection direction) {
  switch (direction) {
    case ContactDirection::ahead: return "ahead";
    case ContactDirection::beside: return "beside";
    case ContactDirection::behind: return "behind";
  }
  return "beside";
}

std::string failure_mode_key(const FailureMode& mode) {
  std::string key = mode.atom;
  key += " | " + std::string(failure_event_name(mode.event));
  // A rule of the ego's own driving (its speed, lamps, indicators) is broken whoever is near: the
  // road user named then is incidental, so it describes the finding but does not split it.
  const bool incidental = mode.event == FailureEvent::rule || mode.other_role.empty();
  key += " | " + (incidental ? std::string("-") : mode.other_role);
  key += " | " + (mode.responsibility.empty() ? std::string("-") : mode.responsibility);
  key += " | " + std::string(ego_phase_name(mode.phase));
  return key;
}

std::string failure_mode_details(const FailureMode& mode) {
  std::string text = mode.other_class.empty() ? std::string("no road user near")
                                              : mode.other_class + " " + mode.other_role;
  if (!mode.other_class.empty() && mode.direction)
    text += " " + std::string(contact_direction_name(*mode.direction));
  text += "; ego " + std::string(ego_activity_name(mode.ego_activity)) + " on a " +
          std::string(road_feature_name(mode.road_feature));
  if (mode.ego_side && mode.other_side)
    text += "; touching ego " + std::string(body_side_name(*mode.ego_side)) + ", " +
            mode.other_role + " " + std::string(body_side_name(*mode.other_side));
  return text;
}

std::string actor_role(const TraceActor& actor) {
  const std::size_t dot = actor.name.rfind('.');
  if (dot == std::string::npos || dot + 1 == actor.name.size()) return actor.name;
  const bool numbered = std::all_of(actor.name.begin() + static_cast<std::ptrdiff_t>(dot) + 1,
                                    actor.name.end(), [](char c) { return c >= '0' && c <= '9'; });
  return numbered ? actor.name.substr(0, dot) : actor.name;
}

std::string actor_class_name(const TraceActor& actor) {
  if (actor.kind == TraceActorKind::obstacle) return "obstacle";
  return std::string(actor_class(actor.category).name);
}

EgoActivity ego_activity_at(const Trace& trace, const RoadMap& map, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  if (reversing_at(ego.reversing, i)) return EgoActivity::reversing;
  if (ego.speed[i] < kEgoStoppedSpeed) return EgoActivity::stopped;
  const std::size_t w = window_samples(trace, kPullOutWindow);
  if (stopped_between(ego, i > w ? i - w : 0, i)) return EgoActivity::pulling_out;
  if (changing_lane(trace, map, i)) return EgoActivity::changing_lane;
  if (const auto turn = turning(map, ego, i)) return *turn;
  if (following(trace, i)) return EgoActivity::following;
  return EgoActivity::cruising;
}

RoadFeature road_feature_at(const Trace& trace, const RoadMap& map, std::size_t i) {
  RoadFeatureMemo memo;
  return road_feature_at(trace, map, i, memo);
}

namespace {

RoadFeatureMemo::Box box_of(const std::vector<MapPoint>& outline) {
  RoadFeatureMemo::Box box;
  if (outline.empty()) return box;
  box = {outline[0].x, outline[0].y, outline[0].x, outline[0].y, false};
  for (const MapPoint& vertex : outline) {
    box.low_x = std::min(box.low_x, vertex.x);
    box.low_y = std::min(box.low_y, vertex.y);
    box.high_x = std::max(box.high_x, vertex.x);
    box.high_y = std::max(box.high_y, vertex.y);
  }
  return box;
}

void box_outlines(const RoadMap& map, RoadFeatureMemo& memo) {
  if (memo.boxed) return;
  for (const Crosswalk& crosswalk : map.crosswalks())
    memo.crosswalks.push_back(box_of(crosswalk.outline));
  for (const Junction& junction : map.junctions())
    memo.junctions.push_back(box_of(junction.outline));
  memo.boxed = true;
}

// Whether p is farther than `margin` (and a micrometre more, for rounding) from the box: then
// near_polygon is false too, and its own pass over the outline is skipped.
bool clear_of(const RoadFeatureMemo::Box& box, MapPoint p, double margin) {
  const double reach = std::max(margin, 0.0) + 1e-6;
  return box.empty || p.x < box.low_x - reach || p.x > box.high_x + reach ||
         p.y < box.low_y - reach || p.y > box.high_y + reach;
}

}  // namespace

RoadFeature road_feature_at(const Trace& trace, const RoadMap& map, std::size_t i,
                            RoadFeatureMemo& memo) {
  box_outlines(map, memo);
  const TraceActor& ego = trace.actors[kEgo];
  const MapPoint p{ego.x[i], ego.y[i]};
  const std::optional<LaneIndex> lane = lane_at(ego, i);
  if (lane && on_roundabout(map, *lane)) return RoadFeature::roundabout;
  for (std::size_t k = 0; k < map.crosswalks().size(); ++k)
    if (!clear_of(memo.crosswalks[k], p, kCrosswalkMargin) &&
        near_polygon(p, map.crosswalks()[k].outline, kCrosswalkMargin))
      return RoadFeature::crosswalk;
  if (lane && map.lane(*lane).junction) return RoadFeature::junction;
  for (std::size_t k = 0; k < map.junctions().size(); ++k)
    if (!clear_of(memo.junctions[k], p, kJunctionMargin) &&
        near_polygon(p, map.junctions()[k].outline, kJunctionMargin))
      return RoadFeature::junction;
  if (lane && merges(map, *lane, ego.s[i], p, memo)) return RoadFeature::merge;
  return RoadFeature::straight;
}

namespace {

const Collision* first_ego_collision(const Trace& trace) {
  for (const Collision& collision : trace.collisions)
    if (collision.first == kEgo || collision.second == kEgo) return &collision;
  return nullptr;
}

std::optional<ActorId> nearest_road_user(const Trace& trace, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  std::optional<ActorId> nearest;
  double best = kNearbyActor;
  for (ActorId id = 1; id < trace.actors.size(); ++id) {
    const TraceActor& other = trace.actors[id];
    if (other.kind == TraceActorKind::obstacle || !present_at(other, i)) continue;
    const double d = std::hypot(other.x[i] - ego.x[i], other.y[i] - ego.y[i]);
    if (d < best) best = d, nearest = id;
  }
  return nearest;
}

}  // namespace

namespace {

// Where `other` was at the sample before contact (at contact when it is the first).
ContactDirection contact_direction(const Trace& trace, ActorId other, std::size_t contact) {
  const std::size_t i = contact > 0 ? contact - 1 : 0;
  const TraceActor& ego = trace.actors[kEgo];
  const TraceActor& them = trace.actors[other];
  const double along = (them.x[i] - ego.x[i]) * std::cos(ego.heading[i]) +
                       (them.y[i] - ego.y[i]) * std::sin(ego.heading[i]);
  if (along >= ego.length / 2) return ContactDirection::ahead;
  if (along <= -ego.length / 2) return ContactDirection::behind;
  return ContactDirection::beside;
}

FailureEvent failure_event(const Trace& trace, const SpecVerdict& verdict) {
  if (first_ego_collision(trace)) return FailureEvent::collision;
  if (verdict.ending == VerdictEnding::stuck) return FailureEvent::stuck;
  if (verdict.actor_distance) return FailureEvent::near_miss;
  return FailureEvent::rule;
}

}  // namespace

FailureMode describe_failure(const Trace& trace, const RoadMap& map, const SpecVerdict& verdict,
                             std::optional<std::size_t> phase_sample) {
  FailureMode mode;
  if (verdict.name == kNoCollisionSpec)
    mode.atom = "collision";
  else
    mode.atom = verdict.name + ": " +
                (!verdict.mode_text.empty()   ? verdict.mode_text
                 : !verdict.atom_text.empty() ? verdict.atom_text
                                              : "-");
  if (trace.sample_count() == 0 || trace.actors.empty()) return mode;
  std::size_t at = sample_at_time(trace, verdict.time);
  std::optional<ActorId> other;
  if (const Collision* collision = first_ego_collision(trace)) {
    at = sample_at_time(trace, collision->time);
    const bool ego_first = collision->first == kEgo;
    other = ego_first ? collision->second : collision->first;
    mode.ego_side = ego_first ? collision->first_side : collision->second_side;
    mode.other_side = ego_first ? collision->second_side : collision->first_side;
    mode.direction = contact_direction(trace, *other, at);
  } else {
    // The one it follows, else the nearest: a road user beside it is nearer at times.
    other = followed_road_user(trace, at);
    if (!other) other = nearest_road_user(trace, at);
  }
  if (other) {
    mode.other_class = actor_class_name(trace.actors[*other]);
    mode.other_role = actor_role(trace.actors[*other]);
  }
  mode.event = failure_event(trace, verdict);
  mode.phase = ego_phase_at(trace, map, std::min(phase_sample.value_or(at), at));
  mode.ego_activity = ego_activity_at(trace, map, at);
  mode.road_feature = road_feature_at(trace, map, at);
  return mode;
}

std::vector<std::size_t> violation_order(const std::vector<SpecVerdict>& verdicts) {
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < verdicts.size(); ++k)
    if (verdicts[k].violated()) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return verdicts[a].time < verdicts[b].time;
  });
  return order;
}

std::size_t sample_at_time(const Trace& trace, double time) {
  if (trace.sample_count() == 0) return 0;
  const double index = std::round(time / trace.dt);
  if (!(index > 0)) return 0;
  return std::min(trace.sample_count() - 1, static_cast<std::size_t>(index));
}

}  // namespace scenfuzz

// The responsibility rules, tried in order (docs/oracle.md, "Responsibility"): an obstacle cannot
// be at fault; one that moved as no road user can just before the impact is; a broken light or stop
// sign, then missing priority at a junction (signs, then a left turn against oncoming traffic, then
// priority to the right where nothing controls the junction), decides a crossing, and a sign a
// merge along one road; an ego standing still is not at fault unless it stopped across a vehicle's
// path too late for it to stop; a turning ego gives way to pedestrians on the crosswalk; a
// pedestrian or a crossing road user is judged by when it entered the other's path; road users
// along the same road by RSS's dangerous time and proper response.
#include "oracle/responsibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "oracle/crosswalk_priority.hpp"
#include "oracle/implausible_motion.hpp"
#include "oracle/junction_priority.hpp"
#include "oracle/merge_lanes.hpp"
#include "oracle/pair_geometry.hpp"
#include "oracle/path_intrusion.hpp"
#include "oracle/right_of_way.hpp"
#include "oracle/right_priority.hpp"
#include "oracle/rss_distances.hpp"
#include "oracle/rss_response.hpp"

namespace scenfuzz {

namespace {

// How far back lights and signs crossed still bear on a collision (s).
constexpr double kRightOfWayMemory = 20;
// Headings within this of each other are one direction, within it of opposite ones oncoming (deg).
constexpr double kAlongRoad = 30;
// How far back a turn at a junction still bears on a pedestrian collision (s).
constexpr double kTurnMemory = 5;
// A stop line this close ahead is what the ego stopped for (m).
constexpr double kStoppedForControl = 30;
// "Braking at its limit": this share of the class's full braking.
constexpr double kAtLimit = 0.95;
// A path entry later than this before impact is the impact itself, seen from the side (s).
constexpr double kEntryLead = 0.1;

struct Verdict {
  Verdict(Responsibility r, std::string why) : responsibility(r), reason(std::move(why)) {}
  Responsibility responsibility = Responsibility::ego;
  std::string reason;
  std::optional<std::size_t> danger_began;  // CollisionResponsibility's; rss_rule sets it
};

std::string tenths(double value) { return format_number(std::round(value * 10) / 10); }

// "1.2 s before impact", or "at impact" for what rounds to 0 s.
std::string before_impact(const Trace& trace, std::size_t sample, std::size_t k) {
  const double before = trace.time[k] - trace.time[sample];
  if (std::round(before * 10) == 0) return "at impact";
  return tenths(before) + " s before impact";
}

// An entry into a path, unless it came only with the impact: a body touching the vehicle's side
// ahead of its centre did not come into its path, it hit its side.
std::optional<PathEntry> lasting_entry(const Trace& trace, std::optional<PathEntry> entry,
                                       std::size_t k) {
  if (entry && !entry->from_start && trace.time[k] - entry->time < kEntryLead) return std::nullopt;
  return entry;
}

// "came into its path 1.2 s before impact, 10.3 m ahead of it at 12 m/s, within its safe
// distance of 76 m" (or "stopped in its path ..."); `unsafe` words the last part.
std::string intrusion_text(const Trace& trace, const PathIntrusion& intrusion, std::size_t k) {
  return std::string(intrusion.came_to_rest ? "stopped in its path " : "came into its path ") +
         before_impact(trace, intrusion.sample, k) + ", " + tenths(intrusion.gap) +
         " m ahead of it at " + tenths(intrusion.speed) + " m/s, " +
         (intrusion.unsafe() ? "within" : "beyond") + " its safe distance of " +
         tenths(intrusion.safe_distance) + " m";
}

BodySide ego_side(const Collision& collision) {
  return collision.first == kEgo ? collision.first_side : collision.second_side;
}

std::size_t sample_of(const Trace& trace, double time) {
  const auto i = static_cast<std::size_t>(std::llround(time / trace.dt));
  return std::min(i, trace.sample_count() - 1);
}

// "a car", "a cyclist", "a pedestrian", "an obstacle".
std::string described(const TraceActor& actor) {
  if (actor.kind == TraceActorKind::obstacle) return "an obstacle";
  if (actor.kind == TraceActorKind::pedestrian) return "a pedestrian";
  switch (actor.category) {
    case ActorCategory::bicycle: return "a cyclist";
    case ActorCategory::motorbicycle: return "a motorcyclist";
    case ActorCategory::pedestrian: return "a pedestrian";
    default: return "a " + std::string(actor_class(actor.category).name);
  }
}

// "the car" from "a car".
std::string definite(const std::string& indefinite) {
  return "the " + indefinite.substr(indefinite.find(' ') + 1);
}

bool is_vehicle(const TraceActor& actor) {
  return actor.kind == TraceActorKind::ego || actor.kind == TraceActorKind::vehicle;
}

double impact_angle(const Trace& trace, ActorId other, std::size_t k) {
  const double a = trace.actors[kEgo].heading[k];
  const double b = trace.actors[other].heading[k];
  return std::abs(wrap_angle(b - a)) * 180 / std::numbers::pi;
}

CollisionTriage triage(const Trace& trace, const RoadMap& map, ActorId other, std::size_t k) {
  const TraceActor& ego = trace.actors[kEgo];
  const TraceActor& o = trace.actors[other];
  CollisionTriage t;
  t.ego_speed = ego.speed[k];
  t.ego_acceleration = ego.acceleration[k];
  const double ve = longitudinal_velocity_at(ego.speed, ego.reversing, k);
  const double vo = longitudinal_velocity_at(o.speed, o.reversing, k);
  const double dvx = ve * std::cos(ego.heading[k]) - vo * std::cos(o.heading[k]);
  const double dvy = ve * std::sin(ego.heading[k]) - vo * std::sin(o.heading[k]);
  t.relative_speed = std::hypot(dvx, dvy);
  t.impact_angle = impact_angle(trace, other, k);
  t.ego_stationary = ego.speed[k] <= kStandstillSpeed;
  t.ego_braking_at_limit =
      -ego.acceleration[k] >= kAtLimit * actor_class(ego.category).max_deceleration;
  t.entry = lasting_entry(trace, path_entry(trace, map, kEgo, other, k), k);
  return t;
}

// ---- what RSS leaves to the map: lights, stop signs, priority ----

std::optional<CrossedControl> first_violation(const std::vector<CrossedControl>& crossed) {
  for (const CrossedControl& control : crossed)
    if (control_violated(control)) return control;
  return std::nullopt;
}

std::optional<CrossedControl> first_sign(const std::vector<CrossedControl>& crossed) {
  for (const CrossedControl& control : crossed)
    if (control.kind != FeatureKind::traffic_light) return control;
  return std::nullopt;
}

std::string violation_text(const Trace& trace, const RoadMap& map, const CrossedControl& control,
                           std::size_t k) {
  const std::string before = before_impact(trace, control.sample, k);
  if (control.kind == FeatureKind::traffic_light)
    return "ran a red light (" + control_id(map, control) + ") " + before;
  return "passed the stop sign " + control_id(map, control) + " without stopping, " + before;
}

// Whether `vehicle`, once `other` was in its path, failed to brake at brake_min after its
// response time (right of way is given, not taken). False for a vehicle `other` never got in front
// of, and for a road user that is not a vehicle.
bool failed_to_respond(const Trace& trace, const RoadMap& map, ActorId vehicle, ActorId other,
                       std::size_t k, const RssParameters& rss) {
  if (!is_vehicle(trace.actors[vehicle])) return false;
  const std::optional<PathEntry> entry = path_entry(trace, map, vehicle, other, k);
  return entry && !braked_properly(trace, vehicle, entry->sample, k, rss.brake_min, rss);
}

std::string no_response_text(ActorId party, const RssParameters& rss) {
  const std::string who = party == kEgo ? "the ego" : "the other";
  return who + " did not brake at " + format_number(rss.brake_min) + " m/s^2 once " +
         (party == kEgo ? "the other" : "the ego") + " was in its path";
}

// One party at fault by the map; the other shares it when it did not respond.
Verdict map_fault(const Trace& trace, const RoadMap& map, ActorId culprit, ActorId other,
                  std::size_t k, std::string what, const RssParameters& rss) {
  const ActorId victim = culprit == kEgo ? other : kEgo;
  const std::string subject = culprit == kEgo ? "" : "the other ";
  Verdict verdict{culprit == kEgo ? Responsibility::ego : Responsibility::other, subject + what};
  if (failed_to_respond(trace, map, victim, culprit, k, rss)) {
    verdict.responsibility = Responsibility::shared;
    verdict.reason += ", and " + no_response_text(victim, rss);
  }
  return verdict;
}

// "drove into the ego, in its path from 1.2 s before impact": the one who had to give way, moving,
// ran into the one with the way while that one was in its path; empty when it did not.
std::string drove_into_text(const Trace& trace, const RoadMap& map, ActorId yielder,
                            ActorId with_way, std::size_t k) {
  const std::optional<PathEntry> entry =
      lasting_entry(trace, path_entry(trace, map, yielder, with_way, k), k);
  if (!entry || trace.actors[yielder].speed[k] <= kStandstillSpeed) return "";
  return "drove into " + std::string(with_way == kEgo ? "the ego" : "it") + ", in its path " +
         (entry->from_start ? "from the start" : "from " + before_impact(trace, entry->sample, k));
}

// Priority between turning and oncoming traffic: the one turning left gives way. It did not when
// it came into the other's path, or stopped in it, within the other's safe distance; otherwise the
// later rules decide.
std::optional<Verdict> turn_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                 std::size_t first, std::size_t k, const RssParameters& rss) {
  const std::optional<TurnPriority> priority = turn_priority(trace, map, other, first, k);
  if (!priority) return std::nullopt;
  // Even a nose put into the other's lane only at impact is the turner's; so is driving on into
  // the one with the way while it crosses the turner's path (the turner hits its side or rear).
  const std::optional<PathIntrusion> intrusion =
      path_intrusion(trace, map, priority->priority, priority->yielder, k, rss);
  std::string how;
  if (intrusion) {
    if (!intrusion->unsafe()) return std::nullopt;
    how = intrusion_text(trace, *intrusion, k);
  } else {
    how = drove_into_text(trace, map, priority->yielder, priority->priority, k);
    if (how.empty()) return std::nullopt;
  }
  const bool u_turn = map.lane(priority->yielder_lane).turn == LaneTurn::u_turn;
  const std::string way = map.lane(priority->priority_lane).turn == LaneTurn::right
                              ? " turning right"
                              : " going straight";
  const std::string whom = priority->yielder == kEgo
                               ? "an oncoming " + described(trace.actors[other]).substr(2)
                               : std::string("the oncoming ego");
  const std::string what = std::string(u_turn ? "made a U-turn" : "turned left") +
                           " without giving way to " + whom + way + ": " + how;
  return map_fault(trace, map, priority->yielder, other, k, what, rss);
}

// Priority to the right where no light or sign controls the junction. The one with the other on
// its right failed to give way when it came into that one's path within its safe distance (or
// stopped in it), or, moving, drove into that one while it was in its own path; one that came into
// the path with room to spare, or stood still, is left to the rules below.
std::optional<Verdict> right_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                  std::size_t first, std::size_t k, const RssParameters& rss) {
  const std::optional<RightPriority> priority = right_priority(trace, map, other, first, k);
  if (!priority) return std::nullopt;
  const ActorId yielder = priority->yielder;
  const ActorId with_way = priority->priority;
  std::string how;
  if (const std::optional<PathIntrusion> intrusion =
          path_intrusion(trace, map, with_way, yielder, k, rss)) {
    if (!intrusion->unsafe()) return std::nullopt;
    how = intrusion_text(trace, *intrusion, k);
  } else {
    how = drove_into_text(trace, map, yielder, with_way, k);
    if (how.empty()) return std::nullopt;
  }
  const std::string whom = yielder == kEgo ? described(trace.actors[other]) : "the ego";
  return map_fault(trace, map, yielder, other, k,
                   "did not give way to " + whom +
                       " coming from its right at a junction without lights or signs: " + how,
                   rss);
}

std::string sign_text(const RoadMap& map, const CrossedControl& sign) {
  return "did not give way at the " +
         std::string(sign.kind == FeatureKind::stop_sign ? "stop" : "yield") + " sign " +
         control_id(map, sign) + " to traffic with priority";
}

// Along one road the map still decides a merge from a stop- or yield-controlled lane into the
// traffic it gives way to (a roundabout's entry into the ring): whatever the angle at which they
// met, the one that crossed the sign failed to give way when it came into the other's path within
// that one's safe distance, the other on a lane it merges into or crosses. Otherwise RSS decides.
std::optional<Verdict> merge_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                  std::size_t k, const std::optional<CrossedControl>& ego_sign,
                                  const std::optional<CrossedControl>& other_sign,
                                  const RssParameters& rss) {
  if (ego_sign.has_value() == other_sign.has_value()) return std::nullopt;
  const CrossedControl& sign = ego_sign ? *ego_sign : *other_sign;
  const ActorId yielder = ego_sign ? kEgo : other;
  const ActorId with_way = ego_sign ? other : kEgo;
  const std::optional<PathIntrusion> intrusion =
      path_intrusion(trace, map, with_way, yielder, k, rss);
  if (!intrusion || !intrusion->unsafe()) return std::nullopt;
  const std::int32_t entry = trace.actors[yielder].lane[sign.sample];
  const std::int32_t lane = trace.actors[with_way].lane[intrusion->sample];
  if (entry < 0 || lane < 0 ||
      !merges_with(map, static_cast<LaneIndex>(entry), static_cast<LaneIndex>(lane)))
    return std::nullopt;
  return map_fault(trace, map, yielder, other, k,
                   sign_text(map, sign) + ": " + intrusion_text(trace, *intrusion, k), rss);
}

std::optional<Verdict> map_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                std::size_t k, const RssParameters& rss) {
  if (!is_vehicle(trace.actors[other])) return std::nullopt;
  const bool along_road = impact_angle(trace, other, k) < kAlongRoad;
  const auto memory = static_cast<std::size_t>(kRightOfWayMemory / trace.dt);
  const std::size_t first = k > memory ? k - memory : 0;
  const std::vector<CrossedControl> ego_crossed = controls_crossed(trace, map, kEgo, first, k);
  const std::vector<CrossedControl> other_crossed = controls_crossed(trace, map, other, first, k);
  // Priority: a stop or yield sign gives way to a road without one.
  const std::optional<CrossedControl> ego_sign = first_sign(ego_crossed);
  const std::optional<CrossedControl> other_sign = first_sign(other_crossed);
  if (along_road) return merge_rule(trace, map, other, k, ego_sign, other_sign, rss);
  const std::optional<CrossedControl> ego_broke = first_violation(ego_crossed);
  const std::optional<CrossedControl> other_broke = first_violation(other_crossed);
  if (ego_broke && other_broke)
    return Verdict{Responsibility::shared, "both broke the right of way: the ego " +
                                               violation_text(trace, map, *ego_broke, k) +
                                               ", the other " +
                                               violation_text(trace, map, *other_broke, k)};
  if (ego_broke)
    return map_fault(trace, map, kEgo, other, k, violation_text(trace, map, *ego_broke, k), rss);
  if (other_broke)
    return map_fault(trace, map, other, other, k, violation_text(trace, map, *other_broke, k), rss);
  if (ego_sign.has_value() == other_sign.has_value()) {
    if (std::optional<Verdict> verdict = turn_rule(trace, map, other, first, k, rss))
      return verdict;
    return right_rule(trace, map, other, first, k, rss);
  }
  const CrossedControl& sign = ego_sign ? *ego_sign : *other_sign;
  return map_fault(trace, map, ego_sign ? kEgo : other, other, k, sign_text(map, sign), rss);
}

// ---- an ego standing still ----

// An ego that came to rest across a vehicle's path is excused only when it stopped early enough for
// that vehicle to stop: RSS's safe distance at the moment it came to rest.
std::optional<Verdict> stopped_in_path(const Trace& trace, const RoadMap& map, ActorId other,
                                       std::size_t k, const std::string& hit,
                                       const RssParameters& rss) {
  if (!is_vehicle(trace.actors[other]) || impact_angle(trace, other, k) < kAlongRoad)
    return std::nullopt;
  const std::optional<PathIntrusion> intrusion = path_intrusion(trace, map, other, kEgo, k, rss);
  if (!intrusion) return std::nullopt;
  const std::string the = definite(described(trace.actors[other]));
  if (!intrusion->unsafe())
    return Verdict{Responsibility::other, hit + ", having " + intrusion_text(trace, *intrusion, k)};
  Verdict verdict{Responsibility::ego,
                  "left " + the + " no room to stop: " + intrusion_text(trace, *intrusion, k)};
  if (!braked_properly(trace, other, intrusion->sample, k, rss.brake_min, rss)) {
    verdict.responsibility = Responsibility::shared;
    verdict.reason += ", and " + no_response_text(other, rss);
  }
  return verdict;
}

std::optional<Verdict> stationary_rule(const Trace& trace, const RoadMap& map,
                                       const Collision& collision, ActorId other, std::size_t k,
                                       const RssParameters& rss) {
  const TraceActor& ego = trace.actors[kEgo];
  if (ego.speed[k] > kStandstillSpeed || (k > 0 && ego.speed[k - 1] > kStandstillSpeed))
    return std::nullopt;
  const BodySide side = ego_side(collision);
  if (trace.actors[other].kind == TraceActorKind::pedestrian)
    return Verdict{Responsibility::other, "a pedestrian walked into the " +
                                              std::string(body_side_name(side)) +
                                              " of the stopped ego"};
  if (side != BodySide::rear) {
    const std::string hit = "hit on its " + std::string(body_side_name(side)) + " by " +
                            described(trace.actors[other]) + " while stopped";
    if (std::optional<Verdict> verdict = stopped_in_path(trace, map, other, k, hit, rss))
      return verdict;
    return Verdict{Responsibility::other, hit};
  }
  const ControlAhead ahead = control_ahead(trace, map, kEgo, k, kStoppedForControl);
  const std::string where = ahead.red_light   ? " at a red light"
                            : ahead.stop_sign ? " at a stop sign"
                                              : "";
  return Verdict{Responsibility::other, "hit from behind while stopped" + where};
}

// ---- entering a path: pedestrians and crossing traffic ----

// A turning ego gives way to pedestrians already on the crosswalk it turns across.
std::optional<Verdict> crosswalk_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                      std::size_t k) {
  if (trace.actors[other].kind != TraceActorKind::pedestrian) return std::nullopt;
  const std::optional<CrosswalkPriority> priority =
      crosswalk_priority(trace, map, other, k, kTurnMemory);
  if (!priority) return std::nullopt;
  const std::string turn = priority->turn == LaneTurn::right  ? "turned right"
                           : priority->turn == LaneTurn::left ? "turned left"
                                                              : "made a U-turn";
  return Verdict{Responsibility::ego, turn + " into a pedestrian on the crosswalk " +
                                          map.crosswalks()[priority->crosswalk].id +
                                          " without giving way: it was on the crosswalk " +
                                          tenths(priority->ahead) + " s before the ego reached it"};
}

// "the other entered the ego's path 1.1 s before impact, less than the ego's stopping time at
// 8 m/s^2 (1.5 s)", or with the gap and the safe distance when there was time to stop.
std::string entry_text(const Trace& trace, const std::string& who, const std::string& where,
                       const PathEntry& entry, std::size_t k, double safe_distance,
                       const RssParameters& rss) {
  const double before = trace.time[k] - entry.time;
  const double stopping = trace.actors[kEgo].speed[entry.sample] / rss.brake_max;
  std::string text =
      who + " entered the ego's " + where + " " + before_impact(trace, entry.sample, k);
  if (entry.from_start)
    text = who + " was in the ego's " + where + " from the start, " +
           before_impact(trace, entry.sample, k);
  if (before < stopping)
    return text + ", less than the ego's stopping time at " + format_number(rss.brake_max) +
           " m/s^2 (" + tenths(stopping) + " s)";
  return text + ", " + tenths(entry.gap) + " m ahead, within the ego's safe distance of " +
         tenths(safe_distance) + " m";
}

// The RSS safe distance when the other entered: behind it on the same way, or, when it came
// against the ego's direction (an overtaker pulling out into the ego's lane), both stopping
// distances with the ego on its own lane.
double safe_distance_at_entry(const Trace& trace, const PathEntry& entry, const RssParameters& rss,
                              bool opposite = false) {
  const double ego_speed = trace.actors[kEgo].speed[entry.sample];
  const double other_along = ego_speed - entry.closing_speed;
  if (opposite)
    return rss_safe_longitudinal_opposite(ego_speed, rss.response_time_ego,
                                          std::max(0.0, -other_along), rss.response_time_other,
                                          rss);
  return rss_safe_longitudinal_same(ego_speed, other_along, rss.response_time_ego, rss);
}

// The other came into the ego's path (or the ego into the other's): the entrant is at fault when
// it left less than the RSS safe distance; the one whose path it was when it then did not brake.
std::optional<Verdict> entry_rule(const Trace& trace, const RoadMap& map, ActorId other,
                                  BodySide ego_side, std::size_t k, const RssParameters& rss) {
  const std::string other_name = described(trace.actors[other]);
  const std::optional<PathEntry> into_ego =
      lasting_entry(trace, path_entry(trace, map, kEgo, other, k), k);
  const bool ego_responded =
      !into_ego || braked_properly(trace, kEgo, into_ego->sample, k, rss.brake_min, rss);
  bool other_unsafe = false;
  double safe = 0;
  if (into_ego) {
    safe = safe_distance_at_entry(trace, *into_ego, rss);
    other_unsafe = into_ego->gap < safe || into_ego->from_start;
  }
  // The ego coming into a vehicle's path too close.
  std::optional<PathIntrusion> into_other;
  if (is_vehicle(trace.actors[other])) into_other = path_intrusion(trace, map, other, kEgo, k, rss);
  const bool ego_unsafe = into_other && into_other->unsafe();
  if (!into_ego && !ego_unsafe) {
    if (trace.actors[other].kind != TraceActorKind::pedestrian) return std::nullopt;
    // Not in the ego's path before the impact: it walked into the ego's side, or into a front
    // corner as it stepped out.
    return Verdict{Responsibility::other, "a pedestrian walked into the " +
                                              std::string(body_side_name(ego_side)) +
                                              " of the moving ego"};
  }
  // Follows "..., and the ego " in a shared verdict.
  const std::string no_brake = "did not brake at " + format_number(rss.brake_min) + " m/s^2 once " +
                               definite(other_name) + " was in its path";
  const bool ego_at_fault = !ego_responded || ego_unsafe;
  const bool other_at_fault = other_unsafe;
  std::string ego_part = ego_unsafe
                             ? "left " + definite(other_name) +
                                   " no room to stop: " + intrusion_text(trace, *into_other, k)
                             : no_brake;
  if (ego_at_fault && other_at_fault)
    return Verdict{Responsibility::shared,
                   entry_text(trace, definite(other_name), "path", *into_ego, k, safe, rss) +
                       ", and the ego " + ego_part};
  if (ego_at_fault) {
    if (!ego_unsafe)
      ego_part = "hit " + other_name + " that entered its path " +
                 before_impact(trace, into_ego->sample, k) + ", " + tenths(into_ego->gap) +
                 " m ahead (safe distance " + tenths(safe) + " m), without braking at " +
                 format_number(rss.brake_min) + " m/s^2";
    return Verdict{Responsibility::ego, ego_part};
  }
  if (!into_ego) return std::nullopt;
  return Verdict{Responsibility::other,
                 entry_text(trace, definite(other_name), "path", *into_ego, k, safe, rss)};
}

// ---- along one road: RSS ----

// How the ego came sideways from lane `from` (at the blame time; `now` at impact) to the other on
// `into`: turning in a junction, changing lane (into the other's lane outside junctions), or
// drifting. Lanes are -1 where the trace has none.
std::string sideways_words(const RoadMap& map, std::int32_t from, std::int32_t now,
                           std::int32_t into) {
  for (const std::int32_t lane : {now, from}) {
    if (lane < 0) continue;
    const Lane& l = map.lane(static_cast<LaneIndex>(lane));
    if (!l.junction) continue;
    if (l.turn == LaneTurn::left) return "turned left";
    if (l.turn == LaneTurn::right) return "turned right";
    if (l.turn == LaneTurn::u_turn) return "made a U-turn";
    return "moved sideways";
  }
  const bool changed_lane = from >= 0 && into >= 0 && from != into;
  return changed_lane ? "changed lane" : "moved sideways";
}

std::string ego_fault_text(const Trace& trace, const RoadMap& map, const ResponseViolation& v,
                           const BlameTime& blame, ActorId other, bool opposite, std::size_t k) {
  const std::string other_name = described(trace.actors[other]);
  const std::string since = before_impact(trace, blame.sample, k);
  switch (v.fault) {
    case ResponseFault::did_not_brake:
      return (opposite ? "met " + other_name + " head-on" : "ran into " + other_name) +
             ": braked at " + tenths(v.value) + " m/s^2 where RSS owes " + format_number(v.limit) +
             " m/s^2 once the gap became unsafe, " + since;
    case ResponseFault::accelerated:
      return "accelerated at " + tenths(v.value) + " m/s^2 towards " + other_name +
             " while the gap was unsafe";
    case ResponseFault::braked_hard:
      return "braked at " + tenths(v.value) + " m/s^2, harder than RSS's " +
             format_number(v.limit) + " m/s^2, in front of " + other_name;
    case ResponseFault::reversed: return "reversed into " + other_name;
    case ResponseFault::moved_sideways: {
      const std::string how =
          sideways_words(map, trace.actors[kEgo].lane[blame.sample], trace.actors[kEgo].lane[k],
                         trace.actors[other].lane[k]);
      // Alongside when the bodies overlapped along the road as it began; else how far apart.
      const PairGeometry g = pair_geometry(trace, map, kEgo, other, blame.sample);
      if (g.gap_lon <= 0) return how + " into " + other_name + " alongside";
      return how + " " + tenths(g.gap_lon) + " m " + (g.dx < 0 ? "in front of " : "behind ") +
             other_name + " " + since;
    }
  }
  return "";
}

std::string other_fault_text(const Trace& trace, const ResponseViolation& v,
                             const CollisionTriage& t, const std::string& other_name, bool opposite,
                             std::size_t k, const RssParameters& rss) {
  const std::string the = definite(other_name);
  switch (v.fault) {
    case ResponseFault::did_not_brake:
      return std::string(opposite ? "met head-on by " : "hit from behind by ") + other_name +
             " that braked at " + tenths(v.value) + " m/s^2 where RSS owes " +
             format_number(v.limit) + " m/s^2";
    case ResponseFault::accelerated:
      return the + " accelerated at " + tenths(v.value) + " m/s^2 towards the ego while too close";
    case ResponseFault::braked_hard:
      return the + " ahead braked at " + tenths(v.value) + " m/s^2, harder than RSS's " +
             format_number(v.limit) + " m/s^2";
    case ResponseFault::reversed: return the + " ahead reversed into the ego";
    case ResponseFault::moved_sideways:
      if (lasting_entry(trace, t.entry, k) && !t.entry->from_start && t.entry->gap > 0)
        return entry_text(trace, the, "lane", *t.entry, k,
                          safe_distance_at_entry(trace, *t.entry, rss, opposite), rss);
      return the + " moved sideways into the ego";
  }
  return "";
}

Verdict rss_verdict(const Trace& trace, const RoadMap& map, ActorId other, std::size_t k,
                    const CollisionTriage& t, const BlameTime& blame, const RssParameters& rss) {
  const std::vector<ResponseViolation> faults =
      rss_improper_responses(trace, map, other, blame, k, rss);
  const std::string other_name = described(trace.actors[other]);
  const bool opposite = opposite_directions(trace, map, other, blame.sample);
  const auto ego_fault = std::find_if(faults.begin(), faults.end(),
                                      [](const ResponseViolation& v) { return v.actor == kEgo; });
  const auto other_fault = std::find_if(faults.begin(), faults.end(),
                                        [](const ResponseViolation& v) { return v.actor != kEgo; });
  const bool ego = ego_fault != faults.end();
  const bool them = other_fault != faults.end();
  if (ego && them)
    return {Responsibility::shared,
            ego_fault_text(trace, map, *ego_fault, blame, other, opposite, k) + ", and " +
                other_fault_text(trace, *other_fault, t, other_name, opposite, k, rss)};
  if (ego)
    return {Responsibility::ego, ego_fault_text(trace, map, *ego_fault, blame, other, opposite, k)};
  if (them)
    return {Responsibility::other,
            other_fault_text(trace, *other_fault, t, other_name, opposite, k, rss)};
  // Nobody broke the proper response: the danger was there from the start or came from what RSS
  // does not see; the ego did what it owed.
  if (lasting_entry(trace, t.entry, k))
    return {Responsibility::other, entry_text(trace, definite(other_name), "path", *t.entry, k,
                                              safe_distance_at_entry(trace, *t.entry, rss), rss) +
                                       "; the ego responded as RSS requires"};
  return {Responsibility::other, "the ego responded as RSS requires to " + other_name};
}

Verdict rss_rule(const Trace& trace, const RoadMap& map, ActorId other, std::size_t k,
                 const CollisionTriage& t, const RssParameters& rss) {
  const BlameTime blame = rss_blame_time(trace, map, other, k, rss);
  Verdict verdict = rss_verdict(trace, map, other, k, t, blame, rss);
  if (blame.which == RssCase::lateral) verdict.danger_began = blame.sample;
  return verdict;
}

Verdict decide(const Trace& trace, const RoadMap& map, const Collision& collision, ActorId other,
               std::size_t k, const CollisionTriage& t, const RssParameters& rss) {
  const TraceActor& o = trace.actors[other];
  if (o.kind == TraceActorKind::obstacle)
    return {Responsibility::ego, "drove into a stationary obstacle (" + o.name + ")"};
  if (std::optional<std::string> motion =
          o.kind == TraceActorKind::vehicle
              ? implausible_motion_before(trace, map, other, collision.time)
              : std::nullopt)
    return {Responsibility::other,
            definite(described(o)) + " moved as no road user can: " + *motion};
  if (std::optional<Verdict> verdict = map_rule(trace, map, other, k, rss)) return *verdict;
  if (std::optional<Verdict> verdict = stationary_rule(trace, map, collision, other, k, rss))
    return *verdict;
  if (std::optional<Verdict> verdict = crosswalk_rule(trace, map, other, k)) return *verdict;
  const double angle = t.impact_angle;
  const bool crossing = angle >= kAlongRoad && angle <= 180 - kAlongRoad;
  if (o.kind == TraceActorKind::pedestrian || crossing)
    if (std::optional<Verdict> verdict = entry_rule(trace, map, other, ego_side(collision), k, rss))
      return *verdict;
  return rss_rule(trace, map, other, k, t, rss);
}

}  // namespace

std::string_view responsibility_name(Responsibility responsibility) {
  switch (responsibility) {
    case Responsibility::ego: return "ego";
    case Responsibility::other: return "other";
    case Responsibility::shared: return "shared";
  }
  return "ego";
}

CollisionResponsibility collision_responsibility(const Trace& trace, const RoadMap& map,
                                                 std::size_t index, const RssParameters& rss) {
  SCENFUZZ_DEMAND(index < trace.collisions.size());
  const Collision& collision = trace.collisions[index];
  SCENFUZZ_DEMAND(collision.first == kEgo && "the responsibility of a collision with the ego");
  SCENFUZZ_DEMAND(trace.sample_count() > 0);
  const ActorId other = collision.second;
  const std::size_t k = sample_of(trace, collision.time);
  CollisionResponsibility result;
  result.collision = index;
  result.other = other;
  result.triage = triage(trace, map, other, k);
  Verdict verdict = decide(trace, map, collision, other, k, result.triage, rss);
  result.responsibility = verdict.responsibility;
  result.reason = std::move(verdict.reason);
  result.danger_began = verdict.danger_began;
  return result;
}

std::vector<CollisionResponsibility> ego_collision_responsibilities(const Trace& trace,
                                                                    const RoadMap& map,
                                                                    const RssParameters& rss) {
  std::vector<CollisionResponsibility> out;
  for (std::size_t i = 0; i < trace.collisions.size(); ++i)
    if (trace.collisions[i].first == kEgo)
      out.push_back(collision_responsibility(trace, map, i, rss));
  return out;
}

}  // namespace scenfuzz

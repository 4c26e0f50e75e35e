// The coarse manoeuvre phase of the ego (ego_phase.hpp for the rules).
#include "oracle/ego_phase.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "oracle/failure_mode.hpp"
#include "oracle/pair_geometry.hpp"

namespace scenfuzz {
namespace {

std::optional<LaneIndex> lane_at(const TraceActor& actor, std::size_t i) {
  if (actor.lane[i] < 0) return std::nullopt;
  return static_cast<LaneIndex>(actor.lane[i]);
}

bool is_forward_neighbour(const Lane& lane, LaneIndex other) {
  auto has = [other](const std::vector<LaneIndex>& lanes) {
    return std::find(lanes.begin(), lanes.end(), other) != lanes.end();
  };
  return has(lane.left_forward_neighbours) || has(lane.right_forward_neighbours);
}

// Off its lane at sample j: on no lane, or pointing or standing away from the lane's centre line.
bool swerving(const RoadMap& map, const TraceActor& ego, std::size_t j) {
  const std::optional<LaneIndex> lane = lane_at(ego, j);
  if (!lane) return true;
  const Polyline& centre = map.lane(*lane).centre_line;
  if (std::abs(wrap_angle(ego.heading[j] - centre.heading_at(ego.s[j]))) > kSwerveHeading)
    return true;
  return centre.project({ego.x[j], ego.y[j]}).distance > kSwerveOffset;
}

// A lane change or swerve anywhere within kLaneChangeWindow of sample i: the window is the
// hysteresis that keeps a manoeuvre one phase from its start to its end.
bool leaving_lane(const Trace& trace, const RoadMap& map, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  const auto w = static_cast<std::size_t>(std::lround(kLaneChangeWindow / trace.dt));
  const std::size_t from = i > w ? i - w : 0;
  const std::size_t to = std::min(trace.sample_count(), i + w + 1);
  const std::optional<LaneIndex> here = lane_at(ego, i);
  for (std::size_t j = from; j < to; ++j) {
    if (ego.speed[j] < kEgoStoppedSpeed) continue;  // standing still is no manoeuvre
    const std::optional<LaneIndex> there = lane_at(ego, j);
    if (here && there && *there != *here && is_forward_neighbour(map.lane(*here), *there))
      return true;
    if (swerving(map, ego, j)) return true;
  }
  return false;
}

std::optional<EgoPhase> turning(const RoadMap& map, const TraceActor& ego, std::size_t i) {
  const std::optional<LaneIndex> lane = lane_at(ego, i);
  if (!lane || !map.lane(*lane).junction) return std::nullopt;
  switch (map.lane(*lane).turn) {
    case LaneTurn::left: return EgoPhase::turning_left;
    case LaneTurn::right: return EgoPhase::turning_right;
    case LaneTurn::u_turn: return EgoPhase::turning_around;
    case LaneTurn::none: return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace

std::string_view ego_phase_name(EgoPhase phase) {
  switch (phase) {
    case EgoPhase::reversing: return "reversing";
    case EgoPhase::standing: return "standing";
    case EgoPhase::turning_left: return "turning left";
    case EgoPhase::turning_right: return "turning right";
    case EgoPhase::turning_around: return "turning around";
    case EgoPhase::leaving_lane: return "leaving lane";
    case EgoPhase::in_lane: return "in lane";
  }
  return "in lane";
}

EgoPhase ego_phase_at(const Trace& trace, const RoadMap& map, std::size_t i) {
  const TraceActor& ego = trace.actors[kEgo];
  if (reversing_at(ego.reversing, i)) return EgoPhase::reversing;
  if (ego.speed[i] < kEgoStoppedSpeed) return EgoPhase::standing;
  if (const auto turn = turning(map, ego, i)) return *turn;
  if (leaving_lane(trace, map, i)) return EgoPhase::leaving_lane;
  return EgoPhase::in_lane;
}

}  // namespace scenfuzz

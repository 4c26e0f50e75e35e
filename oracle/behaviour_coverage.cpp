// Behaviour coverage read from a trace in one pass over its samples (see behaviour_coverage.hpp
// and docs/coverage.md for the features). What the ego was doing and where come from
// failure_mode.hpp, the gaps between bodies from pair_geometry.hpp and the sectors from WMG SDL's
// relative_sector, so that coverage and failure modes never disagree on a word.
#include "oracle/behaviour_coverage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "lang/demand.hpp"
#include "oracle/failure_mode.hpp"
#include "oracle/pair_geometry.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/simulation/manoeuvre_trigger.hpp"

namespace scenfuzz {
namespace {

// The fixed features other than interactions, one flag each.
enum Flag : std::size_t {
  following,
  lane_change_left,
  lane_change_right,
  turn_left,
  turn_right,
  u_turn,
  stop_at_red_light,
  stop_at_stop_sign,
  pulling_out,
  overtaking,
  junction_signalised,
  junction_stop_sign,
  junction_yield,
  junction_uncontrolled,
  light_red,
  light_yellow,
  light_green,
  crosswalk,
  roundabout,
  merge,
  flag_count,
};

constexpr std::array<std::string_view, flag_count> kFlagNames{
    "ego.following",
    "ego.lane_change_left",
    "ego.lane_change_right",
    "ego.turn_left",
    "ego.turn_right",
    "ego.u_turn",
    "ego.stop_at_red_light",
    "ego.stop_at_stop_sign",
    "ego.pulling_out",
    "ego.overtaking",
    "road.junction.signalised",
    "road.junction.stop_sign",
    "road.junction.yield",
    "road.junction.uncontrolled",
    "road.light.red",
    "road.light.yellow",
    "road.light.green",
    "road.crosswalk",
    "road.roundabout",
    "road.merge",
};

constexpr std::array<std::string_view, 8> kSectorNames{"F", "FSR", "SR", "RSR",
                                                       "R", "RSL", "SL", "FSL"};
constexpr std::array<std::string_view, 6> kClosingBands{
    "not_closing", "closing_0_2", "closing_2_5", "closing_5_10", "closing_10_20", "closing_20_up"};
constexpr std::array<double, 5> kClosingEdges{0.5, 2, 5, 10, 20};  // m/s
constexpr std::array<std::string_view, 5> kDistanceBands{"contact", "close", "near", "mid", "far"};
constexpr std::array<double, 3> kDistanceEdges{1, 5, 15};  // m; far: up to kInteractionReach
constexpr std::array<std::string_view, 3> kWeatherKinds{"fog", "rain", "snow"};
constexpr std::array<std::string_view, 3> kLightBands{"day", "twilight", "night"};
// Same direction: headings within this of each other (overtaking).
constexpr double kSameDirection = std::numbers::pi / 4;
// How far back on the lane before a junction lane its controls are looked for.
constexpr double kApproachControls = 15;  // m

using Flags = std::array<bool, flag_count>;

// What one other road user did around the ego, per sector.
struct Encounter {
  std::array<bool, 8> seen{};
  std::array<double, 8> least_gap{};
  std::array<double, 8> most_closing{};
  std::array<bool, 8> contact{};
  bool ahead_in_lane = false;  // was in F, going the ego's way (overtaking)
};

KinematicState state_at(const TraceActor& actor, std::size_t i) {
  KinematicState state;
  state.x = actor.x[i];
  state.y = actor.y[i];
  state.heading = actor.heading[i];
  state.speed = actor.speed[i];
  return state;
}

// The centres' range rate towards each other (m/s, positive closing).
double closing_speed(const TraceActor& ego, const TraceActor& other, std::size_t i) {
  const double dx = other.x[i] - ego.x[i], dy = other.y[i] - ego.y[i];
  const double d = std::hypot(dx, dy);
  if (d < 1e-9) return 0;
  const double ve = longitudinal_velocity_at(ego.speed, ego.reversing, i);
  const double vo = longitudinal_velocity_at(other.speed, other.reversing, i);
  const double rvx = vo * std::cos(other.heading[i]) - ve * std::cos(ego.heading[i]);
  const double rvy = vo * std::sin(other.heading[i]) - ve * std::sin(ego.heading[i]);
  return -(dx * rvx + dy * rvy) / d;
}

// The least distance between the bodies, from the gaps along and across the ego's frame.
double body_gap(const BodyGaps& g) {
  return std::hypot(std::max(g.lon, 0.0), std::max(g.lat, 0.0));
}

std::size_t sector_index(const TraceActor& ego, const TraceActor& other, std::size_t i) {
  return static_cast<std::size_t>(
      relative_sector(state_at(other, i), other.length, state_at(ego, i), ego.length));
}

void record(Encounter& encounter, std::size_t sector, double gap, double closing) {
  if (!encounter.seen[sector]) {
    encounter.seen[sector] = true;
    encounter.least_gap[sector] = gap;
    encounter.most_closing[sector] = closing;
    return;
  }
  encounter.least_gap[sector] = std::min(encounter.least_gap[sector], gap);
  encounter.most_closing[sector] = std::max(encounter.most_closing[sector], closing);
}

// The radius of a circle round the actor's body about its centre.
double body_radius(const TraceActor& actor) {
  return actor.shape == BodyShape::box ? std::hypot(actor.length, actor.width) / 2
                                       : actor.length / 2;
}

// The gap between the bodies at sample i, or nullopt when it cannot lower the sector's least gap
// (`lower` bounds it from below) and the bodies are surely within reach (the centres' distance
// bounds it from above): the gap (pair_geometry) is the costly part of the pass.
// `frame`: the ego's frame at sample i (pair_frame_heading, a lane lookup), worked out at the
// first gap the sample needs and kept for its other road users.
std::optional<double> gap_if_needed(const Trace& trace, const RoadMap& map, ActorId id,
                                    std::size_t i, const Encounter& encounter, std::size_t sector,
                                    double centres, double lower, std::optional<double>& frame) {
  const bool may_lower = !encounter.seen[sector] || lower < encounter.least_gap[sector];
  if (!may_lower && centres <= kInteractionReach) return std::nullopt;
  if (!frame) frame = pair_frame_heading(trace, map, kEgo, i);
  return body_gap(body_gaps(trace, kEgo, id, i, *frame));
}

// Every other road user present and within reach at sample i, by sector; and overtaking.
void note_encounters(const Trace& trace, const RoadMap& map, std::size_t i,
                     std::vector<Encounter>& encounters, Flags& flags) {
  const TraceActor& ego = trace.actors[kEgo];
  std::optional<double> frame;
  for (ActorId id = 1; id < trace.actors.size(); ++id) {
    const TraceActor& other = trace.actors[id];
    if (!present_at(other, i)) continue;
    const double centres = std::hypot(other.x[i] - ego.x[i], other.y[i] - ego.y[i]);
    // The gap is at least the larger of the gaps along and across, each at least the centres'
    // offset on that axis (>= centres / sqrt 2 on one of them) less the bodies' radii.
    const double lower = centres / std::numbers::sqrt2 - body_radius(ego) - body_radius(other);
    if (lower > kInteractionReach) continue;
    Encounter& encounter = encounters[id];
    const std::size_t sector = sector_index(ego, other, i);
    const std::optional<double> gap =
        gap_if_needed(trace, map, id, i, encounter, sector, centres, lower, frame);
    if (gap && *gap > kInteractionReach) continue;
    record(encounter, sector, gap.value_or(encounter.least_gap[sector]),
           closing_speed(ego, other, i));
    if (other.kind != TraceActorKind::vehicle) continue;
    const auto where = static_cast<RelativeSector>(sector);
    const bool behind =
        where == RelativeSector::R || where == RelativeSector::RSL || where == RelativeSector::RSR;
    if (where != RelativeSector::F && !(behind && encounter.ahead_in_lane)) continue;
    const bool same_way = std::abs(wrap_angle(other.heading[i] - ego.heading[i])) < kSameDirection;
    if (same_way && where == RelativeSector::F) encounter.ahead_in_lane = true;
    if (same_way && behind && encounter.ahead_in_lane) flags[overtaking] = true;
  }
}

// Calls `visit(feature, distance)` for every feature on `lane` from `s` on and on its successors,
// up to `reach` metres ahead (distance from s to the feature's start, down to -overshoot).
template <class Visit>
void features_ahead(const RoadMap& map, LaneIndex lane, double s, double reach, int depth,
                    Visit&& visit) {
  const Lane& here = map.lane(lane);
  for (const LaneFeature& feature : here.features) {
    const double distance = feature.s_begin - s;
    if (distance >= -kStopLineOvershoot && distance <= reach) visit(feature, distance);
  }
  const double left = here.length() - s;
  if (depth == 0 || left > reach) return;
  for (LaneIndex next : here.successors) features_ahead(map, next, -left, reach, depth - 1, visit);
}

// Lights met and stops made at a light or stop sign, at sample i.
void note_controls(const Trace& trace, const RoadMap& map, std::size_t i,
                   const std::vector<int>& light_column, Flags& flags) {
  const TraceActor& ego = trace.actors[kEgo];
  if (ego.lane[i] < 0) return;
  const bool stopped = ego.speed[i] < kEgoStoppedSpeed;
  const double front = ego.s[i] + ego.length / 2;
  features_ahead(map, static_cast<LaneIndex>(ego.lane[i]), front, kLightMetReach, 2,
                 [&](const LaneFeature& feature, double distance) {
                   if (feature.kind == FeatureKind::stop_sign) {
                     const bool stop = map.signs()[feature.index].kind == SignKind::stop;
                     if (stop && stopped && distance <= kStopLineReach)
                       flags[stop_at_stop_sign] = true;
                     return;
                   }
                   if (feature.kind != FeatureKind::traffic_light) return;
                   const int column = light_column[feature.index];
                   if (column < 0) return;
                   const SignalColour colour =
                       trace.lights[static_cast<std::size_t>(column)].colour[i];
                   flags[colour == SignalColour::red      ? light_red
                         : colour == SignalColour::yellow ? light_yellow
                                                          : light_green] = true;
                   if (colour == SignalColour::red && stopped && distance <= kStopLineReach)
                     flags[stop_at_red_light] = true;
                 });
}

// The control of a junction lane's approach: a light, a stop or yield sign on the lane itself
// near its start or on a lane leading into it near that lane's end; else uncontrolled.
Flag junction_control(const RoadMap& map, LaneIndex lane) {
  bool light = false, stop = false, yield = false;
  auto note = [&](const LaneFeature& feature) {
    if (feature.kind == FeatureKind::traffic_light) light = true;
    if (feature.kind == FeatureKind::stop_sign)
      (map.signs()[feature.index].kind == SignKind::stop ? stop : yield) = true;
  };
  for (const LaneFeature& feature : map.lane(lane).features)
    if (feature.s_begin <= kStopLineOvershoot) note(feature);
  for (LaneIndex previous : map.lane(lane).predecessors) {
    const Lane& approach = map.lane(previous);
    for (const LaneFeature& feature : approach.features)
      if (feature.s_begin >= approach.length() - kApproachControls) note(feature);
  }
  return light   ? junction_signalised
         : stop  ? junction_stop_sign
         : yield ? junction_yield
                 : junction_uncontrolled;
}

// Lane changes by the map's neighbours and junction kinds when a junction lane is entered.
void note_lane(const RoadMap& map, std::int32_t lane, std::int32_t& previous, Flags& flags) {
  if (lane < 0 || lane == previous) return;
  const auto here = static_cast<LaneIndex>(lane);
  if (previous >= 0) {
    const Lane& before = map.lane(static_cast<LaneIndex>(previous));
    auto has = [&](const std::vector<LaneIndex>& lanes) {
      return std::find(lanes.begin(), lanes.end(), here) != lanes.end();
    };
    if (has(before.left_forward_neighbours)) flags[lane_change_left] = true;
    if (has(before.right_forward_neighbours)) flags[lane_change_right] = true;
  }
  if (map.lane(here).junction) flags[junction_control(map, here)] = true;
  previous = lane;
}

void note_activity(const Trace& trace, const RoadMap& map, std::size_t i, RoadFeatureMemo& memo,
                   Flags& flags) {
  switch (ego_activity_at(trace, map, i)) {
    case EgoActivity::following: flags[following] = true; break;
    case EgoActivity::turning_left: flags[turn_left] = true; break;
    case EgoActivity::turning_right: flags[turn_right] = true; break;
    case EgoActivity::turning_around: flags[u_turn] = true; break;
    case EgoActivity::pulling_out: flags[pulling_out] = true; break;
    default: break;
  }
  switch (road_feature_at(trace, map, i, memo)) {
    case RoadFeature::crosswalk: flags[crosswalk] = true; break;
    case RoadFeature::roundabout: flags[roundabout] = true; break;
    case RoadFeature::merge: flags[merge] = true; break;
    default: break;
  }
}

// A collision of the ego is contact in the sector the other was in at that sample.
void note_collisions(const Trace& trace, std::vector<Encounter>& encounters) {
  for (const Collision& collision : trace.collisions) {
    if (collision.first != kEgo && collision.second != kEgo) continue;
    const ActorId other = collision.first == kEgo ? collision.second : collision.first;
    const std::size_t i = sample_at_time(trace, collision.time);
    const TraceActor& ego = trace.actors[kEgo];
    const std::size_t sector = sector_index(ego, trace.actors[other], i);
    record(encounters[other], sector, 0, closing_speed(ego, trace.actors[other], i));
    encounters[other].contact[sector] = true;
  }
}

std::string interaction_name(std::string_view actor, std::size_t sector, double closing, double gap,
                             bool contact) {
  std::string name = "interaction.";
  name += actor;
  name += '.';
  name += kSectorNames[sector];
  name += '.';
  name += closing_speed_band(closing);
  name += '.';
  name += distance_band(gap, contact);
  return name;
}

void add_environment(const Conditions& conditions, std::vector<std::string>& features) {
  const std::array<double, 3> intensities{conditions.fog, conditions.rain, conditions.snow};
  bool clear = true;
  for (std::size_t k = 0; k < intensities.size(); ++k) {
    const std::string_view band = weather_band(intensities[k]);
    if (band == "none") continue;
    clear = false;
    features.push_back("weather." + std::string(kWeatherKinds[k]) + "." + std::string(band));
  }
  if (clear) features.emplace_back("weather.clear");
  features.push_back("light." + std::string(light_band(conditions.darkness)));
}

// Trace light columns by the map's light index; -1 where the trace has none.
std::vector<int> light_columns(const Trace& trace, const RoadMap& map) {
  std::vector<int> columns(map.traffic_lights().size(), -1);
  for (std::size_t j = 0; j < map.traffic_lights().size(); ++j)
    for (std::size_t k = 0; k < trace.lights.size(); ++k)
      if (trace.lights[k].id == map.traffic_lights()[j].id &&
          trace.lights[k].colour.size() == trace.sample_count())
        columns[j] = static_cast<int>(k);
  return columns;
}

}  // namespace

std::string_view closing_speed_band(double closing_speed) {
  std::size_t band = 0;
  while (band < kClosingEdges.size() && closing_speed >= kClosingEdges[band]) ++band;
  return kClosingBands[band];
}

std::string_view distance_band(double gap, bool contact) {
  if (contact) return kDistanceBands[0];
  std::size_t band = 0;
  while (band < kDistanceEdges.size() && gap >= kDistanceEdges[band]) ++band;
  return kDistanceBands[band + 1];
}

std::string_view weather_band(double intensity) {
  // LawBreaker's levels light 0.1, middle 0.5, heavy 0.8 each fall inside their band.
  if (intensity < 0.05) return "none";
  if (intensity < 0.3) return "light";
  if (intensity < 0.65) return "moderate";
  return "heavy";
}

std::string_view light_band(double darkness) {
  if (darkness <= 0) return kLightBands[0];
  return darkness >= 1 ? kLightBands[2] : kLightBands[1];
}

std::vector<std::string> behaviour_feature_names() {
  std::vector<std::string> names(kFlagNames.begin(), kFlagNames.end());
  for (const ActorClass& actor : actor_classes())
    for (std::size_t sector = 0; sector < kSectorNames.size(); ++sector)
      for (std::string_view closing : kClosingBands)
        for (std::string_view distance : kDistanceBands)
          names.push_back("interaction." + std::string(actor.name) + "." +
                          std::string(kSectorNames[sector]) + "." + std::string(closing) + "." +
                          std::string(distance));
  for (std::size_t sector = 0; sector < kSectorNames.size(); ++sector)
    for (std::string_view closing : kClosingBands)
      for (std::string_view distance : kDistanceBands)
        names.push_back("interaction.obstacle." + std::string(kSectorNames[sector]) + "." +
                        std::string(closing) + "." + std::string(distance));
  names.emplace_back("weather.clear");
  for (std::string_view kind : kWeatherKinds)
    for (std::string_view band : {"light", "moderate", "heavy"})
      names.push_back("weather." + std::string(kind) + "." + std::string(band));
  for (std::string_view band : kLightBands) names.push_back("light." + std::string(band));
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> behaviour_coverage(const Trace& trace, const RoadMap& map,
                                            const Conditions& conditions) {
  std::vector<std::string> features;
  add_environment(conditions, features);
  if (trace.sample_count() > 0 && !trace.actors.empty()) {
    // A trace's columns have one entry per sample (trace.hpp); the pass reads them unchecked.
    for (const TraceActor& actor : trace.actors)
      SCENFUZZ_DEMAND(actor.x.size() == trace.sample_count() &&
                      actor.lane.size() == trace.sample_count() &&
                      actor.s.size() == trace.sample_count());
    Flags flags{};
    std::vector<Encounter> encounters(trace.actors.size());
    const std::vector<int> lights = light_columns(trace, map);
    std::int32_t previous_lane = -1;
    RoadFeatureMemo memo;
    for (std::size_t i = 0; i < trace.sample_count(); ++i) {
      note_lane(map, trace.actors[kEgo].lane[i], previous_lane, flags);
      note_activity(trace, map, i, memo, flags);
      note_controls(trace, map, i, lights, flags);
      note_encounters(trace, map, i, encounters, flags);
    }
    note_collisions(trace, encounters);
    for (std::size_t k = 0; k < flag_count; ++k)
      if (flags[k]) features.emplace_back(kFlagNames[k]);
    for (ActorId id = 1; id < trace.actors.size(); ++id) {
      const Encounter& e = encounters[id];
      const std::string actor = actor_class_name(trace.actors[id]);
      for (std::size_t sector = 0; sector < kSectorNames.size(); ++sector)
        if (e.seen[sector])
          features.push_back(interaction_name(actor, sector, e.most_closing[sector],
                                              e.least_gap[sector], e.contact[sector]));
    }
  }
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  return features;
}

}  // namespace scenfuzz

// scenest's traffic-law signals on a simulated trace. LawBreaker finds road objects "ahead" with a
// 45-degree fan in front of the car; we follow the lanes instead: the lane the ego is on, then the
// lanes it drives onto next in the run, then (past what the run shows) every successor, so a
// stop line on the opposite approach or a car in the next lane is never "ahead".
#include "oracle/law_signals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "physics/map/lane_route.hpp"
#include "physics/trace/trace_footprint.hpp"

namespace scenfuzz {

namespace {

constexpr double kKilometresPerHourPerMetrePerSecond = 3.6;
constexpr double kNoon = 12 * 3600;  // s since midnight: the time of day when none is given
// LawBreaker's light codes (Apollo's TrafficLight.Color), and what it reports with no light.
constexpr double kRedCode = 1, kYellowCode = 2, kGreenCode = 3;
constexpr double kNoLightCode = kGreenCode;
// The lane graph branches at every junction; this bounds the walk on maps with many short lanes.
constexpr std::size_t kMaxStretches = 512;

double colour_code(SignalColour colour) {
  switch (colour) {
    case SignalColour::red: return kRedCode;
    case SignalColour::yellow: return kYellowCode;
    case SignalColour::green: return kGreenCode;
  }
  return kNoLightCode;
}

// [s_begin, s_end] of `lane` on the way ahead of the ego; s_begin lies `offset` metres along the
// lanes from the ego's centre (negative behind it).
struct LaneStretch {
  LaneIndex lane = 0;
  double s_begin = 0;
  double s_end = 0;
  double offset = 0;
};

// The lanes the ego drives on, in order, each with the sample where it enters it; samples off
// the lanes are skipped.
struct LaneVisits {
  std::vector<LaneIndex> lanes;
  std::vector<std::optional<std::size_t>> visit_at;  // per sample: index into lanes
};

LaneVisits lane_visits(const TraceActor& ego) {
  LaneVisits visits;
  visits.visit_at.resize(ego.lane.size());
  for (std::size_t i = 0; i < ego.lane.size(); ++i) {
    if (ego.lane[i] < 0) continue;
    const auto lane = static_cast<LaneIndex>(ego.lane[i]);
    if (visits.lanes.empty() || visits.lanes.back() != lane) visits.lanes.push_back(lane);
    visits.visit_at[i] = visits.lanes.size() - 1;
  }
  return visits;
}

// The lanes ahead of the ego at sample i, from its rear bumper to `reach` metres ahead of its
// centre; empty when it is on no lane. Where the ego's next lane in the run is a successor, only
// that branch is followed.
std::vector<LaneStretch> stretches_ahead(const RoadMap& map, const Trace& trace,
                                         const LaneVisits& visits, std::size_t i, double reach) {
  std::vector<LaneStretch> stretches;
  const TraceActor& ego = trace.actors[kEgo];
  if (!visits.visit_at[i]) return stretches;
  struct Pending {
    LaneStretch stretch;
    std::optional<std::size_t> visit;  // the ego's own visit of this lane, while known
  };
  const double rear = ego.s[i] - ego.length / 2;
  const double start = std::max(0.0, rear);
  std::vector<Pending> pending = {
      {{visits.lanes[*visits.visit_at[i]], start, 0, start - ego.s[i]}, visits.visit_at[i]}};
  while (!pending.empty() && stretches.size() < kMaxStretches) {
    Pending next = pending.back();
    pending.pop_back();
    const Lane& lane = map.lane(next.stretch.lane);
    next.stretch.s_end = lane.length();
    stretches.push_back(next.stretch);
    std::optional<LaneIndex> driven_next;
    if (next.visit && *next.visit + 1 < visits.lanes.size()) {
      const LaneIndex candidate = visits.lanes[*next.visit + 1];
      if (std::find(lane.successors.begin(), lane.successors.end(), candidate) !=
          lane.successors.end())
        driven_next = candidate;
    }
    for (LaneIndex successor : lane.successors) {
      if (driven_next && successor != *driven_next) continue;
      const LinkPoints link = link_points(map, next.stretch.lane, successor);
      if (link.exit_s < next.stretch.s_begin) continue;
      const double offset = next.stretch.offset + (link.exit_s - next.stretch.s_begin);
      if (offset > reach) continue;
      std::optional<std::size_t> visit;
      if (driven_next) visit = *next.visit + 1;
      pending.push_back({{successor, link.entry_s, 0, offset}, visit});
    }
  }
  return stretches;
}

// Everything the lane-following signals of one sample need.
struct AheadView {
  std::vector<LaneStretch> stretches;
  double half_length = 0;  // the ego's
};

// How far ahead of the ego's front bumper an object at [s_begin, s_end] of a stretch's lane is:
// 0 while the ego is over it, nullopt once its end is behind the rear bumper, or when it is not
// on the stretch.
std::optional<double> distance_on(const AheadView& view, const LaneStretch& stretch, double s_begin,
                                  double s_end) {
  if (s_end < stretch.s_begin || s_begin > stretch.s_end) return std::nullopt;
  const double begin = stretch.offset + (s_begin - stretch.s_begin);
  const double end = stretch.offset + (s_end - stretch.s_begin);
  if (end < -view.half_length) return std::nullopt;
  return std::max(0.0, begin - view.half_length);
}

struct FeatureFound {
  double distance = kNoRoadObjectAhead;
  std::optional<std::uint32_t> index;  // into the map's lights, signs or crosswalks
};

// The nearest road object of one of `kinds` ahead, within kNoRoadObjectAhead.
FeatureFound nearest_feature(const RoadMap& map, const AheadView& view,
                             std::span<const FeatureKind> kinds) {
  FeatureFound found;
  for (const LaneStretch& stretch : view.stretches)
    for (const LaneFeature& feature : map.lane(stretch.lane).features) {
      if (std::find(kinds.begin(), kinds.end(), feature.kind) == kinds.end()) continue;
      std::optional<double> distance = distance_on(view, stretch, feature.s_begin, feature.s_end);
      if (!distance || *distance > kNoRoadObjectAhead) continue;
      if (!found.index || *distance < found.distance) found = {*distance, feature.index};
    }
  return found;
}

double junction_distance(const RoadMap& map, const AheadView& view) {
  double nearest = kNoRoadObjectAhead;
  for (const LaneStretch& stretch : view.stretches)
    if (map.lane(stretch.lane).junction)
      nearest = std::min(nearest, std::max(0.0, stretch.offset - view.half_length));
  return nearest;
}

struct VehicleFound {
  double distance = kNoVehicle;
  double speed = 0;  // m/s; 0 when there is none (LawBreaker)
};

double footprint_gap(const Trace& trace, ActorId other, std::size_t i) {
  return std::max(0.0,
                  signed_distance(footprint_at(trace, kEgo, i), footprint_at(trace, other, i)));
}

// The nearest vehicle whose centre is on the lanes ahead, in front of the ego's centre.
VehicleFound vehicle_ahead(const Trace& trace, const AheadView& view, std::size_t i) {
  const double reach = kNoRoadObjectAhead + view.half_length;
  VehicleFound found;
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    const TraceActor& vehicle = trace.actors[k];
    if (vehicle.kind != TraceActorKind::vehicle || vehicle.lane[i] < 0) continue;
    const auto lane = static_cast<LaneIndex>(vehicle.lane[i]);
    bool ahead = false;
    for (const LaneStretch& stretch : view.stretches) {
      if (stretch.lane != lane || vehicle.s[i] < stretch.s_begin || vehicle.s[i] > stretch.s_end)
        continue;
      const double along = stretch.offset + (vehicle.s[i] - stretch.s_begin);
      if (along > 0 && along <= reach) ahead = true;
    }
    if (!ahead) continue;
    const double gap = footprint_gap(trace, static_cast<ActorId>(k), i);
    if (gap < found.distance) found = {gap, vehicle.speed[i]};
  }
  return found;
}

VehicleFound nearest_vehicle(const Trace& trace, std::size_t i) {
  VehicleFound found;
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    if (trace.actors[k].kind != TraceActorKind::vehicle) continue;
    const double gap = footprint_gap(trace, static_cast<ActorId>(k), i);
    if (gap < found.distance) found = {gap, trace.actors[k].speed[i]};
  }
  return found;
}

// Lanes side by side in the ego's direction: its own and its forward neighbours, transitively.
double lane_count_of_road(const RoadMap& map, LaneIndex lane) {
  std::vector<LaneIndex> road = {lane};
  for (std::size_t k = 0; k < road.size(); ++k) {
    const Lane& member = map.lane(road[k]);
    for (const auto* neighbours :
         {&member.left_forward_neighbours, &member.right_forward_neighbours})
      for (LaneIndex neighbour : *neighbours)
        if (std::find(road.begin(), road.end(), neighbour) == road.end()) road.push_back(neighbour);
  }
  return static_cast<double>(road.size());
}

double weather_intensity(const ScenarioTemplate& scenario, std::span<const double> parameters,
                         const std::string& kind, const SourceLocation& location) {
  if (!scenario.environment) return 0;
  for (const WeatherComponent& component : scenario.environment->weather)
    if (component.kind == kind) {
      const double intensity = evaluate(component.intensity, parameters);
      if (!std::isfinite(intensity))
        throw OracleError(location, "the scenario's " + kind + " intensity is not a number");
      return intensity;
    }
  return 0;
}

double time_of_day(const ScenarioTemplate& scenario, std::span<const double> parameters,
                   const SourceLocation& location) {
  if (!scenario.environment || !scenario.environment->time_of_day) return kNoon;
  const double seconds = evaluate(*scenario.environment->time_of_day, parameters);
  if (!std::isfinite(seconds))
    throw OracleError(location, "the scenario's time of day is not a number");
  return seconds;
}

// A signal that looks along the ego's lanes: `compute(view, sample)` at every sample.
template <typename Compute>
std::vector<double> along_the_lanes(const Trace& trace, const RoadMap& map, Compute compute) {
  const LaneVisits visits = lane_visits(trace.actors[kEgo]);
  const double half_length = trace.actors[kEgo].length / 2;
  std::vector<double> values(trace.sample_count());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const AheadView view{stretches_ahead(map, trace, visits, i, kNoRoadObjectAhead + half_length),
                         half_length};
    values[i] = compute(view, i);
  }
  return values;
}

template <typename Compute>
std::vector<double> each_sample(std::size_t count, Compute compute) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = compute(i);
  return values;
}

constexpr std::array kTrafficLights = {FeatureKind::traffic_light};
constexpr std::array kStopLines = {FeatureKind::traffic_light, FeatureKind::stop_sign};
constexpr std::array kStopSigns = {FeatureKind::stop_sign};
constexpr std::array kCrosswalks = {FeatureKind::crosswalk};

const TraceLight& light_colours(const Trace& trace, const RoadMap& map, std::uint32_t light,
                                const SourceLocation& location) {
  const std::string& id = map.traffic_lights()[light].id;
  for (const TraceLight& colours : trace.lights)
    if (colours.id == id) return colours;
  throw OracleError(location, "the trace has no colours for traffic light '" + id + "'");
}

}  // namespace

SignalValues law_signal(const SpecTerm& term, const Trace& trace, const ScenarioTemplate& scenario,
                        std::span<const double> parameters, const RoadMap& map) {
  const std::string& name = term.name;
  const std::size_t count = trace.sample_count();
  const TraceActor& ego = trace.actors[kEgo];
  auto numeric = [](std::vector<double> values) { return SignalValues{std::move(values), false}; };
  auto discrete = [](std::vector<double> values) { return SignalValues{std::move(values), true}; };

  if (name == "speed")
    return numeric(each_sample(
        count, [&](std::size_t i) { return ego.speed[i] * kKilometresPerHourPerMetrePerSecond; }));
  if (name == "acc")
    return numeric(each_sample(count, [&](std::size_t i) {
      return std::hypot(ego.acceleration[i], ego.speed[i] * ego.yaw_rate[i]);
    }));
  if (name == "Time") {
    const double start = time_of_day(scenario, parameters, term.location);
    return numeric(each_sample(count, [&](std::size_t i) { return start + trace.time[i]; }));
  }
  if (name == "rain" || name == "fog" || name == "snow" || name == "wetness")
    return numeric(
        std::vector<double>(count, weather_intensity(scenario, parameters, name, term.location)));
  if (name == "NPCAhead")
    return numeric(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
      return vehicle_ahead(trace, view, i).distance;
    }));
  if (name == "NPCAhead.speed")
    return numeric(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
      return vehicle_ahead(trace, view, i).speed;
    }));
  if (name == "NearestNPC")
    return numeric(
        each_sample(count, [&](std::size_t i) { return nearest_vehicle(trace, i).distance; }));
  if (name == "NearestNPC.speed")
    return numeric(
        each_sample(count, [&](std::size_t i) { return nearest_vehicle(trace, i).speed; }));
  if (name == "trafficLightAhead.color")
    return discrete(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
      const FeatureFound light = nearest_feature(map, view, kTrafficLights);
      if (!light.index) return kNoLightCode;
      return colour_code(light_colours(trace, map, *light.index, term.location).colour[i]);
    }));
  if (name == "signalAhead")
    return discrete(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t) {
      return nearest_feature(map, view, kTrafficLights).index ? 1.0 : 0.0;
    }));
  if (name == "stoplineAhead" || name == "stopSignAhead" || name == "crosswalkAhead") {
    std::span<const FeatureKind> kinds = kCrosswalks;
    if (name == "stoplineAhead") kinds = kStopLines;
    if (name == "stopSignAhead") kinds = kStopSigns;
    return numeric(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t) {
      return nearest_feature(map, view, kinds).distance;
    }));
  }
  if (name == "junctionAhead")
    return numeric(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t) {
      return junction_distance(map, view);
    }));
  if (name == "currentLane.number")
    return numeric(each_sample(count, [&](std::size_t i) {
      if (ego.lane[i] < 0) return -1.0;  // TrashFuzz's value off the lanes (LawBreaker crashes)
      const auto lane = static_cast<LaneIndex>(ego.lane[i]);
      return map.lane(lane).junction ? 0.0 : lane_count_of_road(map, lane);
    }));
  throw OracleError(term.location,
                    "the oracle does not compute '" + name + "' on simulated traces yet");
}

}  // namespace scenfuzz

// scenest's traffic-law signals on a simulated trace. LawBreaker finds road objects "ahead" with a
// 45-degree fan in front of the car; we follow the lanes instead: the lane the ego is on, then the
// lanes it drives onto next in the run, then (past what the run shows) every successor, so a
// stop line on the opposite approach or a car in the next lane is never "ahead". The ego's
// manoeuvres (`direction`, ...) are read in law_manoeuvre.cpp, the priority flags in
// law_priority.cpp.
#include "oracle/law_signals.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "oracle/law_manoeuvre.hpp"
#include "oracle/law_priority.hpp"
#include "oracle/law_street_lights.hpp"
#include "oracle/law_vehicle_signals.hpp"
#include "physics/actors/actor_class.hpp"
#include "physics/actors/road_friction.hpp"
#include "physics/ego/perception.hpp"
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
// LawBreaker's speed limits where none is known.
constexpr double kNoUpperLimit = 1000, kNoLowerLimit = 0;  // km/h
// A vehicle driving against the ego: its heading more than this from the ego's lane's.
constexpr double kOncoming = 3 * std::numbers::pi / 4;
// isTrafficJam: this many vehicles slower than kStoppedSpeed in the junction ahead.
constexpr std::size_t kJamVehicles = 3;
constexpr double kStoppedSpeed = 1;  // m/s
// Apollo's gear code for DRIVE: the ego never reverses (only WMG SDL NPCs do).
constexpr double kDriveGear = 1;

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
    if (vehicle.kind != TraceActorKind::vehicle || vehicle.lane[i] < 0 || !present_at(vehicle, i))
      continue;
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
    if (trace.actors[k].kind != TraceActorKind::vehicle || !present_at(trace.actors[k], i))
      continue;
    const double gap = footprint_gap(trace, static_cast<ActorId>(k), i);
    if (gap < found.distance) found = {gap, trace.actors[k].speed[i]};
  }
  return found;
}

// `lanes` and the lanes side by side with them in their direction: forward neighbours,
// transitively.
std::vector<LaneIndex> side_by_side(const RoadMap& map, std::vector<LaneIndex> lanes) {
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const Lane& member = map.lane(lanes[k]);
    for (const auto* neighbours :
         {&member.left_forward_neighbours, &member.right_forward_neighbours})
      for (LaneIndex neighbour : *neighbours)
        if (std::find(lanes.begin(), lanes.end(), neighbour) == lanes.end())
          lanes.push_back(neighbour);
  }
  return lanes;
}

double lane_count_of_road(const RoadMap& map, LaneIndex lane) {
  return static_cast<double>(side_by_side(map, {lane}).size());
}

// The lanes of the carriageway beside a lane that runs the other way, per lane, found once.
class OppositeLanes {
 public:
  explicit OppositeLanes(const RoadMap& map) : map_(map) {}

  bool contains(LaneIndex lane, LaneIndex other) {
    auto found = cache_.find(lane);
    if (found == cache_.end()) found = cache_.emplace(lane, find(lane)).first;
    return std::find(found->second.begin(), found->second.end(), other) != found->second.end();
  }

 private:
  std::vector<LaneIndex> find(LaneIndex lane) const {
    std::vector<LaneIndex> reverse;
    for (LaneIndex member : side_by_side(map_, {lane})) {
      const Lane& beside = map_.lane(member);
      for (const auto* neighbours :
           {&beside.left_reverse_neighbours, &beside.right_reverse_neighbours})
        for (LaneIndex neighbour : *neighbours)
          if (std::find(reverse.begin(), reverse.end(), neighbour) == reverse.end())
            reverse.push_back(neighbour);
    }
    return side_by_side(map_, std::move(reverse));
  }

  const RoadMap& map_;
  std::unordered_map<LaneIndex, std::vector<LaneIndex>> cache_;
};

// The nearest vehicle ahead that drives against the ego: on the opposite carriageway beside a
// lane ahead (or, where that lane is in a junction, on any lane of the junction), its centre
// beside the lane ahead of the ego's centre, heading more than kOncoming from the lane's
// direction there (in a junction: from the ego's heading).
VehicleFound vehicle_opposite(const Trace& trace, const RoadMap& map, const AheadView& view,
                              OppositeLanes& opposite, std::size_t i) {
  const double reach = kNoRoadObjectAhead + view.half_length;
  VehicleFound found;
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    const TraceActor& vehicle = trace.actors[k];
    if (vehicle.kind != TraceActorKind::vehicle || vehicle.lane[i] < 0 || !present_at(vehicle, i))
      continue;
    const auto lane = static_cast<LaneIndex>(vehicle.lane[i]);
    const MapPoint centre{vehicle.x[i], vehicle.y[i]};
    bool oncoming = false;
    for (const LaneStretch& stretch : view.stretches) {
      const Lane& ahead = map.lane(stretch.lane);
      const bool same_junction = ahead.junction && ahead.junction == map.lane(lane).junction;
      if (!same_junction && !opposite.contains(stretch.lane, lane)) continue;
      const PolylineProjection beside = ahead.centre_line.project(centre);
      if (beside.s < stretch.s_begin || beside.s > stretch.s_end) continue;
      const double along = stretch.offset + (beside.s - stretch.s_begin);
      if (along <= 0 || along > reach) continue;
      // Junction lanes cross one another: there the ego's own heading says which way is back.
      const double way =
          ahead.junction ? trace.actors[kEgo].heading[i] : ahead.centre_line.heading_at(beside.s);
      if (std::abs(angle_difference(vehicle.heading[i], way)) > kOncoming) oncoming = true;
    }
    if (!oncoming) continue;
    const double gap = footprint_gap(trace, static_cast<ActorId>(k), i);
    if (gap < found.distance) found = {gap, vehicle.speed[i]};
  }
  return found;
}

bool inside_polygon(const std::vector<MapPoint>& polygon, MapPoint point) {
  bool inside = false;
  for (std::size_t a = 0, b = polygon.size() - 1; a < polygon.size(); b = a++) {
    const MapPoint p = polygon[a], q = polygon[b];
    if ((p.y > point.y) != (q.y > point.y) &&
        point.x < p.x + (point.y - p.y) * (q.x - p.x) / (q.y - p.y))
      inside = !inside;
  }
  return inside;
}

// 1 when at least kJamVehicles nearly stopped vehicles are in the junction junctionAhead
// reports: on its lanes or with their centre inside its outline.
double traffic_jam(const Trace& trace, const RoadMap& map, const AheadView& view, std::size_t i) {
  std::optional<std::uint32_t> junction;
  double nearest = 0;
  for (const LaneStretch& stretch : view.stretches) {
    const std::optional<std::uint32_t> here = map.lane(stretch.lane).junction;
    if (here && (!junction || stretch.offset < nearest)) {
      junction = here;
      nearest = stretch.offset;
    }
  }
  if (!junction) return 0;
  const std::vector<MapPoint>& outline = map.junctions()[*junction].outline;
  std::size_t stopped = 0;
  for (std::size_t k = 1; k < trace.actors.size(); ++k) {
    const TraceActor& vehicle = trace.actors[k];
    if (vehicle.kind != TraceActorKind::vehicle || vehicle.speed[i] >= kStoppedSpeed ||
        !present_at(vehicle, i))
      continue;
    const bool on_its_lanes =
        vehicle.lane[i] >= 0 &&
        map.lane(static_cast<LaneIndex>(vehicle.lane[i])).junction == junction;
    if (on_its_lanes ||
        (outline.size() >= 3 && inside_polygon(outline, {vehicle.x[i], vehicle.y[i]})))
      ++stopped;
  }
  return stopped >= kJamVehicles ? 1 : 0;
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

// The ego's speed limits on each lane, km/h: the scenario's SpeedLimit for the lane, else the
// map's limit (a maximum only), else LawBreaker's placeholders.
class SpeedLimits {
 public:
  SpeedLimits(const ScenarioTemplate& scenario, std::span<const double> parameters,
              const RoadMap& map, const SourceLocation& location)
      : map_(map) {
    for (const SpeedLimit& limit : scenario.traffic.speed_limits) {
      const double lower = evaluate(limit.lower, parameters);
      const double upper = evaluate(limit.upper, parameters);
      if (!std::isfinite(lower) || !std::isfinite(upper))
        throw OracleError(
            location, "the scenario's speed limit on lane '" + limit.lane + "' is not a number");
      scenario_.push_back({limit.lane, lower * kKilometresPerHourPerMetrePerSecond,
                           upper * kKilometresPerHourPerMetrePerSecond});
    }
  }

  // {lower, upper} on lane `lane` (-1: on no lane).
  std::pair<double, double> on(std::int32_t lane) const {
    if (lane < 0) return {kNoLowerLimit, kNoUpperLimit};
    const Lane& on_map = map_.lane(static_cast<LaneIndex>(lane));
    for (const Limit& limit : scenario_)
      if (limit.lane == on_map.id) return {limit.lower, limit.upper};
    if (on_map.speed_limit > 0)
      return {kNoLowerLimit, on_map.speed_limit * kKilometresPerHourPerMetrePerSecond};
    return {kNoLowerLimit, kNoUpperLimit};
  }

 private:
  struct Limit {
    std::string lane;
    double lower = 0, upper = 0;
  };
  const RoadMap& map_;
  std::vector<Limit> scenario_;
};

// The road's friction as the simulation took it (docs/simulation.md, "Road friction"); a value it
// refused never reaches a trace, so anything but a friction here is a dry road.
double road_friction(const ScenarioTemplate& scenario, std::span<const double> parameters) {
  if (!scenario.environment || !scenario.environment->road_friction) return kDryRoad;
  const double friction = evaluate(*scenario.environment->road_friction, parameters);
  return is_road_friction(friction) ? friction : kDryRoad;
}

// How far the ego's perception sees vehicles (m) in the scenario's weather and light, as the
// simulation degrades it from the default clear-weather range.
double visibility(const ScenarioTemplate& scenario, std::span<const double> parameters,
                  const SourceLocation& location) {
  Conditions conditions;
  auto intensity = [&](const std::string& kind) {
    return std::clamp(weather_intensity(scenario, parameters, kind, location), 0.0, 1.0);
  };
  conditions.fog = intensity("fog");
  conditions.rain = intensity("rain");
  conditions.snow = intensity("snow");
  conditions.darkness = darkness_at(time_of_day(scenario, parameters, location));
  return degraded(PerceptionSettings{}, conditions).vehicle_range;
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

// Every name law_signal answers besides the ego's lamps and horn (law_vehicle_signals.hpp); a
// test checks this list against it.
constexpr std::string_view kComputed[] = {"speed",
                                          "acc",
                                          "Time",
                                          "rain",
                                          "fog",
                                          "snow",
                                          "wetness",
                                          "NPCAhead",
                                          "NPCAhead.speed",
                                          "NearestNPC",
                                          "NearestNPC.speed",
                                          "trafficLightAhead.color",
                                          "signalAhead",
                                          "stoplineAhead",
                                          "stopSignAhead",
                                          "crosswalkAhead",
                                          "junctionAhead",
                                          "currentLane.number",
                                          "currentLane.direction",
                                          "direction",
                                          "isLaneChanging",
                                          "isTurningAround",
                                          "PriorityNPCAhead",
                                          "isOverTaking",
                                          "PriorityPedsAhead",
                                          "isTrafficJam",
                                          "NPCOpposite",
                                          "NPCOpposite.speed",
                                          "speedLimit.upperLimit",
                                          "speedLimit.lowerLimit",
                                          "visibility",
                                          "gear",
                                          "brake",
                                          "honkingAllowed",
                                          "streetLightOn",
                                          "specialLocationAhead",
                                          "specialLocationAhead.type"};

}  // namespace

bool law_signal_computed(std::string_view name) {
  return is_vehicle_law_signal(name) ||
         std::find(std::begin(kComputed), std::end(kComputed), name) != std::end(kComputed);
}

std::string uncomputed_law_signal_message(std::string_view name) {
  return "the oracle does not compute '" + std::string(name) + "' on simulated traces yet";
}

SignalValues law_signal(const SpecTerm& term, const Trace& trace, const ScenarioTemplate& scenario,
                        std::span<const double> parameters, const RoadMap& map) {
  const std::string& name = term.name;
  const std::size_t count = trace.sample_count();
  const TraceActor& ego = trace.actors[kEgo];
  auto numeric = [](std::vector<double> values) { return SignalValues{std::move(values), false}; };
  auto discrete = [](std::vector<double> values) { return SignalValues{std::move(values), true}; };

  if (std::optional<SignalValues> vehicle = vehicle_law_signal(name, trace)) return *vehicle;
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
  if (name == "currentLane.direction") return discrete(current_lane_direction(trace, map));
  auto manoeuvre = [&] {
    return ego_manoeuvre(trace, map, ego_target(scenario, parameters, trace, map));
  };
  if (name == "direction") return discrete(manoeuvre().direction);
  if (name == "isLaneChanging") {
    const EgoManoeuvre changes = manoeuvre();
    return discrete(
        each_sample(count, [&](std::size_t i) { return changes.lane_changing[i] ? 1.0 : 0.0; }));
  }
  if (name == "isTurningAround") return discrete(turning_around(trace, manoeuvre()));
  if (name == "PriorityNPCAhead") {
    const std::vector<double> ahead =
        along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
          return vehicle_ahead(trace, view, i).distance;
        });
    return discrete(priority_vehicle_ahead(trace, manoeuvre(), ahead));
  }
  if (name == "isOverTaking") return discrete(overtaking(trace, map, manoeuvre()));
  if (name == "PriorityPedsAhead") return discrete(priority_pedestrian_ahead(trace, manoeuvre()));
  if (name == "isTrafficJam")
    return discrete(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
      return traffic_jam(trace, map, view, i);
    }));
  if (name == "NPCOpposite" || name == "NPCOpposite.speed") {
    OppositeLanes opposite(map);
    const bool speed = name == "NPCOpposite.speed";
    return numeric(along_the_lanes(trace, map, [&](const AheadView& view, std::size_t i) {
      const VehicleFound found = vehicle_opposite(trace, map, view, opposite, i);
      return speed ? found.speed : found.distance;
    }));
  }
  if (name == "speedLimit.upperLimit" || name == "speedLimit.lowerLimit") {
    const SpeedLimits limits(scenario, parameters, map, term.location);
    const bool upper = name == "speedLimit.upperLimit";
    return numeric(each_sample(count, [&](std::size_t i) {
      const auto [lower_limit, upper_limit] = limits.on(ego.lane[i]);
      return upper ? upper_limit : lower_limit;
    }));
  }
  if (name == "visibility")
    return numeric(std::vector<double>(count, visibility(scenario, parameters, term.location)));
  if (name == "gear") return discrete(std::vector<double>(count, kDriveGear));
  if (name == "brake") {
    // Full braking on this road: on ice the pedal is floored at a fraction of the dry limit.
    const double full_braking =
        on_road(actor_class(ego.category), road_friction(scenario, parameters)).max_deceleration;
    return numeric(each_sample(count, [&](std::size_t i) {
      return std::clamp(-ego.acceleration[i] / full_braking * 100, 0.0, 100.0);
    }));
  }
  if (name == "streetLightOn")
    return discrete(street_lights_on(trace, map, time_of_day(scenario, parameters, term.location)));
  // Honking is allowed everywhere and no special location is ever ahead, by what the maps hold:
  // Apollo's HD map format has no no-honking sign, and neither it nor the built-in maps have
  // school zones, tunnels or bridges (docs/oracle.md).
  if (name == "honkingAllowed") return discrete(std::vector<double>(count, 1));
  if (name == "specialLocationAhead")
    return numeric(std::vector<double>(count, kNoRoadObjectAhead));
  if (name == "specialLocationAhead.type") return discrete(std::vector<double>(count, 0));
  throw OracleError(term.location, uncomputed_law_signal_message(name));
}

}  // namespace scenfuzz

// Background traffic: flows resolved onto the map, their vehicles drawn once per run, and the
// entry check that makes a late arrival wait rather than spawn into whatever stands there.
#include "physics/simulation/traffic_flows.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "lang/number_format.hpp"
#include "physics/actors/path_pose.hpp"
#include "physics/actors/trajectory.hpp"
#include "physics/map/junction_stretch.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/simulation/scenario_checks.hpp"

namespace scenfuzz {
namespace {

// A flow without a destination drives along successors this much beyond what the duration needs,
// as scripted NPCs do.
constexpr double kRouteMargin = 50;  // m
// The speed of a flow that gives none: the source lane's limit, or a town's 50 km/h.
constexpr double kDefaultFlowSpeed = 50 / 3.6;  // m/s
// The safe gap between flow vehicles: their length, this much bumper to bumper, and this long at
// their speed.
constexpr double kStandstillGap = 2;  // m
constexpr double kGapTime = 1;        // s
// Beside each other within this much across, two bodies are in one another's way.
constexpr double kSideMargin = 0.5;  // m
// m/s^2 a faster actor behind a pre-filled car is given room to brake at to its speed.
constexpr double kClosingDeceleration = 3;
// Keeps the draws of flows and of actors (scenario_setup.cpp's actor_seed) apart.
constexpr std::uint64_t kFlowStream = 0x666c6f77ull;

std::uint64_t flow_seed(std::uint64_t seed, std::size_t flow) {
  // SplitMix64 of (seed, stream, flow): neighbouring flows get unrelated streams.
  std::uint64_t z = (seed ^ kFlowStream) + 0x9E3779B97F4A7C15ull * (flow + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// SplitMix64 as a generator with an exponential draw of its own: std's distributions differ
// between standard libraries, and a schedule must not.
struct FlowRandom {
  std::uint64_t state;

  std::uint64_t next() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Exponentially distributed with `mean`.
  double exponential(double mean) {
    const double u = static_cast<double>(next() >> 11) * 0x1.0p-53;  // in [0, 1)
    return -mean * std::log1p(-u);
  }
};

double safe_gap(const ActorClass& body, double speed) {
  return body.length + kStandstillGap + kGapTime * speed;
}

// A body that stands somewhere: an actor's initial pose, or a placed flow vehicle.
struct Occupant {
  MapPose pose;
  double length = 0, width = 0;
  double speed = 0;  // m/s at t = 0
};

// Whether `other` is in the way of a flow vehicle at `at`: bodies that (nearly) touch, or one in
// line with it within its safe gap, ahead or behind.
bool in_the_way(const MapPose& at, const ActorClass& body, double gap, double speed,
                const Occupant& other) {
  const double dx = other.pose.position.x - at.position.x;
  const double dy = other.pose.position.y - at.position.y;
  const double reach =
      (std::hypot(body.length, body.width) + std::hypot(other.length, other.width)) / 2 +
      kSideMargin;
  if (std::hypot(dx, dy) < reach) return true;
  const double along = dx * std::cos(at.heading) + dy * std::sin(at.heading);
  const double across = -dx * std::sin(at.heading) + dy * std::cos(at.heading);
  double centres = gap - body.length / 2 + other.length / 2;
  // One behind (the ego at 30 m/s behind a flow car at 10) needs room to slow down to it.
  if (along < 0) {
    const double closing = std::max(0.0, other.speed - speed);
    centres = std::max(centres, (body.length + other.length) / 2 + kStandstillGap +
                                    kGapTime * other.speed +
                                    closing * closing / (2 * kClosingDeceleration));
  }
  return std::abs(across) < (body.width + other.width) / 2 + kSideMargin &&
         std::abs(along) < centres;
}

// Whether a vehicle pre-filled at s (its centre, route distance) would be in a junction, or too
// near one to stop before it: crossing flows' vehicles placed so could not give way to each other
// (san_francisco's background traffic, seed 7: two side impacts in the first half second).
bool near_junction(const FlowPlan& flow, double s, const ActorClass& body, double speed) {
  const double stopping =
      speed * speed / (2 * body.comfortable_deceleration) + kStandstillGap + body.length / 2;
  return std::any_of(flow.junctions.begin(), flow.junctions.end(), [&](const auto& junction) {
    return s + stopping > junction.first && s - body.length / 2 < junction.second;
  });
}

MapPose pose_on(const Polyline& path, double s) {
  return {path.point_at(s), direction_at(path, s).heading};
}

std::vector<Occupant> initial_occupants(const SimulationSetup& setup) {
  std::vector<Occupant> occupants;
  occupants.push_back({{{setup.ego_initial.x, setup.ego_initial.y}, setup.ego_initial.heading},
                       setup.ego_body.length,
                       setup.ego_body.width,
                       setup.ego_initial.speed});
  for (const ScriptedActor& actor : setup.actors) {
    const KinematicState start = actor.trajectory.state_at(0);
    occupants.push_back(
        {{{start.x, start.y}, start.heading}, actor.body.length, actor.body.width, start.speed});
  }
  for (const StaticObstacle& obstacle : setup.obstacles)
    occupants.push_back({obstacle.pose, obstacle.geometry.length, obstacle.geometry.width});
  return occupants;
}

// The vehicles one flow sends: the pre-fill along its path, nearest the start first, with
// headways of mean speed x 3600 / rate metres and never less than the safe gap (an exponential
// beyond the gap, so that the mean and so the density stay the flow's), then arrivals at its
// start with exponential inter-arrival times of mean 3600 / rate seconds up to `duration`.
// Stops after kMaxFlowVehicles + 1 (the cap is applied over all flows).
std::vector<FlowVehicle> draw_flow(const FlowPlan& flow, std::size_t index, double duration,
                                   std::vector<Occupant>& occupants) {
  std::vector<FlowVehicle> vehicles;
  if (!(flow.rate > 0)) return vehicles;
  const ActorClass& body = flow.body;
  const double speed = std::min(flow.speed, body.max_speed);
  const double gap = safe_gap(body, speed);
  const double headway = speed * 3600 / flow.rate;
  FlowRandom random{flow_seed(flow.seed, index)};
  auto name = [&] { return flow.name + "." + std::to_string(vehicles.size() + 1); };
  const double last = flow.path.length() - body.length / 2;
  for (double s = 0; vehicles.size() <= kMaxFlowVehicles;) {
    s += headway > gap ? gap + random.exponential(headway - gap) : gap;
    if (s > last) break;
    if (near_junction(flow, s, body, speed)) continue;
    const MapPose pose = pose_on(flow.path, s);
    const bool clear = std::none_of(occupants.begin(), occupants.end(), [&](const Occupant& o) {
      return in_the_way(pose, body, gap, speed, o);
    });
    if (!clear) continue;
    occupants.push_back({pose, body.length, body.width, speed});
    vehicles.push_back({index, name(), 0, s, true});
  }
  const double interval = 3600 / flow.rate;
  for (double t = random.exponential(interval);
       t <= duration && vehicles.size() <= kMaxFlowVehicles; t += random.exponential(interval))
    vehicles.push_back({index, name(), t, 0, false});
  return vehicles;
}

// The first kMaxFlowVehicles of all flows' vehicles by when they are due (pre-filled ones first),
// kept in flow order.
FlowSchedule capped(std::vector<FlowVehicle> vehicles, std::size_t flow_count) {
  FlowSchedule schedule;
  if (vehicles.size() <= kMaxFlowVehicles) {
    schedule.vehicles = std::move(vehicles);
    return schedule;
  }
  std::vector<std::size_t> order(vehicles.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return vehicles[a].due < vehicles[b].due; });
  std::vector<std::uint8_t> kept(vehicles.size(), 0), lost(flow_count, 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i < kMaxFlowVehicles)
      kept[order[i]] = 1;
    else
      lost[vehicles[order[i]].flow] = 1;
  }
  for (std::size_t i = 0; i < vehicles.size(); ++i)
    if (kept[i]) schedule.vehicles.push_back(std::move(vehicles[i]));
  for (std::size_t flow = 0; flow < flow_count; ++flow)
    if (lost[flow]) schedule.capped.push_back(flow);
  return schedule;
}

// The flow's vehicles' desired speed: as given, or the source lane's limit, or 50 km/h.
std::optional<double> flow_speed(const TrafficFlow& flow, std::span<const double> values,
                                 const Lane& source, Diagnostics& diagnostics) {
  if (!flow.speed) return source.speed_limit > 0 ? source.speed_limit : kDefaultFlowSpeed;
  const double speed = evaluate(*flow.speed, values);
  const SourceLocation& where =
      flow.speed->location.line > 0 ? flow.speed->location : flow.location;
  if (!check_speed(speed, false, "flow " + flow.name, where, diagnostics)) return std::nullopt;
  if (speed <= 0) {
    diagnostics.error(where, "flow " + flow.name + "'s vehicles must move: its speed is 0 m/s");
    return std::nullopt;
  }
  return speed;
}

std::optional<double> flow_rate(const TrafficFlow& flow, std::span<const double> values,
                                Diagnostics& diagnostics) {
  const double rate = evaluate(flow.rate, values);
  if (std::isfinite(rate) && rate >= 0) return rate;
  diagnostics.error(flow.rate.location.line > 0 ? flow.rate.location : flow.location,
                    "flow " + flow.name + "'s rate must be a finite number of vehicles per hour " +
                        ">= 0, not " + format_number(rate));
  return std::nullopt;
}

std::optional<LaneIndex> flow_lane(const RoadMap& map, const std::string& id,
                                   const TrafficFlow& flow, Diagnostics& diagnostics) {
  auto lane = map.find_lane(id);
  if (!lane)
    diagnostics.error(flow.location, "unknown lane '" + id + "' on map '" + map.name() +
                                         "' (flow " + flow.name + ")");
  return lane;
}

// To the end of the destination lane (or, when that cannot be reached, its start), or along
// successors for what the duration needs.
std::optional<LaneRoute> flow_route(const RoadMap& map, const TrafficFlow& flow, LaneIndex source,
                                    double speed, double duration, Diagnostics& diagnostics) {
  if (flow.destination_lane.empty())
    return route_ahead(map, LanePosition{source, 0, 0}, speed * duration + kRouteMargin);
  auto destination = flow_lane(map, flow.destination_lane, flow, diagnostics);
  if (!destination) return std::nullopt;
  const LanePosition from{source, 0, 0};
  auto route =
      find_route(map, from, LanePosition{*destination, map.lane(*destination).length(), 0});
  if (!route) route = find_route(map, from, LanePosition{*destination, 0, 0});
  if (!route)
    diagnostics.error(flow.location, "no route over the lanes of map '" + map.name() +
                                         "' leads from lane '" + flow.source_lane + "' to lane '" +
                                         flow.destination_lane + "' (flow " + flow.name + ")");
  return route;
}

std::vector<std::pair<double, double>> junctions_on(const RoadMap& map, const LaneRoute& route) {
  std::vector<double> starts;
  double distance = 0;
  for (const RouteSegment& segment : route.segments) {
    starts.push_back(distance);
    distance += segment.s_end - segment.s_begin;
  }
  std::vector<std::pair<double, double>> junctions;
  for (double from = 0;;) {
    auto stretch = junction_stretch_ahead(map, route.segments, starts, from);
    if (!stretch) break;
    junctions.emplace_back(stretch->entry, stretch->exit);
    from = stretch->exit;
  }
  return junctions;
}

std::optional<FlowPlan> prepare_flow(const TrafficFlow& flow, std::span<const double> values,
                                     const RoadMap& map, std::uint64_t seed, double duration,
                                     double road_friction, Diagnostics& diagnostics) {
  auto source = flow_lane(map, flow.source_lane, flow, diagnostics);
  auto rate = flow_rate(flow, values, diagnostics);
  if (!source || !rate) return std::nullopt;
  auto speed = flow_speed(flow, values, map.lane(*source), diagnostics);
  if (!speed) return std::nullopt;
  auto route = flow_route(map, flow, *source, *speed, duration, diagnostics);
  if (!route) return std::nullopt;
  if (route->segments.empty() || route->length < flow_vehicle_body().length) {
    diagnostics.warning(flow.location, "flow " + flow.name + "'s route from lane '" +
                                           flow.source_lane + "' is only " +
                                           format_number(route->length) +
                                           " m long; it sends no vehicles");
    return std::nullopt;
  }
  std::vector<PathPlace> places;
  Polyline path = rounded_route_path(map, *route, 0, planning_radius(flow_vehicle_body()), places);
  return FlowPlan{flow.name,
                  flow.location,
                  *route,
                  std::move(path),
                  std::move(places),
                  *rate,
                  *speed,
                  seed,
                  junctions_on(map, *route),
                  on_road(flow_vehicle_body(), road_friction)};
}

}  // namespace

ActorClass flow_vehicle_body() { return actor_class(ActorCategory::car); }

void prepare_flows(const ScenarioTemplate& scenario, std::span<const double> values,
                   const RoadMap& map, std::uint64_t seed, SimulationSetup& setup,
                   Diagnostics& diagnostics) {
  const auto& flows = scenario.traffic.flows;
  for (std::size_t i = 0; i < flows.size(); ++i) {
    auto plan =
        prepare_flow(flows[i], values, map, seed, setup.duration, setup.road_friction, diagnostics);
    if (plan) setup.flows.push_back(std::move(*plan));
  }
  const FlowSchedule schedule = draw_flow_schedule(setup, setup.duration);
  for (std::size_t flow : schedule.capped)
    diagnostics.warning(setup.flows[flow].location,
                        "flow " + setup.flows[flow].name + " sends fewer vehicles than its rate " +
                            "asks for: a run has at most " + std::to_string(kMaxFlowVehicles) +
                            " background vehicles, and the latest arrivals are left out");
}

FlowSchedule draw_flow_schedule(const SimulationSetup& setup, double duration) {
  std::vector<Occupant> occupants = initial_occupants(setup);
  std::vector<FlowVehicle> vehicles;
  for (std::size_t i = 0; i < setup.flows.size(); ++i) {
    std::vector<FlowVehicle> drawn = draw_flow(setup.flows[i], i, duration, occupants);
    vehicles.insert(vehicles.end(), std::make_move_iterator(drawn.begin()),
                    std::make_move_iterator(drawn.end()));
  }
  return capped(std::move(vehicles), setup.flows.size());
}

std::optional<double> flow_entry_speed(const FlowPlan& flow, std::span<const KinematicState> states,
                                       std::span<const double> lengths,
                                       std::span<const double> widths,
                                       std::span<const std::uint8_t> present) {
  const ActorClass& body = flow.body;
  const double desired = std::min(flow.speed, body.max_speed);
  const MapPose entry = pose_on(flow.path, 0);
  const double c = std::cos(entry.heading), s = std::sin(entry.heading);
  // In line with the entry, the slowest within braking reach ahead sets the speed to enter at;
  // whatever is then within the safe gap at that speed, ahead or behind, blocks the entry.
  const double reach =
      desired * desired / (2 * body.comfortable_deceleration) + safe_gap(body, desired);
  double speed = desired;
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (!present.empty() && present[k] == 0) continue;
    const double dx = states[k].x - entry.position.x, dy = states[k].y - entry.position.y;
    const double along = dx * c + dy * s, across = -dx * s + dy * c;
    if (along <= 0 || along > reach + lengths[k] ||
        std::abs(across) >= (body.width + widths[k]) / 2 + kSideMargin)
      continue;
    const double heading_along = std::cos(states[k].heading - entry.heading);
    speed = std::min(speed, std::max(0.0, states[k].speed * heading_along));
  }
  const double gap = safe_gap(body, speed);
  for (std::size_t k = 0; k < states.size(); ++k) {
    if (!present.empty() && present[k] == 0) continue;
    const Occupant other{
        {{states[k].x, states[k].y}, states[k].heading}, lengths[k], widths[k], states[k].speed};
    if (in_the_way(entry, body, gap, speed, other)) return std::nullopt;
  }
  return speed;
}

}  // namespace scenfuzz

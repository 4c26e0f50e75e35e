// The default duration of a run (default_duration.hpp says the rule).
#include "physics/simulation/default_duration.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "lang/spec_horizon.hpp"
#include "physics/ego/reference_driver.hpp"
#include "physics/map/lane_queries.hpp"

namespace scenfuzz {

double route_time_at_limits(const RoadMap& map, const LaneRoute& route,
                            std::span<const std::pair<LaneIndex, double>> speed_limits,
                            double max_speed) {
  const double unlimited = DriverSettings{}.default_speed_limit;
  double seconds = 0;
  for (const RouteSegment& segment : route.segments) {
    const double own = map.lane(segment.lane).speed_limit;
    double limit = own > 0 ? own : unlimited;
    for (const auto& [lane, speed] : speed_limits)
      if (lane == segment.lane && speed > 0) limit = speed;
    limit = std::min(limit, max_speed);
    if (limit > 0) seconds += (segment.s_end - segment.s_begin) / limit;
  }
  return seconds;
}

namespace {

// Seconds a fixed-time plan shows anything but green in one cycle.
double non_green_time(const SignalPlan& plan) {
  double seconds = 0;
  for (const SignalPhase& phase : plan.phases)
    if (phase.colour != SignalColour::green) seconds += phase.duration;
  return seconds;
}

bool controls_route(const TrafficLight& light, const LaneRoute& route) {
  for (const LaneCrossing& crossing : light.lanes)
    for (const RouteSegment& segment : route.segments)
      if (segment.lane == crossing.lane) return true;
  return false;
}

// Whether `point` lies inside the stretch of a lane the route drives.
bool on_route(const RoadMap& map, const LaneRoute& route, MapPoint point) {
  for (const RouteSegment& segment : route.segments) {
    const PolylineProjection p = map.lane(segment.lane).centre_line.project(point);
    if (p.s < segment.s_begin || p.s > segment.s_end) continue;
    const double half_width = p.lateral >= 0 ? lane_left_width_at(map, segment.lane, p.s)
                                             : lane_right_width_at(map, segment.lane, p.s);
    if (std::abs(p.lateral) <= half_width) return true;
  }
  return false;
}

}  // namespace

double route_waits(const RoadMap& map, const LaneRoute& route,
                   std::span<const MapPoint> obstacles) {
  std::set<std::uint32_t> junctions;
  for (const RouteSegment& segment : route.segments)
    if (const auto junction = map.lane(segment.lane).junction) junctions.insert(*junction);
  double seconds = kJunctionWait * static_cast<double>(junctions.size());
  for (const MapPoint& obstacle : obstacles)
    if (on_route(map, route, obstacle)) seconds += kJunctionWait;
  for (const TrafficLight& light : map.traffic_lights())
    if (light.plan && controls_route(light, route)) seconds += non_green_time(*light.plan);
  return seconds;
}

double default_duration(std::span<const Spec> specs, std::optional<double> route_time,
                        double waits) {
  double duration = kDefaultDuration;
  if (const std::optional<SpecHorizon> longest = longest_horizon(specs))
    duration = std::max(duration, longest->seconds);
  if (route_time)
    duration = std::max(duration, kRouteTimeMargin * *route_time + kStartStopAllowance + waits);
  return duration;
}

}  // namespace scenfuzz

#include "physics/simulation/default_duration.hpp"

#include <algorithm>

#include "lang/spec_horizon.hpp"
#include "physics/ego/reference_driver.hpp"

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

double default_duration(std::span<const Spec> specs, std::optional<double> route_time) {
  double duration = kDefaultDuration;
  if (const std::optional<SpecHorizon> longest = longest_horizon(specs))
    duration = std::max(duration, longest->seconds);
  if (route_time)
    duration = std::max(duration, kRouteTimeMargin * *route_time + kStartStopAllowance);
  return duration;
}

}  // namespace scenfuzz

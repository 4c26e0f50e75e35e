// An actor's lane position as a distance along a lane route: a walk over the route's segments.
#include "physics/simulation/route_place.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

std::optional<RoutePlace> place_on_route(const LaneRoute& route, std::span<const double> starts,
                                         const LaneFix& fix, std::size_t from, double until,
                                         double tolerance) {
  SCENFUZZ_DEMAND(starts.size() == route.segments.size());
  if (fix.lane < 0) return std::nullopt;
  const auto lane = static_cast<LaneIndex>(fix.lane);
  for (std::size_t k = from; k < route.segments.size() && starts[k] < until; ++k) {
    const RouteSegment& segment = route.segments[k];
    if (segment.lane != lane) continue;
    // A lane left sideways (a lane change) is not on the route beyond where the route leaves it.
    if (fix.s < segment.s_begin - tolerance || fix.s > segment.s_end + tolerance) continue;
    return RoutePlace{k, starts[k] + (fix.s - segment.s_begin)};
  }
  return std::nullopt;
}

}  // namespace scenfuzz

// Where an actor tracked on a lane (LaneTracker's lane and s) is along a lane route, in route
// distance: how a lane follower measures the gap to its leader between scans, along the lanes as
// traffic simulators do (SUMO: the leader's lane position less the follower's), instead of
// searching its path for the leader's points at every step.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "physics/map/lane_route.hpp"
#include "physics/simulation/lane_tracker.hpp"

namespace scenfuzz {

struct RoutePlace {
  std::size_t segment = 0;  // the route segment whose lane the actor is on
  double distance = 0;      // m along the route
};

// The first route segment from `from` on, among those beginning before route distance `until`,
// that runs along `fix`'s lane over fix.s (within `tolerance` of its ends), and fix's route
// distance there; nullopt when none does (the actor is on no lane, or off the route there).
// `starts` holds the route distance where each route segment begins.
std::optional<RoutePlace> place_on_route(const LaneRoute& route, std::span<const double> starts,
                                         const LaneFix& fix, std::size_t from, double until,
                                         double tolerance);

}  // namespace scenfuzz

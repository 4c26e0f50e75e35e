// The duration of a run when neither --duration nor the scenario gives one, decided here and
// nowhere else (docs/search.md, "Duration"): long enough for every spec to be decided and for
// the ego to reach its target.
//   duration = max(30 s, the longest spec horizon, route time)
//   route time = 1.2 x (the ego's route driven at the speed limits along it) + 15 s + waits
//   waits = 10 s for each junction the route passes through (giving way, pedestrians on its
//           crossings) and for each static obstacle in one of its lanes (waiting for a gap in
//           the next lane to pass it) + for each traffic light on the route with a plan, its red
//           and amber time
// where a lane's limit is the scenario's SpeedLimit, else the map's, else the reference driver's
// default (50 km/h), and never above the ego body's top speed; the 20 % are for bends, lane
// changes and slower traffic, the 15 s for starting, stopping and the slow last metres to the
// target (at the reference driver's 1.5 m/s^2 and 2.5 m/s^2, reaching and leaving 17 m/s costs
// about 9 s over driving at it throughout).
// A scenario without a target has no route time. What the run does beyond that is the oracle's
// concern: a run cut short while the ego still makes progress is a time-out, not a finding
// (oracle/judge.hpp).
#pragma once

#include <optional>
#include <span>
#include <utility>

#include "lang/spec.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

inline constexpr double kDefaultDuration = 30;     // s: the shortest default
inline constexpr double kRouteTimeMargin = 1.2;    // times the route's time at the limits
inline constexpr double kStartStopAllowance = 15;  // s added to it
inline constexpr double kJunctionWait = 10;        // s for each junction on the route

// Seconds to drive `route` at the speed limit of every lane along it (`speed_limits` override the
// map's), at most `max_speed`.
double route_time_at_limits(const RoadMap& map, const LaneRoute& route,
                            std::span<const std::pair<LaneIndex, double>> speed_limits,
                            double max_speed);

// Seconds the ego may have to wait along `route`: kJunctionWait for each junction it passes
// through and for each of `obstacles` (positions of obstacles and of vehicles at their start, which
// it may follow and pass) inside one of its lanes, and the red and
// amber time of each planned light that controls one of its lanes.
double route_waits(const RoadMap& map, const LaneRoute& route,
                   std::span<const MapPoint> obstacles = {});

// The default duration for `specs`, and for an ego whose route to its target takes
// `route_time` seconds at the limits (nullopt: no target) and may wait `waits` seconds.
double default_duration(std::span<const Spec> specs, std::optional<double> route_time,
                        double waits = 0);

}  // namespace scenfuzz

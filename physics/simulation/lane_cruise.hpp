// How an actor that knows only its lane position (a WMG SDL actor between its manoeuvre phases)
// drives on reactively: the Intelligent Driver Model towards its cruising speed, behind the
// nearest actor ahead along the lanes it will take (or, out on the oncoming lane after pulling
// out to overtake, ahead in the band of road it covers there), stopping for red lights on them
// and before a dead end. LaneFollower does the same for actors with a planned route and path.
#pragma once

#include <cstdint>

#include "physics/actors/actor_class.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/simulation/lanes_ahead.hpp"
#include "physics/simulation/world_snapshot.hpp"

namespace scenfuzz {

// Whom an actor on a lane follows. Out on the oncoming lane after pulling out to overtake (one
// lane each way), it keeps its own lane's frame, for its direction and route; what is in that
// lane is then beside it, what it passes, and what it must not run into is what lies in the band
// of road its body covers there, whichever lane it is in: the oncoming traffic.
enum class LeaderScope {
  lanes,     // what is in the lanes it takes
  corridor,  // what overlaps the band at.lateral +- half its width (and a margin) along them
};

// The acceleration along the heading (m/s^2, within the class's limits) for actor `self` of
// `world`, at `at` moving forwards, aiming for `cruise_speed`, behind the leader `scope` says.
double cruise_acceleration(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                           const NextLane& next_lane, const ActorClass& body, double cruise_speed,
                           LeaderScope scope);

// For a WMG actor in a manoeuvre phase: the most acceleration (m/s^2, at least minus the class's
// braking) that keeps it from running into the nearest actor other than the ego ahead on the lanes
// it takes from `at`, or, while a lane change has its centre in another lane (world.lanes[self]),
// ahead on that lane and still beside it (with LeaderScope::corridor: the nearest such actor in
// its band of road instead); +infinity while the script may run as written. The script keeps its
// speeds until firm braking is needed to stop behind its leader (at 2 m plus 0.5 s), and then
// brakes as much as that needs; within that gap it drops back. The script is the fuzzer's
// adversary to the ego, not to the rest of the traffic: it may still hit the ego.
double phase_leader_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                          const NextLane& next_lane, const ActorClass& body, LeaderScope scope);

// For a vehicle in a manoeuvre phase: the most acceleration that stops it at a red light (or a
// yellow one it can stop for) on the lanes it takes from `at`, IDM's braking for a stop line
// (as cruise_acceleration's, without its free-road term: the phase keeps its speed until the
// light needs braking); +infinity when no light stops it.
double red_light_limit(const WorldSnapshot& world, std::uint32_t self, LanePosition at,
                       const NextLane& next_lane, const ActorClass& body);

// IDM's braking (m/s^2, at least minus the class's full braking) for an actor at `speed` to stop
// 1 m short of a stop line `gap` m ahead of its front bumper, without IDM's free-road term.
double stop_line_limit(double speed, double gap, const ActorClass& body);

// The deceleration (negative, m/s^2) that stops an actor at `at` moving at `speed` before the
// end of the lanes ahead, or +infinity when there is room for comfortable braking later.
double dead_end_braking(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                        const ActorClass& body, double speed, double dt);

// The deceleration (negative, m/s^2) an actor at `at` moving at `speed` needs so as to take the
// bends of the lanes ahead within `lateral_acceleration` (speed^2 x curvature), braking at its
// comfortable deceleration; +infinity when it needs none yet.
double bend_braking(const RoadMap& map, LanePosition at, const NextLane& next_lane,
                    const ActorClass& body, double speed, double lateral_acceleration);

}  // namespace scenfuzz

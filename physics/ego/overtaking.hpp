// Overtaking for the reference driver: when a stopped or much slower vehicle, cyclist or obstacle
// blocks its lane, the driver moves sideways into a free lane beside (same direction) or into the
// oncoming lane, passes, and comes back. The manoeuvre is a sideways offset from the route's path
// as a function of path arc length, so that steering and the search for objects in the way both
// follow it. The rules (which lines may be crossed, how clear the oncoming lane must be) are in
// docs/simulation.md ("Overtaking").
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/actors/kinematics.hpp"
#include "physics/ego/perception.hpp"
#include "physics/ego/route_tracker.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

// m/s: below it a blocker is swept as if standing and kept room behind, and the ego itself may
// pull out at full lock.
inline constexpr double kWalkingPace = 1.5;

struct OvertakingSettings {
  bool enabled = true;
  double lateral_speed = 1.0;               // m/s, mean sideways speed of a lane change
  double fastest_lateral_speed = 2.0;       // m/s, when the room ahead asks for a quicker one
  double shortest_move = 12.0;              // m of travel for a sideways move (at walking pace)
  double waiting_gap = 12.0;                // m kept behind a blocker the driver waits to pass
  double slower_by = 3.0;                   // m/s: a lead this much below the desired speed ...
  double slower_fraction = 0.7;             // ... and below this fraction of it is "much slower"
  double slow_enough_for_solid_line = 4.5;  // m/s (10 mph): may cross a solid line to pass it
  double oncoming_margin = 2.0;             // s the oncoming traffic must still be away at the end
  double sight_distance = 200.0;  // m of oncoming lane it trusts is empty when it sees none
  double longest_cluster = 60.0;  // m: a longer row of slow objects is a queue, not passed
  double gap_ahead = 5.0;         // m, plus the time gap, kept to others when moving over
  double time_gap = 1.0;          // s
  // Indicate, then move: the indicator is on this long before the pull-out starts (the notice
  // the signal policy gives a lane change, IndicationNotice: 3 s), and the lane is checked
  // again then (the mirror, then the shoulder).
  double indicate_time = 3.0;  // s
  // s the pass must have been found possible without a break before the ego pulls out: one
  // step's answer may be the perception noise's luck (a pull-out's margin to a standing car).
  double steady_time = 0.5;
  // A car behind in the passing lane must not have to brake harder than this for the ego
  // (MOBIL's safe-braking criterion, Kesting, Treiber, Helbing 2007).
  double rear_braking = 2.0;     // m/s^2
  double sweep_margin = 0.6;     // m the body keeps from a standing blocker while pulling out
  double tight_lookahead = 2.5;  // m: the pure-pursuit aim of a pull-out at full lock
  double return_notice = 1.5;    // s the indicator is on towards its lane before moving back
};

// An overtaking manoeuvre under way, in path arc length of the ego's centre.
struct OvertakePlan {
  bool active = false;
  bool oncoming = false;  // into the oncoming lane (the timing check applies throughout)
  LaneIndex lane = 0;     // the passing lane
  double offset = 0;      // m, left positive: the passing lane's centre from the path
  double out_begin = 0, out_end = 0;
  double back_begin = std::numeric_limits<double>::infinity();
  double back_end = std::numeric_limits<double>::infinity();
  double back_from = 0;  // the sideways offset where the move back begins
  // The objects being passed: their rear's and front's last known path arc length, and speed.
  struct Passed {
    ActorId id = 0;
    double rear_s = 0;
    double front_s = 0;
    double speed = 0;
  };
  std::vector<Passed> passing;
  // m: the pure-pursuit lookahead through the move out (a tight pull-out from close behind
  // something standing); 0 for the driver's usual one.
  double pull_out_lookahead = 0;
  // Not active yet: indicating towards `lane` (at `offset`) since `indicating_since` (s), to
  // pull out once the indicator has been on long enough and the lane is still free.
  bool indicating = false;
  double indicating_since = 0;
  double possible_since = -1;  // s: the pass found possible at every step since; -1 not now
  // Active, past what it passes: indicating back since this time (s), the move back to follow
  // after the return notice; negative before.
  double back_indicating_since = -1;
};

// The sideways offset (left positive) the plan puts the ego at, at path arc length s.
double planned_lateral(const OvertakePlan& plan, double s);

// An object in the ego's way, as the driver sees it along its path.
struct Blocker {
  const WorldObject* object = nullptr;
  double rear_s = 0;   // path arc length of its rear
  double front_s = 0;  // and of its front
  double speed = 0;    // along the path
};

// What the ego knows when deciding about a pass.
struct OvertakeContext {
  const RoadMap& map;
  const RouteTracker& route;
  const ActorClass& vehicle;
  const KinematicState& ego;
  std::span<const WorldObject> objects;
  double desired_speed = 0;  // what the ego would drive on a free road here
  double comfortable_acceleration = 0;
  double dt = 0.1;              // s since the previous step
  double lookahead_time = 0.8;  // s and m: the driver's pure-pursuit lookahead (pursuit.hpp)
  double min_lookahead = 5.0;
  double time = 0;  // s, now
};

// Whether the driver should start to pass `blockers` (the slow objects in its way, nearest
// first) now; `waiting` is set when a pass is allowed by the road but the traffic or the room
// ahead does not allow it yet (then the driver waits further back, room to pull out).
std::optional<OvertakePlan> plan_overtake(const OvertakeContext& context,
                                          std::span<const Blocker> blockers,
                                          const OvertakingSettings& settings, bool& waiting);

// Moves a plan on by one step: aborts a pass that became unsafe while the ego is still mostly in
// its own lane (into the oncoming lane: until it drew level), starts the move back once the passed
// objects are far enough behind, and ends the plan once the ego is back. `slow_ahead` are slow
// objects in the original lane ahead (they must not be cut in front of).
void update_overtake(OvertakePlan& plan, const OvertakeContext& context,
                     std::span<const Blocker> slow_ahead, const OvertakingSettings& settings);

}  // namespace scenfuzz

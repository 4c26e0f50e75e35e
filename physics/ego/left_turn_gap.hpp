// Gap acceptance on a left turn across oncoming traffic (a permissive, unprotected left turn),
// as a competent driver does it. The rule:
//   - A route's junction lane that turns left (by the map, or by turning more than 45 degrees left)
//     crosses some junction lanes of the same junction that start heading against it: the
//     oncoming approach's straight (and right-turning) movements (lane_conflicts.hpp's
//     lines_cross). Where the ego's body would overlap such a lane (its half width + 0.5 m) is
//     that lane's conflict area on the ego's path.
//   - The ego waits with its centre short of the first conflict area, and goes only when no
//     perceived vehicle on those lanes or on the lanes feeding them (up to 200 m back) will reach
//     the conflict area of its lane before the ego has cleared it with 1.5 s to spare, nor within
//     the critical gap of 5 s (the Highway Capacity Manual's critical gap for a left turn across
//     oncoming traffic is 4.1 s from standstill, observed gaps 4.5-5 s): time to arrive = its
//     perceived distance to the conflict area / its perceived speed; a vehicle standing (under
//     0.5 m/s) more than 5 m away is not coming. The ego's time to clear is its free-road IDM
//     run (from its speed now, capped by the speeds of the bend) to where its body leaves that
//     area.
//   - Once the ego's centre is at the first conflict area (or it can no longer stop before it),
//     it is committed: it does not wait there, and it does not stop for oncoming vehicles coming
//     towards its path (only for one already in it): it clears the conflict area.
// It uses what the driver perceives, never the truth. docs/simulation.md, "The reference driver".
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "physics/actors/actor_class.hpp"
#include "physics/actors/kinematics.hpp"
#include "physics/ego/perception.hpp"
#include "physics/ego/route_tracker.hpp"

namespace scenfuzz {

struct LeftTurnGapSettings {
  double critical_gap = 5.0;     // s: the least gap accepted (HCM, above)
  double clearing_margin = 1.5;  // s between the ego clearing a conflict area and anyone arriving
  double lateral_margin = 0.5;   // m beyond an oncoming lane's half width that counts as in it
  double upstream = 200;         // m of oncoming approach searched for vehicles
  double moving_speed = 0.5;     // m/s: slower, a vehicle is standing
  double standing_reach = 5;     // m: a vehicle standing nearer than this to the area may go
  double acceleration = 1.5;     // m/s^2, the driver's IDM a (its time to clear)
};

// One oncoming junction lane the turn crosses. Path arc lengths are of the ego's centre.
struct OncomingConflict {
  LaneIndex lane = 0;
  double ego_enter = 0;   // path s where the ego's body first reaches into the lane
  double ego_exit = 0;    // path s where it has left it
  double lane_enter = 0;  // s on `lane` where an oncoming vehicle's front reaches the ego's path
  double lane_exit = 0;   // s on `lane` where its rear has left the ego's path
  // The lane and the lanes feeding it, each with the offset that turns s on it into s on `lane`.
  std::vector<std::pair<LaneIndex, double>> approach;
};

// A left turn on the route and the oncoming lanes it crosses.
struct LeftTurn {
  double wait = 0;  // path s of the ego's centre at the first conflict area
  std::vector<OncomingConflict> conflicts;
};

// What the rule says at one step.
struct GapDecision {
  std::optional<double> wait_gap;  // m from the ego's front to where it must stop (its centre
                                   // then at LeftTurn::wait), when it must wait
  bool committed = false;          // inside or past the point of no return: clear the area
};

// The left turns across oncoming traffic on a route (in order along its path).
std::vector<LeftTurn> find_left_turns(const RoadMap& map, const RouteTracker& route,
                                      const ActorClass& vehicle,
                                      const LeftTurnGapSettings& settings = {});

class LeftTurnGap {
 public:
  LeftTurnGap(const RoadMap& map, const RouteTracker& route, const ActorClass& vehicle,
              const LeftTurnGapSettings& settings = {});

  // `desired` is the driver's desired speed at each path vertex (its speed envelope: the speed
  // limit and the bends), capped at `speed_cap` (what it can see).
  GapDecision decide(const KinematicState& ego, std::span<const WorldObject> objects,
                     std::span<const double> desired, double speed_cap, double max_deceleration);
  // Whether a perceived object is a vehicle on one of the oncoming lanes the current turn
  // crosses, or on one feeding it.
  bool is_oncoming(const WorldObject& object) const;
  const std::vector<LeftTurn>& turns() const { return turns_; }

  // The time the ego needs from its state to get its centre to path s `to` (the rule's time to
  // clear); public for tests.
  double time_to_reach(double speed, double to, std::span<const double> desired,
                       double speed_cap) const;
  // When a perceived object on an oncoming lane will reach that lane's conflict area: 0 when it
  // is in it, infinity when it has passed it, stands or is on none of the conflict's lanes.
  double time_to_arrive(const OncomingConflict& conflict, const WorldObject& object) const;

 private:
  const LeftTurn* current() const;

  const RoadMap& map_;
  const RouteTracker& route_;
  ActorClass vehicle_;
  LeftTurnGapSettings settings_;
  std::vector<LeftTurn> turns_;
  bool committed_ = false;  // to the current turn
  std::size_t committed_turn_ = 0;
};

}  // namespace scenfuzz

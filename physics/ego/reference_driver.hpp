// The built-in ego under test: a reference driver competent enough that what the fuzzer finds is
// interesting. It follows its route (pure pursuit on the route's path), keeps the speed limit and
// slows for bends, follows the perceived lead with the Intelligent Driver Model, brakes hard on a
// short time-to-collision, stops for red (and catchable yellow) lights, stops at stop signs and
// then goes on, passes stopped or much slower vehicles, cyclists and obstacles when a lane beside
// allows it (overtaking.hpp), yields to pedestrians on or walking into its path and in crosswalks
// ahead but not to ones standing beside it, slows for pedestrians on the carriageway walking
// towards its path, turning left across oncoming traffic waits for a gap and then clears the
// oncoming lanes without stopping in them (left_turn_gap.hpp), never drives faster than it can stop
// within what it can see in the weather and light (sight_distance.hpp), and stops at its target. It
// sees only what perception gives it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/ego/left_turn_gap.hpp"
#include "physics/ego/motion_filter.hpp"
#include "physics/ego/overtaking.hpp"
#include "physics/ego/perception.hpp"
#include "physics/ego/priority_traffic.hpp"
#include "physics/ego/route_tracker.hpp"
#include "physics/ego/sight_distance.hpp"
#include "physics/map/lane_neighbourhood.hpp"

namespace scenfuzz {

// For a dry road: on_road (driver_on_road.hpp) makes them a careful driver's on a slippery one.
struct DriverSettings {
  double time_gap = 1.5;                     // s, IDM's desired time headway
  double standstill_gap = 2.5;               // m, bumper to bumper behind a stopped lead
  double stop_line_gap = 1.0;                // m between the front bumper and a stop line
  double comfortable_acceleration = 1.5;     // m/s^2, IDM's a
  double comfortable_deceleration = 2.5;     // m/s^2, IDM's b
  double emergency_time_to_collision = 1.5;  // s: below it, full braking
  double lateral_acceleration = 2.0;         // m/s^2 allowed in bends
  double default_speed_limit = 13.9;         // m/s on lanes without a limit (50 km/h)
  double stop_sign_wait = 1.0;               // s standing at a stop sign before going on
  double crosswalk_clearance = 1.5;          // m around a crosswalk where a pedestrian counts
  double lookahead_time = 0.8;               // s of travel to the pure-pursuit target point
  double min_lookahead = 5.0;                // m
  double lane_change_gap = 5.0;              // m kept free ahead of and behind the ego in the
  double lane_change_time_gap = 1.0;         // next lane, plus this many seconds of the speed of
                                             // whoever would be behind (or of the ego, ahead)
  double standing_speed = 0.4;     // m/s: a pedestrian slower than this (smoothed) is standing
  double pedestrian_patience = 5;  // s held by standing pedestrians before creeping on
  double junction_patience = 5;    // s held at a junction's entry before going on carefully
  // Giving way at signs (priority_traffic.hpp): the least time until a vehicle with the way
  // reaches the ego's path that it pulls out in front of, after a stop and at a yield sign.
  double stop_critical_gap = 6.5;   // s, HCM's two-way-stop critical headway going straight
  double yield_critical_gap = 5.0;  // s, HCM's roundabout entry critical headway, about
  double creeping_speed = 1.5;      // m/s past standing pedestrians after that
  SightSettings sight;              // the speed limit of what it can see
  LeftTurnGapSettings left_turn;    // gap acceptance turning left across oncoming traffic
  double sight_braking = 4.0;       // m/s^2 at most when it finds itself faster than that limit
                                    // (starting in fog, say): firm, not full
  OvertakingSettings overtaking;
};

// What the driver knows at one step.
struct DriverInput {
  double time = 0;
  KinematicState ego;                    // its own state (odometry is exact)
  std::span<const WorldObject> objects;  // perceived objects
  std::span<const SignalColour> lights;  // every map light's colour now (index as the map's)
};

// Why the driver chose its acceleration, for tests and the trace's reading.
enum class DriverReason {
  cruise,
  lead,
  emergency,
  red_light,
  stop_sign,
  pedestrian,
  target,
  lane_change,  // waiting for a gap in the next lane
  creeping,     // past pedestrians that stood in its way longer than its patience
  sight,        // no faster than it can stop within what it can see
  give_way,     // turning left: waiting for a gap in the oncoming traffic; or held at a
                // junction's entry by the junction priority rule (hold_at_junction)
};

class ReferenceDriver {
 public:
  // `sensing` is its perception's settings in the scenario's weather and light (degraded): the
  // ranges it can see to. The default, clear daylight.
  ReferenceDriver(const RoadMap& map, const RouteTracker& route, const ActorClass& vehicle,
                  bool route_ends_at_target, const DriverSettings& settings = {},
                  const PerceptionSettings& sensing = {});

  VehicleControl step(const DriverInput& input);
  DriverReason last_reason() const { return reason_; }
  const OvertakePlan& overtake() const { return overtake_; }

 private:
  struct Constraint {
    double gap = 0;          // m from the front bumper (the centre, for the target) to it
    double clearance = 0;    // m to keep when standing behind it (IDM's s0)
    double lead_speed = 0;   // m/s along the path
    bool is_object = false;  // a real object (time-to-collision braking applies)
    DriverReason reason = DriverReason::lead;
  };

  double desired_speed(double s) const;
  double steering(const KinematicState& ego) const;
  std::vector<Blocker>& objects_in_lane(const DriverInput& input);
  void start_locating(const DriverInput& input);
  // Object k of the step's input on the route (RouteTracker::locate), located at most once a
  // step: the plan and the constraints ask for the same objects.
  const std::optional<PathCoordinate>& located(std::size_t k, const WorldObject& object);
  // `desired`: the speed the ego would drive on a free road here (desired_speed).
  void plan_manoeuvre(const DriverInput& input, double dt, double desired);
  void indicate_then_go(const OvertakePlan& plan, double time);
  void watch_patience(const DriverInput& input);
  bool on_own_lane(MapPoint point) const;
  void collect_object_constraints(const DriverInput& input, double front_s);
  void collect_feature_constraints(const DriverInput& input, double front_s);
  void collect_lane_change_constraints(const DriverInput& input, double front_s);
  void add_road_end(double speed);
  void hold_at_junction(const DriverInput& input, double front_s);
  bool box_blocked(const JunctionStretch& stretch, double front_s) const;
  bool crossing_inside(const DriverInput& input, const JunctionStretch& stretch);
  // The lanes crossing or merging with the stretch's junction lanes (kept in conflicts_).
  const std::vector<LaneIndex>& stretch_conflicts(const JunctionStretch& stretch);
  // Whether, at the stop or yield line at route distance `line`, a vehicle with the way is in or
  // within `critical_gap` of the junction lanes beyond it.
  bool must_give_way(const DriverInput& input, double line, double critical_gap);
  void add_crossing_pedestrian(const WorldObject& object, double ego_speed, double gap,
                               double clearance, double lateral_speed, double along_speed);
  double idm_acceleration(double speed, double desired, const Constraint& constraint) const;
  double vehicle_body_heading(const WorldObject& object, double path_heading) const;
  double vehicle_lateral_speed(const WorldObject& object, double velocity, double relative,
                               double path_heading) const;

  const RoadMap& map_;
  const RouteTracker& route_;
  ActorClass vehicle_;
  bool route_ends_at_target_;
  DriverSettings settings_;
  double sight_speed_;    // m/s: it can stop within its sight distance from this speed
  double heading_noise_;  // rad, perception's standard deviation in this weather and light
  std::vector<double> speed_envelope_;  // per path vertex: the speed limit and bends, braked back
  std::vector<Constraint> constraints_;
  std::vector<Blocker> in_lane_;  // objects_in_lane's answer (kept, so as not to allocate a step)
  // This step's locations (located()): the window searched, how far aside, and per object
  // whether it was located yet and where.
  PathWindow located_window_;
  double located_horizon_ = 0;
  std::vector<std::uint8_t> located_known_;
  std::vector<std::optional<PathCoordinate>> located_;
  std::vector<bool> stop_sign_served_;  // per route feature
  double stopped_since_ = -1;
  DriverReason reason_ = DriverReason::cruise;
  MotionFilter motion_;
  OvertakePlan overtake_;
  std::optional<ActorId> waiting_to_pass_;  // the blocker stood behind with room to pull out
  double last_time_ = -1;
  double last_dt_ = 0.1;           // s since the step before
  bool held_by_standing_ = false;  // a standing pedestrian would stop the ego (this step)
  double held_since_ = -1;         // since when, without a break
  bool patience_over_ = false;
  bool creeping_ = false;  // this step: creeping past standing pedestrians
  LeftTurnGap left_turn_;
  bool turn_committed_ = false;  // this step: inside a left turn's conflict area, clearing it
  // The junction priority rule (hold_at_junction): the lanes crossing or merging with the route's
  // junction stretch it last looked at, and since when the ego stands held at its entry.
  double conflicts_entry_ = -1;
  std::vector<LaneIndex> conflicts_;
  std::vector<ConflictPoint> conflict_points_;  // where the stretch's lanes meet them
  LaneNeighbourhood junction_lanes_;            // the lane segments around that stretch's junction
  double held_since_junction_ = -1;
  double released_entry_ = -1;
  double next_glance_ = 0;        // s: when crossing_inside is looked at again
  bool crossing_inside_ = false;  // its answer at the last glance
};

}  // namespace scenfuzz

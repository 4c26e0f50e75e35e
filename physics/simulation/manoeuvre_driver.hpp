// Drives one WMG SDL actor through its manoeuvre phases, online: its phases start and end on
// conditions over the current world (the ego's speed, offsets, lights, timers), so its motion
// cannot be planned before the run as scripted NPCs' is. Outside its phases a vehicle on a lane
// drives on reactively (lane_cruise.hpp), or keeps its speed when its script is heedless, and it
// stops before the end of a lane leading nowhere. Out on the oncoming lane after pulling out to
// overtake, it follows what is ahead in that lane, not what it passes in its own.
// Vehicles move along the lane graph (arc length, lateral offset and velocity along the heading,
// negative when reversing, integrated each step; lane changes are smooth sideways curves in the
// target lane's frame); pedestrians and vehicles off every lane move freely with the point-mass and
// bicycle models.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>

#include "physics/actors/actor_class.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/simulation/lane_cruise.hpp"
#include "physics/simulation/manoeuvre_script.hpp"
#include "physics/simulation/phase_junction.hpp"
#include "physics/simulation/world_snapshot.hpp"

namespace scenfuzz {

class ManoeuvreDriver {
 public:
  // Starts at script.initial. `script` and `map` must outlive the driver.
  ManoeuvreDriver(const RoadMap& map, const ManoeuvreScript& script, const ActorClass& body,
                  bool pedestrian);

  const KinematicState& state() const { return state_; }
  // The index of the phase running, or -1 while none is (before the first, between phases that
  // wait for their start condition, after the last).
  int phase() const;
  // When the first phase began (world time, s); NaN before.
  double sequence_start() const { return sequence_start_; }
  // The indicator it shows: through a sideways move to a neighbour lane (towards it), and through
  // a turn phase until the turn is done; 0 otherwise. Its phases start on conditions met during
  // the run, so it indicates from the phase's start, not before.
  VehicleSignals indicator() const;

  // Starts and ends phases by what holds in `world` (where this actor is actor `self`), then
  // moves the actor on by dt.
  void step(const WorldSnapshot& world, std::uint32_t self, double dt);

 private:
  void update_phases(const WorldSnapshot& world, std::uint32_t self);
  void start_phase(const WorldSnapshot& world, std::uint32_t self);
  bool phase_complete(const WorldSnapshot& world, std::uint32_t self) const;
  void change_lane(const WorldSnapshot& world, std::uint32_t self, LaneSide side, double duration);
  std::optional<LaneIndex> lane_change_target(const WorldSnapshot& world, std::uint32_t self,
                                              LaneSide side) const;
  // One lane to the left: the left neighbour, else out onto the oncoming lane (Overtake).
  void overtake(double duration);
  // Whether its centre is beyond its lane's left edge: out on the oncoming lane after an overtake.
  bool out_on_oncoming_lane() const;
  // Whom it follows on its lane: out on the oncoming lane, what is in its band of road there (the
  // oncoming traffic), not what is in its own lane beside it (what it is passing).
  LeaderScope leader_scope() const;
  // Continues in `lane`'s frame, starting as far to its side as the actor now is.
  void move_into(LaneIndex lane);
  // Starts a sideways move from the present lateral offset to `to` in on_lane_'s frame.
  void start_lateral_move(double to, double duration);
  void plan_cut_in(const WorldSnapshot& world, const PhaseMotion& phase);
  // The velocity along the heading the phase aims for (negative backwards), if it sets one.
  std::optional<double> target_velocity(const PhaseMotion& phase) const;
  // How long a calm driver takes to go from one velocity along the heading to another.
  double calm_change_time(double from, double to) const;
  // Bumper-to-bumper distance along the reference's heading, negative while level with it.
  double clearance_to(const WorldSnapshot& world, std::uint32_t reference) const;
  bool gap_reached(const WorldSnapshot& world, const PhaseMotion& phase) const;
  // Along the heading, negative backwards.
  double longitudinal_acceleration(double dt) const;
  // Outside its phases: a vehicle on a lane drives on reactively at its cruising speed (heedless:
  // back to it, whatever is ahead).
  double between_phases(const WorldSnapshot& world, std::uint32_t self, double dt) const;
  void move_on_lane(double acceleration, double dt);
  void move_free(const WorldSnapshot& world, double acceleration, double dt);
  LaneIndex next_lane(LaneIndex from) const;
  LaneIndex previous_lane(LaneIndex to) const;
  const PhaseMotion* current() const;

  const RoadMap* map_;
  const ManoeuvreScript* script_;
  ActorClass body_;
  bool pedestrian_;
  KinematicState state_;
  double cruise_speed_ = 0;  // m/s outside its phases: its initial speed, then where one ended
  double phase_speed_ = 0;   // m/s a phase without a speed keeps: its speed when the phase began

  std::size_t next_ = 0;  // the phase running, or the next to start
  bool running_ = false;
  double phase_start_ = 0;  // s, world time the current phase started
  double sequence_start_ = std::numeric_limits<double>::quiet_NaN();
  double phase_time_ = 0;    // s, how long the current phase has run
  bool while_held_ = false;  // the current phase's continue_while has held at some step
  // How long the current primitive takes (the phase's duration, or what its speed change needs).
  double primitive_duration_ = 0;

  // On a lane: where along it and how far to its left.
  std::optional<LanePosition> on_lane_;
  double lateral_rate_ = 0;  // m/s, for the heading
  // A lateral move: from `lateral_from_` when it starts to `lateral_to_` (the lane's centre line,
  // or the oncoming lane's when overtaking on a road with one lane each way) `lateral_duration_`
  // seconds later; none when lateral_duration_ is 0. It runs to its end even when the phase that
  // started it ends first: a car does not stop half-way across a lane line.
  double lateral_from_ = 0;
  double lateral_to_ = 0;
  double lateral_duration_ = 0;
  double lateral_elapsed_ = 0;  // s since it started, at the planned pace
  double lateral_speed_ = 1;    // m/s the curve is planned for: slower, it progresses less
  double lateral_slope_ = 0;    // the curve's sideways metres per metre along the lane

  // At the last step the traffic ahead held the phase's acceleration back (phase_leader_limit,
  // a red light, the junction rule).
  bool held_back_ = false;
  JunctionWait junction_wait_;  // CH vehicles' junction rule (phase_junction.hpp)

  // A cut-in's accelerations over the first and second half of its duration.
  std::array<double, 2> cut_in_acceleration_{};

  // Reverse_Towards / Away: whether the phase started on the far side of its `gap` (beyond it for
  // Towards, within it for Away), so that reversing can bring the actor to it.
  bool gap_ahead_ = false;

  // Turns: the connector kind wanted at the next fork, and how far the turn got.
  LaneTurn turn_wanted_ = LaneTurn::none;
  bool turn_entered_ = false;
  bool turn_done_ = false;
  bool turn_available_ = false;

  // Pedestrians: where they walk; crossings: whether they have been on a lane yet.
  double walk_heading_ = 0;
  bool crossed_onto_lane_ = false;
};

}  // namespace scenfuzz

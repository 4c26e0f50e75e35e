#include "physics/simulation/manoeuvre_driver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/actors/path_pose.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/simulation/lane_cruise.hpp"

namespace scenfuzz {
namespace {

// A lane change (cut-in, cut-out) without a duration takes this long: typical of real ones.
constexpr double kDefaultLaneChangeTime = 4;  // s
// A pedestrian phase without a speed walks at a typical pace.
constexpr double kDefaultWalkingSpeed = 1.4;  // m/s
// A reversing phase without a speed backs up at the pace of a parking manoeuvre.
constexpr double kDefaultReversingSpeed = 2;  // m/s
// How far ahead a turn looks for a junction connector of its kind.
constexpr double kTurnSearchDistance = 1000;  // m
// The peak lateral acceleration of a minimum-jerk sideways move of 1 m over 1 s (10 / sqrt(3)).
constexpr double kMinimumJerkPeak = 5.7735;
// A lane change, or a bend in a phase, uses at most this share of the grip full braking uses.
constexpr double kLaneChangeGripShare = 0.8;
// A speed within this of its target counts as reached.
constexpr double kSpeedTolerance = 0.1;  // m/s
// A heedless script (ManoeuvreScript::heedless) outside its phases: cruising slower than this is
// standing (as lane_cruise's), and it gets back to its speed at most this briskly (IDM's a there).
constexpr double kStandingCruise = 0.5;        // m/s
constexpr double kHeedlessAcceleration = 1.5;  // m/s^2
// A phase without a speed held below its speed (by a leader, a red light or a bend) gets back to
// it this briskly.
constexpr double kResumeAcceleration = 1.5;  // m/s^2

// Minimum-jerk progress of a lateral move over normalised time x in [0, 1]: 0 to 1 with zero
// velocity and acceleration at both ends, the shape of a human lane change.
double smooth_progress(double x) { return x * x * x * (10 - 15 * x + 6 * x * x); }
double smooth_progress_rate(double x) { return 30 * x * x * (1 - x) * (1 - x); }

bool contains(const std::vector<LaneIndex>& lanes, LaneIndex lane) {
  return std::find(lanes.begin(), lanes.end(), lane) != lanes.end();
}

bool is_turn(const Lane& lane, LaneTurn turn) { return lane.junction && lane.turn == turn; }

// The lane's direction at s, turning smoothly through its centre line's vertices: the segment's
// own direction jumps there, which at a crawl reads as a turn tighter than any steering allows.
double smooth_lane_heading(const RoadMap& map, LaneIndex lane, double s) {
  return direction_at(map.lane(lane).centre_line, s).heading;
}

// How far `other`'s centre line lies from `lane`'s at s.
double centre_line_distance(const RoadMap& map, LaneIndex lane, double s, LaneIndex other) {
  const MapPoint centre = map.lane(lane).centre_line.point_at(s);
  return std::abs(map.lane(other).centre_line.project(centre).lateral);
}

}  // namespace

ManoeuvreDriver::ManoeuvreDriver(const RoadMap& map, const ManoeuvreScript& script,
                                 const ActorClass& body, bool pedestrian)
    : map_(&map), script_(&script), body_(body), pedestrian_(pedestrian), state_(script.initial) {
  walk_heading_ = state_.heading;
  if (pedestrian_) return;
  auto lane = project_to_lane(map, {state_.x, state_.y}, state_.heading);
  if (lane && lane->inside) {
    on_lane_ = LanePosition{lane->lane, lane->s, lane->lateral};
    // On a lane it faces along it from the start, as it will at every step after.
    state_.heading = smooth_lane_heading(map, lane->lane, lane->s);
  }
  cruise_speed_ = state_.speed;
}

const PhaseMotion* ManoeuvreDriver::current() const {
  return running_ ? &script_->phases[next_] : nullptr;
}

int ManoeuvreDriver::phase() const { return running_ ? static_cast<int>(next_) : -1; }

VehicleSignals ManoeuvreDriver::indicator() const {
  if (pedestrian_) return 0;
  // m a sideways move that is a lane change covers, not a small correction towards the centre.
  constexpr double kLaneChangeOffset = 1.0;
  if (lateral_duration_ > 0 && lateral_elapsed_ < lateral_duration_ &&
      std::abs(lateral_to_ - lateral_from_) > kLaneChangeOffset)
    return lateral_from_ > lateral_to_ ? vehicle_signal::right_indicator
                                       : vehicle_signal::left_indicator;
  if (turn_available_ && !turn_done_) {
    if (turn_wanted_ == LaneTurn::left) return vehicle_signal::left_indicator;
    if (turn_wanted_ == LaneTurn::right) return vehicle_signal::right_indicator;
  }
  return 0;
}

void ManoeuvreDriver::step(const WorldSnapshot& world, std::uint32_t self, double dt) {
  update_phases(world, self);
  double acceleration = running_ ? longitudinal_acceleration(dt) : between_phases(world, self, dt);
  held_back_ = false;
  if (running_ && on_lane_ && !state_.reversing && !script_->heedless) {
    // A phase drives as scripted, but not into the traffic ahead (the ego aside), nor through a
    // red light when its script heeds lights, unless its script drives without looking.
    NextLane next = [this](LaneIndex lane) { return next_lane(lane); };
    double limit = phase_leader_limit(world, self, *on_lane_, next, body_, leader_scope());
    if (script_->heeds_lights)
      limit = std::min(limit, red_light_limit(world, self, *on_lane_, next, body_));
    if (limit < acceleration) {
      acceleration = limit;
      held_back_ = true;
    }
  }
  if (on_lane_ && !state_.reversing && script_->heeds_lights) {
    // A CH vehicle gives way in junctions, in its phases and between them.
    NextLane next = [this](LaneIndex lane) { return next_lane(lane); };
    const double limit = junction_entry_limit(world, self, *on_lane_, next, body_, junction_wait_);
    if (limit < acceleration) {
      acceleration = limit;
      held_back_ = running_;
    }
  }
  if (on_lane_ && !state_.reversing && state_.speed > 0) {
    NextLane next = [this](LaneIndex lane) { return next_lane(lane); };
    // In a phase the script may corner up to most of the grip; cruising, as a calm driver.
    double lateral = running_ ? kLaneChangeGripShare * body_.max_deceleration
                              : body_.comfortable_lateral_acceleration;
    acceleration =
        std::min({acceleration, dead_end_braking(*map_, *on_lane_, next, body_, state_.speed, dt),
                  bend_braking(*map_, *on_lane_, next, body_, state_.speed, lateral)});
  }
  if (on_lane_)
    move_on_lane(acceleration, dt);
  else
    move_free(world, acceleration, dt);
}

void ManoeuvreDriver::update_phases(const WorldSnapshot& world, std::uint32_t self) {
  const auto& phases = script_->phases;
  // Each round ends a phase or starts one, so a chain of instant phases is bounded.
  for (std::size_t round = 0; round <= 2 * phases.size(); ++round) {
    if (running_) {
      const PhaseMotion& phase = phases[next_];
      phase_time_ = world.time - phase_start_;
      if (phase.choice.primitive == MotionPrimitive::walk_cross && world.lanes[self].lane >= 0)
        crossed_onto_lane_ = true;
      // A WHILE ends the phase when it becomes false; until it has first held (a walker not yet
      // in the lane its WHILE names), the phase ends as one without a WHILE would.
      bool ends = phase_complete(world, self);
      if (phase.continue_while) {
        bool holds = trigger_holds(*phase.continue_while, world);
        ends = while_held_ ? !holds : !holds && ends;
        while_held_ = while_held_ || holds;
      }
      if (!ends) return;
      // Between phases and after the last, the actor keeps its lane offset and drives on at its
      // speed, reacting to what is ahead (between_phases).
      cruise_speed_ = state_.reversing ? 0 : state_.speed;
      running_ = false;
      ++next_;
      turn_wanted_ = LaneTurn::none;
    }
    if (next_ >= phases.size()) return;
    const PhaseMotion& phase = phases[next_];
    if (phase.start_when && !trigger_holds(*phase.start_when, world)) return;
    running_ = true;
    phase_start_ = world.time;
    if (std::isnan(sequence_start_)) sequence_start_ = world.time;
    phase_time_ = 0;
    start_phase(world, self);
  }
}

void ManoeuvreDriver::start_phase(const WorldSnapshot& world, std::uint32_t self) {
  const PhaseMotion& phase = script_->phases[next_];
  const double speed = state_.speed;
  phase_speed_ = state_.reversing ? 0 : speed;
  turn_wanted_ = LaneTurn::none;
  turn_entered_ = turn_done_ = turn_available_ = false;
  crossed_onto_lane_ = false;
  while_held_ = false;

  // Without a duration, a speed change takes what a calm driver needs for it.
  primitive_duration_ = 0;
  if (auto target = target_velocity(phase))
    primitive_duration_ = calm_change_time(longitudinal_velocity(state_), *target);
  if (phase.duration) primitive_duration_ = *phase.duration;

  switch (phase.choice.primitive) {
    case MotionPrimitive::keep_lane: break;
    case MotionPrimitive::lane_change:
    case MotionPrimitive::cut_in:
      primitive_duration_ = phase.duration.value_or(kDefaultLaneChangeTime);
      change_lane(world, self, phase.choice.side, primitive_duration_);
      if (phase.gap) plan_cut_in(world, phase);
      break;
    case MotionPrimitive::overtake:
      primitive_duration_ = phase.duration.value_or(kDefaultLaneChangeTime);
      overtake(primitive_duration_);
      break;
    case MotionPrimitive::stop:
      primitive_duration_ = phase.duration.value_or(speed / body_.comfortable_deceleration);
      break;
    case MotionPrimitive::stopped: primitive_duration_ = 0; break;
    case MotionPrimitive::turn_left:
    case MotionPrimitive::turn_right: {
      turn_wanted_ =
          phase.choice.primitive == MotionPrimitive::turn_left ? LaneTurn::left : LaneTurn::right;
      if (!on_lane_) break;
      // Look along the lanes this actor will take for a fork offering the turn.
      LaneIndex lane = on_lane_->lane;
      double travelled = -on_lane_->s;
      if (is_turn(map_->lane(lane), turn_wanted_)) turn_available_ = turn_entered_ = true;
      for (int hops = 0; !turn_available_ && travelled < kTurnSearchDistance && hops < 64; ++hops) {
        for (LaneIndex successor : map_->lane(lane).successors)
          if (is_turn(map_->lane(successor), turn_wanted_)) turn_available_ = true;
        travelled += map_->lane(lane).length();
        LaneIndex next = next_lane(lane);
        if (next == lane) break;
        lane = next;
      }
      // Without a junction ahead the actor keeps its lane (docs/simulation.md).
      break;
    }
    case MotionPrimitive::collide:
      on_lane_.reset();  // it leaves the lanes to head for its reference
      break;
    case MotionPrimitive::reverse_towards:
    case MotionPrimitive::reverse_away: {
      // A gap the actor is already past (closer than it for Towards) is not one reversing
      // reaches: such a phase ends on its duration alone.
      const double clearance = clearance_to(world, phase.reference);
      const bool towards = phase.choice.primitive == MotionPrimitive::reverse_towards;
      gap_ahead_ = phase.gap && (towards ? clearance > *phase.gap : clearance < *phase.gap);
      walk_heading_ = state_.heading + std::numbers::pi;  // a pedestrian turns round
      break;
    }
    case MotionPrimitive::reverse_cut_in:
    case MotionPrimitive::reverse_cut_out:
      primitive_duration_ = phase.duration.value_or(kDefaultLaneChangeTime);
      change_lane(world, self, phase.choice.side, primitive_duration_);
      walk_heading_ = state_.heading + std::numbers::pi;
      break;
    case MotionPrimitive::walk: walk_heading_ = state_.heading; break;
    case MotionPrimitive::walk_cross: {
      // Across the nearest lane of the road the phase names, else the nearest lane: from a
      // pavement, towards the road; standing in a lane (WMG SDL places pavement walkers in the
      // kerb-side lane), towards the side with more road.
      const MapPoint here{state_.x, state_.y};
      auto lane = phase.road_lanes.empty() ? project_to_lane(*map_, here)
                                           : project_onto_lanes(*map_, here, phase.road_lanes);
      if (!lane) break;
      const Lane& nearest = map_->lane(lane->lane);
      bool left = lane->lateral < 0;
      if (lane->inside)
        left = !nearest.left_forward_neighbours.empty() || !nearest.left_reverse_neighbours.empty();
      double across = left ? std::numbers::pi / 2 : -std::numbers::pi / 2;
      walk_heading_ = lane_heading_at(*map_, lane->lane, lane->s) + across;
      break;
    }
    case MotionPrimitive::walk_towards:
    case MotionPrimitive::walk_away: break;
  }
}

void ManoeuvreDriver::change_lane(const WorldSnapshot& world, std::uint32_t self, LaneSide side,
                                  double duration) {
  if (!on_lane_) return;
  if (auto target = lane_change_target(world, self, side)) move_into(*target);
  // Also without a target lane: settle onto the centre line of the lane it is in.
  start_lateral_move(0, duration);
}

std::optional<LaneIndex> ManoeuvreDriver::lane_change_target(const WorldSnapshot& world,
                                                             std::uint32_t self,
                                                             LaneSide side) const {
  // Out on the oncoming lane after an overtake, the way back to the right is its own lane.
  if (side == LaneSide::right && out_on_oncoming_lane()) return std::nullopt;
  const PhaseMotion& phase = script_->phases[next_];
  const Lane& lane = map_->lane(on_lane_->lane);
  const std::int32_t reference_lane = world.lanes[phase.reference].lane;
  const bool cut_in = phase.choice.primitive == MotionPrimitive::cut_in ||
                      phase.choice.primitive == MotionPrimitive::reverse_cut_in;
  const auto& left = lane.left_forward_neighbours;
  const auto& right = lane.right_forward_neighbours;
  std::optional<LaneIndex> target;
  auto reference_in = [&](const std::vector<LaneIndex>& lanes) {
    return cut_in && reference_lane >= 0 && contains(lanes, static_cast<LaneIndex>(reference_lane));
  };
  auto first = [](const std::vector<LaneIndex>& lanes) -> std::optional<LaneIndex> {
    if (lanes.empty()) return std::nullopt;
    return lanes.front();
  };
  switch (side) {
    case LaneSide::towards_reference:
      if (reference_in(left) || reference_in(right)) {
        target = static_cast<LaneIndex>(reference_lane);
      } else if (reference_lane != static_cast<std::int32_t>(on_lane_->lane)) {
        // The reference is further away: one lane towards it.
        bool reference_left = lateral_offset(world.states[phase.reference], world.states[self]) > 0;
        target = reference_left ? first(left) : first(right);
      }
      break;
    case LaneSide::left:
      target = reference_in(left) ? static_cast<LaneIndex>(reference_lane) : first(left);
      // A cut-out must leave the lane: to the other side when the named one has no lane.
      if (!target && !cut_in) target = first(right);
      break;
    case LaneSide::right:
      target = reference_in(right) ? static_cast<LaneIndex>(reference_lane) : first(right);
      if (!target && !cut_in) target = first(left);
      break;
    case LaneSide::left_else_right: target = left.empty() ? first(right) : first(left); break;
  }
  return target;
}

void ManoeuvreDriver::overtake(double duration) {
  if (!on_lane_) return;
  const Lane& lane = map_->lane(on_lane_->lane);
  double to = 0;
  if (!lane.left_forward_neighbours.empty()) {
    move_into(lane.left_forward_neighbours.front());
  } else if (!lane.left_reverse_neighbours.empty()) {
    // Onto the oncoming lane, but still driving its own way: its own lane's frame keeps its
    // heading and its route, the offset puts it on the other centre line.
    to = centre_line_distance(*map_, on_lane_->lane, on_lane_->s,
                              lane.left_reverse_neighbours.front());
  }
  start_lateral_move(to, duration);
}

bool ManoeuvreDriver::out_on_oncoming_lane() const {
  // Only a lane with no neighbour its way on the left: after a lane change to the right the
  // actor is beyond its new lane's left edge too, in the lane it is leaving.
  const Lane& lane = map_->lane(on_lane_->lane);
  return lane.left_forward_neighbours.empty() && on_lane_->lateral > lane.narrowest_left_width;
}

LeaderScope ManoeuvreDriver::leader_scope() const {
  // Its own lane's frame keeps its route out there, but the lane is no longer the one it is in.
  return out_on_oncoming_lane() ? LeaderScope::corridor : LeaderScope::lanes;
}

void ManoeuvreDriver::move_into(LaneIndex lane) {
  PolylineProjection there = map_->lane(lane).centre_line.project({state_.x, state_.y});
  on_lane_ = LanePosition{lane, there.s, there.lateral};
}

void ManoeuvreDriver::start_lateral_move(double to, double duration) {
  // No faster than its tyres allow (a minimum-jerk move of w metres over T seconds peaks at
  // 5.77 w / T^2).
  lateral_from_ = on_lane_->lateral;
  lateral_to_ = to;
  const double width = std::abs(lateral_to_ - lateral_from_);
  const double grip = kLaneChangeGripShare * body_.max_deceleration;
  lateral_duration_ = std::max({duration, std::sqrt(kMinimumJerkPeak * width / grip), 1e-3});
  lateral_elapsed_ = 0;
  // Sideways only as it moves on: over at least the distance that keeps the curve within full
  // lock, so that a car slowed to a crawl (or standing) mid-change does not turn on the spot.
  const double shortest = std::sqrt(kMinimumJerkPeak * width * planning_radius(body_));
  lateral_speed_ = std::max(state_.speed, shortest / lateral_duration_);
}

void ManoeuvreDriver::plan_cut_in(const WorldSnapshot& world, const PhaseMotion& phase) {
  // Cover, over the duration, the distance that puts this actor's rear bumper `gap` ahead of the
  // reference's front bumper, the reference going on at its present speed (the plan is made
  // once, as a driver commits to a cut-in; the reference may then react): accelerate evenly to
  // a middle speed over the first half, then evenly to the phase's speed over the second, each
  // within the class's limits.
  const double duration = primitive_duration_;
  const double half = duration / 2;
  const double speed = state_.speed;
  const KinematicState& reference = world.states[phase.reference];
  const double gap_now = longitudinal_offset(state_, reference) -
                         world.lengths[phase.reference] / 2 - body_.length / 2;
  const double distance = *phase.gap - gap_now + reference.speed * duration;
  auto limited = [&](double a) {
    return std::clamp(a, -body_.max_deceleration, body_.max_acceleration);
  };
  if (!phase.speed) {
    double even = limited(2 * (distance - speed * duration) / (duration * duration));
    cut_in_acceleration_ = {even, even};
    return;
  }
  double middle = std::max(0.0, (2 * distance / half - speed - *phase.speed) / 2);
  cut_in_acceleration_[0] = limited((middle - speed) / half);
  double reached = std::max(0.0, speed + cut_in_acceleration_[0] * half);
  cut_in_acceleration_[1] = limited((*phase.speed - reached) / half);
}

std::optional<double> ManoeuvreDriver::target_velocity(const PhaseMotion& phase) const {
  // A pedestrian turns round to walk back, so it still moves along its heading.
  if (reverses(phase.choice.primitive) && !pedestrian_)
    return -phase.speed.value_or(kDefaultReversingSpeed);
  return phase.speed;
}

double ManoeuvreDriver::calm_change_time(double from, double to) const {
  // A change of direction passes through a standstill: braking to it, then setting off.
  if (from * to < 0) return calm_change_time(from, 0) + calm_change_time(0, to);
  const double faster = std::abs(to) - std::abs(from);
  return faster > 0 ? faster / body_.max_acceleration : -faster / body_.comfortable_deceleration;
}

double ManoeuvreDriver::clearance_to(const WorldSnapshot& world, std::uint32_t reference) const {
  return std::abs(longitudinal_offset(state_, world.states[reference])) -
         (world.lengths[reference] + body_.length) / 2;
}

bool ManoeuvreDriver::gap_reached(const WorldSnapshot& world, const PhaseMotion& phase) const {
  if (!gap_ahead_) return false;
  const double clearance = clearance_to(world, phase.reference);
  return phase.choice.primitive == MotionPrimitive::reverse_towards ? clearance <= *phase.gap
                                                                    : clearance >= *phase.gap;
}

double ManoeuvreDriver::longitudinal_acceleration(double dt) const {
  const PhaseMotion* phase = current();
  if (!phase) return 0;
  const double velocity = longitudinal_velocity(state_);
  const double remaining = primitive_duration_ - phase_time_;
  auto towards = [&](double target) { return (target - velocity) / std::max(remaining, dt); };
  double acceleration = 0;
  switch (phase->choice.primitive) {
    case MotionPrimitive::stop: acceleration = towards(0); break;
    case MotionPrimitive::stopped:
      // Full braking, whichever way the actor moves; move_on_lane stops it at 0.
      if (velocity > 0) acceleration = -body_.max_deceleration;
      if (velocity < 0) acceleration = body_.max_deceleration;
      break;
    case MotionPrimitive::cut_in:
      if (phase->gap && remaining > 0) {
        acceleration = phase_time_ < primitive_duration_ / 2 ? cut_in_acceleration_[0]
                                                             : cut_in_acceleration_[1];
      } else if (phase->speed) {
        acceleration = towards(*phase->speed);
      }
      break;
    default:
      if (auto target = target_velocity(*phase))
        acceleration = towards(*target);
      else if (velocity >= 0 && velocity < phase_speed_)
        acceleration = std::min((phase_speed_ - velocity) / dt, kResumeAcceleration);
      break;
  }
  // The class's limits bound the change of speed: braking a reversing actor pushes it forwards,
  // and an actor setting off backwards accelerates towards its rear.
  const bool backwards = velocity < 0 || (velocity == 0 && acceleration < 0);
  if (backwards) return std::clamp(acceleration, -body_.max_acceleration, body_.max_deceleration);
  return std::clamp(acceleration, -body_.max_deceleration, body_.max_acceleration);
}

double ManoeuvreDriver::between_phases(const WorldSnapshot& world, std::uint32_t self,
                                       double dt) const {
  if (pedestrian_ || !on_lane_ || state_.reversing) return 0;
  if (script_->heedless) {
    // Back to its cruising speed after a bend, whatever is ahead; standing where a phase ended
    // at a standstill.
    const double wanted = cruise_speed_ < kStandingCruise ? 0 : cruise_speed_;
    return std::clamp((wanted - state_.speed) / dt, -body_.comfortable_deceleration,
                      std::min(kHeedlessAcceleration, body_.max_acceleration));
  }
  NextLane next = [this](LaneIndex lane) { return next_lane(lane); };
  return cruise_acceleration(world, self, *on_lane_, next, body_, cruise_speed_, leader_scope());
}

LaneIndex ManoeuvreDriver::previous_lane(LaneIndex to) const {
  // Backing out of a lane: into the lane that leads straight into it, if one does.
  const auto& predecessors = map_->lane(to).predecessors;
  if (predecessors.empty()) return to;
  for (LaneIndex predecessor : predecessors)
    if (map_->lane(predecessor).turn == LaneTurn::none) return predecessor;
  return predecessors.front();
}

LaneIndex ManoeuvreDriver::next_lane(LaneIndex from) const {
  const auto& successors = map_->lane(from).successors;
  if (successors.empty()) return from;
  if (turn_wanted_ != LaneTurn::none && !turn_done_)
    for (LaneIndex successor : successors)
      if (map_->lane(successor).turn == turn_wanted_) return successor;
  for (LaneIndex successor : successors)
    if (map_->lane(successor).turn == LaneTurn::none) return successor;
  return successors.front();
}

void ManoeuvreDriver::move_on_lane(double acceleration, double dt) {
  LanePosition& at = *on_lane_;
  const double v0 = longitudinal_velocity(state_);
  double v1 = std::clamp(v0 + acceleration * dt, -body_.max_speed, body_.max_speed);
  // The direction of travel changes only at a standstill, as a gearbox allows, and only a
  // reversing phase sets off backwards (a braking actor stops rather than reverses).
  const PhaseMotion* phase = current();
  const bool may_set_off_backwards = phase && reverses(phase->choice.primitive);
  if (v0 * v1 < 0 || (v0 == 0 && v1 < 0 && !may_set_off_backwards)) v1 = 0;
  at.s += (v0 + v1) / 2 * dt;
  while (at.s < 0) {
    LaneIndex previous = previous_lane(at.lane);
    if (previous == at.lane) {  // the start of a lane nothing leads into: it stops there
      at.s = 0;
      v1 = 0;
      break;
    }
    LinkPoints link = link_points(*map_, previous, at.lane);
    at.s = at.s - link.entry_s + link.exit_s;
    at.lane = previous;
  }
  while (at.s > map_->lane(at.lane).length()) {
    LaneIndex next = next_lane(at.lane);
    if (next == at.lane) {  // a dead end: the actor stops there
      at.s = map_->lane(at.lane).length();
      v1 = 0;
      break;
    }
    if (turn_entered_ && is_turn(map_->lane(at.lane), turn_wanted_)) turn_done_ = true;
    LinkPoints link = link_points(*map_, at.lane, next);
    at.s = at.s - link.exit_s + link.entry_s;
    at.lane = next;
    if (turn_wanted_ != LaneTurn::none && is_turn(map_->lane(next), turn_wanted_))
      turn_entered_ = true;
  }
  lateral_rate_ = 0;
  lateral_slope_ = 0;
  if (lateral_duration_ > 0) {
    // The lateral curve's state at the end of this step.
    // Slower than planned, the curve is drawn over the same distance, more slowly.
    const double pace = std::min(1.0, (std::abs(v0) + std::abs(v1)) / 2 / lateral_speed_);
    lateral_elapsed_ += dt * pace;
    double x = std::clamp(lateral_elapsed_ / lateral_duration_, 0.0, 1.0);
    // Written so that a move to 0 computes what it did before moves had other targets.
    at.lateral = lateral_from_ * (1 - smooth_progress(x)) + lateral_to_ * smooth_progress(x);
    lateral_slope_ = (lateral_to_ - lateral_from_) * smooth_progress_rate(x) /
                     (lateral_duration_ * lateral_speed_);
    lateral_rate_ = lateral_slope_ * std::min(std::abs(v1), lateral_speed_);
  }
  auto pose = lane_pose_at(*map_, at.lane, at.s, at.lateral);
  if (!pose) {
    state_.yaw_rate = 0;  // the actor stays where it was: its heading did not change
    return;
  }
  // The heading follows the path the sideways move draws: its slope along the lane, as planned,
  // or flatter when faster than planned. Backing up sideways, the body turns the other way: its
  // rear leads.
  const double slope =
      std::abs(v1) > lateral_speed_ ? lateral_rate_ / std::abs(v1) : lateral_slope_;
  double sideways = lateral_duration_ > 0 ? std::atan(slope) : 0;
  double heading = smooth_lane_heading(*map_, at.lane, at.s) + (v1 < 0 ? -sideways : sideways);
  state_.acceleration = (std::abs(v1) - std::abs(v0)) / dt;
  state_.yaw_rate = step_yaw_rate(state_.heading, heading, dt);
  state_.x = pose->position.x;
  state_.y = pose->position.y;
  state_.heading = heading;
  state_.speed = std::abs(v1);
  state_.reversing = v1 < 0;
}

void ManoeuvreDriver::move_free(const WorldSnapshot& world, double acceleration, double dt) {
  const PhaseMotion* phase = current();
  MotionPrimitive primitive = phase ? phase->choice.primitive : MotionPrimitive::walk;
  double target_heading = state_.heading;
  if (phase && (primitive == MotionPrimitive::walk_towards ||
                primitive == MotionPrimitive::walk_away || primitive == MotionPrimitive::collide)) {
    const KinematicState& reference = world.states[phase->reference];
    target_heading = std::atan2(reference.y - state_.y, reference.x - state_.x);
    if (primitive == MotionPrimitive::walk_away) target_heading += std::numbers::pi;
  } else if (phase && (primitive == MotionPrimitive::walk ||
                       primitive == MotionPrimitive::walk_cross || reverses(primitive))) {
    // A reversing vehicle keeps its heading; a reversing pedestrian has turned round.
    target_heading = pedestrian_ || !reverses(primitive) ? walk_heading_ : state_.heading;
  }

  if (pedestrian_) {
    PedestrianControl control{target_heading, state_.speed};
    if (phase) {
      if (primitive == MotionPrimitive::stop || primitive == MotionPrimitive::stopped)
        control.speed = 0;
      else if (phase->speed)
        control.speed = *phase->speed;
      else if (primitive != MotionPrimitive::keep_lane && state_.speed <= 0)
        control.speed = kDefaultWalkingSpeed;
    }
    state_ = step_pedestrian(state_, control, body_, dt);
    return;
  }
  // Pure pursuit of the target direction, looking a speed-dependent distance ahead. The bicycle
  // model takes the acceleration on the speed, whichever way the vehicle moves.
  const bool reversing_phase = phase && reverses(primitive);
  const bool backwards = state_.speed > 0 ? state_.reversing : reversing_phase;
  VehicleControl control{backwards ? -acceleration : acceleration, 0, reversing_phase};
  double bearing = angle_difference(target_heading, state_.heading);
  double look_ahead = std::max(5.0, state_.speed);
  control.steering_angle = std::atan(2 * body_.wheelbase * std::sin(bearing) / look_ahead);
  state_ = step_bicycle(state_, control, body_, dt);
}

bool ManoeuvreDriver::phase_complete(const WorldSnapshot& world, std::uint32_t self) const {
  const PhaseMotion& phase = script_->phases[next_];
  const bool elapsed = phase_time_ >= primitive_duration_;
  const std::optional<double> target = target_velocity(phase);
  const bool speed_reached =
      !target || std::abs(longitudinal_velocity(state_) - *target) < kSpeedTolerance;
  switch (phase.choice.primitive) {
    // Held back by the traffic ahead, the phase's speed may never be reached: its time is up.
    case MotionPrimitive::keep_lane: return elapsed && (speed_reached || held_back_);
    case MotionPrimitive::lane_change:
    case MotionPrimitive::overtake:
    case MotionPrimitive::cut_in: return elapsed && (speed_reached || held_back_);
    case MotionPrimitive::stop:
    case MotionPrimitive::stopped: return state_.speed <= 0;
    case MotionPrimitive::turn_left:
    case MotionPrimitive::turn_right:
      return turn_available_ ? turn_done_ : elapsed && speed_reached;
    case MotionPrimitive::walk_cross:
      return (phase.duration && elapsed) || (crossed_onto_lane_ && world.lanes[self].lane < 0);
    case MotionPrimitive::reverse_towards:
    case MotionPrimitive::reverse_away:
      return (elapsed && speed_reached) || gap_reached(world, phase);
    case MotionPrimitive::reverse_cut_in:
    case MotionPrimitive::reverse_cut_out: return elapsed && speed_reached;
    case MotionPrimitive::collide:
    case MotionPrimitive::walk:
    case MotionPrimitive::walk_towards:
    case MotionPrimitive::walk_away: return phase.duration && elapsed;
  }
  return false;
}

}  // namespace scenfuzz

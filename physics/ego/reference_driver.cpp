// The reference driver: lateral control by pure pursuit on the route's path, longitudinal
// control by the Intelligent Driver Model (Treiber, Hennecke, Helbing 2000) against every
// constraint ahead (perceived objects, stop lines, crosswalks with pedestrians, the target),
// overridden by full braking when the time to collision with an object gets short, and capped by
// the speed from which it can stop within its sight distance.
#include "physics/ego/reference_driver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "physics/ego/constant_acceleration_heuristic.hpp"
#include "physics/ego/priority_traffic.hpp"
#include "physics/ego/pursuit.hpp"
#include "physics/ego/sight_distance.hpp"
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/polygon.hpp"

namespace scenfuzz {
namespace {

constexpr double kMinimumDesiredSpeed = 0.1;  // m/s, keeps IDM's free-road term finite
constexpr double kTargetClearance = 0.5;      // m the centre stops short of the target
constexpr double kRoadEndClearance = 1.0;     // m the front stops short of a road's end
constexpr double kRoadEndNotice = 30;         // m beyond twice the stopping distance
constexpr double kStoppedSpeed = 0.2;         // m/s: standing, for a stop sign
constexpr double kPredictionTime = 3.0;       // s a pedestrian's or cut-in's motion is projected
constexpr double kCorridorMargin = 0.4;       // m beside the ego's body that must stay clear

// IDM's free-road term (v/v0)^4, without std::pow's cost.
double fourth_power(double x) {
  double squared = x * x;
  return squared * squared;
}

// Half the extent of a box along and across a direction at `relative_heading` to it.
double extent_along(const WorldObject& object, double relative_heading) {
  return std::abs(std::cos(relative_heading)) * object.length / 2 +
         std::abs(std::sin(relative_heading)) * object.width / 2;
}
double extent_across(const WorldObject& object, double relative_heading) {
  return std::abs(std::sin(relative_heading)) * object.length / 2 +
         std::abs(std::cos(relative_heading)) * object.width / 2;
}
// At least extent_across and extent_along at any heading.
double greatest_extent(const WorldObject& object) { return (object.length + object.width) / 2; }

// s more a crossing pedestrian might take to reach the ego's path, or the ego to clear it, than
// their speeds say: people hurry, hesitate and change their minds.
constexpr double kCrossingMargin = 2.0;
// m/s a pedestrian crossing the road may break into (a jog) when it sees a car coming.
constexpr double kPedestrianHurry = 3.0;

// s within which a vehicle moving towards the ego's path counts as in it.
constexpr double kVehicleEntryTime = 1.0;
// The longest time_to_enter that puts an object in the ego's path (collect_object_constraints).
double longest_entry_time(const WorldObject& object) {
  return object.kind == TraceActorKind::pedestrian ? kPredictionTime + 2.0 : kVehicleEntryTime;
}
// The farthest an object can move sideways in that time (a pedestrian at least at a jog: the
// crossing rule, add_crossing_pedestrian, heeds ones that could hurry into the path).
double farthest_entry(const WorldObject& object) {
  double speed = std::abs(object.speed);
  if (object.kind == TraceActorKind::pedestrian) speed = std::max(speed, kPedestrianHurry);
  return speed * longest_entry_time(object);
}
// m added to a bound before an object is rejected by it unlocated: above locate's 1e-6 for an
// end point and the rounding of the bounding boxes, below anything that matters.
constexpr double kSurelyAside = 1e-3;

}  // namespace

ReferenceDriver::ReferenceDriver(const RoadMap& map, const RouteTracker& route,
                                 const ActorClass& vehicle, bool route_ends_at_target,
                                 const DriverSettings& settings, const PerceptionSettings& sensing)
    : map_(map),
      route_(route),
      vehicle_(vehicle),
      route_ends_at_target_(route_ends_at_target),
      settings_(settings),
      sight_speed_(
          vehicle.max_deceleration > 0
              ? sight_speed(sensing, vehicle.length / 2, vehicle.max_deceleration, settings.sight)
              : std::numeric_limits<double>::infinity()),
      heading_noise_(sensing.heading_noise),
      stop_sign_served_(route.features().size(), false),
      left_turn_(map, route, vehicle, settings.left_turn) {
  // The speed the driver may have at each path vertex: the limit, the bend, and what braking
  // comfortably for the bends and limits further on allows (one backward pass).
  const auto& arc = route.path().arc_lengths();
  speed_envelope_.resize(arc.size());
  for (std::size_t i = 0; i < arc.size(); ++i) {
    double limit = std::min(route.speed_limit_at(arc[i]), vehicle.max_speed);
    double curvature = route.curvature_at(arc[i], i);
    if (curvature > 1e-6)
      limit = std::min(limit, std::sqrt(settings.lateral_acceleration / curvature));
    speed_envelope_[i] = limit;
  }
  for (std::size_t i = arc.size(); i-- > 1;) {
    double reachable = std::sqrt(speed_envelope_[i] * speed_envelope_[i] +
                                 2 * settings.comfortable_deceleration * (arc[i] - arc[i - 1]));
    speed_envelope_[i - 1] = std::min(speed_envelope_[i - 1], reachable);
  }
}

double ReferenceDriver::desired_speed(double s) const {
  if (speed_envelope_.empty()) return std::min(settings_.default_speed_limit, vehicle_.max_speed);
  const auto& arc = route_.path().arc_lengths();
  std::size_t segment = route_.segment_at(s);  // as path().segment_at(s), for any s
  double t = std::clamp((s - arc[segment]) / (arc[segment + 1] - arc[segment]), 0.0, 1.0);
  return std::max(
      kMinimumDesiredSpeed,
      speed_envelope_[segment] + t * (speed_envelope_[segment + 1] - speed_envelope_[segment]));
}

double ReferenceDriver::steering(const KinematicState& ego) const {
  double progress = route_.progress();
  double lookahead = std::max(settings_.min_lookahead, settings_.lookahead_time * ego.speed);
  // A pull-out from close behind something standing aims nearer, to turn at full lock.
  if (overtake_.active && overtake_.pull_out_lookahead > 0 && progress < overtake_.out_end)
    lookahead = overtake_.pull_out_lookahead;
  return pursuit_steering(route_, overtake_, progress, ego, vehicle_, lookahead);
}

std::vector<Blocker>& ReferenceDriver::objects_in_lane(const DriverInput& input) {
  // Every vehicle and obstacle across the route's own lane (as if the ego kept to it), from a
  // little behind the ego on: what it might pass, and what it has been passing. Pedestrians
  // standing in its way count too once its patience with them is over.
  std::vector<Blocker>& found = in_lane_;
  found.clear();
  const KinematicState& ego = input.ego;
  const double horizon = located_horizon_;
  double half_width = vehicle_.width / 2 + kCorridorMargin;
  const MapPoint direction = route_.direction();
  for (std::size_t k = 0; k < input.objects.size(); ++k) {
    const WorldObject& object = input.objects[k];
    bool pedestrian = object.kind == TraceActorKind::pedestrian;
    if (pedestrian && !(patience_over_ && motion_.speed(object.id) < settings_.standing_speed))
      continue;
    double dx = object.x - ego.x, dy = object.y - ego.y;
    if (dx * dx + dy * dy > (horizon + object.length) * (horizon + object.length)) continue;
    // Farther from the path than any extent across it reaches: not across the lane. An object
    // near the ego is located without that bound (collect_object_constraints locates nearly all
    // of those anyway), its location then being as far aside; one far aside or behind (by the
    // path's line at the ego) is bounded first, and so is one without a finite heading, which
    // the tests below never reject.
    const bool finite = std::isfinite(object.heading);
    const double across = direction.x * dy - direction.y * dx;
    const double ahead = direction.x * dx + direction.y * dy;
    const double near = greatest_extent(object) + half_width + farthest_entry(object);
    const bool bounded = !finite || std::abs(across) > near || ahead < -near;
    if (bounded && route_.surely_farther({object.x, object.y}, located_window_,
                                         greatest_extent(object) + half_width + kSurelyAside))
      continue;
    const auto& at = located(k, object);
    if (!at || at->beyond_end) continue;
    // The test below with greatest_extent, no less than any extent across as computed too: it
    // rejects what that test would, without the heading's sine and cosine.
    if (finite && std::abs(at->lateral) - greatest_extent(object) - half_width > 0) continue;
    double relative = angle_difference(object.heading, route_.heading_at(at->s, at->segment));
    if (std::abs(at->lateral) - extent_across(object, relative) - half_width > 0) continue;
    double along = extent_along(object, relative);
    double velocity = object.reversing ? -object.speed : object.speed;
    found.push_back({&object, at->s - along, at->s + along, velocity * std::cos(relative)});
  }
  std::sort(found.begin(), found.end(),
            [](const Blocker& a, const Blocker& b) { return a.rear_s < b.rear_s; });
  return found;
}

void ReferenceDriver::start_locating(const DriverInput& input) {
  located_horizon_ = std::max(60.0, input.ego.speed * 6 + 30);
  // From a little behind the ego: the plan looks at what it has been passing.
  located_window_ = route_.window(30, located_horizon_);
  located_known_.assign(input.objects.size(), 0);
  located_.resize(input.objects.size());
}

const std::optional<PathCoordinate>& ReferenceDriver::located(std::size_t k,
                                                              const WorldObject& object) {
  if (!located_known_[k]) {
    located_[k] = route_.locate({object.x, object.y}, located_window_, located_horizon_);
    located_known_[k] = 1;
  }
  return located_[k];
}

void ReferenceDriver::plan_manoeuvre(const DriverInput& input, double dt, double desired) {
  waiting_to_pass_.reset();
  if (route_.empty()) return;
  OvertakeContext context{map_,
                          route_,
                          vehicle_,
                          input.ego,
                          input.objects,
                          desired,
                          settings_.comfortable_acceleration,
                          dt,
                          settings_.lookahead_time,
                          settings_.min_lookahead,
                          input.time};
  std::vector<Blocker>& in_lane = objects_in_lane(input);
  if (overtake_.active) {
    update_overtake(overtake_, context, in_lane, settings_.overtaking);
    return;
  }
  double front_s = route_.progress() + vehicle_.length / 2;
  std::erase_if(in_lane, [&](const Blocker& b) { return b.rear_s <= front_s; });
  bool waiting = false;
  auto plan = plan_overtake(context, in_lane, settings_.overtaking, waiting);
  if (plan) {
    indicate_then_go(*plan, input.time);
  } else if (!waiting) {
    overtake_ = OvertakePlan{};  // nothing to pass any more: the indicator goes off
  } else {
    overtake_.possible_since = -1;  // indicating (if it was), waiting for a gap
  }
  // Behind what it means to pass (waiting for a gap, or indicating), standing or crawling below
  // walking pace, it keeps room: a crawler then draws away until the pull-out clears it.
  if (!overtake_.active && (waiting || overtake_.indicating) &&
      in_lane.front().speed < kWalkingPace)
    waiting_to_pass_ = in_lane.front().object->id;
}

// Indicate, then move (docs/simulation.md, "Overtaking"): a pass the road and the traffic allow
// first turns the indicator on towards its lane; only once it has been on for the indicate time,
// and the pass has been found possible at every step of the last steady time (the lane checked
// again, the pull-out's swept path too), does the ego pull out. A plan towards another lane
// starts the wait afresh; one that waits for a gap keeps indicating.
void ReferenceDriver::indicate_then_go(const OvertakePlan& plan, double time) {
  constexpr double kTolerance = 1e-9;  // s, of the step times' rounding
  const OvertakingSettings& rules = settings_.overtaking;
  bool same_lane = overtake_.indicating && overtake_.lane == plan.lane;
  double since = same_lane ? overtake_.indicating_since : time;
  double possible = same_lane && overtake_.possible_since >= 0 ? overtake_.possible_since : time;
  if (time - since >= rules.indicate_time - kTolerance &&
      time - possible >= rules.steady_time - kTolerance) {
    overtake_ = plan;
    return;
  }
  overtake_ = OvertakePlan{};
  overtake_.indicating = true;
  overtake_.indicating_since = since;
  overtake_.possible_since = possible;
  overtake_.lane = plan.lane;
  overtake_.offset = plan.offset;
}

void ReferenceDriver::watch_patience(const DriverInput& input) {
  if (!held_by_standing_) {
    held_since_ = -1;
    patience_over_ = false;
    return;
  }
  if (held_since_ < 0 && input.ego.speed < kStoppedSpeed) held_since_ = input.time;
  if (held_since_ >= 0 && input.time - held_since_ >= settings_.pedestrian_patience)
    patience_over_ = true;
}

bool ReferenceDriver::on_own_lane(MapPoint point) const {
  auto at = route_.locate(point, 5, 200, 20);
  if (!at || at->beyond_end) return false;
  auto lane = route_.lane_at(at->s);
  if (!lane) return false;
  double lateral = at->lateral - planned_lateral(overtake_, at->s);
  return lateral >= 0 ? lateral <= lane_left_width_at(map_, lane->lane, lane->lane_s)
                      : -lateral <= lane_right_width_at(map_, lane->lane, lane->lane_s);
}

void ReferenceDriver::collect_object_constraints(const DriverInput& input, double front_s) {
  const KinematicState& ego = input.ego;
  const double horizon = located_horizon_;
  double half_width = vehicle_.width / 2 + kCorridorMargin;
  // What is behind the ego's centre is not ahead; the window is found when first asked for.
  std::optional<PathWindow> ahead;
  auto ahead_window = [&] {
    if (!ahead) ahead = route_.window(0, horizon);
    return *ahead;
  };
  for (std::size_t k = 0; k < input.objects.size(); ++k) {
    const WorldObject& object = input.objects[k];
    double dx = object.x - ego.x, dy = object.y - ego.y;
    if (dx * dx + dy * dy > (horizon + object.length) * (horizon + object.length)) continue;
    // Too far aside to be in the path or to enter it in time, however it moves (below; off the
    // path, the ego's own lateral plan would shift it). A vehicle located already needs no bound:
    // its location is then as far aside, and only a pedestrian is heeded beyond (as crossing).
    const bool bounded = object.kind == TraceActorKind::pedestrian || !located_known_[k];
    if (!overtake_.active && bounded &&
        route_.surely_farther(
            {object.x, object.y}, ahead_window(),
            greatest_extent(object) + half_width + farthest_entry(object) + kSurelyAside))
      continue;
    const auto& at = located(k, object);
    // Beside or behind the ego's centre, or past the end of the route (where the ego stops).
    if (!at || at->beyond_end || at->s <= route_.progress()) continue;
    double path_heading = route_.heading_at(at->s, at->segment);
    double relative = angle_difference(object.heading, path_heading);
    // Sideways from where the ego will be there (off the path while it overtakes).
    double lateral = at->lateral - planned_lateral(overtake_, at->s);
    bool pedestrian = object.kind == TraceActorKind::pedestrian;
    bool standing = pedestrian && motion_.speed(object.id) < settings_.standing_speed;
    double body_relative = vehicle_body_heading(object, path_heading) - path_heading;
    double across = extent_across(object, body_relative);
    double along = extent_along(object, body_relative);
    double gap = at->s - along - front_s;
    // A reversing object moves against its heading: one backing towards the ego closes in.
    double velocity = object.reversing ? -object.speed : object.speed;
    double lead_speed = velocity * std::cos(relative);
    double lateral_speed = pedestrian
                               ? velocity * std::sin(relative)
                               : vehicle_lateral_speed(object, velocity, relative, path_heading);
    double clearance = std::abs(lateral) - across - half_width;

    bool in_path = clearance <= 0;
    // A pedestrian standing beside the path is not about to enter it (what perception makes of
    // its speed and heading is noise).
    bool approaching = !in_path && !standing && lateral_speed * lateral < 0;
    // Committed to a left turn, the ego clears the oncoming lanes: an oncoming vehicle coming
    // towards its path must wait (stopping in its lane would not help); one in it still counts.
    if (approaching && turn_committed_ && left_turn_.is_oncoming(object)) approaching = false;
    if (approaching) {
      // Moving towards the path: will it be there by the time the ego is?
      double time_to_enter = clearance / std::abs(lateral_speed);
      double time_to_arrive = gap / std::max(ego.speed, 1.0);
      double window = pedestrian ? time_to_arrive + 2.0 : kVehicleEntryTime;
      in_path = time_to_enter < std::min(window, kPredictionTime + (pedestrian ? 2.0 : 0.0));
      if (in_path && pedestrian) lead_speed = 0;  // it will stand in the way, not drive ahead
    }
    if (!in_path) {
      if (approaching && pedestrian)
        add_crossing_pedestrian(object, ego.speed, gap, clearance, lateral_speed, lead_speed);
      continue;
    }
    if (standing) held_by_standing_ = true;
    DriverReason reason = pedestrian ? DriverReason::pedestrian : DriverReason::lead;
    // Behind something it means to pass, the ego keeps room to pull out, as much as it still
    // has: winning back a gap it is already inside would take a harsh brake at walking pace.
    double clearance_kept = settings_.standstill_gap;
    if (waiting_to_pass_ == object.id)
      clearance_kept =
          std::clamp(gap, settings_.standstill_gap,
                     std::max(settings_.standstill_gap, settings_.overtaking.waiting_gap));
    constraints_.push_back({gap, clearance_kept, std::max(lead_speed, 0.0), true, reason});
  }
}

// A vehicle's speed towards the path's left (heading `path_heading` there). Perception's heading
// noise alone makes a fast car beside the path (an oncoming one passing close by) seem to swerve
// into it now and then, and one such step made the ego brake in full. So a speed across counts
// when this step's measurement is beyond 4 standard deviations of that noise (a sharp cut-in,
// seen at once), or the smoothed velocity's beyond 3 of its own (a gentle lane change, seen
// within a few steps); else the vehicle keeps its line.
double ReferenceDriver::vehicle_lateral_speed(const WorldObject& object, double velocity,
                                              double relative, double path_heading) const {
  constexpr double kRawSigmas = 4;
  constexpr double kSmoothedSigmas = 3;
  const double sigma = heading_noise_ * std::abs(velocity);
  const double raw = velocity * std::sin(relative);
  if (std::abs(raw) > kRawSigmas * sigma) return raw;
  const auto smoothed = motion_.velocity(object.id);
  if (!smoothed) return 0;  // an obstacle: it stands
  const double lateral =
      smoothed->y * std::cos(path_heading) - smoothed->x * std::sin(path_heading);
  return std::abs(lateral) > kSmoothedSigmas * sigma * motion_.noise_reduction(last_dt_) ? lateral
                                                                                         : 0.0;
}

// The heading a perceived body lies along, the path heading `path_heading` there. A slow
// vehicle's (a parked or crawling one) or an oncoming one's is its smoothed heading: the noise of
// one step's would swing a long one's corners in and out of the corridor (a 12 m bus's by 0.3 m
// at 3 degrees, parked beside the path or passing on a narrow road). Unless this step's differs
// from it by more than 3 standard deviations of that noise: a real turn, seen at once. A faster
// one going the ego's way takes this step's: it may be cutting in.
double ReferenceDriver::vehicle_body_heading(const WorldObject& object, double path_heading) const {
  constexpr double kRawSigmas = 3;
  constexpr double kSlow = 3;                             // m/s
  constexpr double kOncoming = 3 * std::numbers::pi / 4;  // rad from the path's heading
  if (object.kind != TraceActorKind::vehicle) return object.heading;
  const bool oncoming = std::abs(angle_difference(object.heading, path_heading)) > kOncoming;
  if (motion_.speed(object.id) >= kSlow && !oncoming) return object.heading;
  const std::optional<double> smoothed = motion_.heading(object.id);
  if (!smoothed ||
      std::abs(angle_difference(object.heading, *smoothed)) > kRawSigmas * heading_noise_)
    return object.heading;
  return *smoothed;
}

// A pedestrian on the carriageway walking towards the ego's path, not (yet) counted as in it:
// the ego gets ready to stop before the point where it would cross the path, as a careful driver
// slows for someone crossing the road ahead, unless the ego will be past that point before the
// pedestrian can reach it. `gap` is from the ego's front to the pedestrian's near side along the
// path, `clearance` sideways from the corridor, the speeds along and across the path.
void ReferenceDriver::add_crossing_pedestrian(const WorldObject& object, double ego_speed,
                                              double gap, double clearance, double lateral_speed,
                                              double along_speed) {
  // Slower across than a standing pedestrian seems to drift: walking along the road, not across.
  if (std::abs(lateral_speed) < settings_.standing_speed) return;
  // Where its line of walking meets the corridor, and how soon it could be there if it hurried.
  double crossing_gap = gap + clearance * along_speed / std::abs(lateral_speed);
  double hurried = kPedestrianHurry * std::abs(lateral_speed) / std::max(object.speed, 1e-6);
  double time_to_enter = clearance / std::max(std::abs(lateral_speed), hurried);
  if (crossing_gap <= 0) return;  // beside or behind the front: stopping cannot help
  // The ego is past the crossing point (its rear, with a margin) before the pedestrian gets there.
  double time_to_clear =
      (crossing_gap + vehicle_.length + greatest_extent(object)) / std::max(ego_speed, 1.0);
  if (time_to_enter > time_to_clear + kCrossingMargin) return;
  // On the pavement the ego only heeds pedestrians about to enter its path (above).
  auto lane = project_to_lane(map_, {object.x, object.y});
  if (!lane || !lane->inside) return;
  constraints_.push_back(
      {crossing_gap, settings_.standstill_gap, 0, false, DriverReason::pedestrian});
}

void ReferenceDriver::collect_feature_constraints(const DriverInput& input, double front_s) {
  const KinematicState& ego = input.ego;
  double horizon = std::max(80.0, ego.speed * 8 + 40);
  double full_stop = ego.speed * ego.speed / (2 * vehicle_.max_deceleration);
  double calm_stop = ego.speed * ego.speed / (2 * settings_.comfortable_deceleration);
  const auto& features = route_.features();
  for (std::size_t i = 0; i < features.size(); ++i) {
    const RouteFeature& feature = features[i];
    double to_line = feature.s - front_s;
    if (to_line > horizon) break;
    if (to_line < -0.5) {
      if (feature.kind == FeatureKind::stop_sign) stop_sign_served_[i] = true;
      continue;
    }
    switch (feature.kind) {
      case FeatureKind::traffic_light: {
        SignalColour colour =
            feature.index < input.lights.size() ? input.lights[feature.index] : SignalColour::green;
        bool stop = (colour == SignalColour::red && to_line > full_stop - 1) ||
                    (colour == SignalColour::yellow && to_line > calm_stop);
        if (stop)
          constraints_.push_back(
              {to_line, settings_.stop_line_gap, 0, false, DriverReason::red_light});
        break;
      }
      case FeatureKind::stop_sign: {
        if (stop_sign_served_[i]) break;
        // Stood long enough, it goes once the traffic with the way leaves it a gap.
        if (to_line < settings_.stop_line_gap + 3 && ego.speed < kStoppedSpeed) {
          if (stopped_since_ < 0) stopped_since_ = input.time;
          if (input.time - stopped_since_ >= settings_.stop_sign_wait &&
              !must_give_way(input, feature.s, settings_.stop_critical_gap)) {
            stop_sign_served_[i] = true;
            stopped_since_ = -1;
            break;
          }
        }
        constraints_.push_back(
            {to_line, settings_.stop_line_gap, 0, false, DriverReason::stop_sign});
        break;
      }
      case FeatureKind::yield_sign: {
        // Near enough to see the junction, it slows to stop at the line while traffic with the way
        // is in or near it; once it can no longer stop there, it goes on.
        constexpr double kYieldNotice = 40;  // m before the line
        if (to_line > kYieldNotice || to_line < full_stop) break;
        if (must_give_way(input, feature.s, settings_.yield_critical_gap))
          constraints_.push_back(
              {to_line, settings_.stop_line_gap, 0, false, DriverReason::give_way});
        break;
      }
      case FeatureKind::crosswalk: {
        if (to_line < full_stop) break;  // too late to stop before it: clear it instead
        // Pedestrians walking in or at the crosswalk stop the ego; ones standing there only
        // when they stand on its lane, and then only until its patience is over.
        const Crosswalk& crosswalk = map_.crosswalks()[feature.index];
        bool walking = false, standing = false;
        for (const WorldObject& o : input.objects) {
          if (o.kind != TraceActorKind::pedestrian ||
              !near_polygon({o.x, o.y}, crosswalk.outline, settings_.crosswalk_clearance))
            continue;
          if (motion_.speed(o.id) >= settings_.standing_speed)
            walking = true;
          else if (on_own_lane({o.x, o.y}))
            standing = true;
        }
        if (standing) held_by_standing_ = true;
        if (standing && patience_over_) creeping_ = true;
        if (walking || (standing && !patience_over_))
          constraints_.push_back(
              {to_line, settings_.stop_line_gap, 0, false, DriverReason::pedestrian});
        break;
      }
    }
  }
  if (route_ends_at_target_)
    constraints_.push_back(
        {route_.length() - route_.progress(), kTargetClearance, 0, false, DriverReason::target});
  else if (!route_.empty())
    add_road_end(input.ego.speed);
}

// The end of the lanes ahead (a map's edge, without a target): stop before it. Only once it is
// near: IDM brakes a little for a standing obstacle however far, and cruising would feel it.
void ReferenceDriver::add_road_end(double speed) {
  const double gap = route_.length() - route_.progress() - vehicle_.length / 2;
  const double near = 2 * speed * speed / (2 * settings_.comfortable_deceleration) + kRoadEndNotice;
  if (gap <= near) constraints_.push_back({gap, kRoadEndClearance, 0, false, DriverReason::target});
}

// The junction priority rule (docs/simulation.md, "Junctions"), as the reactive NPCs keep it:
// before a junction it can still stop for, the ego waits at the entry while (a) a lead it would
// stop behind stands or crawls so near that the ego would stand inside the junction (do not block
// the box), or (b) a vehicle inside the junction is on a lane crossing or merging with the ego's
// (it entered first and clears it). Held longer than its patience it goes on, still stopping for
// whatever is in its path (a standstill breaker, as for a car parked in the junction).
void ReferenceDriver::hold_at_junction(const DriverInput& input, double front_s) {
  auto stretch = route_.junction_ahead(front_s);
  const double speed = input.ego.speed;
  if (!stretch || stretch->entry <= front_s || stretch->entry == released_entry_) {
    held_since_junction_ = -1;
    return;
  }
  // m before the entry from which the ego looks at the junction: beyond it, whoever is inside
  // now has long left when the ego arrives.
  constexpr double kJunctionNotice = 40;
  const double to_entry = stretch->entry - front_s;
  if (to_entry > kJunctionNotice || to_entry < speed * speed / (2 * vehicle_.max_deceleration))
    return;
  // Who is inside is looked at twice a second, as a driver glances round a junction.
  constexpr double kGlanceInterval = 0.5;  // s
  if (input.time >= next_glance_) {
    next_glance_ = input.time + kGlanceInterval;
    crossing_inside_ = crossing_inside(input, *stretch);
  }
  if (!box_blocked(*stretch, front_s) && !crossing_inside_) {
    held_since_junction_ = -1;
    return;
  }
  if (speed < kStoppedSpeed && held_since_junction_ < 0) held_since_junction_ = input.time;
  if (held_since_junction_ >= 0 &&
      input.time - held_since_junction_ >= settings_.junction_patience) {
    released_entry_ = stretch->entry;
    held_since_junction_ = -1;
    return;
  }
  constraints_.push_back({to_entry, settings_.stop_line_gap, 0, false, DriverReason::give_way});
}

bool ReferenceDriver::box_blocked(const JunctionStretch& stretch, double front_s) const {
  constexpr double kCrawling = 1.0;  // m/s: slower than this, a lead holds the ego where it is
  for (const Constraint& constraint : constraints_) {
    if (!constraint.is_object || constraint.reason != DriverReason::lead) continue;
    const double standing_front = front_s + constraint.gap - constraint.clearance;
    if (constraint.lead_speed < kCrawling && standing_front < stretch.exit + vehicle_.length)
      return true;
  }
  return false;
}

const std::vector<LaneIndex>& ReferenceDriver::stretch_conflicts(const JunctionStretch& stretch) {
  if (conflicts_entry_ != stretch.entry) {
    conflicts_entry_ = stretch.entry;
    conflicts_.clear();
    for (std::size_t k = stretch.first; k <= stretch.last; ++k) {
      std::vector<LaneIndex> more = conflicting_lanes(map_, route_.segments()[k].lane);
      conflicts_.insert(conflicts_.end(), more.begin(), more.end());
    }
    std::sort(conflicts_.begin(), conflicts_.end());
    conflicts_.erase(std::unique(conflicts_.begin(), conflicts_.end()), conflicts_.end());
    std::vector<LaneIndex> own;
    for (std::size_t k = stretch.first; k <= stretch.last; ++k)
      own.push_back(route_.segments()[k].lane);
    conflict_points_ = conflict_points(map_, own, conflicts_);
    // Vehicles up to 20 m long near the outline are covered (crossing_inside's test).
    junction_lanes_ = junction_neighbourhood(map_, stretch.junction, 10);
  }
  return conflicts_;
}

bool ReferenceDriver::must_give_way(const DriverInput& input, double line, double critical_gap) {
  const auto stretch = route_.junction_ahead(line);
  if (!stretch) return false;
  PriorityTrafficSettings priority;
  priority.critical_gap = critical_gap;
  stretch_conflicts(*stretch);
  return priority_traffic(map_, conflict_points_, input.objects, {input.ego.x, input.ego.y},
                          priority);
}

bool ReferenceDriver::crossing_inside(const DriverInput& input, const JunctionStretch& stretch) {
  constexpr double kJunctionWatch = 60;  // m from the ego within which the junction lies
  stretch_conflicts(stretch);
  const auto& outline = map_.junctions()[stretch.junction].outline;
  for (const WorldObject& object : input.objects) {
    if (object.kind != TraceActorKind::vehicle) continue;
    const double dx = object.x - input.ego.x, dy = object.y - input.ego.y;
    if (dx * dx + dy * dy > kJunctionWatch * kJunctionWatch) continue;
    // Most are outside the junction's outline: no lane search for them.
    if (!outline.empty() && !near_polygon({object.x, object.y}, outline, object.length / 2))
      continue;
    // The junction's own segments answer as project_to_lane would, without its map-wide search;
    // a vehicle outside them (a very long one, a junction without an outline) searches the map.
    const MapPoint at{object.x, object.y};
    auto on = covers(junction_lanes_, at) && std::isfinite(object.heading)
                  ? lane_containing(map_, junction_lanes_, at, object.heading)
                  : project_to_lane(map_, at, object.heading);
    // On a lane across the ego's and not yet past where they meet. A roundabout's ring is one
    // lane: a car that has gone by the ego's entry no longer holds it, nor does one still farther
    // round than it drives within the entry's critical gap.
    const double reach = object.length + std::abs(object.speed) * settings_.yield_critical_gap;
    if (on && on->inside && std::binary_search(conflicts_.begin(), conflicts_.end(), on->lane) &&
        short_of_conflict(map_, conflict_points_, on->lane, on->s, object.length, reach))
      return true;
  }
  return false;
}

// A lane change's duration: at no less than a crawl's speed, and no longer than this.
constexpr double kLaneChangeCrawl = 2.0;  // m/s
constexpr double kLongestChange = 8.0;    // s

void ReferenceDriver::collect_lane_change_constraints(const DriverInput& input, double front_s) {
  const KinematicState& ego = input.ego;
  double lookahead = std::max(30.0, ego.speed * 4);
  for (const LaneChangeStretch& change : route_.lane_changes()) {
    if (change.begin <= route_.progress()) continue;  // under way: finish it
    if (change.begin - front_s > lookahead) break;
    const Polyline& next_lane = map_.lane(change.to).centre_line;
    PolylineProjection ego_beside = next_lane.project({ego.x, ego.y});
    // Until it is over in the next lane (the stretch's end), one coming up behind faster closes
    // in, and the ego would move over right in front of it.
    const double change_time =
        std::min((change.end - front_s) / std::max(ego.speed, kLaneChangeCrawl), kLongestChange);
    bool blocked =
        std::any_of(input.objects.begin(), input.objects.end(), [&](const WorldObject& o) {
          if (o.kind == TraceActorKind::pedestrian) return false;
          PolylineProjection on = next_lane.project({o.x, o.y});
          double half_width = on.lateral >= 0 ? lane_left_width_at(map_, change.to, on.s)
                                              : lane_right_width_at(map_, change.to, on.s);
          if (on.distance > half_width + o.width / 2) return false;
          double ahead = on.s - ego_beside.s;  // along the next lane, centre to centre
          double reach = (vehicle_.length + o.length) / 2 + settings_.lane_change_gap;
          double behind_room = reach + settings_.lane_change_time_gap * o.speed +
                               std::max(0.0, o.speed - ego.speed) * change_time;
          double ahead_room = reach + settings_.lane_change_time_gap * ego.speed;
          return ahead > -behind_room && ahead < ahead_room;
        });
    if (blocked)
      constraints_.push_back(
          {change.begin - front_s, settings_.stop_line_gap, 0, false, DriverReason::lane_change});
    break;  // only the next lane change matters now
  }
}

double ReferenceDriver::idm_acceleration(double speed, double desired,
                                         const Constraint& constraint) const {
  double a = settings_.comfortable_acceleration;
  double b = settings_.comfortable_deceleration;
  double approach = speed * (speed - constraint.lead_speed) / (2 * std::sqrt(a * b));
  double wanted_gap = constraint.clearance + std::max(0.0, speed * settings_.time_gap + approach);
  double gap = std::max(constraint.gap, 0.01);
  const double idm =
      a * (1 - fourth_power(speed / desired) - (wanted_gap / gap) * (wanted_gap / gap));
  if (!constraint.is_object || constraint.lead_speed < kStoppedSpeed) return idm;
  return with_constant_acceleration_heuristic(idm, speed, constraint.lead_speed, gap, b);
}

VehicleControl ReferenceDriver::step(const DriverInput& input) {
  const KinematicState& ego = input.ego;
  double dt = last_time_ >= 0 ? input.time - last_time_ : 0.1;
  last_time_ = input.time;
  last_dt_ = dt;
  motion_.update(input.objects, dt);
  start_locating(input);
  // The free road's speed here, for the plan and the acceleration alike.
  const double free_speed = desired_speed(route_.progress());
  plan_manoeuvre(input, dt, free_speed);
  double front_s = route_.progress() + vehicle_.length / 2;
  constraints_.clear();
  held_by_standing_ = false;
  creeping_ = false;
  GapDecision gap =
      left_turn_.decide(ego, input.objects, speed_envelope_,
                        std::min(sight_speed_, vehicle_.max_speed), vehicle_.max_deceleration);
  turn_committed_ = gap.committed;
  if (gap.wait_gap)
    constraints_.push_back(
        {*gap.wait_gap, settings_.stop_line_gap, 0, false, DriverReason::give_way});
  collect_object_constraints(input, front_s);
  collect_feature_constraints(input, front_s);
  collect_lane_change_constraints(input, front_s);
  hold_at_junction(input, front_s);
  watch_patience(input);

  double desired = free_speed;
  if (creeping_) desired = std::min(desired, settings_.creeping_speed);
  double a = settings_.comfortable_acceleration;
  // Found above the desired speed (a scenario starting over an icy road's limit), it slows at
  // its comfortable deceleration, not at IDM's full braking for v >> v0.
  double acceleration =
      std::max(a * (1 - fourth_power(ego.speed / desired)), -settings_.comfortable_deceleration);
  reason_ = creeping_ ? DriverReason::creeping : DriverReason::cruise;
  if (sight_speed_ < desired) {
    // What it can see caps the speed as a lower desired speed would; found above it (a scenario
    // starting fast in fog), it slows firmly, not at IDM's full braking for v >> v0.
    double sighted =
        std::max(a * (1 - fourth_power(ego.speed / sight_speed_)), -settings_.sight_braking);
    if (sighted < acceleration) {
      acceleration = sighted;
      reason_ = DriverReason::sight;
    }
  }
  for (const Constraint& constraint : constraints_) {
    double candidate = idm_acceleration(ego.speed, desired, constraint);
    if (candidate < acceleration) {
      acceleration = candidate;
      reason_ = constraint.reason;
    }
    if (!constraint.is_object) continue;
    double closing = ego.speed - constraint.lead_speed;
    bool collision_course =
        closing > 0 && constraint.gap / closing < settings_.emergency_time_to_collision;
    if (collision_course || (constraint.gap < 0.5 && ego.speed > 0)) {
      acceleration = -vehicle_.max_deceleration;
      reason_ = DriverReason::emergency;
    }
  }
  if (!route_.empty() && route_.progress() >= route_.length() - 0.01 && !route_ends_at_target_) {
    // The end of the lanes: stop rather than drive off the map.
    acceleration = -settings_.comfortable_deceleration;
  }
  acceleration = std::clamp(acceleration, -vehicle_.max_deceleration, vehicle_.max_acceleration);
  return {acceleration,
          std::clamp(steering(ego), -vehicle_.max_steering_angle, vehicle_.max_steering_angle)};
}

}  // namespace scenfuzz

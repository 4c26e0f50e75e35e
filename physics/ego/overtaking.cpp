// Overtaking: which lane to pass in (the lines that may be crossed, the lane's extent, no
// junction, light, sign, crosswalk or lane change of the route during the manoeuvre), whether the
// traffic there leaves room, how long the pass takes, and the sideways profile of the manoeuvre.
#include "physics/ego/overtaking.hpp"

#include <algorithm>
#include <cmath>

#include "physics/ego/pull_out_sweep.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/point_at_from.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kStationary = 0.5;      // m/s: a blocker slower than this is standing
constexpr double kTimingStep = 0.1;      // s, of the pass's time integration
constexpr double kLongestPass = 40.0;    // s: a pass that would take longer is not started
constexpr double kLaneTolerance = 0.75;  // m the passing lane may wander from its offset
constexpr double kHardlyOut = 0.3;       // m: a pull-out given up before this is simply dropped
                                         // may be a tight one

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// Where smoothstep reaches `fraction` (in [0, 1]): bisection, smoothstep being increasing.
double smoothstep_reaching(double fraction) {
  double low = 0, high = 1;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (low + high);
    (smoothstep(mid) < fraction ? low : high) = mid;
  }
  return high;
}

// The longest pull-out from a standstill `room` metres behind a standing blocker: one whose body
// is clear of the blocker's side (its own width and a margin across, the blocker no wider than
// its lane) by the time its front reaches the blocker, rather than one fully in the next lane.
// nullopt when even the tightest move its steering allows (a smoothstep of length L bends at most
// 6 |offset| / L^2) cannot do that. Stopped close behind a blocker while traffic went by, the
// driver would otherwise wait there for ever: its usual pull-out needs 12 m.
std::optional<double> standing_pull_out(double room, double offset, const ActorClass& vehicle) {
  constexpr double kSideMargin = 0.5;  // m between its side and the blocker's when level
  const double fraction = std::min(1.0, (vehicle.width + kSideMargin) / std::abs(offset));
  const double longest = 0.9 * room / smoothstep_reaching(fraction);
  const double tightest = std::sqrt(6 * std::abs(offset) * 1.2 * vehicle.min_turning_radius());
  if (tightest > longest) return std::nullopt;
  return longest;
}

// Whether a lane boundary may be crossed to pass an object moving at `speed`: broken lines and
// unknown ones (maps that do not say) always; solid and double lines only to pass something
// standing or as slow as a bicycle (as UK Highway Code rule 129 and many US states allow);
// a kerb never.
bool may_cross(BoundaryType type, double speed, const OvertakingSettings& settings) {
  switch (type) {
    case BoundaryType::unknown:
    case BoundaryType::dotted_yellow:
    case BoundaryType::dotted_white: return true;
    case BoundaryType::solid_yellow:
    case BoundaryType::solid_white:
    case BoundaryType::double_yellow: return speed <= settings.slow_enough_for_solid_line;
    case BoundaryType::curb: return false;
  }
  return false;
}

struct Candidate {
  LaneIndex lane = 0;
  bool oncoming = false;
  BoundaryType boundary = BoundaryType::unknown;
};

// The row of slow objects to pass: the first blocker and those close enough behind each other
// that the ego could not slot in between.
struct Cluster {
  double rear_s = 0, front_s = 0, speed = 0;
  std::size_t count = 0;
};

double return_room(const ActorClass& vehicle, double speed, const OvertakingSettings& settings) {
  return vehicle.length + settings.gap_ahead + settings.time_gap * speed;
}

Cluster cluster_of(std::span<const Blocker> blockers, const ActorClass& vehicle, double slow_below,
                   const OvertakingSettings& settings) {
  Cluster cluster{blockers[0].rear_s, blockers[0].front_s, blockers[0].speed, 1};
  for (std::size_t i = 1; i < blockers.size(); ++i) {
    const Blocker& next = blockers[i];
    if (next.rear_s - cluster.front_s > return_room(vehicle, cluster.speed, settings) ||
        next.speed >= slow_below)
      break;
    cluster.front_s = std::max(cluster.front_s, next.front_s);
    cluster.speed = std::min(cluster.speed, next.speed);
    ++cluster.count;
  }
  return cluster;
}

// How long the pass takes and how far the ego travels meanwhile: it accelerates comfortably to
// its desired speed until it is a return room past the cluster's front, then moves back.
struct PassTiming {
  bool possible = false;
  double time = 0;
  double travel = 0;
};

PassTiming pass_timing(const OvertakeContext& context, double gap, const Cluster& cluster,
                       double offset, const OvertakingSettings& settings) {
  PassTiming timing;
  double passing_speed = std::max(context.desired_speed, context.ego.speed);
  if (passing_speed < cluster.speed + 1.0) return timing;
  double needed = gap + (cluster.front_s - cluster.rear_s) + context.vehicle.length +
                  settings.gap_ahead + settings.time_gap * cluster.speed;
  // The loop below gains at most (passing_speed - cluster.speed) * kTimingStep a step, for about
  // kLongestPass / kTimingStep steps: a pass needing far more is not possible, and its timing is
  // not read. (A step more and a 1 % margin, far beyond the sums' rounding.)
  const double most_gained =
      1.01 * (passing_speed - cluster.speed) * (kLongestPass + 2 * kTimingStep) + 1e-6;
  if (needed > most_gained) return timing;
  double speed = context.ego.speed, relative = 0;
  const double gain = context.comfortable_acceleration * kTimingStep;
  // Speeding up, until the passing speed: from then on min() keeps it there (a gain >= 0 added
  // cannot round below it), and every step adds the same amounts (the loop below).
  while (relative < needed && !(speed == passing_speed && gain >= 0)) {
    if (timing.time > kLongestPass) return timing;
    speed = std::min(passing_speed, speed + gain);
    relative += (speed - cluster.speed) * kTimingStep;
    timing.travel += speed * kTimingStep;
    timing.time += kTimingStep;
  }
  const double relative_step = (speed - cluster.speed) * kTimingStep;
  const double travel_step = speed * kTimingStep;
  while (relative < needed) {
    if (timing.time > kLongestPass) return timing;
    relative += relative_step;
    timing.travel += travel_step;
    timing.time += kTimingStep;
  }
  // The ego has left the passing lane about 70 % of the way through its move back.
  double back = 0.7 * std::abs(offset) / settings.lateral_speed;
  timing.time += back;
  timing.travel += speed * back;
  timing.possible = true;
  return timing;
}

// Whether the route left after the pass (`remaining`, from where the ego is back in its lane) lets
// it come to a stop at the route's end (its target, the lanes' end) before the passed row, which
// need not brake, catches up: a driver does not pass a car only to stop in front of it (the
// reference driver did, and was rear-ended at its target: cut_in_straight's findings). The ego
// returns `gap_ahead + time_gap * v` ahead of the row (pass_timing), cruises at the passing speed
// u, then brakes at b to stop at the end; the row at v keeps at least gap_ahead from it when
// remaining * (1 - v / u) >= v * (u / (2 b) - time_gap). b is half the comfortable deceleration:
// the driver's approach to a stop (IDM's) eases off towards it and takes longer than braking at
// a constant rate would (with the whole of it, cut_in_straight's ego was still caught at 1.4 m/s
// short of its target).
bool room_to_stop_after(const OvertakeContext& context, const Cluster& cluster, double remaining,
                        const OvertakingSettings& settings) {
  if (cluster.speed < kStationary) return true;
  const double passing_speed = std::max(context.desired_speed, context.ego.speed);
  const double braking = context.vehicle.comfortable_deceleration / 2;
  if (passing_speed <= cluster.speed || braking <= 0) return false;
  const double needed = cluster.speed * (passing_speed / (2 * braking) - settings.time_gap) /
                        (1 - cluster.speed / passing_speed);
  return remaining >= needed;
}

// The signed offset (left positive) of `lane`'s centre line from the path at arc length s, and
// whether the lane runs beside the path there.
std::optional<double> lane_offset(const OvertakeContext& context, LaneIndex lane, double s) {
  const Polyline& path = context.route.path();
  // The point and the heading lie on one segment: it is searched for once.
  const std::size_t segment = context.route.segment_at(s);
  MapPoint p = point_at_from(path, s, segment);
  // The route's kept segment headings: path.heading_at's atan2, computed once.
  double heading = context.route.heading_at(s, segment);
  const Polyline& centre_line = context.map.lane(lane).centre_line;
  PolylineProjection on = centre_line.project(p);
  if (on.distance > std::abs(on.lateral) + 1e-6) return std::nullopt;  // off its ends
  MapPoint q = point_at_from(centre_line, on.s, on.segment);
  return std::cos(heading) * (q.y - p.y) - std::sin(heading) * (q.x - p.x);
}

// Whether nothing on the route keeps the ego from leaving its lane between path arc lengths
// `from` and `to`: the route stays on the lane, without a junction, feature or lane change.
bool route_allows(const OvertakeContext& context, LaneIndex lane, double from, double to) {
  const RouteTracker& route = context.route;
  if (to > route.length() - 1) return false;
  auto here = route.lane_at(from);
  if (!here || here->lane != lane || here->lane_end < to) return false;
  if (context.map.lane(lane).junction) return false;
  for (const RouteFeature& feature : route.features())
    if (feature.s_end >= from && feature.s <= to) return false;
  for (const LaneChangeStretch& change : route.lane_changes())
    if (change.end >= from && change.begin <= to) return false;
  return true;
}

// Whether the traffic in the passing lane leaves room for the whole pass. `ignored(id)` tells the
// objects being passed.
template <typename Ignored>
bool passing_lane_clear(const OvertakeContext& context, const Candidate& candidate,
                        const Cluster& cluster, const PassTiming& timing,
                        const OvertakingSettings& settings, const Ignored& ignored) {
  const Lane& lane = context.map.lane(candidate.lane);
  const KinematicState& ego = context.ego;
  if (candidate.oncoming) {
    double limit = lane.speed_limit > 0 ? lane.speed_limit : context.desired_speed;
    // Traffic the ego cannot see yet may come at the limit from beyond what it can see; it
    // gets the margin that traffic in sight gets.
    double reach = context.vehicle.length + settings.gap_ahead;
    if (timing.travel + reach + limit * (timing.time + settings.oncoming_margin) >
        settings.sight_distance)
      return false;
  }
  PolylineProjection ego_on = lane.centre_line.project({ego.x, ego.y});
  for (const WorldObject& o : context.objects) {
    if (ignored(o.id)) continue;
    PolylineProjection on = lane.centre_line.project({o.x, o.y});
    double half_width = on.lateral >= 0 ? lane_left_width_at(context.map, candidate.lane, on.s)
                                        : lane_right_width_at(context.map, candidate.lane, on.s);
    if (on.distance > half_width + o.width / 2) continue;
    double reach = (context.vehicle.length + o.length) / 2 + settings.gap_ahead;
    double velocity = o.reversing ? -o.speed : o.speed;
    double along = velocity * std::cos(angle_difference(o.heading, ego.heading));
    // Centre to centre, along the ego's direction of travel.
    double ahead = candidate.oncoming ? ego_on.s - on.s : on.s - ego_on.s;
    if (candidate.oncoming) {
      if (ahead < -reach) continue;  // behind the ego
      double closing = std::max(0.0, -along);
      if (ahead < timing.travel + reach + closing * (timing.time + settings.oncoming_margin))
        return false;
      continue;
    }
    if (ahead < 0) {
      // The mirror: whoever comes from behind must not have to brake harder than the
      // safe-braking limit (nor than comfortably) to keep its time gap to the ego.
      double closing = std::max(0.0, along - ego.speed);
      double braking = std::min(context.comfortable_acceleration, settings.rear_braking);
      double behind_room = reach + settings.time_gap * along + closing * closing / (2 * braking);
      if (-ahead < behind_room) return false;
    } else {
      if (ahead < reach + settings.time_gap * ego.speed) return false;
      // Something slow in the passing lane within the pass would only be caught up with there.
      if (along < cluster.speed + settings.slower_by && ahead < timing.travel + reach) return false;
    }
  }
  return true;
}

// Calls `visit` on each lane the driver may pass in, in the order they are tried, until it
// returns true.
template <typename Visit>
void visit_candidates(const Lane& lane, bool standing, Visit visit) {
  for (LaneIndex next : lane.left_forward_neighbours)
    if (visit(Candidate{next, false, lane.left_boundary_type})) return;
  // Passing on the right only round something standing (a parked or broken-down car).
  if (standing)
    for (LaneIndex next : lane.right_forward_neighbours)
      if (visit(Candidate{next, false, lane.right_boundary_type})) return;
  for (LaneIndex next : lane.left_reverse_neighbours)
    if (visit(Candidate{next, true, lane.left_boundary_type})) return;
}

// What a pass in any of the lanes beside depends on: plan_overtake's findings.
struct PassSetup {
  const OvertakeContext& context;
  std::span<const Blocker> blockers;
  const OvertakingSettings& settings;
  Cluster cluster;
  double gap = 0;         // m from the ego's front to the first blocker's rear
  LaneIndex lane = 0;     // the route's lane at the ego
  bool crawling = false;  // the cluster is no faster than walking pace
};

void start_back(OvertakePlan& plan, double s, double speed, const OvertakingSettings& settings) {
  plan.back_from = planned_lateral(plan, s);
  plan.back_begin = s;
  plan.back_end = s + std::max(settings.shortest_move,
                               speed * std::abs(plan.back_from) / settings.lateral_speed);
}

// Whether the pull-out `plan` clears the standing blocker `first` by the sweep margin
// (pull_out_sweep.hpp). At walking pace a tight pull-out (full lock) is weighed against the usual
// aim and the one with more room kept: whichever is chosen, it is the one that was checked, and
// not one that clears only by the luck of this step's perception noise. Far behind the blocker
// the check is not needed: the pull-out is over long before the ego gets there.
bool sweep_clears(const OvertakeContext& context, OvertakePlan& plan, const Blocker& first,
                  const OvertakingSettings& settings) {
  if (first.rear_s - plan.out_end > context.vehicle.length) return true;
  double usual = pull_out_clearance(context, plan, first, settings.sweep_margin);
  if (context.ego.speed < kWalkingPace) {
    OvertakePlan tight = plan;
    tight.pull_out_lookahead = settings.tight_lookahead;
    double room = pull_out_clearance(context, tight, first, settings.sweep_margin);
    if (room > usual) {
      plan = tight;
      usual = room;
    }
  }
  return usual >= settings.sweep_margin;
}

// The move out's length (m of travel) and the shortest it may be: at the usual sideways speed,
// quicker when the room to the blocker (what the ego travels before it reaches the blocker's
// rear) asks for it.
struct MoveOut {
  double length = 0;
  double shortest = 0;
};

MoveOut move_out(const PassSetup& setup, double offset) {
  const KinematicState& ego = setup.context.ego;
  const OvertakingSettings& settings = setup.settings;
  const double gap = setup.gap;
  double closing = ego.speed - setup.cluster.speed;
  double room = closing > 0.1 ? gap * ego.speed / closing : kInfinity;
  if (ego.speed < 0.1) room = gap;
  double usual =
      std::max(settings.shortest_move, ego.speed * std::abs(offset) / settings.lateral_speed);
  double quickest = std::max(settings.shortest_move,
                             ego.speed * std::abs(offset) / settings.fastest_lateral_speed);
  double length = std::min(usual, 0.9 * room);
  double shortest = quickest;
  bool at_walking_pace = ego.speed < kWalkingPace;
  if (length < quickest && at_walking_pace && setup.crawling) {
    // The swept-path check (sweep_clears) decides whether the pull-out is possible; where the
    // smoothstep's bend bound doubts it, the tight pull-out may still clear.
    std::optional<double> pull_out = standing_pull_out(room, offset, setup.context.vehicle);
    length = pull_out ? std::min(*pull_out, usual) : length;
    shortest = length;
  }
  return {length, shortest};
}

// The pass of the cluster in `candidate`'s lane, if the road, the traffic and the room ahead
// allow it now; `waiting` is set when only the traffic or the room keeps it from starting.
std::optional<OvertakePlan> try_pass(const PassSetup& setup, const Candidate& candidate,
                                     bool& waiting) {
  const OvertakeContext& context = setup.context;
  const OvertakingSettings& settings = setup.settings;
  const Cluster& cluster = setup.cluster;
  const double progress = context.route.progress();
  const double gap = setup.gap;
  if (!may_cross(candidate.boundary, cluster.speed, settings)) return std::nullopt;
  auto offset = lane_offset(context, candidate.lane, progress);
  if (!offset) return std::nullopt;
  PassTiming timing = pass_timing(context, gap, cluster, *offset, settings);
  if (!timing.possible) return std::nullopt;
  double end = progress + timing.travel;
  if (!route_allows(context, setup.lane, progress, end)) return std::nullopt;
  if (!room_to_stop_after(context, cluster, context.route.length() - end, settings))
    return std::nullopt;
  auto offset_at_end = lane_offset(context, candidate.lane, end);
  if (!offset_at_end || std::abs(*offset_at_end - *offset) > kLaneTolerance) return std::nullopt;

  const MoveOut out = move_out(setup, *offset);
  const std::span<const Blocker> passed = setup.blockers.first(cluster.count);
  auto ignored = [&](ActorId id) {
    return std::any_of(passed.begin(), passed.end(),
                       [&](const Blocker& b) { return b.object->id == id; });
  };
  if (out.length < out.shortest ||
      !passing_lane_clear(context, candidate, cluster, timing, settings, ignored)) {
    waiting = true;
    return std::nullopt;
  }
  OvertakePlan plan;
  plan.active = true;
  plan.oncoming = candidate.oncoming;
  plan.lane = candidate.lane;
  plan.offset = *offset;
  plan.out_begin = progress;
  plan.out_end = progress + out.length;
  for (const Blocker& b : passed)
    plan.passing.push_back({b.object->id, b.rear_s, b.front_s, b.speed});
  // A blocker crawling at walking pace is swept as if standing where it is: it only moves away
  // during the pull-out, so the check errs on the safe side (a 0.6 m/s car was clipped unchecked).
  if (setup.crawling && !sweep_clears(context, plan, passed.front(), settings)) {
    waiting = true;
    return std::nullopt;
  }
  return plan;
}

}  // namespace

double planned_lateral(const OvertakePlan& plan, double s) {
  if (!plan.active) return 0;
  if (s >= plan.back_begin) {
    double span = std::max(plan.back_end - plan.back_begin, 1e-6);
    return plan.back_from * (1 - smoothstep((s - plan.back_begin) / span));
  }
  double span = std::max(plan.out_end - plan.out_begin, 1e-6);
  return plan.offset * smoothstep((s - plan.out_begin) / span);
}

std::optional<OvertakePlan> plan_overtake(const OvertakeContext& context,
                                          std::span<const Blocker> blockers,
                                          const OvertakingSettings& settings, bool& waiting) {
  waiting = false;
  if (!settings.enabled || blockers.empty() || context.route.empty()) return std::nullopt;
  const Blocker& first = blockers[0];
  double desired = context.desired_speed;
  double slow_below = std::min(desired - settings.slower_by, settings.slower_fraction * desired);
  if (first.speed >= slow_below) return std::nullopt;
  const KinematicState& ego = context.ego;
  double progress = context.route.progress();
  double front = progress + context.vehicle.length / 2;
  double gap = first.rear_s - front;
  if (gap > std::max(30.0, ego.speed * 4)) return std::nullopt;  // decide when closer
  Cluster cluster = cluster_of(blockers, context.vehicle, slow_below, settings);
  if (cluster.front_s - cluster.rear_s > settings.longest_cluster) return std::nullopt;
  auto here = context.route.lane_at(progress);
  if (!here) return std::nullopt;
  const PassSetup setup{
      context, blockers, settings, cluster, gap, here->lane, cluster.speed < kWalkingPace};
  std::optional<OvertakePlan> plan;
  visit_candidates(context.map.lane(here->lane), cluster.speed < kStationary,
                   [&](const Candidate& candidate) {
                     plan = try_pass(setup, candidate, waiting);
                     return plan.has_value();
                   });
  return plan;
}

void update_overtake(OvertakePlan& plan, const OvertakeContext& context,
                     std::span<const Blocker> slow_ahead, const OvertakingSettings& settings) {
  if (!plan.active) return;
  const RouteTracker& route = context.route;
  double progress = route.progress();
  if (progress >= plan.back_end) {
    plan = OvertakePlan{};
    return;
  }
  // What the ego knows of the objects it passes: refreshed when seen, else moved on.
  for (OvertakePlan::Passed& passed : plan.passing) {
    auto seen = std::find_if(slow_ahead.begin(), slow_ahead.end(),
                             [&](const Blocker& b) { return b.object->id == passed.id; });
    if (seen != slow_ahead.end()) {
      passed.rear_s = seen->rear_s;
      passed.front_s = seen->front_s;
      passed.speed = seen->speed;
    } else {
      passed.rear_s += passed.speed * context.dt;
      passed.front_s += passed.speed * context.dt;
    }
  }
  if (plan.back_begin < kInfinity) return;  // on the way back

  double front = progress + context.vehicle.length / 2;
  double rear = progress - context.vehicle.length / 2;
  double first_rear = kInfinity, last_front = -kInfinity, slowest = kInfinity;
  for (const OvertakePlan::Passed& passed : plan.passing) {
    first_rear = std::min(first_rear, passed.rear_s);
    last_front = std::max(last_front, passed.front_s);
    slowest = std::min(slowest, passed.speed);
  }
  // Still mostly in its own lane on the way out (or, into the oncoming lane, not yet level): if
  // the passing lane no longer leaves room, give up and go back.
  bool mostly_in_own_lane = progress < plan.out_end &&
                            std::abs(planned_lateral(plan, progress)) < std::abs(plan.offset) / 2;
  if ((plan.oncoming && front < first_rear) || (!plan.oncoming && mostly_in_own_lane)) {
    Cluster cluster{first_rear, last_front, slowest, plan.passing.size()};
    PassTiming timing = pass_timing(context, first_rear - front, cluster, plan.offset, settings);
    auto ignored = [&](ActorId id) {
      return std::any_of(plan.passing.begin(), plan.passing.end(),
                         [&](const auto& passed) { return passed.id == id; });
    };
    Candidate lane{plan.lane, plan.oncoming, BoundaryType::unknown};
    if (!timing.possible ||
        !passing_lane_clear(context, lane, cluster, timing, settings, ignored)) {
      // Hardly out yet, there is no way back to drive: a move back planned from a standstill
      // behind the blocker would wait for progress the blocker forbids, indicating for ever.
      if (std::abs(planned_lateral(plan, progress)) < kHardlyOut)
        plan = OvertakePlan{};
      else
        start_back(plan, progress, context.ego.speed, settings);
      return;
    }
  }
  // Slow objects in the original lane just past the passed ones are passed too.
  double back_length = std::max(settings.shortest_move,
                                context.ego.speed * std::abs(plan.offset) / settings.lateral_speed);
  for (const Blocker& b : slow_ahead) {
    bool known = std::any_of(plan.passing.begin(), plan.passing.end(),
                             [&](const auto& passed) { return passed.id == b.object->id; });
    if (known || b.rear_s < front) continue;
    bool in_the_way = b.rear_s - front < back_length + return_room(context.vehicle, 0, settings);
    if (in_the_way && b.speed < context.ego.speed - 1.0)
      plan.passing.push_back({b.object->id, b.rear_s, b.front_s, b.speed});
    else if (in_the_way && b.rear_s - front < back_length)
      return;  // too close to move back in front of yet
  }
  // Indicate back first, then move back: the indicator comes on the return notice before the
  // ego will be far enough past (at its speed now), and the move back waits for the notice
  // (except in the oncoming lane, whose clear stretch was reckoned without a wait).
  auto passed_within = [&](double notice) {
    return std::all_of(plan.passing.begin(), plan.passing.end(), [&](const auto& p) {
      double closing = std::max(0.0, context.ego.speed - p.speed);
      return rear + closing * notice - p.front_s >=
             settings.gap_ahead + settings.time_gap * p.speed;
    });
  };
  if (plan.back_indicating_since < 0 && passed_within(settings.return_notice))
    plan.back_indicating_since = context.time;
  if (!passed_within(0)) return;
  if (plan.oncoming || context.time - plan.back_indicating_since >= settings.return_notice - 1e-9)
    start_back(plan, progress, context.ego.speed, settings);
}

}  // namespace scenfuzz

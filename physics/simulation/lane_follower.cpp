// The reactive lane follower: each step, every reason to slow down (a bend, whatever is in the
// path ahead, a stop line, a crosswalk, the path's end) is an IDM constraint, the most cautious
// wins, and the result is held to the class's acceleration and jerk limits before it moves the
// actor along its path.
#include "physics/simulation/lane_follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lang/demand.hpp"
#include "physics/actors/path_pose.hpp"
#include "physics/ego/priority_traffic.hpp"
#include "physics/map/lane_conflicts.hpp"
#include "physics/map/lane_queries.hpp"
#include "physics/map/nearest_on_path.hpp"
#include "physics/map/polygon.hpp"
#include "physics/map/segment_walk.hpp"
#include "physics/simulation/bend_envelope.hpp"
#include "physics/simulation/predicted_points.hpp"
#include "physics/simulation/route_place.hpp"

namespace scenfuzz {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kStandingSpeed = 0.2;       // m/s: standing, for a stop sign
constexpr double kStandingDesire = 0.05;     // m/s: a desired speed below this parks the actor
constexpr double kStopSignReach = 3;         // m before the line that count as at it
constexpr double kMovingSpeed = 1.0;         // m/s: crossing traffic slower than this waits too
constexpr double kMinimumGap = 0.1;          // m, keeps IDM's interaction term finite
constexpr std::size_t kFeatureLimit = 4096;  // stop lines looked up along one route
// s between looks ahead (what to stop behind); IDM answers for what was seen at every step.
constexpr double kLookInterval = 0.1;
constexpr double kScanInterval = 0.2;    // s between looks at every actor (see find_leader)
constexpr double kSpeedBoundMargin = 2;  // m/s above its desired speed it is never driven
constexpr double kPreparedChunk = 100;   // m of path prepared beyond a step's lookahead
// m of route behind the follower whose lanes are watched: a lane change's sideways move
// (route_path, 30 m) runs on past where the route enters the new lane, so the lane left may
// still be under the follower's path.
constexpr double kWatchedBehind = 35;
// m of route beyond the lookahead whose lanes are watched: an actor filed on the next lane can
// have its point within reach of the watched path's end.
constexpr double kWatchedBeyond = 15;
// m a leader's lane position may lie beyond the ends of its route segment's stretch of lane and
// still count as on it (the lane tracker's s runs on a little past a lane's ends at joints).
constexpr double kLaneLeadTolerance = 0.5;
// m the gap found at a scan may differ from the leader's route distance ahead: half lengths and
// the path's smoothing of lane changes. More means it is not where the route meets its lane
// (a route through the same lane twice), and it is followed by geometry.
constexpr double kLaneLeadMismatch = 20;

double fourth_power(double x) {
  double squared = x * x;
  return squared * squared;
}

}  // namespace

LaneFollower::LaneFollower(const RoadMap& map, const LaneRoute& route, const Polyline& path,
                           std::span<const PathPlace> places, const ActorClass& body,
                           double desired_speed, double initial_speed, bool leaves_at_end,
                           const FollowerSettings& settings)
    : map_(&map),
      route_(&route),
      path_(&path),
      places_(places),
      body_(body),
      desired_speed_(std::min(desired_speed, body.max_speed)),
      leaves_at_end_(leaves_at_end),
      settings_(settings),
      root_ab_(std::sqrt(std::min(settings.acceleration, body.max_acceleration) *
                         body.comfortable_deceleration)) {
  SCENFUZZ_DEMAND(path_->segment_count() > 0);
  SCENFUZZ_DEMAND(places_.empty() || places_.size() == path_->points().size());
  headings_ = lazy_headings(*path_);
  blends_.resize(path_->points().size());
  frames_.reserve(path_->segment_count());
  double lateral = body_.comfortable_lateral_acceleration > 0
                       ? body_.comfortable_lateral_acceleration
                       : body_.max_deceleration;
  // IDM keeps it at its desired speed or below, overshooting by the jerk limit's little; should
  // it ever be faster than the bound, prepare_ahead raises it.
  const double bound =
      std::min(body_.max_speed, std::max(desired_speed_, initial_speed) + kSpeedBoundMargin);
  envelope_ = BendEnvelope(*path_, lateral, body_.comfortable_deceleration, bound);
  double distance = 0;
  for (const RouteSegment& segment : route_->segments) {
    route_starts_.push_back(distance);
    distance += segment.s_end - segment.s_begin;
  }
  for (double from = 0; features_.size() < kFeatureLimit;) {
    auto next = next_feature_ahead(map, *route_, from);
    if (!next) break;
    features_.push_back({*next, from + next->distance, false});
    from += next->distance + 0.01;
  }
  // A start faster than the bends ahead allow is the nearest feasible one: as fast as they do.
  prepare_ahead();
  double speed = std::min({initial_speed, body_.max_speed, envelope_.at(0)});
  make_headings_known();
  state_ = state_on_path(*path_, headings_.values, 0, speed, 0);
  state_.yaw_rate = 0;
}

void LaneFollower::start_at(double progress) {
  SCENFUZZ_DEMAND(std::isfinite(progress) && progress >= 0 && progress <= path_->length());
  s_ = progress;
  // No faster than the bends ahead can be taken from: a car placed in a bend drives it as one
  // that came to it would.
  segment_ = path_->segment_at(s_);
  prepare_ahead();
  const double limit = envelope_.at(std::min(segment_ + 1, path_->points().size() - 1));
  make_headings_known();
  state_ = state_on_path(*path_, headings_.values, s_, std::min(state_.speed, limit), 0);
  state_.yaw_rate = 0;
}

// Between two points of the path, its lane position by how far along the segment it is: the
// points were drawn from the centre lines at those lane positions, every metre or so, so this is
// the projection onto the centre line up to far less than a millimetre (rounded corners move a
// point a little aside, not along).
std::optional<LaneFix> LaneFollower::lane_fix() const {
  if (places_.empty()) return std::nullopt;
  const PathPlace& from = places_[segment_];
  const PathPlace& to = places_[segment_ + 1];
  if (!from.on_lane || !to.on_lane) return std::nullopt;
  const auto& arc = path_->arc_lengths();
  const double fraction = (s_ - arc[segment_]) / (arc[segment_ + 1] - arc[segment_]);
  const RouteSegment& on = route_->segments[from.segment];
  if (to.segment == from.segment)
    return LaneFix{static_cast<std::int32_t>(on.lane), from.s + fraction * (to.s - from.s)};
  // Over a successor link: as far on the next lane as it is past the end of this one.
  if (to.segment != from.segment + 1) return std::nullopt;
  const RouteSegment& next = route_->segments[to.segment];
  const std::vector<LaneIndex>& successors = map_->lane(on.lane).successors;
  if (std::find(successors.begin(), successors.end(), next.lane) == successors.end())
    return std::nullopt;  // a lane change with no room for a sideways move: a jump aside
  const double along = fraction * ((on.s_end - from.s) + (to.s - next.s_begin));
  if (from.s + along <= on.s_end)
    return LaneFix{static_cast<std::int32_t>(on.lane), from.s + along};
  return LaneFix{static_cast<std::int32_t>(next.lane), next.s_begin + (from.s + along - on.s_end)};
}

void LaneFollower::decide(const WorldSnapshot& world, std::uint32_t self, double dt) {
  if (finished_) return;
  prepare_ahead();
  if (world.time + 1e-9 >= next_look_) {
    next_look_ = world.time + kLookInterval;
    look_ahead(world, self, std::max(dt, kLookInterval));
  }
  decided_ = choose_acceleration(world.time);
}

// The cosine and sine of its heading, for the look (surely_not_in_path, lane_lead): the
// simulation's (PointPredictor::facing, the same numbers, shared with whoever else asks this
// step), or its own when the world has none.
void LaneFollower::update_facing(const WorldSnapshot& world, std::uint32_t self) {
  if (state_.heading == facing_heading_) return;
  facing_heading_ = state_.heading;
  facing_ = world.predictions != nullptr && world.states[self].heading == state_.heading
                ? world.predictions->facing(self)
                : MapPoint{std::cos(state_.heading), std::sin(state_.heading)};
}

// What to stop behind, as far as it can see now: whatever is in its path, stop lines, the
// junction ahead, the path's end.
void LaneFollower::look_ahead(const WorldSnapshot& world, std::uint32_t self, double dt) {
  looked_at_ = world.time;
  looked_from_ = s_;
  stops_.clear();
  if (desired_speed_ < kStandingDesire) return;
  update_facing(world, self);
  find_leader(world, self, stops_);
  find_stop_lines(world, self, dt, stops_);
  hold_at_junction(world, self, stops_);
  if (!leaves_at_end_) {
    // Written in place: a Stop built on the stack and copied stalls the copy's wide loads on
    // its narrow stores (store forwarding fails).
    Stop& end = stops_.emplace_back();
    end.gap = path_->length() - s_;
    end.reason = FollowerReason::path_end;
  }
}

// The most cautious of IDM's answers: for the free road, the bend ahead and each stop found at the
// last look, its gap moved on by how far this follower has driven since and how far the stop
// moves at its speed (at the look itself, the gap as found).
double LaneFollower::choose_acceleration(double now) {
  const double v = state_.speed;
  if (desired_speed_ < kStandingDesire) {
    reason_ = FollowerReason::cruise;
    return v > 0 ? -body_.comfortable_deceleration : 0;
  }
  const double a = std::min(settings_.acceleration, body_.max_acceleration);
  const double free_road = 1 - fourth_power(v / desired_speed_);
  double best = a * free_road;
  reason_ = FollowerReason::cruise;
  double bend = bend_acceleration();
  if (bend < best) {
    best = bend;
    reason_ = FollowerReason::bend;
  }
  // IDM behind each stop: the free road's term less the interaction term (computed here, once a
  // step for every stop, rather than in a call per stop).
  const double driven = s_ - looked_from_, elapsed = now - looked_at_;
  const double headway = v * settings_.time_gap, braking = 2 * root_ab_;
  for (const Stop& stop : stops_) {
    const double gap = std::max(stop.gap - driven + stop.speed * elapsed, kMinimumGap);
    const double desired_gap = stop.clearance + headway + v * (v - stop.speed) / braking;
    const double ratio = std::max(desired_gap, 0.0) / gap;
    const double wanted = a * (free_road - ratio * ratio);
    if (wanted < best) {
      best = wanted;
      reason_ = stop.reason;
    }
  }
  return best;
}

double LaneFollower::bend_acceleration() const {
  std::size_t next = std::min(segment_ + 1, path_->points().size() - 1);
  double limit = envelope_.at(next);
  double v = state_.speed;
  if (!(v > limit)) return kInfinity;
  double to_vertex = std::max(path_->arc_lengths()[next] - s_, 0.5);
  return (limit * limit - v * v) / (2 * to_vertex);
}

bool LaneFollower::surely_not_in_path(const WorldSnapshot& world, std::uint32_t k) const {
  const double lookahead = this->lookahead();
  const KinematicState& other = world.states[k];
  const double dx = other.x - state_.x, dy = other.y - state_.y;
  const double reach_k = lookahead + world.lengths[k];
  if (dx * dx + dy * dy > reach_k * reach_k) return true;
  // Behind this actor's front it is in nobody's way ahead (paths do not turn back within the
  // lookahead), wherever it moves in the next seconds.
  const double ahead = dx * facing_.x + dy * facing_.y;
  const double tau = other.speed > kPredictedMinSpeed ? settings_.prediction_time : 0;
  return ahead < -(world.lengths[k] + other.speed * tau);
}

// Whatever is in the path ahead, now or (moving) within the prediction time: the nearest is the
// leader. Every actor is looked at every scan interval, as a driver's glance goes round; between
// scans only the leader is followed (its gap and speed every step), along the lanes when it can be
// (lane_lead), else by searching the path as the scan did.
void LaneFollower::find_leader(const WorldSnapshot& world, std::uint32_t self,
                               std::vector<Stop>& stops) {
  scanning_ = world.time + 1e-9 >= next_scan_;
  if (scanning_) {
    next_scan_ = world.time + kScanInterval;
    leader_ = -1;
    double best_gap = kInfinity;
    std::optional<Stop> best;
    auto look_at = [&](std::uint32_t k) {
      if (k == self || !present_in(world, k) || surely_not_in_path(world, k)) return;
      auto stop = in_path(world, k);
      if (stop && stop->gap < best_gap) {
        best_gap = stop->gap;
        best = stop;
        leader_ = static_cast<std::int64_t>(k);
      }
    };
    // In ascending order either way, so that of equal gaps the same actor leads.
    if (on_lanes_ahead(world, candidates_) || near_path(world, candidates_)) {
      for (std::uint32_t k : candidates_) look_at(k);
    } else {
      for (std::uint32_t k = 0; k < world.states.size(); ++k) look_at(k);
    }
    // The leader as the scan found it (in_path would answer the same again).
    lane_lead_.reset();
    if (best) {
      stops.push_back(*best);
      start_lane_lead(world, *best);
    }
    return;
  }
  if (leader_ < 0 || !present_in(world, static_cast<std::uint32_t>(leader_))) return;
  if (lane_lead_) {
    if (auto stop = lane_lead(world)) {
      stops.push_back(*stop);
      return;
    }
    lane_lead_.reset();
  }
  if (auto stop = in_path(world, static_cast<std::uint32_t>(leader_))) stops.push_back(*stop);
}

// What a step reads of the path's boxes, frames and envelope (this step's lookahead, the next
// vertex) made, a chunk at a time: the rest of a path laid for the whole scenario may never be
// driven in a run. Most steps only compare (prepare_ahead, inline).
void LaneFollower::prepare_further() {
  if (state_.speed > envelope_.speed_bound())
    envelope_.raise_bound(*path_, headings_, std::max(body_.max_speed, state_.speed));
  const double until = s_ + lookahead();
  if (until > prepared_until_) {
    prepared_until_ = until + kPreparedChunk;
    constexpr std::size_t unit = PolylineBoxes::kRun * PolylineBoxes::kGroup;
    const std::size_t last = path_->segment_at(std::min(prepared_until_, path_->length()));
    if (prepared_until_ >= path_->length()) prepared_until_ = kInfinity;  // the whole path
    const std::size_t segments = std::min(path_->segment_count(), (last / unit + 1) * unit);
    boxes_.extend(*path_, segments);
    frames_.extend(*path_, segments);
    envelope_.extend(*path_, headings_, last + 1);
  }
  envelope_.extend(*path_, headings_, segment_ + 1);
}

// A vehicle (or the ego) found by where it is, on a lane of the route ahead: between scans its gap
// moves with its lane position, as in traffic simulators, which costs no search of the path. Not
// a pedestrian or obstacle (off the lanes' order), nor an actor found where it will be (crossing
// or oncoming: standing there, it has no lane position to follow).
void LaneFollower::start_lane_lead(const WorldSnapshot& world, const Stop& stop) {
  const auto k = static_cast<std::uint32_t>(leader_);
  if (stop.predicted || route_starts_.empty()) return;
  if (world.kinds[k] != TraceActorKind::vehicle && world.kinds[k] != TraceActorKind::ego) return;
  // From the segment before this follower's: in a lane change it may still be beside the lane
  // it leaves, and so may its leader.
  const auto after = std::upper_bound(route_starts_.begin(), route_starts_.end(), s_);
  const auto mine =
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - route_starts_.begin() - 2, 0));
  auto place = place_on_route(*route_, route_starts_, world.lanes[k], mine,
                              s_ + lookahead() + kWatchedBeyond, kLaneLeadTolerance);
  if (!place) return;
  const double offset = stop.gap - (place->distance - s_);
  if (!(std::abs(offset) <= kLaneLeadMismatch)) return;
  lane_lead_ = LaneLead{place->segment, offset};
}

std::optional<LaneFollower::Stop> LaneFollower::lane_lead(const WorldSnapshot& world) {
  const auto k = static_cast<std::uint32_t>(leader_);
  const double until = s_ + lookahead() + kWatchedBeyond;
  auto place = place_on_route(*route_, route_starts_, world.lanes[k], lane_lead_->segment, until,
                              kLaneLeadTolerance);
  if (!place) return std::nullopt;
  lane_lead_->segment = place->segment;
  const double gap = place->distance - s_ + lane_lead_->offset;
  // Passed, or gone beyond what a scan would watch: in_path judges.
  if (gap < -world.lengths[k] / 2 || gap > lookahead()) return std::nullopt;
  const KinematicState& other = world.states[k];
  // The cosine of the heading difference, as in_path's, from the step's cosines and sines.
  double alignment = 0;
  if (world.predictions != nullptr) {
    const MapPoint theirs = world.predictions->facing(k);
    alignment = facing_.x * theirs.x + facing_.y * theirs.y;
  } else {
    alignment = std::cos(angle_difference(other.heading, state_.heading));
  }
  const double speed_along = std::max(0.0, longitudinal_velocity(other) * alignment);
  return Stop{gap, settings_.standstill_gap, speed_along, FollowerReason::leader, false};
}

// The actors on the lanes this follower's path runs over from a little behind it to beyond what
// it watches, or on the lanes of the junctions it passes there (among them those crossing or
// merging with its own), and every loose actor (the world's LaneOccupancy): what a driver
// keeping to its lanes has to look at. False when the world has no occupancy.
bool LaneFollower::on_lanes_ahead(const WorldSnapshot& world, std::vector<std::uint32_t>& actors) {
  if (world.occupancy == nullptr || route_starts_.empty()) return false;
  const double lookahead = this->lookahead();
  watch_lanes(s_ - kWatchedBehind, s_ + lookahead + kWatchedBeyond);
  world.occupancy->gather(watched_, actors);
  return true;
}

void LaneFollower::watch_lanes(double from, double to) {
  // The route segments ending after `from` and beginning before `to` (at least one).
  const auto begins = route_starts_.begin(), ends = route_starts_.end();
  const auto first_after = std::upper_bound(begins, ends, from);
  const std::size_t first =
      first_after == begins ? 0 : static_cast<std::size_t>(first_after - begins) - 1;
  const auto before_to = static_cast<std::size_t>(std::lower_bound(begins, ends, to) - begins);
  const std::size_t last = before_to == 0 ? first : std::max(first, before_to - 1);
  if (first == watched_first_ && last == watched_last_) return;
  watched_first_ = first;
  watched_last_ = last;
  watched_.clear();
  for (std::size_t k = first; k <= last && k < route_->segments.size(); ++k) {
    const LaneIndex lane = route_->segments[k].lane;
    watched_.push_back(lane);
    // Every lane of its junction: more than those crossing or merging with it (junction_conflicts),
    // whose centre lines cost far more to test than the few actors more to look at.
    if (auto junction = map_->lane(lane).junction) {
      const std::vector<LaneIndex>& lanes = map_->junctions()[*junction].lanes;
      watched_.insert(watched_.end(), lanes.begin(), lanes.end());
    }
  }
  std::sort(watched_.begin(), watched_.end());
  watched_.erase(std::unique(watched_.begin(), watched_.end()), watched_.end());
}

// The actors that in_path could find in the path ahead, from the world's grid: those with a point
// within reach of the boxes of the path it watches (in_path looks no farther). False when the
// world has no grid, or predicts for another horizon than this follower (then every actor is
// looked at).
bool LaneFollower::near_path(const WorldSnapshot& world, std::vector<std::uint32_t>& actors) const {
  if (world.grid == nullptr || world.predictions == nullptr ||
      world.prediction_time != settings_.prediction_time)
    return false;
  const double until = s_ + lookahead();
  // in_path's boxes run from the one holding this actor's segment to the last starting by
  // `until`; every point of them is at most `along` metres of path, so as many in a straight
  // line, from this actor, which is on the path at s_.
  const auto& arc = path_->arc_lengths();
  constexpr std::size_t run = PolylineBoxes::kRun;
  std::size_t last = segment_ / run;
  while (last + 1 < boxes_.size() && arc[(last + 1) * run] <= until) ++last;
  const double along = std::max(s_ - arc[segment_ / run * run],
                                arc[std::min((last + 1) * run, path_->segment_count())] - s_);
  // Beyond that, the most any actor's reach (in_path's) can be, and a margin far above rounding.
  const double reach =
      along + body_.width / 2 + world.grid->largest_half_extent() + settings_.path_margin + 1e-3;
  const MapPoint at{state_.x, state_.y};
  world.grid->near({at.x - reach, at.y - reach}, {at.x + reach, at.y + reach}, actors);
  return true;
}

// The first segment from this follower's on that can come within `reach` of `point`. The
// follower is on its path at s_, and a path point s' is at most |s' - s_| from it in a straight
// line: a point D away is out of reach of every point nearer than D - reach along the path, so
// the segments that lie wholly there are skipped without looking at their boxes (nearest_on_path
// would find none of them within reach).
std::size_t LaneFollower::first_within(MapPoint point, double reach) const {
  const double dx = point.x - state_.x, dy = point.y - state_.y;
  // Far above the rounding of arc lengths and of the follower's position on its path.
  constexpr double kMargin = 1e-3;
  const double clear = std::sqrt(dx * dx + dy * dy) - reach - kMargin;
  if (!(clear > s_ - path_->arc_lengths()[segment_])) return segment_;
  return first_segment_reaching(*path_, segment_, s_ + clear);
}

// first_within's answer exactly, walking from segment `from` (where the answer was at the last
// look, or the segment nearest then) instead of galloping from this follower's: between looks it
// moves by a few segments. A long walk ends in first_within's search.
std::size_t LaneFollower::first_within_from(MapPoint point, double reach, std::size_t from) const {
  const double dx = point.x - state_.x, dy = point.y - state_.y;
  constexpr double kMargin = 1e-3;  // as first_within's
  const double clear = std::sqrt(dx * dx + dy * dy) - reach - kMargin;
  const auto& arc = path_->arc_lengths();
  if (!(clear > s_ - arc[segment_])) return segment_;
  return first_segment_reaching_from(*path_, segment_, s_ + clear, from);
}

// Whether anything in the path within `reach` of `point` (reaching `extent` along it either way)
// lies at a gap of at least `gap`. The path point found is ahead at s_ + d with d at least the
// point's straight-line distance less the reach (chord <= arc), so the gap in_path computes is at
// least that less half this body's length and the extent (1 mm of margin for rounding).
bool LaneFollower::surely_no_nearer(MapPoint point, double reach, double extent, double gap) const {
  const double dx = point.x - state_.x, dy = point.y - state_.y;
  constexpr double kMargin = 1e-3;
  return std::sqrt(dx * dx + dy * dy) - reach - body_.length / 2 - extent - kMargin >= gap;
}

// Where actor k will be within the prediction time (in_path's second point): the simulation's
// prediction for every follower of the step when it made one for this horizon, else the same
// computed here. Its position when it stands.
MapPoint LaneFollower::predicted_of(const WorldSnapshot& world, std::uint32_t k) const {
  const KinematicState& other = world.states[k];
  if (!(other.speed > kPredictedMinSpeed)) return {other.x, other.y};
  return world.predictions != nullptr && world.prediction_time == settings_.prediction_time
             ? world.predictions->point(k)
             : predicted_point(other, settings_.prediction_time);
}

// Actor k is behind the follower in its lane: where it will be is for it to mind (it must brake),
// not a stop for the follower, which would otherwise brake hard for a faster car closing from
// behind (its point 1.5 s on lies ahead of the follower).
bool LaneFollower::behind_in_lane(const WorldSnapshot& world, std::uint32_t k) const {
  const KinematicState& other = world.states[k];
  const PolylineProjection p = frames_.project(*path_, {other.x, other.y}, segment_);
  return p.s < s_ && std::abs(p.lateral) <= body_.width / 2 + world.widths[k] / 2;
}

// A point ahead of the path's end, within `reach` of the line the last segment runs on: what is
// there stands where this follower stops, or beyond it (a car parked at the next target, its rear
// reaching back over this one's). Its place along the path: the path's length and how far on.
PolylineProjection LaneFollower::beyond_end(MapPoint point, double reach) const {
  PolylineProjection none;
  none.distance = kInfinity;
  const std::size_t last = path_->segment_count() - 1;
  const MapPoint end = path_->points().back();
  const MapPoint u = frames_.direction(last);
  const double px = point.x - end.x, py = point.y - end.y;
  const double along = px * u.x + py * u.y;
  const double lateral = u.x * py - u.y * px;
  if (!(along > 0) || !(std::abs(lateral) <= reach)) return none;
  PolylineProjection beyond;
  beyond.s = path_->length() + along;
  beyond.lateral = lateral;
  beyond.distance = std::abs(lateral);
  beyond.segment = last;
  return beyond;
}

// Actor k as something to stop behind: where it is, or where it will be within the prediction
// time (standing there), whichever is nearer along the path; nullopt when neither is in the path
// ahead. A vehicle coming the other way counts as standing. Between where it is and where it will
// be, points no farther apart than the reach are searched too: a car crossing the path (in a
// junction, both on green) is on one side of it now and on the other 1.5 s on, and would be seen
// by neither end.
std::optional<LaneFollower::Stop> LaneFollower::in_path(const WorldSnapshot& world,
                                                        std::uint32_t k) {
  if (surely_not_in_path(world, k)) return std::nullopt;
  const KinematicState& other = world.states[k];
  const bool moving = other.speed > kPredictedMinSpeed;
  const double tau = moving ? settings_.prediction_time : 0;
  if (hints_.size() < 2 * world.states.size()) {
    hints_.resize(2 * world.states.size(), 0);
    starts_.resize(2 * world.states.size(), 0);
  }
  const double reach =
      body_.width / 2 + world.lengths[k] / 2 + world.widths[k] / 2 + settings_.path_margin;
  const MapPoint here{other.x, other.y};
  // Where it will be: the simulation's prediction for every follower of the step when it made one
  // for this horizon, else the same computed here.
  const bool predicts = tau > 0 && !behind_in_lane(world, k);
  const MapPoint there = predicts ? predicted_of(world, k) : here;
  if (surely_clear_of_path(here, there, reach)) return std::nullopt;
  std::optional<Stop> best = stop_at(world, k, here, Sighting::is, reach, std::nullopt);
  if (!predicts) return best;
  const double way = distance(here, there);
  const int between = may_cross(world, k, way) ? static_cast<int>(std::ceil(way / reach)) - 1 : 0;
  for (int j = 1; j <= between; ++j) {
    const double fraction = static_cast<double>(j) / (between + 1);
    const MapPoint on_the_way{here.x + fraction * (there.x - here.x),
                              here.y + fraction * (there.y - here.y)};
    best = stop_at(world, k, on_the_way, Sighting::on_the_way, reach, best);
  }
  return stop_at(world, k, there, Sighting::will_be, reach, best);
}

// Whether every point from `a` to `b` (where an actor is and where it will be: in_path searches
// there and between) is surely out of `reach` of the path in_path searches, so that none of its
// searches can find anything. Most actors near a path but not in it (on the pavement, crossing
// elsewhere in a junction) are ruled out so at the cost of a few box tests instead of a search per
// point.
bool LaneFollower::surely_clear_of_path(MapPoint a, MapPoint b, double reach) const {
  const double until = s_ + lookahead();
  // Beyond the path's end in_path finds what stands ahead of its last segment (beyond_end).
  if (!leaves_at_end_ && path_->length() <= until) return false;
  return surely_clear_of(*path_, boxes_, a, b, segment_, until, reach);
}

// Whether actor k may cross this follower's path on its next `way` metres: off the lanes, in a
// junction, or about to enter one. On a road's lane it keeps to it, or moves aside slowly (a lane
// change takes seconds): where it is and where it will be then say all there is.
bool LaneFollower::may_cross(const WorldSnapshot& world, std::uint32_t k, double way) const {
  if (world.lanes.size() <= k || world.lanes[k].lane < 0) return true;
  const Lane& lane = map_->lane(static_cast<LaneIndex>(world.lanes[k].lane));
  if (lane.junction) return true;
  if (lane.length() - world.lanes[k].s >= way) return false;
  return std::any_of(lane.successors.begin(), lane.successors.end(),
                     [&](LaneIndex next) { return map_->lane(next).junction.has_value(); });
}

// in_path's search for actor k at `point` (where it is, where it will be, or on its way there;
// standing at either of the last two): the nearer of that stop and `best`.
std::optional<LaneFollower::Stop> LaneFollower::stop_at(const WorldSnapshot& world, std::uint32_t k,
                                                        MapPoint point, Sighting which,
                                                        double reach, std::optional<Stop> best) {
  const KinematicState& other = world.states[k];
  // Where it will be cannot be nearer than where it is when the path is too far along there
  // (most leaders drive on ahead): the search would be rejected by the gap test below.
  if (best && surely_no_nearer(point, reach, (world.lengths[k] + world.widths[k]) / 2, best->gap))
    return best;
  const double until = s_ + lookahead();
  // Where it is and where it will be keep the nearest segment and first_within's answer of the
  // last look as hints (their slots); points on its way are searched afresh.
  std::uint32_t unhinted = 0, unstarted = 0;
  const std::size_t slot =
      2 * std::size_t{k} + static_cast<std::size_t>(which == Sighting::will_be);
  std::uint32_t& hint = which == Sighting::on_the_way ? unhinted : hints_[slot];
  std::uint32_t& start = which == Sighting::on_the_way ? unstarted : starts_[slot];
  double known = kInfinity;
  std::size_t first = 0;
  if (hint > segment_ && path_->arc_lengths()[hint - 1] <= until) {
    // The segment nearest at the last look, as it is: walking on to a nearer neighbour cost
    // more than the tighter bound saved (measured).
    const std::size_t near = hint - 1;
    known = std::sqrt(frames_.distance_squared(*path_, point, near));
    first = first_within_from(point, std::min(reach, known), near);
  } else if (start != 0) {
    first = first_within_from(point, reach, start - 1);
  } else {
    first = first_within(point, reach);
  }
  start = static_cast<std::uint32_t>(first + 1);
  PolylineProjection nearest =
      nearest_on_path(*path_, boxes_, frames_, point, first, until, reach, known);
  if (!std::isfinite(nearest.distance) && !leaves_at_end_ && path_->length() <= until)
    nearest = beyond_end(point, reach);
  hint = std::isfinite(nearest.distance) ? static_cast<std::uint32_t>(nearest.segment + 1) : 0;
  if (!std::isfinite(nearest.distance) || nearest.s <= s_) return best;
  const double half_width = body_.width / 2;
  double relative = angle_difference(other.heading, heading_of(headings_, *path_, nearest.segment));
  double across = std::abs(std::sin(relative)) * world.lengths[k] / 2 +
                  std::abs(std::cos(relative)) * world.widths[k] / 2;
  double along = std::abs(std::cos(relative)) * world.lengths[k] / 2 +
                 std::abs(std::sin(relative)) * world.widths[k] / 2;
  if (std::abs(nearest.lateral) > half_width + across + settings_.path_margin) return best;
  double gap = nearest.s - s_ - body_.length / 2 - along;
  if (gap < -along) return best;  // beside it, not ahead
  if (best && gap >= best->gap) return best;
  double speed_along =
      which != Sighting::is
          ? 0
          : std::max(0.0, longitudinal_velocity(other) *
                              std::cos(angle_difference(other.heading, state_.heading)));
  return Stop{gap, settings_.standstill_gap, speed_along,
              world.kinds[k] == TraceActorKind::pedestrian ? FollowerReason::pedestrian
                                                           : FollowerReason::leader,
              which != Sighting::is};
}

void LaneFollower::find_stop_lines(const WorldSnapshot& world, std::uint32_t self, double dt,
                                   std::vector<Stop>& stops) {
  const double v = state_.speed;
  const double front = s_ + body_.length / 2;
  const double comfortable_stop = v * v / (2 * body_.comfortable_deceleration);
  const double full_stop = v * v / (2 * body_.max_deceleration);
  while (next_feature_ < features_.size() && features_[next_feature_].at - front < -0.5)
    ++next_feature_;  // passed
  for (std::size_t f = next_feature_; f < features_.size(); ++f) {
    Feature& feature = features_[f];
    double gap = feature.at - front;
    if (gap > std::max(settings_.min_lookahead, v * settings_.lookahead_time)) break;
    Stop line{gap, settings_.stop_line_gap, 0, FollowerReason::red_light};
    switch (feature.feature.kind) {
      case FeatureKind::traffic_light: {
        SignalColour colour = feature.feature.index < world.lights.size()
                                  ? world.lights[feature.feature.index]
                                  : SignalColour::green;
        bool stop = colour == SignalColour::red ||
                    (colour == SignalColour::yellow && gap >= comfortable_stop);
        if (stop && gap >= full_stop) stops.push_back(line);
        break;
      }
      case FeatureKind::stop_sign: {
        if (feature.served) break;
        line.reason = FollowerReason::stop_sign;
        if (gap < settings_.stop_line_gap + kStopSignReach && v < kStandingSpeed) {
          if (stopped_since_ < 0) stopped_since_ = world.time;
          if (world.time + dt - stopped_since_ >= settings_.stop_sign_wait &&
              !crossing_traffic(world, self, feature)) {
            feature.served = true;
            stopped_since_ = -1;
            break;
          }
        }
        stops.push_back(line);
        break;
      }
      case FeatureKind::yield_sign:
        if (gap >= full_stop && crossing_traffic(world, self, feature)) {
          line.reason = FollowerReason::give_way;
          stops.push_back(line);
        }
        break;
      case FeatureKind::crosswalk:
        // Looked at once a scan, as the actors are (find_leader).
        if (scanning_)
          feature.occupied =
              world.occupancy != nullptr
                  ? world.occupancy->walkers_at(feature.feature.index, settings_.walking_speed,
                                                settings_.crosswalk_clearance)
                  : pedestrians_at(world, map_->crosswalks()[feature.feature.index]);
        if (gap >= full_stop && feature.occupied) {
          line.reason = FollowerReason::pedestrian;
          stops.push_back(line);
        }
        break;
    }
  }
}

std::optional<LaneIndex> LaneFollower::junction_lane_after(const FeatureAhead& feature) const {
  if (map_->lane(feature.lane).junction) return feature.lane;
  for (std::size_t k = 0; k + 1 < route_->segments.size(); ++k)
    if (route_->segments[k].lane == feature.lane) {
      LaneIndex next = route_->segments[k + 1].lane;
      if (map_->lane(next).junction) return next;
    }
  return std::nullopt;
}

// Whether a vehicle is on a lane that crosses or merges with the junction lane behind the stop
// line, or will be there within the give-way time.
bool LaneFollower::crossing_traffic(const WorldSnapshot& world, std::uint32_t self,
                                    const Feature& feature) {
  auto junction_lane = junction_lane_after(feature.feature);
  if (!junction_lane) return false;
  const std::vector<LaneIndex>& conflicts = map_->junction_conflicts(*junction_lane);
  for (std::uint32_t k = 0; k < world.states.size(); ++k) {
    if (k == self || world.lanes[k].lane < 0 || !present_in(world, k)) continue;
    if (world.kinds[k] == TraceActorKind::pedestrian || world.kinds[k] == TraceActorKind::obstacle)
      continue;
    const auto lane = static_cast<LaneIndex>(world.lanes[k].lane);
    const double speed = world.states[k].speed;
    if (std::find(conflicts.begin(), conflicts.end(), lane) != conflicts.end() &&
        meets_soon(*junction_lane, lane, world.lanes[k].s, world.lengths[k], speed))
      return true;
    if (speed < kMovingSpeed) continue;  // waiting at its own line: first come, first served
    double to_end = map_->lane(lane).length() - world.lanes[k].s;
    if (to_end / speed > settings_.give_way_time) continue;
    for (LaneIndex next : map_->lane(lane).successors)
      if (std::find(conflicts.begin(), conflicts.end(), next) != conflicts.end() &&
          meets(*junction_lane, next))
        return true;
  }
  return false;
}

bool LaneFollower::pedestrians_at(const WorldSnapshot& world, const Crosswalk& crosswalk) const {
  for (std::uint32_t k = 0; k < world.states.size(); ++k) {
    if (world.kinds[k] != TraceActorKind::pedestrian || !present_in(world, k)) continue;
    const KinematicState& walker = world.states[k];
    if (walker.speed >= settings_.walking_speed &&
        near_polygon({walker.x, walker.y}, crosswalk.outline, settings_.crosswalk_clearance))
      return true;
  }
  return false;
}

namespace {

// Whether a light or sign orders the traffic entering a junction by `lane` (the junction lane):
// on it or on a lane leading into it.
bool controlled_entry(const RoadMap& map, LaneIndex lane) {
  auto controls = [&](LaneIndex l) {
    for (const LaneFeature& feature : map.lane(l).features)
      if (feature.kind != FeatureKind::crosswalk) return true;
    return false;
  };
  if (controls(lane)) return true;
  for (LaneIndex before : map.lane(lane).predecessors)
    if (controls(before)) return true;
  return false;
}

// Whether lane `lane` ends into one of `conflicts`, and carries no light or sign of its own.
bool uncontrolled_approach_to(const RoadMap& map, LaneIndex lane,
                              const std::vector<LaneIndex>& conflicts) {
  const Lane& approach = map.lane(lane);
  for (const LaneFeature& feature : approach.features)
    if (feature.kind != FeatureKind::crosswalk) return false;
  for (LaneIndex next : approach.successors)
    if (std::find(conflicts.begin(), conflicts.end(), next) != conflicts.end()) return true;
  return false;
}

}  // namespace

// Before a junction it has not entered, the follower stops at the entry while (a) what it
// follows stands or crawls where it would hold the follower inside the junction (do not block the
// box), or (b) it must give way there (gives_way_in_junction). Once inside it has priority over
// everyone still outside, and clears the junction behind whatever is in its path. Standing held
// longer than its patience it goes on (the standstill breaker), still stopping for what is in
// its path. Too near the entry to stop before it, it is committed and drives on.
void LaneFollower::hold_at_junction(const WorldSnapshot& world, std::uint32_t self,
                                    std::vector<Stop>& stops) {
  const double front = s_ + body_.length / 2;
  if (!stretch_known_ || (stretch_ && stretch_->exit <= front)) {
    stretch_ = junction_stretch_ahead(*map_, route_->segments, route_starts_, front);
    stretch_known_ = true;
  }
  const std::optional<JunctionStretch>& stretch = stretch_;
  if (!stretch || stretch->entry <= front || stretch->entry == released_entry_) {
    held_since_ = -1;
    return;
  }
  const double v = state_.speed;
  const double to_entry = stretch->entry - front;
  if (to_entry > lookahead() || to_entry < v * v / (2 * body_.max_deceleration)) return;
  // Who is in or at the junction is looked at once a scan, as the actors are (find_leader).
  if (scanning_) gives_way_ = gives_way_in_junction(world, self, *stretch);
  if (!box_blocked(stops, *stretch, front) && !gives_way_) {
    held_since_ = -1;
    return;
  }
  if (v < kStandingSpeed && held_since_ < 0) held_since_ = world.time;
  if (held_since_ >= 0 && world.time - held_since_ >= settings_.junction_patience) {
    released_entry_ = stretch->entry;
    held_since_ = -1;
    return;
  }
  stops.push_back({to_entry, settings_.stop_line_gap, 0, FollowerReason::give_way});
}

// Whatever the follower stops behind (a leader, a crossing actor where it will be) is slow and so
// near that the follower, standing behind it, would not have cleared the junction's exit.
bool LaneFollower::box_blocked(const std::vector<Stop>& stops, const JunctionStretch& stretch,
                               double front) const {
  for (const Stop& stop : stops) {
    if (stop.reason != FollowerReason::leader) continue;
    const double standing_front = front + stop.gap - stop.clearance;
    if (stop.speed < kMovingSpeed && standing_front < stretch.exit + body_.length) return true;
  }
  return false;
}

// A vehicle (or the ego) on a junction lane crossing or merging with the follower's is inside
// and has priority. At a junction no light or sign orders, one that arrived at it first
// (JunctionArrivals; of equal arrivals the lower actor id) and is about to enter a crossing or
// merging lane from an approach without light or sign goes first too; the ego, arrived there,
// always does.
bool LaneFollower::gives_way_in_junction(const WorldSnapshot& world, std::uint32_t self,
                                         const JunctionStretch& stretch) {
  const bool arrivals = world.junction_arrivals.size() == world.states.size() &&
                        !std::isnan(world.junction_arrivals[self]);
  for (std::size_t segment = stretch.first; segment <= stretch.last; ++segment) {
    const LaneIndex mine = route_->segments[segment].lane;
    const std::vector<LaneIndex>& conflicts = map_->junction_conflicts(mine);
    const bool first_come = arrivals && !controlled_entry(*map_, mine);
    for (std::uint32_t k = 0; k < world.states.size(); ++k) {
      if (k == self || world.lanes[k].lane < 0 || !present_in(world, k)) continue;
      if (world.kinds[k] != TraceActorKind::vehicle && world.kinds[k] != TraceActorKind::ego)
        continue;
      const auto lane = static_cast<LaneIndex>(world.lanes[k].lane);
      if (std::find(conflicts.begin(), conflicts.end(), lane) != conflicts.end() &&
          meets_soon(mine, lane, world.lanes[k].s, world.lengths[k], world.states[k].speed))
        return true;
      if (!first_come || map_->lane(lane).junction || std::isnan(world.junction_arrivals[k]))
        continue;
      const double theirs = world.junction_arrivals[k], ours = world.junction_arrivals[self];
      // The ego under test sees no arrival times: it goes when nobody crossing is inside, and
      // the NPCs let it, whenever it arrived.
      const bool before =
          world.kinds[k] == TraceActorKind::ego || theirs < ours || (theirs == ours && k < self);
      if (before && uncontrolled_approach_to(*map_, lane, conflicts)) return true;
    }
  }
  return false;
}

bool LaneFollower::meets(LaneIndex mine, LaneIndex other) const {
  const std::vector<ConflictPoint>& points = map_->junction_conflict_points(mine);
  return std::any_of(points.begin(), points.end(),
                     [&](const ConflictPoint& point) { return point.lane == other; });
}

bool LaneFollower::meets_soon(LaneIndex mine, LaneIndex other, double s, double length,
                              double speed) const {
  if (!meets(mine, other)) return false;
  if (!runs_into_itself(*map_, other)) return true;
  return short_of_conflict(*map_, map_->junction_conflict_points(mine), other, s, length,
                           length + std::abs(speed) * settings_.give_way_time);
}

void LaneFollower::make_headings_known() {
  constexpr std::size_t kHeadingRun = 16;  // segments ahead whose headings are computed at once
  headed_until_ = segment_ + 2 + kHeadingRun;
  ensure_headings(headings_, *path_, segment_ > 0 ? segment_ - 1 : 0, headed_until_ - 1);
  const std::size_t last = std::min(headed_until_ - 1, path_->segment_count() - 1);
  for (std::size_t vertex = std::max<std::size_t>(segment_, 1); vertex <= last; ++vertex)
    blends_[vertex] = vertex_blend(*path_, headings_.values, vertex);
}

void LaneFollower::advance(double acceleration, double dt) {
  const double jerk = body_.max_jerk * dt;
  acceleration = std::clamp(acceleration, applied_ - jerk, applied_ + jerk);
  acceleration = std::clamp(acceleration, -body_.max_deceleration, body_.max_acceleration);
  const double v = state_.speed;
  double next = std::clamp(v + acceleration * dt, 0.0, body_.max_speed);
  double moved = 0.5 * (v + next) * dt;
  if (acceleration < 0 && next == 0) moved = v * v / (2 * -acceleration);
  const double heading = state_.heading;
  s_ += moved;
  if (s_ >= path_->length()) {
    s_ = path_->length();
    if (leaves_at_end_) finished_ = true;
    if (!leaves_at_end_) next = 0;
  }
  segment_ = segment_at_from(*path_, s_, segment_);
  // The pose reads the headings of segment_ and its neighbours (the blends at its ends).
  if (segment_ + 1 >= headed_until_) make_headings_known();
  const MapPose pose = pose_on_segment(*path_, headings_.values, blends_, segment_, s_);
  state_ = KinematicState{};
  state_.x = pose.position.x;
  state_.y = pose.position.y;
  state_.heading = pose.heading;
  state_.speed = next;
  state_.acceleration = (next - v) / dt;
  state_.yaw_rate = step_yaw_rate(heading, state_.heading, dt);
  // At a standstill the brakes hold without effort: no braking is carried into setting off.
  applied_ = next == 0 && acceleration < 0 ? 0 : acceleration;
}

}  // namespace scenfuzz

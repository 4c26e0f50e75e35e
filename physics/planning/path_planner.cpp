// Car-like paths through waypoints: per leg OMPL's analytic Dubins / Reeds-Shepp curve, and, only
// when that curve touches a static obstacle, RRTConnect in the same state space. The only file
// that includes OMPL.
//
// Determinism: OMPL hands out the seeds of default-constructed RNGs in the order threads ask for
// them, so nothing random here comes from such an RNG. The planner's state sampler owns a
// generator seeded from the request's seed and the leg; nearest-neighbour search is an exact
// linear scan (GNAT picks random pivots); shortcuts are greedy instead of OMPL's randomised
// simplifier. The planner stops at its first exact solution or after a fixed iteration count, so
// a plan found before the request's time limit (a safety net against slow validity checks) is
// the same on every machine and thread.
#include "physics/planning/path_planner.hpp"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace scenfuzz {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

using SE2State = ob::SE2StateSpace::StateType;

// Validity is checked at poses at most this far apart along every curve (the contract is 0.25 m).
constexpr double kCheckStep = 0.2;
// Poses one leg may produce before the request is refused as degenerate (1000 km at 1 m).
constexpr double kMaxPosesPerLeg = 1e6;
// Sampling-planner iterations (tree extensions plus connection attempts) per leg. Around a disc a
// leg needs a handful, through a 2 m gap in a wall a median of about 100 and at most about 2300
// in 40 seeds. A leg that needs more is reported unplannable even if time is left, so that
// failures, too, mostly do not depend on machine speed.
constexpr unsigned kMaxPlannerIterations = 5000;
// Poses closer than this along a leg are one pose (e.g. a cusp that falls on a spacing step).
constexpr double kSameArcLength = 1e-6;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string leg_name(std::size_t leg) {
  return "leg " + std::to_string(leg + 1) + " (waypoint " + std::to_string(leg + 1) + " -> " +
         std::to_string(leg + 2) + ")";
}

std::string waypoint_name(std::size_t index, const MapPose& pose) {
  return "waypoint " + std::to_string(index + 1) + " at (" + number(pose.position.x) + ", " +
         number(pose.position.y) + ")";
}

// Headings outside [-pi, pi] are wrapped; headings inside are returned untouched so that the
// waypoints come back exactly as given.
double wrapped_heading(double heading) {
  if (heading >= -std::numbers::pi && heading <= std::numbers::pi) return heading;
  return std::remainder(heading, 2 * std::numbers::pi);
}

MapPose pose_of(const ob::State* state) {
  const auto* se2 = state->as<SE2State>();
  return MapPose{{se2->getX(), se2->getY()}, se2->getYaw()};
}

void set_pose(ob::State* state, const MapPose& pose) {
  auto* se2 = state->as<SE2State>();
  se2->setXY(pose.position.x, pose.position.y);
  se2->setYaw(wrapped_heading(pose.heading));
}

// OMPL 1.5's Dubins solver snaps an arc angle within 5e-7 rad of a full turn to 0 and then
// asserts on the error that makes, which grows with the leg's length: a long, nearly straight leg
// whose headings lie a hair off its chord aborts the whole process (a search found one: a
// bicycle's 208 m leg 4.7e-5 m off straight). Headings that close to the chord are made exactly
// the chord's direction as OMPL computes it, a turn of at most 1e-5 rad.
void align_with_chord(MapPose& from, MapPose& to) {
  const double chord = std::atan2(to.position.y - from.position.y, to.position.x - from.position.x);
  for (MapPose* pose : {&from, &to})
    if (std::abs(std::remainder(pose->heading - chord, 2 * std::numbers::pi)) < 1e-5)
      pose->heading = chord;
}

// The state space of one request: Dubins when the vehicle only drives forwards, Reeds-Shepp when
// it may also reverse. Both measure distance as curve length in metres.
struct CarSpace {
  ob::StateSpacePtr space;
  const ob::DubinsStateSpace* dubins = nullptr;
  const ob::ReedsSheppStateSpace* reeds_shepp = nullptr;
  double turning_radius = 0;
};

CarSpace make_car_space(double turning_radius, bool reversing_allowed) {
  CarSpace car;
  car.turning_radius = turning_radius;
  if (reversing_allowed) {
    auto space = std::make_shared<ob::ReedsSheppStateSpace>(turning_radius);
    car.reeds_shepp = space.get();
    car.space = space;
  } else {
    auto space = std::make_shared<ob::DubinsStateSpace>(turning_radius);
    car.dubins = space.get();
    car.space = space;
  }
  return car;
}

// A stretch of a curve driven in one direction.
struct Stretch {
  double length = 0;
  std::int8_t direction = 1;
};

// The shortest car-like curve between two states, computed once and then sampled by arc length.
class Curve {
 public:
  Curve(const CarSpace& car, const ob::State* from, const ob::State* to)
      : car_(&car), from_(car.space, from), to_(car.space, to) {
    if (car.dubins != nullptr) {
      auto path = car.dubins->dubins(from, to);
      length_ = car.turning_radius * path.length();
      stretches_.push_back({length_, 1});
      path_ = path;
    } else {
      auto path = car.reeds_shepp->reedsShepp(from, to);
      length_ = car.turning_radius * path.length();
      for (int i = 0; i < 5 && path.type_[i] != ob::ReedsSheppStateSpace::RS_NOP; ++i) {
        const double signed_length = car.turning_radius * path.length_[i];
        if (signed_length == 0) continue;
        const std::int8_t direction = signed_length > 0 ? 1 : -1;
        if (!stretches_.empty() && stretches_.back().direction == direction) {
          stretches_.back().length += std::abs(signed_length);
        } else {
          stretches_.push_back({std::abs(signed_length), direction});
        }
      }
      if (stretches_.empty()) stretches_.push_back({0, 1});
      path_ = path;
    }
  }

  double length() const { return length_; }
  const ob::State* from() const { return from_.get(); }
  const ob::State* to() const { return to_.get(); }
  const std::vector<Stretch>& stretches() const { return stretches_; }

  void state_at(double arc_length, ob::State* out) const {
    const double t = length_ > 0 ? std::clamp(arc_length / length_, 0.0, 1.0) : 0.0;
    bool first_time = false;  // the path is already computed: interpolate along it
    if (const auto* dubins_path = std::get_if<ob::DubinsStateSpace::DubinsPath>(&path_)) {
      auto path = *dubins_path;
      car_->dubins->interpolate(from_.get(), to_.get(), t, first_time, path, out);
    } else {
      auto path = std::get<ob::ReedsSheppStateSpace::ReedsSheppPath>(path_);
      car_->reeds_shepp->interpolate(from_.get(), to_.get(), t, first_time, path, out);
    }
  }

  // Whether every pose at most kCheckStep apart along the curve, beyond its start, is valid.
  bool is_valid(const ob::SpaceInformation& space_information, ob::State* scratch,
                double* last_valid_fraction = nullptr) const {
    const auto steps = static_cast<unsigned>(std::ceil(length_ / kCheckStep));
    for (unsigned i = 1; i <= steps; ++i) {
      state_at(length_ * i / steps, scratch);
      if (!space_information.isValid(scratch)) {
        if (last_valid_fraction != nullptr) *last_valid_fraction = double(i - 1) / steps;
        return false;
      }
    }
    return true;
  }

 private:
  const CarSpace* car_;
  ob::ScopedState<> from_;
  ob::ScopedState<> to_;
  std::variant<ob::DubinsStateSpace::DubinsPath, ob::ReedsSheppStateSpace::ReedsSheppPath> path_;
  double length_ = 0;
  std::vector<Stretch> stretches_;
};

// Checks a motion along the same curve the path will follow, at most kCheckStep apart (OMPL's
// discrete validators space their checks by a fraction of the space's extent instead).
class DenseCurveValidator : public ob::MotionValidator {
 public:
  DenseCurveValidator(ob::SpaceInformation* space_information, const CarSpace& car)
      : ob::MotionValidator(space_information), car_(car) {}

  bool checkMotion(const ob::State* from, const ob::State* to) const override {
    ob::ScopedState<> scratch(car_.space);
    const bool valid = Curve(car_, from, to).is_valid(*si_, scratch.get());
    ++(valid ? valid_ : invalid_);
    return valid;
  }

  bool checkMotion(const ob::State* from, const ob::State* to,
                   std::pair<ob::State*, double>& last_valid) const override {
    ob::ScopedState<> scratch(car_.space);
    const Curve curve(car_, from, to);
    double fraction = 1;
    const bool valid = curve.is_valid(*si_, scratch.get(), &fraction);
    if (!valid) {
      last_valid.second = fraction;
      if (last_valid.first != nullptr) curve.state_at(fraction * curve.length(), last_valid.first);
    }
    ++(valid ? valid_ : invalid_);
    return valid;
  }

 private:
  const CarSpace& car_;
};

struct Box {
  double min_x, min_y, max_x, max_y;
};

// Uniform poses in a box, from a generator of its own, so that a plan depends only on its seed.
class SeededPoseSampler : public ob::StateSampler {
 public:
  SeededPoseSampler(const ob::StateSpace* space, std::uint_fast32_t seed, Box box)
      : ob::StateSampler(space), box_(box) {
    rng_.setLocalSeed(seed);
  }

  void sampleUniform(ob::State* state) override {
    set(state, rng_.uniformReal(box_.min_x, box_.max_x), rng_.uniformReal(box_.min_y, box_.max_y),
        rng_.uniformReal(-std::numbers::pi, std::numbers::pi));
  }

  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    const MapPose centre = pose_of(near);
    set(state, centre.position.x + rng_.uniformReal(-distance, distance),
        centre.position.y + rng_.uniformReal(-distance, distance),
        centre.heading + rng_.uniformReal(-distance, distance));
  }

  void sampleGaussian(ob::State* state, const ob::State* mean, double standard_deviation) override {
    const MapPose centre = pose_of(mean);
    set(state, rng_.gaussian(centre.position.x, standard_deviation),
        rng_.gaussian(centre.position.y, standard_deviation),
        rng_.gaussian(centre.heading, standard_deviation));
  }

 private:
  void set(ob::State* state, double x, double y, double heading) const {
    set_pose(state,
             MapPose{{std::clamp(x, box_.min_x, box_.max_x), std::clamp(y, box_.min_y, box_.max_y)},
                     heading});
  }

  Box box_;
};

// Exact nearest neighbour by linear scan, skipping elements whose straight-line distance (a lower
// bound of any Dubins or Reeds-Shepp curve length) already exceeds the best so far. Ties go to
// the element added first, so the result never depends on anything random.
template <typename Motion>
class PrunedLinearNearest : public ompl::NearestNeighborsLinear<Motion> {
 public:
  Motion nearest(const Motion& query) const override {
    const auto& motions = this->data_;
    if (motions.empty()) throw ompl::Exception("nearest neighbour of an empty tree");
    const MapPoint target = pose_of(query->state).position;
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < motions.size(); ++i) {
      if (distance(pose_of(motions[i]->state).position, target) > best_distance) continue;
      const double curve_length = this->distFun_(motions[i], query);
      if (curve_length < best_distance) {
        best = i;
        best_distance = curve_length;
      }
    }
    return motions[best];
  }
};

std::uint_fast32_t leg_seed(std::uint64_t seed, std::size_t leg) {
  // splitmix64, so that neighbouring seeds and legs get unrelated sample sequences
  std::uint64_t mixed = seed + 0x9e3779b97f4a7c15ull * (leg + 1);
  mixed = (mixed ^ (mixed >> 30)) * 0xbf58476d1ce4e5b9ull;
  mixed = (mixed ^ (mixed >> 27)) * 0x94d049bb133111ebull;
  mixed ^= mixed >> 31;
  return static_cast<std::uint32_t>(mixed ^ (mixed >> 32));
}

// From each kept state, the farthest later state that its curve reaches validly; the result is
// never longer, because no curve is longer than a detour. Nothing when some kept state reaches no
// later state at all (only possible for states the planner did not connect itself).
std::optional<std::vector<ob::ScopedState<>>> shortcut(const std::vector<ob::ScopedState<>>& states,
                                                       const ob::MotionValidator& validator) {
  std::vector<ob::ScopedState<>> kept{states.front()};
  std::size_t current = 0;
  while (current + 1 < states.size()) {
    std::size_t next = states.size() - 1;
    while (next > current && !validator.checkMotion(states[current].get(), states[next].get())) {
      --next;
    }
    if (next == current) return std::nullopt;
    kept.push_back(states[next]);
    current = next;
  }
  return kept;
}

// The path with states added at most a turning radius apart along its curves, so that a shortcut
// may also end part-way along a curve.
std::vector<ob::ScopedState<>> densified(const CarSpace& car,
                                         const std::vector<ob::ScopedState<>>& states) {
  std::vector<ob::ScopedState<>> dense{states.front()};
  for (std::size_t i = 0; i + 1 < states.size(); ++i) {
    const Curve curve(car, states[i].get(), states[i + 1].get());
    const auto steps = static_cast<unsigned>(std::ceil(curve.length() / car.turning_radius));
    for (unsigned k = 1; k < steps; ++k) {
      dense.emplace_back(car.space);
      curve.state_at(curve.length() * k / steps, dense.back().get());
    }
    dense.push_back(states[i + 1]);
  }
  return dense;
}

// The planner's path, shortened by greedy shortcuts (deterministic, unlike OMPL's randomised
// simplifier): first between its own states, then between states along its curves.
std::vector<ob::ScopedState<>> shortened(const CarSpace& car, std::vector<ob::ScopedState<>> states,
                                         const ob::MotionValidator& validator) {
  if (auto direct = shortcut(states, validator)) states = std::move(*direct);
  if (auto along = shortcut(densified(car, states), validator)) states = std::move(*along);
  return states;
}

// A leg's curves from RRTConnect around the obstacles.
std::vector<Curve> plan_around_obstacles(const CarSpace& car, const PathRequest& request,
                                         std::size_t leg, const ob::State* from,
                                         const ob::State* to) {
  const MapPose start = pose_of(from);
  const MapPose goal = pose_of(to);
  const double margin = 4 * request.turning_radius + 30;
  const Box box{std::min(start.position.x, goal.position.x) - margin,
                std::min(start.position.y, goal.position.y) - margin,
                std::max(start.position.x, goal.position.x) + margin,
                std::max(start.position.y, goal.position.y) + margin};
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, box.min_x);
  bounds.setLow(1, box.min_y);
  bounds.setHigh(0, box.max_x);
  bounds.setHigh(1, box.max_y);
  car.space->as<ob::SE2StateSpace>()->setBounds(bounds);
  const std::uint_fast32_t seed = leg_seed(request.seed, request.first_leg + leg);
  car.space->setStateSamplerAllocator([seed, box](const ob::StateSpace* space) {
    return std::make_shared<SeededPoseSampler>(space, seed, box);
  });

  auto space_information = std::make_shared<ob::SpaceInformation>(car.space);
  space_information->setStateValidityChecker(
      [&request](const ob::State* state) { return request.is_free(pose_of(state)); });
  auto validator = std::make_shared<DenseCurveValidator>(space_information.get(), car);
  space_information->setMotionValidator(validator);
  space_information->setup();

  auto problem = std::make_shared<ob::ProblemDefinition>(space_information);
  problem->setStartAndGoalStates(from, to);
  og::RRTConnect planner(space_information);
  planner.setProblemDefinition(problem);
  planner.setNearestNeighbors<PrunedLinearNearest>();  // also sets the planner up

  unsigned iterations = 0;
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(request.time_limit));
  const ob::PlannerTerminationCondition stop([&] {
    return ++iterations > kMaxPlannerIterations || std::chrono::steady_clock::now() > deadline;
  });
  const ob::PlannerStatus status = planner.solve(stop);
  if (status != ob::PlannerStatus::EXACT_SOLUTION) {
    const std::string limit = iterations > kMaxPlannerIterations
                                  ? std::to_string(kMaxPlannerIterations) + " planner iterations"
                                  : "the time limit of " + number(request.time_limit) + " s";
    throw PlanningError(leg_name(request.first_leg + leg) +
                        ": no path around the static obstacles found within " + limit);
  }

  std::vector<ob::ScopedState<>> states;
  for (const ob::State* state : problem->getSolutionPath()->as<og::PathGeometric>()->getStates()) {
    states.emplace_back(car.space, state);
  }
  states = shortened(car, std::move(states), *validator);
  std::vector<Curve> curves;
  for (std::size_t i = 0; i + 1 < states.size(); ++i) {
    curves.emplace_back(car, states[i].get(), states[i + 1].get());
  }
  return curves;
}

// Whether the curve is free between its ends (which are waypoints, checked already), at poses at
// most kCheckStep apart.
bool curve_is_free(const Curve& curve, const PathRequest& request, ob::State* scratch) {
  const auto steps = static_cast<unsigned>(std::ceil(curve.length() / kCheckStep));
  for (unsigned i = 1; i < steps; ++i) {
    curve.state_at(curve.length() * i / steps, scratch);
    if (!request.is_free(pose_of(scratch))) return false;
  }
  return true;
}

struct LegSamples {
  std::vector<MapPose> poses;
  std::vector<double> s;  // from the leg's start
  std::vector<std::int8_t> direction;
};

// The direction of the motion leaving arc length `at` of a curve (arriving, at its end).
std::int8_t direction_at(const Curve& curve, double at) {
  double stretch_end = 0;
  for (const Stretch& stretch : curve.stretches()) {
    stretch_end += stretch.length;
    if (stretch_end > at + kSameArcLength) return stretch.direction;
  }
  return curve.stretches().back().direction;
}

// Poses evenly between the leg's start, its cusps (where the direction of motion flips) and its
// end, at most `spacing` metres apart. Even, so that no sliver of a segment is left before a cusp
// or the end: a path's heading turns through a vertex over half its shorter segment
// (path_pose.hpp), and a sliver would turn it in one step, tighter than any vehicle can.
LegSamples sample_leg(const std::vector<Curve>& curves, double spacing, const MapPose& end,
                      ob::State* scratch) {
  std::vector<double> curve_start{0};
  for (const Curve& curve : curves) curve_start.push_back(curve_start.back() + curve.length());
  const double length = curve_start.back();

  std::vector<double> breaks{0};
  std::int8_t previous_direction = direction_at(curves.front(), 0);
  for (std::size_t c = 0; c < curves.size(); ++c) {
    double stretch_start = curve_start[c];
    for (const Stretch& stretch : curves[c].stretches()) {
      if (stretch.direction != previous_direction) breaks.push_back(stretch_start);
      previous_direction = stretch.direction;
      stretch_start += stretch.length;
    }
  }
  breaks.push_back(length);
  std::vector<double> at;
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    const double from = breaks[piece], piece_length = breaks[piece + 1] - from;
    const double steps = std::max(1.0, std::ceil(piece_length / spacing - kSameArcLength));
    for (double k = 0; k < steps; ++k) at.push_back(from + piece_length * k / steps);
  }
  at.push_back(length);

  LegSamples samples;
  for (double arc_length : at) {
    if (!samples.s.empty() && arc_length - samples.s.back() < kSameArcLength) continue;
    const auto after = std::upper_bound(curve_start.begin(), curve_start.end() - 1, arc_length);
    const auto c = static_cast<std::size_t>(
        std::max<std::ptrdiff_t>(0, std::distance(curve_start.begin(), after) - 1));
    const double local = std::min(arc_length - curve_start[c], curves[c].length());
    curves[c].state_at(local, scratch);
    samples.poses.push_back(pose_of(scratch));
    samples.s.push_back(arc_length);
    samples.direction.push_back(direction_at(curves[c], local));
  }
  if (samples.poses.size() > 1) samples.poses.back() = end;
  return samples;
}

void check_request(const PathRequest& request) {
  if (request.waypoints.size() < 2) {
    throw PlanningError("a path needs at least two waypoints, got " +
                        std::to_string(request.waypoints.size()));
  }
  for (std::size_t i = 0; i < request.waypoints.size(); ++i) {
    const MapPose& waypoint = request.waypoints[i];
    if (!std::isfinite(waypoint.position.x) || !std::isfinite(waypoint.position.y) ||
        !std::isfinite(waypoint.heading)) {
      throw PlanningError("waypoint " + std::to_string(request.first_leg + i + 1) +
                          " has a non-finite position or heading");
    }
  }
  if (!(request.turning_radius > 0) || !std::isfinite(request.turning_radius)) {
    throw PlanningError("the turning radius must be positive and finite, got " +
                        number(request.turning_radius) + " m");
  }
  if (!(request.spacing > 0) || !std::isfinite(request.spacing)) {
    throw PlanningError("the pose spacing must be positive and finite, got " +
                        number(request.spacing) + " m");
  }
  if (!(request.time_limit > 0) || !std::isfinite(request.time_limit)) {
    throw PlanningError("the planning time limit must be positive and finite, got " +
                        number(request.time_limit) + " s");
  }
  if (request.is_free) {
    for (std::size_t i = 0; i < request.waypoints.size(); ++i) {
      if (!request.is_free(request.waypoints[i])) {
        throw PlanningError(waypoint_name(request.first_leg + i, request.waypoints[i]) +
                            " lies inside a static obstacle");
      }
    }
  }
}

// OMPL reports progress on stdout at its default level; only its warnings and errors belong in
// scenfuzz's output.
void quieten_ompl() {
  static const bool quiet = [] {
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    return true;
  }();
  (void)quiet;
}

}  // namespace

PlannedPath plan_path(const PathRequest& request) {
  check_request(request);
  quieten_ompl();

  PlannedPath path;
  path.poses.push_back(request.waypoints.front());
  path.poses.front().heading = wrapped_heading(path.poses.front().heading);
  path.s.push_back(0);
  path.direction.push_back(1);
  path.waypoint_at.push_back(0);

  for (std::size_t leg = 0; leg + 1 < request.waypoints.size(); ++leg) {
    // A space per leg: the sampling planner gives it the leg's bounds and seeded sampler.
    const CarSpace car = make_car_space(request.turning_radius, request.reversing_allowed);
    ob::ScopedState<> from(car.space);
    ob::ScopedState<> to(car.space);
    ob::ScopedState<> scratch(car.space);
    MapPose leg_start = request.waypoints[leg], leg_end = request.waypoints[leg + 1];
    align_with_chord(leg_start, leg_end);
    set_pose(from.get(), leg_start);
    set_pose(to.get(), leg_end);
    MapPose end = request.waypoints[leg + 1];
    end.heading = wrapped_heading(end.heading);

    std::vector<Curve> curves{Curve(car, from.get(), to.get())};
    if (request.is_free && !curve_is_free(curves.front(), request, scratch.get())) {
      curves = plan_around_obstacles(car, request, leg, from.get(), to.get());
      ++path.sampled_legs;
    }
    double length = 0;
    for (const Curve& curve : curves) length += curve.length();
    if (length / request.spacing > kMaxPosesPerLeg) {
      throw PlanningError(leg_name(request.first_leg + leg) + ": the path is " + number(length) +
                          " m long, over " + number(kMaxPosesPerLeg) + " poses at a spacing of " +
                          number(request.spacing) + " m");
    }

    const LegSamples samples = sample_leg(curves, request.spacing, end, scratch.get());
    // The shared waypoint leaves in this leg's direction.
    path.direction.back() = samples.direction.front();
    for (std::size_t i = 1; i < samples.poses.size(); ++i) {
      path.poses.push_back(samples.poses[i]);
      path.s.push_back(path.length + samples.s[i]);
      path.direction.push_back(samples.direction[i]);
    }
    path.length += samples.s.back();
    path.waypoint_at.push_back(path.poses.size() - 1);
  }
  return path;
}

}  // namespace scenfuzz

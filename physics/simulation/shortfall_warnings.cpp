// Shortfall warnings: naming the script's points and saying what the actor does instead.
#include "physics/simulation/shortfall_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "physics/actors/path_pose.hpp"

namespace scenfuzz {
namespace {

// Speeds and distances to a tenth: the warning says what happens, not every digit of it.
std::string tenths(double value) { return format_number(std::round(value * 10) / 10); }
std::string speed_text(double value) { return tenths(value) + " m/s"; }

const SourceLocation& state_location(const State& state, const SourceLocation& fallback) {
  if (state.speed && state.speed->location.line > 0) return state.speed->location;
  if (state.location.line > 0) return state.location;
  return fallback;
}

// What a braking shortfall slows down for.
std::string ahead_of(const SpeedShortfall& shortfall, std::span<const ScriptPoint> points,
                     double path_length) {
  if (shortfall.other_point && *shortfall.other_point < points.size())
    return points[*shortfall.other_point].other;
  return shortfall.other_s >= path_length - 1e-6 ? "the end of its path" : "a bend";
}

std::string message(const SpeedShortfall& shortfall, const std::string& actor,
                    std::span<const ScriptPoint> points, double path_length) {
  const ScriptPoint& point = points[shortfall.point];
  const std::string distance = tenths(std::abs(shortfall.other_s - shortfall.s)) + " m";
  switch (shortfall.cause) {
    case ShortfallCause::acceleration: {
      std::string before = shortfall.other_point && *shortfall.other_point < points.size()
                               ? points[*shortfall.other_point].other
                               : "the bend before it";
      return actor + " cannot reach " + speed_text(shortfall.wanted) + " at " + point.own + " (" +
             distance + " after " + before + " at " + speed_text(shortfall.other_speed) +
             "): reaches " + speed_text(shortfall.reached);
    }
    case ShortfallCause::braking:
      return actor + " cannot keep " + speed_text(shortfall.wanted) + " at " + point.own +
             ": it has to be at " + speed_text(shortfall.other_speed) + " " + distance +
             " further on (" + ahead_of(shortfall, points, path_length) + "), so it " +
             (shortfall.point == 0 ? "starts at " : "passes there at ") +
             speed_text(shortfall.reached);
    case ShortfallCause::bend:
      return actor + " cannot keep " + speed_text(shortfall.wanted) + " at " + point.own +
             ": the bend there allows " + speed_text(shortfall.reached);
  }
  return {};
}

}  // namespace

ScriptPoint start_point(const Actor& actor) {
  return {"its start", "its start", state_location(actor.initial, actor.location)};
}

std::vector<ScriptPoint> waypoint_points(const Actor& actor, std::span<const State> states,
                                         std::size_t pose_count,
                                         std::span<const std::size_t> point_poses) {
  const SourceLocation& fallback =
      actor.motion.location.line > 0 ? actor.motion.location : actor.location;
  // Every state made a pose unless some coincided with the one before: then name poses.
  const bool one_to_one = pose_count == states.size() + 1;
  std::vector<ScriptPoint> points;
  for (std::size_t pose : point_poses) {
    if (pose == 0) {
      points.push_back(start_point(actor));
      continue;
    }
    if (one_to_one && actor.target && pose == states.size()) {
      points.push_back({"its target", "its target", state_location(states[pose - 1], fallback)});
      continue;
    }
    std::string name = "waypoint " + std::to_string(pose);
    points.push_back(
        {"its " + name, name, one_to_one ? state_location(states[pose - 1], fallback) : fallback});
  }
  return points;
}

void warn_shortfalls(const Trajectory& trajectory, const std::string& actor,
                     std::span<const ScriptPoint> points, Diagnostics& diagnostics) {
  for (const SpeedShortfall& shortfall : trajectory.shortfalls()) {
    SCENFUZZ_DEMAND(shortfall.point < points.size());
    diagnostics.warning(points[shortfall.point].location,
                        message(shortfall, actor, points, trajectory.path().length()));
  }
}

double reactive_start_limit(const Polyline& path, const ActorClass& body) {
  // LaneFollower's bend envelope at the path's start: the lateral limit and braking it uses.
  const double lateral = body.comfortable_lateral_acceleration > 0
                             ? body.comfortable_lateral_acceleration
                             : body.max_deceleration;
  const double braking = body.comfortable_deceleration;
  const std::vector<double> headings = segment_headings(path);
  const std::size_t count = path.points().size();
  double envelope = std::numeric_limits<double>::infinity();
  for (std::size_t i = count; i-- > 0;) {
    const double curvature = vertex_curvature(path, headings, i);
    double cap =
        curvature > 1e-9 ? std::sqrt(lateral / curvature) : std::numeric_limits<double>::infinity();
    if (i + 1 < count) {
      const double ds = path.arc_lengths()[i + 1] - path.arc_lengths()[i];
      cap = std::min(cap, std::sqrt(envelope * envelope + 2 * braking * ds));
    }
    envelope = cap;
  }
  return std::min(envelope, body.max_speed);
}

void warn_reactive_start(const Polyline& path, const ActorClass& body, double initial_speed,
                         const std::string& actor, const ScriptPoint& start,
                         Diagnostics& diagnostics) {
  const double limit = reactive_start_limit(path, body);
  // Rounding is not a shortfall: a tenth of a m/s is what the message shows.
  if (!(initial_speed > limit + 0.05)) return;
  diagnostics.warning(start.location, actor + " cannot start at " + speed_text(initial_speed) +
                                          ": the bends ahead (or its class's top speed) allow " +
                                          speed_text(limit) + ", so it starts at that");
}

}  // namespace scenfuzz

// The built-in `roundabout` map: a single-lane ring `ring_0` round (0, 0), counter-clockwise, and
// four two-way arms with one lane each way. Connectors `<arm>_entry` and `<arm>_exit` join the
// arms to the ring; a yield sign ends every in lane. Rings range from a mini roundabout's (5 m
// radius) to a large one's (100 m).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "physics/map/builtin_geometry.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz::builtin {

namespace {

// Arms end this far outside the ring's centre line unless the entry curve needs more room.
constexpr double kArmGapOutsideRing = 5;
constexpr std::size_t kOutlineCorners = 72;
constexpr const char* kJunctionId = "roundabout";
constexpr const char* kRingId = "ring_0";
// An entry or exit curve is never tighter than a car can drive: the sedan's tightest turning
// circle has a 4.24 m radius (physics/actors/actor_class.cpp).
constexpr double kMinimumEntryRadius = 4.25;
// On a small ring the entries join further round than `entry_angle` says, so that their curves
// stay that wide; but an entry must join before the next arm's exit leaves, 90 degrees minus the
// angle round, with a few degrees of ring left between them.
constexpr double kMaximumEntryAngleDegrees = 42;

struct Arm {
  std::string name;
  double angle = 0;  // of its axis, counter-clockwise from +x
};

struct RoundaboutLayout {
  double ring_radius = 0;
  double entry_angle = 0;  // radians between an arm's axis and where its entry joins the ring
  double lane_width = 0;
  double arm_length = 0;
  double arm_end = 0;  // distance from the centre at which the arm lanes meet the connectors
};

MapPoint axis(const Arm& arm) { return unit_vector(arm.angle); }
MapPoint inbound_right(const Arm& arm) { return right_normal(-1 * axis(arm)); }
MapPoint outbound_right(const Arm& arm) { return right_normal(axis(arm)); }

// The ring's pose at polar angle `angle`: counter-clockwise, so heading a quarter turn ahead.
MapPose ring_pose(const RoundaboutLayout& layout, double angle) {
  return {layout.ring_radius * unit_vector(angle), angle + std::numbers::pi / 2};
}

// From the end of the in lane (on its line, `arm_end` out) into the ring at the entry angle
// after the arm: a straight, then an arc tangent to the ring.
std::vector<MapPoint> entry_centre_line(const RoundaboutLayout& layout, const Arm& arm) {
  MapPoint start = layout.arm_end * axis(arm) + (layout.lane_width / 2) * inbound_right(arm);
  MapPose join = ring_pose(layout, arm.angle + layout.entry_angle);
  LineArcFit fit = fit_line_then_arc(start, arm.angle + std::numbers::pi, join);
  std::vector<MapPoint> points{start};
  append_continuation(points, {start, fit.tangent_point});
  append_continuation(points,
                      arc_between(fit.tangent_point, join.position, fit.centre, fit.turns_left));
  return points;
}

// The mirror image of an entry: fitted backwards from the out lane's start to the ring at the
// entry angle before the arm, then reversed.
std::vector<MapPoint> exit_centre_line(const RoundaboutLayout& layout, const Arm& arm) {
  MapPoint end = layout.arm_end * axis(arm) + (layout.lane_width / 2) * outbound_right(arm);
  MapPose leave = ring_pose(layout, arm.angle - layout.entry_angle);
  MapPose leave_backwards{leave.position, leave.heading + std::numbers::pi};
  LineArcFit fit = fit_line_then_arc(end, arm.angle + std::numbers::pi, leave_backwards);
  std::vector<MapPoint> points{end};
  append_continuation(points, {end, fit.tangent_point});
  append_continuation(points,
                      arc_between(fit.tangent_point, leave.position, fit.centre, fit.turns_left));
  std::reverse(points.begin(), points.end());
  return points;
}

// Where the entry curve begins, measured along the arm's axis; arms must end there or further
// out. Every arm has the same shape, so the east arm stands for all.
double entry_curve_start(const RoundaboutLayout& layout) {
  MapPose join = ring_pose(layout, layout.entry_angle);
  LineArcFit fit =
      fit_line_then_arc({layout.ring_radius, layout.lane_width / 2}, std::numbers::pi, join);
  return fit.tangent_point.x;
}

// The smallest angle after an arm's axis at which an entry can join the ring with a curve of
// kMinimumEntryRadius: from the in lane, half a lane width off the axis, the curve of radius R
// that touches the ring at angle a has R = (r sin a - w / 2) / (1 - sin a); solved for sin a.
double sine_of_smallest_entry_angle(double ring_radius, double lane_width) {
  return (kMinimumEntryRadius + lane_width / 2) / (ring_radius + kMinimumEntryRadius);
}

// `entry_angle` (radians), or further round where the ring is too small for a curve that a car
// can drive at that angle. Throws MapError when even kMaximumEntryAngleDegrees is not enough.
double entry_angle_for(double ring_radius, double lane_width, double entry_angle) {
  const double largest = radians(kMaximumEntryAngleDegrees);
  const double smallest_sine = sine_of_smallest_entry_angle(ring_radius, lane_width);
  if (smallest_sine > std::sin(largest)) {
    const double smallest_ring =
        (kMinimumEntryRadius + lane_width / 2) / std::sin(largest) - kMinimumEntryRadius;
    std::ostringstream message;
    message << "built-in map 'roundabout': ring_radius " << ring_radius
            << " m is too small for lanes " << lane_width << " m wide: entries joining the ring "
            << kMaximumEntryAngleDegrees << " degrees after their arm with curves no tighter than "
            << kMinimumEntryRadius << " m need a ring_radius of at least " << smallest_ring << " m";
    throw MapError(message.str());
  }
  return std::max(entry_angle, std::asin(smallest_sine));
}

}  // namespace

MapDescription generate_roundabout(const MapParameters& parameters) {
  RoundaboutLayout layout;
  layout.ring_radius = parameters.value("ring_radius");
  layout.lane_width = parameters.value("lane_width");
  layout.entry_angle = entry_angle_for(layout.ring_radius, layout.lane_width,
                                       radians(parameters.value("entry_angle")));
  layout.arm_length = parameters.value("arm_length");
  layout.arm_end = std::max(layout.ring_radius + kArmGapOutsideRing, entry_curve_start(layout));
  const double arm_speed_limit = parameters.value("speed_limit");
  const double ring_speed_limit = parameters.value("ring_speed_limit");
  const std::vector<Arm> arms = {{"north", std::numbers::pi / 2},
                                 {"east", 0},
                                 {"south", 3 * std::numbers::pi / 2},
                                 {"west", std::numbers::pi}};

  MapDescription map;
  map.name = "roundabout";
  map.source = "built-in";
  map.default_lane_width = layout.lane_width;
  const double half_lane = layout.lane_width / 2;
  const double far = layout.arm_end + layout.arm_length;

  LaneDescription ring;
  ring.id = kRingId;
  // s = radius * angle from +x: the loop starts and ends at angle 0 and is its own successor.
  const std::size_t ring_segments = arc_segment_count(layout.ring_radius, 2 * std::numbers::pi);
  for (std::size_t i = 0; i < ring_segments; ++i) {
    double angle =
        2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(ring_segments);
    ring.centre_line.push_back(layout.ring_radius * unit_vector(angle));
  }
  ring.centre_line.push_back(ring.centre_line.front());
  ring.left_boundary_type = BoundaryType::curb;  // the central island
  ring.speed_limit = ring_speed_limit;
  ring.junction = kJunctionId;
  ring.successors = {kRingId};
  ring.predecessors = {kRingId};

  std::vector<LaneDescription> connectors;
  for (const Arm& arm : arms) {
    const std::string in_id = arm.name + "_in_0";
    const std::string out_id = arm.name + "_out_0";
    const std::string entry_id = arm.name + "_entry";
    const std::string exit_id = arm.name + "_exit";

    LaneDescription in;
    in.id = in_id;
    in.centre_line = {far * axis(arm) + half_lane * inbound_right(arm),
                      layout.arm_end * axis(arm) + half_lane * inbound_right(arm)};
    in.right_boundary_type = BoundaryType::curb;
    in.left_boundary_type = BoundaryType::solid_yellow;
    in.speed_limit = arm_speed_limit;
    in.left_reverse_neighbours = {out_id};
    in.successors = {entry_id};
    map.lanes.push_back(std::move(in));

    LaneDescription out;
    out.id = out_id;
    out.centre_line = {layout.arm_end * axis(arm) + half_lane * outbound_right(arm),
                       far * axis(arm) + half_lane * outbound_right(arm)};
    out.right_boundary_type = BoundaryType::curb;
    out.left_boundary_type = BoundaryType::solid_yellow;
    out.speed_limit = arm_speed_limit;
    out.left_reverse_neighbours = {in_id};
    out.predecessors = {exit_id};
    map.lanes.push_back(std::move(out));

    // Entries and exits meet ring_0 part-way along it, at s = radius * angle: the one place in
    // the built-in maps where a successor link does not join an end to a start.
    LaneDescription entry;
    entry.id = entry_id;
    entry.centre_line = entry_centre_line(layout, arm);
    entry.turn = LaneTurn::right;
    entry.speed_limit = ring_speed_limit;
    entry.junction = kJunctionId;
    entry.predecessors = {in_id};
    entry.successors = {kRingId};
    ring.predecessors.push_back(entry_id);
    connectors.push_back(std::move(entry));

    LaneDescription exit;
    exit.id = exit_id;
    exit.centre_line = exit_centre_line(layout, arm);
    exit.turn = LaneTurn::right;
    exit.speed_limit = ring_speed_limit;
    exit.junction = kJunctionId;
    exit.predecessors = {kRingId};
    exit.successors = {out_id};
    ring.successors.push_back(exit_id);
    connectors.push_back(std::move(exit));

    SignDescription yield;
    yield.id = "yield_" + arm.name;
    yield.kind = SignKind::yield;
    yield.stop_lines = {{layout.arm_end * axis(arm),
                         layout.arm_end * axis(arm) + layout.lane_width * inbound_right(arm)}};
    yield.lanes = {{in_id, layout.arm_length, layout.arm_length}};
    map.signs.push_back(std::move(yield));
  }
  map.lanes.push_back(std::move(ring));
  for (LaneDescription& connector : connectors) map.lanes.push_back(std::move(connector));

  JunctionDescription junction;
  junction.id = kJunctionId;
  for (std::size_t i = 0; i < kOutlineCorners; ++i)
    junction.outline.push_back(layout.arm_end *
                               unit_vector(2 * std::numbers::pi * static_cast<double>(i) /
                                           static_cast<double>(kOutlineCorners)));
  map.junctions.push_back(std::move(junction));
  return map;
}

}  // namespace scenfuzz::builtin

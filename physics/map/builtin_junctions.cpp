// The built-in `crossroads` and `t_junction` maps: straight arms meeting at a junction centred on
// (0, 0), connector lanes `<from>_<to>_<k>` through it, stop lines 6 m before it, crosswalks 1 to
// 5 m outside it; signals on the crossroads, a stop sign on the T's side road. The main road runs
// west-east; the crossing road (the T's side road) meets it at `angle`, its south arm that far
// counter-clockwise from the west arm. At 90 degrees the junction is a square box.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "physics/map/builtin_geometry.hpp"
#include "physics/map/signal_plans.hpp"

namespace scenfuzz::builtin {

namespace {

constexpr double kPavementWidth = 3;
constexpr double kStopLineBeforeBox = 6;
constexpr double kCrosswalkNearEdge = 1;  // from the junction box
constexpr double kCrosswalkFarEdge = 5;
constexpr const char* kJunctionId = "junction";

struct Arm {
  std::string name;
  MapPoint outward;  // unit vector from the centre along the arm
  double start = 0;  // distance from the centre at which the arm's lanes begin
};

// The unit vector `degrees` counter-clockwise from +x; exact at quarter turns, so that a
// right-angled junction is built from the exact axis vectors, as it always was.
MapPoint direction_at(double degrees) {
  const double quarter_turns = degrees / 90;
  if (quarter_turns != std::round(quarter_turns)) return unit_vector(radians(degrees));
  switch ((static_cast<long>(quarter_turns) % 4 + 4) % 4) {
    case 0: return {1, 0};
    case 1: return {0, 1};
    case 2: return {-1, 0};
    default: return {0, -1};
  }
}

// The other arm of the same straight road. 0 - x rather than -x: an axis vector's zero stays +0,
// so a right-angled junction's coordinates keep their signs.
MapPoint opposite(MapPoint direction) { return {0.0 - direction.x, 0.0 - direction.y}; }

// Right of a car driving towards the centre on this arm, and right of one driving away.
MapPoint inbound_right(const Arm& arm) { return right_normal(-1 * arm.outward); }
MapPoint outbound_right(const Arm& arm) { return right_normal(arm.outward); }

struct JunctionLayout {
  int lanes = 0;  // each way, on every arm
  double lane_width = 0;
  double arm_length = 0;
  double speed_limit = 0;
  // Half the width of a road with its pavements: at a right angle the box reaches this far
  // across the crossing road.
  double half_size() const { return lanes * lane_width + kPavementWidth; }
  double road_half_width() const { return lanes * lane_width; }
  // Lane k's centre line from the arm's axis; k = 0 at the kerb.
  double lane_offset(int k) const { return (lanes - k - 0.5) * lane_width; }
  double stop_line_s() const { return arm_length - kStopLineBeforeBox; }
};

std::string in_lane(const Arm& arm, int k) { return lane_id(arm.name + "_in_", k); }
std::string out_lane(const Arm& arm, int k) { return lane_id(arm.name + "_out_", k); }

MapPoint in_lane_point(const JunctionLayout& layout, const Arm& arm, int k, double distance) {
  return distance * arm.outward + layout.lane_offset(k) * inbound_right(arm);
}
MapPoint out_lane_point(const JunctionLayout& layout, const Arm& arm, int k, double distance) {
  return distance * arm.outward + layout.lane_offset(k) * outbound_right(arm);
}

void add_arm_lanes(MapDescription& map, const JunctionLayout& layout, const Arm& arm) {
  const int n = layout.lanes;
  const double near = arm.start;
  const double far = near + layout.arm_length;
  for (int k = 0; k < n; ++k) {
    LaneDescription in;
    in.id = in_lane(arm, k);
    in.centre_line = {in_lane_point(layout, arm, k, far), in_lane_point(layout, arm, k, near)};
    in.right_boundary_type = right_boundary_of(k);
    in.left_boundary_type = left_boundary_of(k, n, BoundaryType::double_yellow);
    in.speed_limit = layout.speed_limit;
    if (k > 0) in.right_forward_neighbours = {in_lane(arm, k - 1)};
    if (k < n - 1) in.left_forward_neighbours = {in_lane(arm, k + 1)};
    if (k == n - 1) in.left_reverse_neighbours = {out_lane(arm, k)};
    map.lanes.push_back(std::move(in));
  }
  for (int k = n - 1; k >= 0; --k) {
    LaneDescription out;
    out.id = out_lane(arm, k);
    out.centre_line = {out_lane_point(layout, arm, k, near), out_lane_point(layout, arm, k, far)};
    out.right_boundary_type = right_boundary_of(k);
    out.left_boundary_type = left_boundary_of(k, n, BoundaryType::double_yellow);
    out.speed_limit = layout.speed_limit;
    if (k > 0) out.right_forward_neighbours = {out_lane(arm, k - 1)};
    if (k < n - 1) out.left_forward_neighbours = {out_lane(arm, k + 1)};
    if (k == n - 1) out.left_reverse_neighbours = {in_lane(arm, k)};
    map.lanes.push_back(std::move(out));
  }
}

// Opposite arms are one straight road; any other arm is a turn to the side it lies on (at 45
// degrees an arm is as near straight on as the junction allows, so no threshold between).
LaneTurn turn_between(const Arm& from, const Arm& to) {
  if (dot(from.outward, to.outward) < -0.99) return LaneTurn::none;
  return dot(to.outward, inbound_right(from)) > 0 ? LaneTurn::right : LaneTurn::left;
}

// Where the kerb lines (pavements included) of two neighbouring arms cross, as the distance
// along either arm: half_size / tan(theta / 2) for arms theta apart, so the box's half-size at a
// right angle, further out at the acute corner, nearer in at the obtuse one. Symmetric in the two
// arms to the last bit.
double corner_distance(const JunctionLayout& layout, const Arm& a, const Arm& b) {
  return layout.half_size() * (1 + dot(a.outward, b.outward)) /
         std::abs(cross(a.outward, b.outward));
}

// The corner between two neighbouring arms: on `a`'s kerb line on the side where `b` lies.
MapPoint corner_between(const JunctionLayout& layout, const Arm& a, const Arm& b) {
  const MapPoint towards_b =
      cross(a.outward, b.outward) > 0 ? left_normal(a.outward) : right_normal(a.outward);
  return corner_distance(layout, a, b) * a.outward + layout.half_size() * towards_b;
}

// Each arm begins where its whole width, pavements included, has cleared its neighbours' roads:
// at the farther of the kerb corners it shares with them (the acute one), and no nearer than the
// half-size, where every corner lies at a right angle. An opposite arm is the same road. On the
// T's main road the arm at the obtuse corner therefore begins at the half-size, clear of the side
// road, which ends at the main road.
void place_arm_starts(const JunctionLayout& layout, std::vector<Arm>& arms) {
  for (Arm& arm : arms) {
    arm.start = layout.half_size();
    for (const Arm& other : arms)
      if (other.name != arm.name && turn_between(arm, other) != LaneTurn::none)
        arm.start = std::max(arm.start, corner_distance(layout, arm, other));
  }
}

// Which in lanes of `from` get a connector for `turn`: all go straight, the kerb lane turns
// right, the lane beside the centre line turns left. A side road without a straight-on (the T's)
// sends all its lanes but the kerb lane left, so that every lane leads somewhere.
std::vector<int> lanes_turning(LaneTurn turn, int lanes, bool arm_has_straight_on) {
  std::vector<int> turning;
  if (turn == LaneTurn::none) {
    for (int k = 0; k < lanes; ++k) turning.push_back(k);
  } else if (turn == LaneTurn::right) {
    turning.push_back(0);
  } else if (arm_has_straight_on || lanes == 1) {
    turning.push_back(lanes - 1);
  } else {
    for (int k = 1; k < lanes; ++k) turning.push_back(k);
  }
  return turning;
}

// A turn circles the corner between the two arms (right: the corner on the near side; left: the
// one across the crossing road), so that connectors of one turn are concentric and never cross.
// The circle touches the in and the out lane where they pass the corner: at the acute corner
// and at a right angle that is where the arms begin, and the turn is all arc; where the corner
// lies nearer the centre than an arm's start (the obtuse corner), the connector runs straight
// along that arm's lane between the two.
std::vector<MapPoint> turn_centre_line(const JunctionLayout& layout, const Arm& from, const Arm& to,
                                       int k, LaneTurn turn) {
  constexpr double kSamePoint = 1e-9;
  const double h = layout.half_size();
  const double along = corner_distance(layout, from, to);
  const MapPoint centre = turn == LaneTurn::right ? along * from.outward + h * inbound_right(from)
                                                  : along * from.outward - h * inbound_right(from);
  const MapPoint start = in_lane_point(layout, from, k, from.start);
  const MapPoint end = out_lane_point(layout, to, k, to.start);
  const bool straight_in = along < from.start - kSamePoint;
  const bool straight_out = along < to.start - kSamePoint;
  const MapPoint turn_start = straight_in ? in_lane_point(layout, from, k, along) : start;
  const MapPoint turn_end = straight_out ? out_lane_point(layout, to, k, along) : end;
  std::vector<MapPoint> line{start};
  if (straight_in) append_continuation(line, {start, turn_start});
  append_continuation(line, arc_between(turn_start, turn_end, centre, turn == LaneTurn::left));
  if (straight_out) append_continuation(line, {turn_end, end});
  return line;
}

// Straight across the junction, or round the corner it turns about.
void add_connector(MapDescription& map, const JunctionLayout& layout, const Arm& from,
                   const Arm& to, int k) {
  LaneDescription connector;
  connector.id = from.name + "_" + to.name + "_" + std::to_string(k);
  connector.turn = turn_between(from, to);
  if (connector.turn == LaneTurn::none) {
    connector.centre_line = {in_lane_point(layout, from, k, from.start),
                             out_lane_point(layout, to, k, to.start)};
  } else {
    connector.centre_line = turn_centre_line(layout, from, to, k, connector.turn);
  }
  connector.speed_limit = layout.speed_limit;
  connector.junction = kJunctionId;
  connector.predecessors = {in_lane(from, k)};
  connector.successors = {out_lane(to, k)};
  lane_named(map, in_lane(from, k)).successors.push_back(connector.id);
  lane_named(map, out_lane(to, k)).predecessors.push_back(connector.id);
  map.lanes.push_back(std::move(connector));
}

void add_connectors(MapDescription& map, const JunctionLayout& layout, const std::vector<Arm>& arms,
                    const Arm& from) {
  bool has_straight_on = false;
  for (const Arm& to : arms)
    if (to.name != from.name && turn_between(from, to) == LaneTurn::none) has_straight_on = true;
  for (const Arm& to : arms) {
    if (to.name == from.name) continue;
    for (int k : lanes_turning(turn_between(from, to), layout.lanes, has_straight_on))
      add_connector(map, layout, from, to, k);
  }
}

// Across the arm's in lanes, from the kerb to the centre line.
std::vector<MapPoint> stop_line(const JunctionLayout& layout, const Arm& arm) {
  double distance = arm.start + kStopLineBeforeBox;
  return {distance * arm.outward + layout.road_half_width() * inbound_right(arm),
          distance * arm.outward};
}

std::vector<LaneCrossingDescription> in_lanes_at_stop_line(const JunctionLayout& layout,
                                                           const Arm& arm) {
  std::vector<LaneCrossingDescription> crossings;
  for (int k = 0; k < layout.lanes; ++k)
    crossings.push_back({in_lane(arm, k), layout.stop_line_s(), layout.stop_line_s()});
  return crossings;
}

// Across the whole arm, lanes and both pavements.
CrosswalkDescription crosswalk(const JunctionLayout& layout, const Arm& arm) {
  const double near = arm.start + kCrosswalkNearEdge;
  const double far = arm.start + kCrosswalkFarEdge;
  const double half_width = layout.road_half_width() + kPavementWidth;
  const MapPoint across = inbound_right(arm);
  CrosswalkDescription crossing;
  crossing.id = "crosswalk_" + arm.name;
  crossing.outline = counter_clockwise(
      {near * arm.outward - half_width * across, far * arm.outward - half_width * across,
       far * arm.outward + half_width * across, near * arm.outward + half_width * across});
  // s on an in lane counts from its far end, on an out lane from the box.
  for (int k = 0; k < layout.lanes; ++k) {
    crossing.lanes.push_back({in_lane(arm, k), layout.arm_length - kCrosswalkFarEdge,
                              layout.arm_length - kCrosswalkNearEdge});
    crossing.lanes.push_back({out_lane(arm, k), kCrosswalkNearEdge, kCrosswalkFarEdge});
  }
  return crossing;
}

// The corners of an arm's start, pavements included, seen from the centre: first the one on its
// right (clockwise), then the one on its left.
MapPoint arm_start_right(const JunctionLayout& layout, const Arm& arm) {
  return arm.start * arm.outward + layout.half_size() * right_normal(arm.outward);
}
MapPoint arm_start_left(const JunctionLayout& layout, const Arm& arm) {
  return arm.start * arm.outward + layout.half_size() * left_normal(arm.outward);
}

// The outline through `points` (counter-clockwise) without repeated points: at an acute corner
// and at a right angle the kerbs' corner is where both arms begin.
std::vector<MapPoint> outline_without_repeats(const std::vector<MapPoint>& points) {
  constexpr double kSamePoint = 1e-9;
  std::vector<MapPoint> outline;
  for (MapPoint point : points)
    if (outline.empty() || distance(outline.back(), point) > kSamePoint) outline.push_back(point);
  while (outline.size() > 1 && distance(outline.back(), outline.front()) <= kSamePoint)
    outline.pop_back();
  return outline;
}

// The crossing road's direction: its north arm's, `angle` degrees counter-clockwise from east,
// so that the south arm lies `angle` degrees counter-clockwise from the west arm.
MapPoint crossing_direction(const MapParameters& parameters) {
  return direction_at(parameters.value("angle"));
}

JunctionLayout read_layout(const MapParameters& parameters) {
  JunctionLayout layout;
  layout.lanes = parameters.count("lanes");
  layout.lane_width = parameters.value("lane_width");
  layout.arm_length = parameters.value("arm_length");
  layout.speed_limit = parameters.value("speed_limit");
  return layout;
}

MapDescription junction_map(const std::string& name, const JunctionLayout& layout,
                            const std::vector<Arm>& arms) {
  MapDescription map;
  map.name = name;
  map.source = "built-in";
  map.default_lane_width = layout.lane_width;
  for (const Arm& arm : arms) add_arm_lanes(map, layout, arm);
  for (const Arm& from : arms) add_connectors(map, layout, arms, from);
  return map;
}

// The arms named, the main road's along the x axis and the crossing road's turned by `angle`,
// each with its start placed.
std::vector<Arm> junction_arms(const MapParameters& parameters, const JunctionLayout& layout,
                               const std::vector<std::string>& names) {
  const MapPoint crossing = crossing_direction(parameters);
  std::vector<Arm> arms;
  for (const std::string& name : names) {
    if (name == "north") arms.push_back({name, crossing});
    if (name == "east") arms.push_back({name, {1, 0}});
    if (name == "south") arms.push_back({name, opposite(crossing)});
    if (name == "west") arms.push_back({name, {-1, 0}});
  }
  place_arm_starts(layout, arms);
  return arms;
}

const Arm& arm_named(const std::vector<Arm>& arms, const std::string& name) {
  for (const Arm& arm : arms)
    if (arm.name == name) return arm;
  throw std::logic_error("built-in junction map: no arm '" + name + "'");
}

// The junction's outline, counter-clockwise through the arms given in that order: each arm's
// start, then the corner its kerb shares with the next arm's.
std::vector<MapPoint> outline_round(const JunctionLayout& layout,
                                    const std::vector<const Arm*>& counter_clockwise) {
  std::vector<MapPoint> outline;
  for (std::size_t i = 0; i < counter_clockwise.size(); ++i) {
    const Arm& arm = *counter_clockwise[i];
    const Arm& next = *counter_clockwise[(i + 1) % counter_clockwise.size()];
    outline.push_back(arm_start_right(layout, arm));
    outline.push_back(arm_start_left(layout, arm));
    outline.push_back(corner_between(layout, arm, next));
  }
  return outline_without_repeats(outline);
}

// Pedestrians walk while the traffic alongside them has green.
SignalPlan walk_plan(double green, double yellow, double all_red, bool second_direction) {
  double half_cycle = green + yellow + all_red;
  SignalPlan plan;
  plan.phases = {{SignalColour::green, green}, {SignalColour::red, 2 * half_cycle - green}};
  plan.offset = second_direction ? half_cycle : 0;
  return plan;
}

}  // namespace

MapDescription generate_crossroads(const MapParameters& parameters) {
  const JunctionLayout layout = read_layout(parameters);
  const double green = parameters.value("green");
  const double yellow = parameters.value("yellow");
  const double all_red = parameters.value("all_red");
  const bool with_crosswalks = parameters.flag("crosswalks");
  const bool east_west_first = parameters.flag("east_west_first");
  const std::vector<Arm> arms =
      junction_arms(parameters, layout, {"north", "east", "south", "west"});

  MapDescription map = junction_map("crossroads", layout, arms);
  map.junctions.push_back(
      {kJunctionId, outline_round(layout, {&arm_named(arms, "south"), &arm_named(arms, "east"),
                                           &arm_named(arms, "north"), &arm_named(arms, "west")})});
  for (const Arm& arm : arms) {
    // North and south go first, east and west half a cycle later; or the other way round.
    const bool east_west = arm.name == "east" || arm.name == "west";
    TrafficLightDescription light;
    light.id = "light_" + arm.name;
    double head_distance = arm.start + kStopLineBeforeBox;
    light.heads = {head_distance * arm.outward +
                   (layout.road_half_width() + kPavementWidth / 2) * inbound_right(arm)};
    light.stop_lines = {stop_line(layout, arm)};
    light.lanes = in_lanes_at_stop_line(layout, arm);
    light.plan = two_direction_plan(green, yellow, all_red, east_west != east_west_first);
    map.traffic_lights.push_back(std::move(light));
  }
  if (with_crosswalks) {
    for (const Arm& arm : arms) {
      // A crosswalk across the east or west arm is walked north-south, beside the north-south
      // traffic, and shares its green.
      const bool walked_north_south = arm.name == "east" || arm.name == "west";
      CrosswalkDescription crossing = crosswalk(layout, arm);
      crossing.walk_plan = walk_plan(green, yellow, all_red, walked_north_south == east_west_first);
      map.crosswalks.push_back(std::move(crossing));
    }
  }
  return map;
}

MapDescription generate_t_junction(const MapParameters& parameters) {
  const JunctionLayout layout = read_layout(parameters);
  const bool with_crosswalks = parameters.flag("crosswalks");
  const std::vector<Arm> arms = junction_arms(parameters, layout, {"west", "east", "south"});
  const Arm& west = arm_named(arms, "west");
  const Arm& east = arm_named(arms, "east");
  const Arm& south = arm_named(arms, "south");

  MapDescription map = junction_map("t_junction", layout, arms);
  // The junction stops at the main road's north edge: the pavement there runs on unbroken.
  // Counter-clockwise from the side road: its start, the corner to the east arm, the east arm's
  // start up to that edge, along it to the west arm, the corner back to the side road.
  const double north_edge = layout.road_half_width();
  map.junctions.push_back(
      {kJunctionId, outline_without_repeats({arm_start_right(layout, south),
                                             arm_start_left(layout, south),
                                             corner_between(layout, south, east),
                                             arm_start_right(layout, east),
                                             {east.start, north_edge},
                                             {-west.start, north_edge},
                                             arm_start_left(layout, west),
                                             corner_between(layout, west, south)})});
  SignDescription stop;
  stop.id = "stop_south";
  stop.kind = SignKind::stop;
  stop.stop_lines = {stop_line(layout, south)};
  stop.lanes = in_lanes_at_stop_line(layout, south);
  map.signs.push_back(std::move(stop));
  if (with_crosswalks)
    for (const Arm& arm : arms) map.crosswalks.push_back(crosswalk(layout, arm));
  return map;
}

}  // namespace scenfuzz::builtin

// The built-in `crossroads` and `t_junction` maps: straight arms meeting at a square junction box
// centred on (0, 0), connector lanes `<from>_<to>_<k>` through the box, stop lines 6 m before the
// box, crosswalks 1 to 5 m outside it; signals on the crossroads, a stop sign on the T's side road.
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "physics/map/builtin_geometry.hpp"

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
};

// Right of a car driving towards the centre on this arm, and right of one driving away.
MapPoint inbound_right(const Arm& arm) { return right_normal(-1 * arm.outward); }
MapPoint outbound_right(const Arm& arm) { return right_normal(arm.outward); }

struct JunctionLayout {
  int lanes = 0;  // each way, on every arm
  double lane_width = 0;
  double arm_length = 0;
  double speed_limit = 0;
  // The box reaches across the crossing road and its pavements.
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

LaneDescription& lane_named(MapDescription& map, const std::string& id) {
  for (LaneDescription& lane : map.lanes)
    if (lane.id == id) return lane;
  throw std::logic_error("built-in junction map: no lane '" + id + "'");
}

void add_arm_lanes(MapDescription& map, const JunctionLayout& layout, const Arm& arm) {
  const int n = layout.lanes;
  const double near = layout.half_size();
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

LaneTurn turn_between(const Arm& from, const Arm& to) {
  if (dot(from.outward, to.outward) < -0.5) return LaneTurn::none;
  return dot(to.outward, inbound_right(from)) > 0.5 ? LaneTurn::right : LaneTurn::left;
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

// Straight across the box, or a quarter circle about the box corner on the side it turns to
// (right: the near corner; left: the far one), so that connectors of one turn never cross.
void add_connector(MapDescription& map, const JunctionLayout& layout, const Arm& from,
                   const Arm& to, int k) {
  const double h = layout.half_size();
  LaneDescription connector;
  connector.id = from.name + "_" + to.name + "_" + std::to_string(k);
  connector.turn = turn_between(from, to);
  MapPoint start = in_lane_point(layout, from, k, h);
  MapPoint end = out_lane_point(layout, to, k, h);
  switch (connector.turn) {
    case LaneTurn::right:
      connector.centre_line =
          arc_between(start, end, h * from.outward + h * inbound_right(from), false);
      break;
    case LaneTurn::left:
      connector.centre_line =
          arc_between(start, end, h * from.outward - h * inbound_right(from), true);
      break;
    default: connector.centre_line = {start, end}; break;
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
  double distance = layout.half_size() + kStopLineBeforeBox;
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
  const double near = layout.half_size() + kCrosswalkNearEdge;
  const double far = layout.half_size() + kCrosswalkFarEdge;
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

const Arm kNorth{"north", {0, 1}};
const Arm kEast{"east", {1, 0}};
const Arm kSouth{"south", {0, -1}};
const Arm kWest{"west", {-1, 0}};

// A fixed-time plan in which the two crossing directions take turns: green, yellow, then red
// while the other direction has its green and yellow plus an all-red gap after each.
SignalPlan traffic_plan(double green, double yellow, double all_red, bool second_direction) {
  double half_cycle = green + yellow + all_red;
  SignalPlan plan;
  plan.phases = {{SignalColour::green, green},
                 {SignalColour::yellow, yellow},
                 {SignalColour::red, half_cycle + all_red}};
  plan.offset = second_direction ? half_cycle : 0;
  return plan;
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
  const std::vector<Arm> arms = {kNorth, kEast, kSouth, kWest};

  MapDescription map = junction_map("crossroads", layout, arms);
  const double h = layout.half_size();
  map.junctions.push_back({kJunctionId, {{-h, -h}, {h, -h}, {h, h}, {-h, h}}});
  for (const Arm& arm : arms) {
    // North and south go first; east and west half a cycle later.
    bool east_west = arm.name == "east" || arm.name == "west";
    TrafficLightDescription light;
    light.id = "light_" + arm.name;
    double head_distance = h + kStopLineBeforeBox;
    light.heads = {head_distance * arm.outward +
                   (layout.road_half_width() + kPavementWidth / 2) * inbound_right(arm)};
    light.stop_lines = {stop_line(layout, arm)};
    light.lanes = in_lanes_at_stop_line(layout, arm);
    light.plan = traffic_plan(green, yellow, all_red, east_west);
    map.traffic_lights.push_back(std::move(light));
  }
  if (with_crosswalks) {
    for (const Arm& arm : arms) {
      // A crosswalk across the east or west arm is walked north-south, beside the north-south
      // traffic, and shares its green.
      bool walked_north_south = arm.name == "east" || arm.name == "west";
      CrosswalkDescription crossing = crosswalk(layout, arm);
      crossing.walk_plan = walk_plan(green, yellow, all_red, !walked_north_south);
      map.crosswalks.push_back(std::move(crossing));
    }
  }
  return map;
}

MapDescription generate_t_junction(const MapParameters& parameters) {
  const JunctionLayout layout = read_layout(parameters);
  const bool with_crosswalks = parameters.flag("crosswalks");
  const std::vector<Arm> arms = {kWest, kEast, kSouth};

  MapDescription map = junction_map("t_junction", layout, arms);
  // The box stops at the main road's north edge: the pavement there runs on unbroken.
  const double h = layout.half_size();
  const double north_edge = layout.road_half_width();
  map.junctions.push_back({kJunctionId, {{-h, -h}, {h, -h}, {h, north_edge}, {-h, north_edge}}});
  SignDescription stop;
  stop.id = "stop_south";
  stop.kind = SignKind::stop;
  stop.stop_lines = {stop_line(layout, kSouth)};
  stop.lanes = in_lanes_at_stop_line(layout, kSouth);
  map.signs.push_back(std::move(stop));
  if (with_crosswalks)
    for (const Arm& arm : arms) map.crosswalks.push_back(crosswalk(layout, arm));
  return map;
}

}  // namespace scenfuzz::builtin

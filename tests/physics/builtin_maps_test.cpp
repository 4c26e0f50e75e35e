// The built-in maps against their contract in corpora/README.md (lane ids, end points, headings,
// lengths, neighbours, junction connectors, stop lines, crosswalks, signal plans, the roundabout's
// ring), the lane graph of every map with default and other parameters, the parameter checks,
// and a few queries through build_road_map, lane_queries and lane_route.
#include "physics/map/builtin_maps.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "physics/map/lane_queries.hpp"
#include "physics/map/lane_route.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

using ::testing::HasSubstr;

// The contract gives coordinates, lengths and s values to the centimetre.
constexpr double kContractTolerance = 0.006;
// Where lanes join, within a centimetre.
constexpr double kJoinTolerance = 0.01;

double degrees(double radians) { return radians * 180 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180; }

const LaneDescription* find_lane(const MapDescription& map, std::string_view id) {
  for (const LaneDescription& lane : map.lanes)
    if (lane.id == id) return &lane;
  return nullptr;
}

// Fails the test (and stops it) when the lane is missing, through the exception GoogleTest
// reports as an error.
const LaneDescription& lane_of(const MapDescription& map, std::string_view id) {
  const LaneDescription* lane = find_lane(map, id);
  if (!lane)
    throw std::runtime_error("map '" + map.name + "' has no lane '" + std::string(id) + "'");
  return *lane;
}

std::set<std::string> lane_ids(const MapDescription& map) {
  std::set<std::string> ids;
  for (const LaneDescription& lane : map.lanes) ids.insert(lane.id);
  return ids;
}

Polyline centre_line(const LaneDescription& lane) { return Polyline(lane.centre_line); }

double start_heading(const LaneDescription& lane) { return centre_line(lane).heading_at(0); }
double end_heading(const LaneDescription& lane) {
  Polyline line = centre_line(lane);
  return line.heading_at(line.length());
}

// Headings compared as angles, so 360° equals 0°.
void expect_heading(double actual_radians, double expected_degrees, double tolerance_degrees,
                    const std::string& what) {
  EXPECT_NEAR(degrees(angle_difference(actual_radians, radians(expected_degrees))), 0,
              tolerance_degrees)
      << what << ": heading " << degrees(actual_radians) << "°, expected " << expected_degrees
      << "°";
}

void expect_point(MapPoint actual, MapPoint expected, double tolerance, const std::string& what) {
  EXPECT_NEAR(actual.x, expected.x, tolerance) << what;
  EXPECT_NEAR(actual.y, expected.y, tolerance) << what;
}

struct LaneRow {
  std::string id;
  MapPoint start;
  MapPoint end;
  double heading = 0;  // degrees, at both ends
  double length = 0;
};

void expect_straight_lanes(const MapDescription& map, const std::vector<LaneRow>& rows) {
  for (const LaneRow& row : rows) {
    SCOPED_TRACE(map.name + " " + row.id);
    const LaneDescription* lane = find_lane(map, row.id);
    ASSERT_NE(lane, nullptr);
    expect_point(lane->centre_line.front(), row.start, kContractTolerance, "start");
    expect_point(lane->centre_line.back(), row.end, kContractTolerance, "end");
    expect_heading(start_heading(*lane), row.heading, 1e-6, "start");
    expect_heading(end_heading(*lane), row.heading, 1e-6, "end");
    EXPECT_NEAR(centre_line(*lane).length(), row.length, kContractTolerance);
  }
}

std::vector<std::string> ids(std::initializer_list<std::string> names) { return names; }

// Successor lists compared regardless of order.
std::set<std::string> id_set(const std::vector<std::string>& names) {
  return {names.begin(), names.end()};
}
std::set<std::string> id_set(std::initializer_list<std::string> names) { return names; }

// The colour of a fixed-time plan at time t, as map_description.hpp defines it.
SignalColour colour_at(const SignalPlan& plan, double t) {
  double period = 0;
  for (const SignalPhase& phase : plan.phases) period += phase.duration;
  double in_cycle = std::fmod(t + plan.offset, period);
  if (in_cycle < 0) in_cycle += period;
  for (const SignalPhase& phase : plan.phases) {
    if (in_cycle < phase.duration) return phase.colour;
    in_cycle -= phase.duration;
  }
  return plan.phases.back().colour;
}

double plan_period(const SignalPlan& plan) {
  double period = 0;
  for (const SignalPhase& phase : plan.phases) period += phase.duration;
  return period;
}

// Expected colour over [from, to): sampled every 0.1 s, a little inside the interval's ends.
void expect_colour(const SignalPlan& plan, double from, double to, SignalColour colour,
                   const std::string& what) {
  for (double t = from + 0.01; t < to; t += 0.1)
    EXPECT_EQ(colour_at(plan, t), colour) << what << " at t = " << t;
}

const TrafficLightDescription& light_of(const MapDescription& map, std::string_view id) {
  for (const TrafficLightDescription& light : map.traffic_lights)
    if (light.id == id) return light;
  throw std::runtime_error("no traffic light '" + std::string(id) + "'");
}

const CrosswalkDescription& crosswalk_of(const MapDescription& map, std::string_view id) {
  for (const CrosswalkDescription& crosswalk : map.crosswalks)
    if (crosswalk.id == id) return crosswalk;
  throw std::runtime_error("no crosswalk '" + std::string(id) + "'");
}

const SignDescription& sign_of(const MapDescription& map, std::string_view id) {
  for (const SignDescription& sign : map.signs)
    if (sign.id == id) return sign;
  throw std::runtime_error("no sign '" + std::string(id) + "'");
}

std::map<std::string, std::pair<double, double>> crossings_by_lane(
    const std::vector<LaneCrossingDescription>& crossings) {
  std::map<std::string, std::pair<double, double>> by_lane;
  for (const LaneCrossingDescription& crossing : crossings)
    by_lane[crossing.lane] = {crossing.s_begin, crossing.s_end};
  return by_lane;
}

// ---------------------------------------------------------------------------------------------
// The lane graph of any built-in map.

struct ParameterSet {
  std::string map;
  std::vector<MapParameterValue> values;
};

std::string describe(const ParameterSet& set) {
  std::string text = set.map;
  for (const MapParameterValue& value : set.values)
    text += " " + value.name + "=" + std::to_string(value.value);
  return text;
}

std::vector<ParameterSet> parameter_sets() {
  std::vector<ParameterSet> sets;
  for (const BuiltinMapInfo& info : builtin_maps()) sets.push_back({info.name, {}});
  sets.push_back({"straight", {{"lanes", 3}, {"two_way", 0}, {"length", 50}}});
  sets.push_back({"straight", {{"lanes", 1}, {"lane_width", 2.5}}});
  sets.push_back({"curve", {{"angle", -120}, {"radius", 50}, {"lanes", 3}, {"lane_width", 3}}});
  sets.push_back({"curve", {{"angle", 180}, {"straight_before", 0}, {"lanes", 1}}});
  sets.push_back({"curve", {{"angle", 0}, {"straight_after", 0}}});
  sets.push_back({"crossroads", {{"lanes", 1}, {"arm_length", 20}}});
  sets.push_back({"crossroads", {{"lanes", 3}, {"lane_width", 3}, {"green", 40}}});
  sets.push_back({"crossroads", {{"lanes", 4}, {"lane_width", 5}, {"crosswalks", 0}}});
  sets.push_back({"t_junction", {{"lanes", 1}}});
  sets.push_back({"t_junction", {{"lanes", 3}, {"lane_width", 4}, {"arm_length", 60}}});
  sets.push_back({"crossroads", {{"angle", 45}, {"lanes", 1}, {"arm_length", 20}}});
  sets.push_back({"crossroads", {{"angle", 60}}});
  sets.push_back({"crossroads", {{"angle", 135}, {"lanes", 3}, {"lane_width", 3}}});
  sets.push_back({"crossroads", {{"angle", 100}, {"lanes", 4}, {"lane_width", 5}}});
  sets.push_back({"t_junction", {{"angle", 45}, {"lanes", 3}}});
  sets.push_back({"t_junction", {{"angle", 135}, {"lanes", 1}}});
  sets.push_back({"t_junction", {{"angle", 80}, {"lane_width", 2.5}}});
  sets.push_back({"roundabout", {{"ring_radius", 60}, {"entry_angle", 30}}});
  sets.push_back({"roundabout", {{"entry_angle", 30}, {"lane_width", 5}}});
  sets.push_back({"roundabout", {{"ring_radius", 35}, {"lane_width", 2.5}, {"arm_length", 20}}});
  sets.push_back({"roundabout", {{"ring_radius", 5}}});
  sets.push_back({"roundabout", {{"ring_radius", 5}, {"lane_width", 3.75}, {"arm_length", 20}}});
  sets.push_back({"roundabout", {{"ring_radius", 8}, {"entry_angle", 30}, {"lane_width", 2.5}}});
  sets.push_back({"roundabout", {{"ring_radius", 100}, {"lane_width", 5}}});
  sets.push_back(
      {"merge", {{"lanes", 1}, {"merge_angle", 45}, {"ramp_radius", 30}, {"ramp_length", 0}}});
  sets.push_back(
      {"merge", {{"lanes", 4}, {"merge_angle", 3}, {"after_length", 0}, {"accel_length", 20}}});
  return sets;
}

// The parameter's value in a set, or its default.
double parameter_value(const ParameterSet& set, std::string_view name) {
  for (const MapParameterValue& value : set.values)
    if (value.name == name) return value.value;
  for (const BuiltinMapInfo& info : builtin_maps())
    if (info.name == set.map)
      for (const MapParameterInfo& parameter : info.parameters)
        if (parameter.name == name) return parameter.default_value;
  throw std::runtime_error("no parameter " + std::string(name));
}

bool contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The one place where links do not join end to start: a roundabout's entries and exits meet the
// closed ring part-way along it (corpora/README.md fixes ring_0 as a single loop).
bool joins_ring_part_way(const MapDescription& map, const std::string& from,
                         const std::string& to) {
  return map.name == "roundabout" && (from == "ring_0") != (to == "ring_0");
}

void check_lane_graph(const ParameterSet& set) {
  SCOPED_TRACE(describe(set));
  MapDescription map = generate_builtin_map(set.map, set.values);
  EXPECT_EQ(map.name, set.map);
  EXPECT_EQ(map.source, "built-in");
  EXPECT_DOUBLE_EQ(map.default_lane_width, parameter_value(set, "lane_width"));
  EXPECT_EQ(lane_ids(map).size(), map.lanes.size()) << "lane ids are unique";

  std::set<std::string> junction_ids;
  for (const JunctionDescription& junction : map.junctions) {
    junction_ids.insert(junction.id);
    EXPECT_GE(junction.outline.size(), 3u) << junction.id;
  }

  for (const LaneDescription& lane : map.lanes) {
    SCOPED_TRACE("lane " + lane.id);
    ASSERT_GE(lane.centre_line.size(), 2u);
    Polyline line = centre_line(lane);
    EXPECT_GT(line.length(), 1);
    EXPECT_GT(lane.speed_limit, 0);
    // Dense and smooth: no kink over 0.011 rad at any vertex, so arcs are sampled at least
    // every 0.01 rad and straights meet arcs tangentially; a segment with a bend at both ends
    // lies on an arc and is at most 1 m long.
    std::vector<double> kink(line.points().size(), 0);
    for (std::size_t i = 1; i < line.segment_count(); ++i) {
      double before = line.heading_at(line.arc_lengths()[i - 1]);
      double after = line.heading_at(line.arc_lengths()[i]);
      kink[i] = std::abs(angle_difference(after, before));
      ASSERT_LT(kink[i], 0.011) << "kink at vertex " << i;
    }
    for (std::size_t i = 1; i + 1 < line.segment_count(); ++i)
      if (kink[i] > 1e-12 && kink[i + 1] > 1e-12) {
        ASSERT_LE(line.arc_lengths()[i + 1] - line.arc_lengths()[i], 1.0 + 1e-9)
            << "arc segment " << i << " longer than 1 m";
      }

    if (lane.junction.empty()) {
      EXPECT_NE(lane.left_boundary_type, BoundaryType::unknown);
      EXPECT_NE(lane.right_boundary_type, BoundaryType::unknown);
    } else {
      EXPECT_TRUE(junction_ids.contains(lane.junction)) << lane.junction;
      EXPECT_EQ(lane.right_boundary_type, BoundaryType::unknown);
    }

    for (const std::string& successor_id : lane.successors) {
      SCOPED_TRACE("successor " + successor_id);
      const LaneDescription* successor = find_lane(map, successor_id);
      ASSERT_NE(successor, nullptr);
      EXPECT_TRUE(contains(successor->predecessors, lane.id)) << "predecessor link missing";
      Polyline next = centre_line(*successor);
      MapPoint end = lane.centre_line.back();
      if (joins_ring_part_way(map, lane.id, successor_id)) {
        // Into the ring: this lane's end lies on it. Out of it: the exit starts on it.
        bool into_ring = successor_id == "ring_0";
        const Polyline& ring = into_ring ? next : line;
        MapPoint join = into_ring ? end : successor->centre_line.front();
        PolylineProjection on_ring = ring.project(join);
        EXPECT_LT(on_ring.distance, kJoinTolerance);
        double lane_heading = into_ring ? end_heading(lane) : start_heading(*successor);
        expect_heading(lane_heading, degrees(ring.heading_at(on_ring.s)), 1, "ring join");
        continue;
      }
      EXPECT_LT(distance(end, successor->centre_line.front()), kJoinTolerance)
          << "ends at (" << end.x << ", " << end.y << "), successor starts at ("
          << successor->centre_line.front().x << ", " << successor->centre_line.front().y << ")";
      expect_heading(start_heading(*successor), degrees(end_heading(lane)), 1, "join");
    }
    for (const std::string& predecessor_id : lane.predecessors) {
      const LaneDescription* predecessor = find_lane(map, predecessor_id);
      ASSERT_NE(predecessor, nullptr) << predecessor_id;
      EXPECT_TRUE(contains(predecessor->successors, lane.id)) << predecessor_id;
    }

    // Neighbours are mutual and lie a lane width away on the side they are named for.
    auto check_neighbours = [&](const std::vector<std::string>& neighbours, double side,
                                bool same_direction) {
      for (const std::string& neighbour_id : neighbours) {
        SCOPED_TRACE("neighbour " + neighbour_id);
        const LaneDescription* neighbour = find_lane(map, neighbour_id);
        ASSERT_NE(neighbour, nullptr);
        const auto& back_links = same_direction ? (side > 0 ? neighbour->right_forward_neighbours
                                                            : neighbour->left_forward_neighbours)
                                                : neighbour->left_reverse_neighbours;
        EXPECT_TRUE(contains(back_links, lane.id)) << "not mutual";
        Polyline other = centre_line(*neighbour);
        // The shorter lane's middle, seen from the longer one (an acceleration lane runs beside
        // only part of the main road).
        bool this_longer = line.length() >= other.length();
        const Polyline& longer = this_longer ? line : other;
        const Polyline& shorter = this_longer ? other : line;
        PolylineProjection seen = longer.project(shorter.point_at(shorter.length() / 2));
        EXPECT_NEAR(seen.distance, parameter_value(set, "lane_width"), kJoinTolerance);
        // Seen from a forward neighbour this lane is on the other side; from a reverse one
        // (both keep the centre line on their left) on the same side.
        double seen_side = this_longer || !same_direction ? side : -side;
        EXPECT_GT(seen_side * seen.lateral, 0) << "on the wrong side";
        double heading_difference = std::abs(
            angle_difference(longer.heading_at(seen.s), shorter.heading_at(shorter.length() / 2)));
        // Chords of an arc lane and of its neighbour's arc need not be parallel: within one
        // sampling step.
        EXPECT_NEAR(heading_difference, same_direction ? 0 : std::numbers::pi, 0.011);
      }
    };
    check_neighbours(lane.left_forward_neighbours, +1, true);
    check_neighbours(lane.right_forward_neighbours, -1, true);
    check_neighbours(lane.left_reverse_neighbours, +1, false);
    EXPECT_TRUE(lane.right_reverse_neighbours.empty()) << "traffic drives on the right";
  }

  auto check_crossings = [&](const std::string& owner,
                             const std::vector<LaneCrossingDescription>& crossings) {
    EXPECT_FALSE(crossings.empty()) << owner;
    for (const LaneCrossingDescription& crossing : crossings) {
      const LaneDescription* lane = find_lane(map, crossing.lane);
      ASSERT_NE(lane, nullptr) << owner << " crosses " << crossing.lane;
      EXPECT_LE(0, crossing.s_begin) << owner;
      EXPECT_LE(crossing.s_begin, crossing.s_end) << owner;
      EXPECT_LE(crossing.s_end, centre_line(*lane).length() + 1e-9) << owner;
    }
  };
  for (const TrafficLightDescription& light : map.traffic_lights) {
    check_crossings(light.id, light.lanes);
    EXPECT_FALSE(light.heads.empty()) << light.id;
    EXPECT_FALSE(light.stop_lines.empty()) << light.id;
    EXPECT_TRUE(light.plan.has_value()) << light.id;
  }
  for (const SignDescription& sign : map.signs) {
    check_crossings(sign.id, sign.lanes);
    EXPECT_FALSE(sign.stop_lines.empty()) << sign.id;
  }
  for (const CrosswalkDescription& crosswalk : map.crosswalks) {
    check_crossings(crosswalk.id, crosswalk.lanes);
    EXPECT_EQ(crosswalk.outline.size(), 4u) << crosswalk.id;
  }

  RoadMap road_map = build_road_map(map);
  EXPECT_TRUE(road_map.warnings().empty())
      << (road_map.warnings().empty() ? "" : road_map.warnings().front());
}

TEST(BuiltinMapGraph, EveryLaneJoinsItsSuccessorsAndNeighboursForEveryParameterSet) {
  for (const ParameterSet& set : parameter_sets()) check_lane_graph(set);
}

TEST(BuiltinMapGraph, GenerationIsAPureFunctionOfTheParameters) {
  for (const ParameterSet& set : parameter_sets()) {
    MapDescription first = generate_builtin_map(set.map, set.values);
    MapDescription second = generate_builtin_map(set.map, set.values);
    ASSERT_EQ(first.lanes.size(), second.lanes.size()) << describe(set);
    for (std::size_t i = 0; i < first.lanes.size(); ++i) {
      EXPECT_EQ(first.lanes[i].id, second.lanes[i].id);
      EXPECT_EQ(first.lanes[i].centre_line, second.lanes[i].centre_line);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The registry and the parameter checks.

TEST(BuiltinMapRegistry, ListsTheSixMapsWithDefaultsInsideTheirRanges) {
  std::vector<std::string> names;
  for (const BuiltinMapInfo& info : builtin_maps()) {
    names.push_back(info.name);
    EXPECT_TRUE(is_builtin_map(info.name));
    EXPECT_FALSE(info.description.empty());
    std::set<std::string> parameter_names;
    for (const MapParameterInfo& parameter : info.parameters) {
      SCOPED_TRACE(info.name + "." + parameter.name);
      EXPECT_TRUE(parameter_names.insert(parameter.name).second) << "listed twice";
      EXPECT_LE(parameter.lower, parameter.default_value);
      EXPECT_LE(parameter.default_value, parameter.upper);
      EXPECT_FALSE(parameter.description.empty());
      if (parameter.unit.empty()) {
        EXPECT_EQ(parameter.default_value, std::round(parameter.default_value));
      }
    }
  }
  EXPECT_EQ(names, ids({"straight", "curve", "t_junction", "crossroads", "roundabout", "merge"}));
  EXPECT_FALSE(is_builtin_map("curved"));
  EXPECT_FALSE(is_builtin_map("san_francisco"));
}

std::string error_of(std::string_view map, const std::vector<MapParameterValue>& parameters) {
  try {
    generate_builtin_map(map, parameters);
  } catch (const MapError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no MapError for " << map;
  return "";
}

TEST(BuiltinMapParameters, AnUnknownMapNamesTheKnownOnes) {
  std::string message = error_of("motorway", {});
  EXPECT_THAT(message, HasSubstr("'motorway'"));
  EXPECT_THAT(message, HasSubstr("straight, curve, t_junction, crossroads, roundabout, merge"));
  EXPECT_THAT(error_of("curved", {}), HasSubstr("did you mean 'curve'?"));
}

TEST(BuiltinMapParameters, AnUnknownParameterListsTheAcceptedOnesWithRanges) {
  std::string message = error_of("straight", {{"lane", 3}});
  EXPECT_THAT(message, HasSubstr("built-in map 'straight'"));
  EXPECT_THAT(message, HasSubstr("unknown parameter 'lane'"));
  EXPECT_THAT(message, HasSubstr("lanes (whole number 1..6, default 2)"));
  EXPECT_THAT(message, HasSubstr("lane_width (2.5..5 m, default 3.5)"));
  EXPECT_THAT(message, HasSubstr("two_way (0 or 1, default 1)"));
  EXPECT_THAT(message, HasSubstr("speed_limit (1..70 m/s, default 22.2)"));
}

TEST(BuiltinMapParameters, ValuesOutsideTheirRangeAreRejected) {
  EXPECT_THAT(error_of("straight", {{"lane_width", 1.5}}),
              HasSubstr("parameter 'lane_width' = 1.5 is outside its range 2.5..5 m"));
  EXPECT_THAT(error_of("crossroads", {{"lanes", 5}}),
              HasSubstr("parameter 'lanes' = 5 is outside its range 1..4"));
  EXPECT_THAT(error_of("straight", {{"two_way", 2}}),
              HasSubstr("parameter 'two_way' = 2 must be 0 or 1"));
  EXPECT_THAT(error_of("curve", {{"angle", 181}}), HasSubstr("'angle' = 181 is outside"));
  EXPECT_THAT(error_of("roundabout", {{"ring_radius", 4}}),
              HasSubstr("parameter 'ring_radius' = 4 is outside its range 5..100 m"));
  EXPECT_THAT(error_of("roundabout", {{"ring_radius", 101}}), HasSubstr("'ring_radius'"));
  EXPECT_THAT(error_of("crossroads", {{"angle", 30}}),
              HasSubstr("parameter 'angle' = 30 is outside its range 45..135 deg"));
  EXPECT_THAT(error_of("t_junction", {{"angle", 140}}),
              HasSubstr("parameter 'angle' = 140 is outside its range 45..135 deg"));
  EXPECT_THAT(error_of("merge", {{"merge_angle", 90}}), HasSubstr("'merge_angle'"));
  EXPECT_THAT(error_of("straight", {{"length", std::numeric_limits<double>::infinity()}}),
              HasSubstr("'length' = inf is outside its range 10..10000 m"));
}

TEST(BuiltinMapParameters, CountsAndFlagsMustBeWholeNumbers) {
  EXPECT_THAT(error_of("straight", {{"lanes", 2.5}}),
              HasSubstr("parameter 'lanes' = 2.5 must be a whole number"));
  EXPECT_THAT(error_of("straight", {{"two_way", 0.5}}),
              HasSubstr("parameter 'two_way' = 0.5 must be 0 or 1"));
  EXPECT_THAT(error_of("crossroads", {{"crosswalks", 0.2}}), HasSubstr("'crosswalks'"));
}

TEST(BuiltinMapParameters, NotANumberIsRejected) {
  EXPECT_THAT(error_of("t_junction", {{"arm_length", std::nan("")}}),
              HasSubstr("built-in map 't_junction': parameter 'arm_length' is not a number"));
}

TEST(BuiltinMapParameters, ACurveTooTightForItsRoadIsRejected) {
  EXPECT_THAT(error_of("curve", {{"radius", 20}, {"lanes", 6}, {"lane_width", 5}}),
              HasSubstr("radius 20 m is too tight"));
  EXPECT_THAT(error_of("curve", {{"angle", 0}, {"straight_before", 0}, {"straight_after", 0}}),
              HasSubstr("no length"));
}

TEST(BuiltinMapParameters, ARingTooSmallForItsLanesIsRejected) {
  // At 42 degrees a 4.25 m entry curve from a 5 m lane needs (4.25 + 2.5) / sin 42° - 4.25 m.
  std::string message = error_of("roundabout", {{"ring_radius", 5}, {"lane_width", 5}});
  EXPECT_THAT(message, HasSubstr("ring_radius 5 m is too small for lanes 5 m wide"));
  EXPECT_THAT(message, HasSubstr("need a ring_radius of at least 5.83"));
}

TEST(BuiltinMapParameters, LaterValuesOverrideEarlierOnes) {
  MapDescription map = generate_builtin_map("straight", {{"lanes", 1}, {"lanes", 3}});
  EXPECT_EQ(map.lanes.size(), 6u);
  EXPECT_NE(find_lane(map, "west_2"), nullptr);
}

// ---------------------------------------------------------------------------------------------
// straight

TEST(BuiltinStraight, LanesMatchTheContract) {
  MapDescription map = generate_builtin_map("straight", {});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"east_0", "east_1", "west_0", "west_1"}));
  expect_straight_lanes(map, {{"east_0", {0, -5.25}, {500, -5.25}, 0, 500},
                              {"east_1", {0, -1.75}, {500, -1.75}, 0, 500},
                              {"west_1", {500, 1.75}, {0, 1.75}, 180, 500},
                              {"west_0", {500, 5.25}, {0, 5.25}, 180, 500}});
  const LaneDescription& east_0 = lane_of(map, "east_0");
  const LaneDescription& east_1 = lane_of(map, "east_1");
  EXPECT_EQ(east_0.left_forward_neighbours, ids({"east_1"}));
  EXPECT_EQ(east_1.right_forward_neighbours, ids({"east_0"}));
  EXPECT_EQ(east_1.left_reverse_neighbours, ids({"west_1"}));
  EXPECT_EQ(lane_of(map, "west_1").left_reverse_neighbours, ids({"east_1"}));
  EXPECT_EQ(east_0.right_boundary_type, BoundaryType::curb);
  EXPECT_EQ(east_0.left_boundary_type, BoundaryType::dotted_white);
  EXPECT_EQ(east_1.left_boundary_type, BoundaryType::double_yellow);
  EXPECT_DOUBLE_EQ(east_0.speed_limit, 22.2);
  EXPECT_TRUE(map.junctions.empty());
  EXPECT_TRUE(map.traffic_lights.empty());
  EXPECT_TRUE(map.crosswalks.empty());
  EXPECT_TRUE(map.signs.empty());
}

TEST(BuiltinStraight, ParametersScaleTheRoad) {
  MapDescription map =
      generate_builtin_map("straight", {{"lanes", 3}, {"lane_width", 3}, {"length", 200}});
  expect_straight_lanes(map, {{"east_0", {0, -7.5}, {200, -7.5}, 0, 200},
                              {"east_2", {0, -1.5}, {200, -1.5}, 0, 200},
                              {"west_2", {200, 1.5}, {0, 1.5}, 180, 200},
                              {"west_0", {200, 7.5}, {0, 7.5}, 180, 200}});
  EXPECT_EQ(lane_of(map, "east_1").left_forward_neighbours, ids({"east_2"}));
  EXPECT_EQ(lane_of(map, "east_1").right_forward_neighbours, ids({"east_0"}));

  MapDescription one_way = generate_builtin_map("straight", {{"two_way", 0}});
  EXPECT_EQ(lane_ids(one_way), (std::set<std::string>{"east_0", "east_1"}));
  EXPECT_EQ(lane_of(one_way, "east_1").left_boundary_type, BoundaryType::curb);
  EXPECT_TRUE(lane_of(one_way, "east_1").left_reverse_neighbours.empty());
}

TEST(BuiltinStraight, QueriesOnTheBuiltMap) {
  RoadMap map = build_road_map(generate_builtin_map("straight", {}));
  EXPECT_EQ(map.name(), "straight");
  auto east_0 = map.find_lane("east_0");
  ASSERT_TRUE(east_0);
  auto pose = lane_pose_at(map, *east_0, 100);
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->position.x, 100, 1e-9);
  EXPECT_NEAR(pose->position.y, -5.25, 1e-9);
  EXPECT_NEAR(pose->heading, 0, 1e-12);
  EXPECT_DOUBLE_EQ(lane_left_width_at(map, *east_0, 100), 1.75);
  EXPECT_DOUBLE_EQ(lane_right_width_at(map, *east_0, 100), 1.75);

  auto west_1 = map.find_lane("west_1");
  ASSERT_TRUE(west_1);
  auto west_pose = lane_pose_at(map, *west_1, 100);
  ASSERT_TRUE(west_pose);
  EXPECT_NEAR(west_pose->position.x, 400, 1e-9);  // "west_k" -> s is at x = 500 - s
  expect_heading(west_pose->heading, 180, 1e-9, "west_1");

  auto east_1 = map.find_lane("east_1");
  ASSERT_TRUE(east_1);
  EXPECT_TRUE(lane_change_allowed(map, *east_0, *east_1));
  EXPECT_TRUE(lane_change_allowed(map, *east_1, *east_0));
  EXPECT_FALSE(lane_change_allowed(map, *east_1, *west_1));
}

// ---------------------------------------------------------------------------------------------
// crossroads

std::vector<LaneRow> crossroads_arm_lanes() {
  return {{"north_in_0", {-5.25, 160}, {-5.25, 10}, 270, 150},
          {"north_in_1", {-1.75, 160}, {-1.75, 10}, 270, 150},
          {"north_out_1", {1.75, 10}, {1.75, 160}, 90, 150},
          {"north_out_0", {5.25, 10}, {5.25, 160}, 90, 150},
          {"east_in_0", {160, 5.25}, {10, 5.25}, 180, 150},
          {"east_in_1", {160, 1.75}, {10, 1.75}, 180, 150},
          {"east_out_1", {10, -1.75}, {160, -1.75}, 0, 150},
          {"east_out_0", {10, -5.25}, {160, -5.25}, 0, 150},
          {"south_in_0", {5.25, -160}, {5.25, -10}, 90, 150},
          {"south_in_1", {1.75, -160}, {1.75, -10}, 90, 150},
          {"south_out_1", {-1.75, -10}, {-1.75, -160}, 270, 150},
          {"south_out_0", {-5.25, -10}, {-5.25, -160}, 270, 150},
          {"west_in_0", {-160, -5.25}, {-10, -5.25}, 0, 150},
          {"west_in_1", {-160, -1.75}, {-10, -1.75}, 0, 150},
          {"west_out_1", {-10, 1.75}, {-160, 1.75}, 180, 150},
          {"west_out_0", {-10, 5.25}, {-160, 5.25}, 180, 150}};
}

MapPoint corner_at(std::string_view from, bool near) {
  // The box corner on the right (near) or left (far) of a car arriving from `from`.
  std::map<std::string, std::pair<MapPoint, MapPoint>, std::less<>> corners = {
      {"north", {{-10, 10}, {10, 10}}},
      {"east", {{10, 10}, {10, -10}}},
      {"south", {{10, -10}, {-10, -10}}},
      {"west", {{-10, -10}, {-10, 10}}}};
  auto found = corners.find(from);
  return near ? found->second.first : found->second.second;
}

// Connector geometry from the contract: straight 20 m lines, right turns radius 4.75 about the
// near corner, left turns radius 11.75 about the far one.
void expect_connector(const MapDescription& map, const std::string& from, const std::string& to,
                      int k, LaneTurn turn) {
  std::string id = from + "_" + to + "_" + std::to_string(k);
  SCOPED_TRACE(map.name + " " + id);
  const LaneDescription* connector = find_lane(map, id);
  ASSERT_NE(connector, nullptr);
  EXPECT_EQ(connector->turn, turn);
  EXPECT_EQ(connector->junction, "junction");
  EXPECT_EQ(connector->predecessors, ids({from + "_in_" + std::to_string(k)}));
  EXPECT_EQ(connector->successors, ids({to + "_out_" + std::to_string(k)}));
  EXPECT_EQ(connector->left_boundary_type, BoundaryType::unknown);
  EXPECT_EQ(connector->right_boundary_type, BoundaryType::unknown);
  double length = centre_line(*connector).length();
  if (turn == LaneTurn::none) {
    EXPECT_EQ(connector->centre_line.size(), 2u);
    EXPECT_NEAR(length, 20, 1e-9);
    return;
  }
  double radius = turn == LaneTurn::right ? 4.75 : 11.75;
  MapPoint centre = corner_at(from, turn == LaneTurn::right);
  for (MapPoint point : connector->centre_line) EXPECT_NEAR(distance(point, centre), radius, 1e-9);
  EXPECT_NEAR(length, radius * std::numbers::pi / 2, 2e-3);
  double turned = degrees(angle_difference(end_heading(*connector), start_heading(*connector)));
  EXPECT_NEAR(turned, turn == LaneTurn::right ? -90 : 90, 1);
}

TEST(BuiltinCrossroads, ArmLanesMatchTheContract) {
  MapDescription map = generate_builtin_map("crossroads", {});
  expect_straight_lanes(map, crossroads_arm_lanes());
  EXPECT_EQ(map.lanes.size(), 16u + 16u);
  const LaneDescription& south_in_0 = lane_of(map, "south_in_0");
  EXPECT_EQ(south_in_0.left_forward_neighbours, ids({"south_in_1"}));
  EXPECT_EQ(lane_of(map, "south_in_1").left_reverse_neighbours, ids({"south_out_1"}));
  EXPECT_EQ(lane_of(map, "south_out_1").left_reverse_neighbours, ids({"south_in_1"}));
  EXPECT_EQ(lane_of(map, "south_out_1").right_forward_neighbours, ids({"south_out_0"}));
  EXPECT_DOUBLE_EQ(south_in_0.speed_limit, 13.9);
  EXPECT_EQ(id_set(south_in_0.successors), id_set({"south_east_0", "south_north_0"}));
  EXPECT_EQ(id_set(lane_of(map, "south_in_1").successors),
            id_set({"south_north_1", "south_west_1"}));
  ASSERT_EQ(map.junctions.size(), 1u);
  for (MapPoint corner : map.junctions[0].outline) {
    EXPECT_DOUBLE_EQ(std::abs(corner.x), 10);
    EXPECT_DOUBLE_EQ(std::abs(corner.y), 10);
  }
}

TEST(BuiltinCrossroads, ConnectorsGoStraightFromEveryLaneRightFromLane0AndLeftFromLane1) {
  MapDescription map = generate_builtin_map("crossroads", {});
  const std::vector<std::string> arms = {"north", "east", "south", "west"};
  // Arms in clockwise order: the next one is on the left of a car arriving.
  std::set<std::string> expected;
  for (std::size_t a = 0; a < 4; ++a) {
    const std::string& from = arms[a];
    const std::string& opposite = arms[(a + 2) % 4];
    const std::string& left = arms[(a + 1) % 4];
    const std::string& right = arms[(a + 3) % 4];
    expect_connector(map, from, opposite, 0, LaneTurn::none);
    expect_connector(map, from, opposite, 1, LaneTurn::none);
    expect_connector(map, from, right, 0, LaneTurn::right);
    expect_connector(map, from, left, 1, LaneTurn::left);
    for (std::string id : {from + "_" + opposite + "_0", from + "_" + opposite + "_1",
                           from + "_" + right + "_0", from + "_" + left + "_1"})
      expected.insert(id);
  }
  std::set<std::string> connectors;
  for (const LaneDescription& lane : map.lanes)
    if (!lane.junction.empty()) connectors.insert(lane.id);
  EXPECT_EQ(connectors, expected);
  // The contract's examples.
  EXPECT_NE(find_lane(map, "south_east_0"), nullptr);
  EXPECT_NE(find_lane(map, "south_west_1"), nullptr);
}

TEST(BuiltinCrossroads, TrafficLightsStopLinesAndCrosswalks) {
  MapDescription map = generate_builtin_map("crossroads", {});
  ASSERT_EQ(map.traffic_lights.size(), 4u);
  for (std::string arm : {"north", "east", "south", "west"}) {
    SCOPED_TRACE(arm);
    const TrafficLightDescription& light = light_of(map, "light_" + arm);
    auto crossings = crossings_by_lane(light.lanes);
    ASSERT_EQ(crossings.size(), 2u);
    for (std::string lane : {arm + "_in_0", arm + "_in_1"}) {
      ASSERT_TRUE(crossings.contains(lane)) << lane;
      EXPECT_DOUBLE_EQ(crossings[lane].first, 144);
      EXPECT_DOUBLE_EQ(crossings[lane].second, 144);
      // 16 m from the centre.
      MapPoint at = centre_line(lane_of(map, lane)).point_at(144);
      EXPECT_NEAR(std::max(std::abs(at.x), std::abs(at.y)), 16, 1e-9);
    }
    ASSERT_EQ(light.stop_lines.size(), 1u);
    for (MapPoint point : light.stop_lines[0])
      EXPECT_NEAR(std::max(std::abs(point.x), std::abs(point.y)), 16, 1e-9);

    const CrosswalkDescription& crosswalk = crosswalk_of(map, "crosswalk_" + arm);
    auto crossed = crossings_by_lane(crosswalk.lanes);
    EXPECT_EQ(crossed.size(), 4u);
    for (std::string lane : {arm + "_in_0", arm + "_in_1"}) {
      EXPECT_DOUBLE_EQ(crossed[lane].first, 145) << lane;
      EXPECT_DOUBLE_EQ(crossed[lane].second, 149) << lane;
    }
    for (std::string lane : {arm + "_out_0", arm + "_out_1"}) {
      EXPECT_DOUBLE_EQ(crossed[lane].first, 1) << lane;
      EXPECT_DOUBLE_EQ(crossed[lane].second, 5) << lane;
    }
    // Across the whole arm, pavements included, 11 to 15 m from the centre.
    bool along_x = arm == "east" || arm == "west";
    double near = 15, far = 0, half_width = 0;
    for (MapPoint corner : crosswalk.outline) {
      double along = std::abs(along_x ? corner.x : corner.y);
      near = std::min(near, along);
      far = std::max(far, along);
      half_width = std::max(half_width, std::abs(along_x ? corner.y : corner.x));
    }
    EXPECT_DOUBLE_EQ(near, 11);
    EXPECT_DOUBLE_EQ(far, 15);
    EXPECT_DOUBLE_EQ(half_width, 10);
  }
}

TEST(BuiltinCrossroads, FixedSignalPlanOf60Seconds) {
  MapDescription map = generate_builtin_map("crossroads", {});
  for (std::string arm : {"north", "south"}) {
    const SignalPlan& plan = *light_of(map, "light_" + arm).plan;
    EXPECT_DOUBLE_EQ(plan_period(plan), 60);
    expect_colour(plan, 0, 25, SignalColour::green, arm);
    expect_colour(plan, 25, 28, SignalColour::yellow, arm);
    expect_colour(plan, 28, 60, SignalColour::red, arm);
    expect_colour(plan, 60, 85, SignalColour::green, arm + " next cycle");
  }
  for (std::string arm : {"east", "west"}) {
    const SignalPlan& plan = *light_of(map, "light_" + arm).plan;
    EXPECT_DOUBLE_EQ(plan_period(plan), 60);
    expect_colour(plan, 0, 30, SignalColour::red, arm);
    expect_colour(plan, 30, 55, SignalColour::green, arm);
    expect_colour(plan, 55, 58, SignalColour::yellow, arm);
    expect_colour(plan, 58, 60, SignalColour::red, arm);
  }
  for (std::string arm : {"east", "west"}) {
    const SignalPlan& walk = *crosswalk_of(map, "crosswalk_" + arm).walk_plan;
    EXPECT_DOUBLE_EQ(plan_period(walk), 60);
    expect_colour(walk, 0, 25, SignalColour::green, "walk " + arm);
    expect_colour(walk, 25, 60, SignalColour::red, "walk " + arm);
  }
  for (std::string arm : {"north", "south"}) {
    const SignalPlan& walk = *crosswalk_of(map, "crosswalk_" + arm).walk_plan;
    expect_colour(walk, 0, 30, SignalColour::red, "walk " + arm);
    expect_colour(walk, 30, 55, SignalColour::green, "walk " + arm);
    expect_colour(walk, 55, 60, SignalColour::red, "walk " + arm);
  }
}

TEST(BuiltinCrossroads, SignalTimingParameters) {
  MapDescription map =
      generate_builtin_map("crossroads", {{"green", 40}, {"yellow", 4}, {"all_red", 1}});
  const SignalPlan& north = *light_of(map, "light_north").plan;
  const SignalPlan& east = *light_of(map, "light_east").plan;
  EXPECT_DOUBLE_EQ(plan_period(north), 90);
  expect_colour(north, 0, 40, SignalColour::green, "north");
  expect_colour(north, 40, 44, SignalColour::yellow, "north");
  expect_colour(north, 44, 90, SignalColour::red, "north");
  expect_colour(east, 0, 45, SignalColour::red, "east");
  expect_colour(east, 45, 85, SignalColour::green, "east");
  expect_colour(east, 85, 89, SignalColour::yellow, "east");
  expect_colour(east, 89, 90, SignalColour::red, "east");
  // Never green both ways.
  for (double t = 0; t < 90; t += 0.25)
    EXPECT_FALSE(colour_at(north, t) != SignalColour::red &&
                 colour_at(east, t) != SignalColour::red)
        << t;
}

TEST(BuiltinCrossroads, ParametersScaleTheJunction) {
  MapDescription map =
      generate_builtin_map("crossroads", {{"lanes", 3}, {"lane_width", 3}, {"arm_length", 80}});
  // Box half-size 3 * 3 + 3 = 12; the middle lane goes straight only.
  expect_straight_lanes(map, {{"south_in_0", {7.5, -92}, {7.5, -12}, 90, 80},
                              {"south_in_1", {4.5, -92}, {4.5, -12}, 90, 80},
                              {"south_in_2", {1.5, -92}, {1.5, -12}, 90, 80},
                              {"north_out_2", {1.5, 12}, {1.5, 92}, 90, 80}});
  EXPECT_EQ(lane_of(map, "south_in_1").successors, ids({"south_north_1"}));
  EXPECT_EQ(id_set(lane_of(map, "south_in_2").successors),
            id_set({"south_north_2", "south_west_2"}));
  EXPECT_EQ(id_set(lane_of(map, "south_in_0").successors),
            id_set({"south_east_0", "south_north_0"}));
  auto crossings = crossings_by_lane(light_of(map, "light_south").lanes);
  EXPECT_DOUBLE_EQ(crossings["south_in_2"].first, 74);
  auto crossed = crossings_by_lane(crosswalk_of(map, "crosswalk_south").lanes);
  EXPECT_DOUBLE_EQ(crossed["south_in_0"].first, 75);
  EXPECT_DOUBLE_EQ(crossed["south_in_0"].second, 79);

  MapDescription single = generate_builtin_map("crossroads", {{"lanes", 1}});
  EXPECT_EQ(id_set(lane_of(single, "south_in_0").successors),
            id_set({"south_east_0", "south_north_0", "south_west_0"}));
  EXPECT_EQ(generate_builtin_map("crossroads", {{"crosswalks", 0}}).crosswalks.size(), 0u);
}

TEST(BuiltinCrossroads, RouteThroughTheJunctionAndTheLightAhead) {
  RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  auto from = map.find_lane("south_in_0");
  auto to = map.find_lane("east_out_0");
  auto turn = map.find_lane("south_east_0");
  ASSERT_TRUE(from && to && turn);
  auto route = find_route(map, LanePosition{*from, 100, 0}, LanePosition{*to, 50, 0});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 3u);
  EXPECT_EQ(route->segments[0].lane, *from);
  EXPECT_EQ(route->segments[1].lane, *turn);
  EXPECT_EQ(route->segments[2].lane, *to);
  EXPECT_EQ(route->lane_changes, 0);
  EXPECT_NEAR(route->length, 50 + 4.75 * std::numbers::pi / 2 + 50, 0.01);

  auto light = next_feature_ahead(map, *route, 0, FeatureKind::traffic_light);
  ASSERT_TRUE(light);
  EXPECT_EQ(map.traffic_lights()[light->index].id, "light_south");
  EXPECT_NEAR(light->distance, 44, 1e-9);
  auto crosswalk = next_feature_ahead(map, *route, 0, FeatureKind::crosswalk);
  ASSERT_TRUE(crosswalk);
  EXPECT_EQ(map.crosswalks()[crosswalk->index].id, "crosswalk_south");
  EXPECT_NEAR(crosswalk->distance, 45, 1e-9);
  EXPECT_FALSE(lane_change_allowed(map, *turn, *from));
}

// ---------------------------------------------------------------------------------------------
// t_junction

TEST(BuiltinTJunction, TheCrossroadsWithoutItsNorthArm) {
  MapDescription map = generate_builtin_map("t_junction", {});
  std::vector<LaneRow> arm_lanes;
  for (const LaneRow& row : crossroads_arm_lanes())
    if (!row.id.starts_with("north")) arm_lanes.push_back(row);
  expect_straight_lanes(map, arm_lanes);
  EXPECT_EQ(find_lane(map, "north_in_0"), nullptr);

  std::set<std::string> connectors;
  for (const LaneDescription& lane : map.lanes)
    if (!lane.junction.empty()) connectors.insert(lane.id);
  EXPECT_EQ(connectors,
            (std::set<std::string>{"west_east_0", "west_east_1", "west_south_0", "east_west_0",
                                   "east_west_1", "east_south_1", "south_east_0", "south_west_1"}));
  expect_connector(map, "west", "east", 0, LaneTurn::none);
  expect_connector(map, "west", "east", 1, LaneTurn::none);
  expect_connector(map, "west", "south", 0, LaneTurn::right);
  expect_connector(map, "east", "west", 0, LaneTurn::none);
  expect_connector(map, "east", "west", 1, LaneTurn::none);
  expect_connector(map, "east", "south", 1, LaneTurn::left);
  expect_connector(map, "south", "east", 0, LaneTurn::right);
  expect_connector(map, "south", "west", 1, LaneTurn::left);
  EXPECT_EQ(map.lanes.size(), 12u + 8u);

  ASSERT_EQ(map.junctions.size(), 1u);
  double min_y = 0, max_y = 0, max_x = 0;
  for (MapPoint corner : map.junctions[0].outline) {
    min_y = std::min(min_y, corner.y);
    max_y = std::max(max_y, corner.y);
    max_x = std::max(max_x, std::abs(corner.x));
  }
  EXPECT_DOUBLE_EQ(min_y, -10);
  EXPECT_DOUBLE_EQ(max_y, 7);
  EXPECT_DOUBLE_EQ(max_x, 10);
}

TEST(BuiltinTJunction, StopSignOnTheSideRoadAndUncontrolledCrosswalks) {
  MapDescription map = generate_builtin_map("t_junction", {});
  EXPECT_TRUE(map.traffic_lights.empty());
  ASSERT_EQ(map.signs.size(), 1u);
  const SignDescription& stop = sign_of(map, "stop_south");
  EXPECT_EQ(stop.kind, SignKind::stop);
  auto crossings = crossings_by_lane(stop.lanes);
  EXPECT_EQ(crossings.size(), 2u);
  for (std::string lane : {"south_in_0", "south_in_1"}) {
    EXPECT_DOUBLE_EQ(crossings[lane].first, 144) << lane;
    EXPECT_DOUBLE_EQ(crossings[lane].second, 144) << lane;
  }
  ASSERT_EQ(map.crosswalks.size(), 3u);
  for (std::string arm : {"west", "east", "south"}) {
    const CrosswalkDescription& crosswalk = crosswalk_of(map, "crosswalk_" + arm);
    EXPECT_FALSE(crosswalk.walk_plan.has_value());
    auto crossed = crossings_by_lane(crosswalk.lanes);
    EXPECT_DOUBLE_EQ(crossed[arm + "_in_1"].first, 145);
    EXPECT_DOUBLE_EQ(crossed[arm + "_in_1"].second, 149);
    EXPECT_DOUBLE_EQ(crossed[arm + "_out_0"].first, 1);
    EXPECT_DOUBLE_EQ(crossed[arm + "_out_0"].second, 5);
  }

  RoadMap road_map = build_road_map(std::move(map));
  EXPECT_EQ(road_map.stop_sign_count(), 1u);
  auto from = road_map.find_lane("south_in_0");
  auto to = road_map.find_lane("east_out_0");
  ASSERT_TRUE(from && to);
  auto route = find_route(road_map, LanePosition{*from, 0, 0}, LanePosition{*to, 20, 0});
  ASSERT_TRUE(route);
  auto sign = next_feature_ahead(road_map, *route, 0, FeatureKind::stop_sign);
  ASSERT_TRUE(sign);
  EXPECT_NEAR(sign->distance, 144, 1e-9);
}

TEST(BuiltinTJunction, WithThreeLanesTheSideRoadsInnerLanesTurnLeft) {
  MapDescription map = generate_builtin_map("t_junction", {{"lanes", 3}});
  EXPECT_EQ(lane_of(map, "south_in_0").successors, ids({"south_east_0"}));
  EXPECT_EQ(lane_of(map, "south_in_1").successors, ids({"south_west_1"}));
  EXPECT_EQ(lane_of(map, "south_in_2").successors, ids({"south_west_2"}));
  EXPECT_EQ(lane_of(map, "west_in_1").successors, ids({"west_east_1"}));
  EXPECT_EQ(id_set(lane_of(map, "east_in_2").successors), id_set({"east_west_2", "east_south_2"}));
  MapDescription single = generate_builtin_map("t_junction", {{"lanes", 1}});
  EXPECT_EQ(id_set(lane_of(single, "south_in_0").successors),
            id_set({"south_east_0", "south_west_0"}));
}

// ---------------------------------------------------------------------------------------------
// junction angle (crossroads and t_junction)

double distance_to_segment(MapPoint p, MapPoint a, MapPoint b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double squared = dx * dx + dy * dy;
  double t = squared > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / squared : 0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, {a.x + t * dx, a.y + t * dy});
}

double distance_to_outline(MapPoint p, const std::vector<MapPoint>& polygon) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i)
    nearest =
        std::min(nearest, distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return nearest;
}

// Inside the polygon, or on its outline within `tolerance`.
bool inside_or_on(MapPoint p, const std::vector<MapPoint>& polygon, double tolerance = 1e-6) {
  if (distance_to_outline(p, polygon) <= tolerance) return true;
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const MapPoint a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

double signed_area(const std::vector<MapPoint>& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const MapPoint a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

MapPoint direction_of(double degrees_ccw) {
  return {std::cos(radians(degrees_ccw)), std::sin(radians(degrees_ccw))};
}
double along(MapPoint p, MapPoint direction) { return p.x * direction.x + p.y * direction.y; }
// Distance from the line through the centre along `direction`.
double off_axis(MapPoint p, MapPoint direction) {
  return std::abs(p.x * direction.y - p.y * direction.x);
}

struct AngledJunction {
  std::string map;
  double angle = 90;
  int lanes = 2;
};

std::string describe(const AngledJunction& junction) {
  return junction.map + " angle=" + std::to_string(junction.angle) +
         " lanes=" + std::to_string(junction.lanes);
}

MapDescription generate_angled_junction(const AngledJunction& junction) {
  return generate_builtin_map(
      junction.map, {{"angle", junction.angle}, {"lanes", static_cast<double>(junction.lanes)}});
}

std::vector<AngledJunction> angled_junctions() {
  std::vector<AngledJunction> junctions;
  for (std::string map : {"crossroads", "t_junction"})
    for (double angle : {45.0, 60.0, 80.0, 100.0, 120.0, 135.0})
      for (int lanes : {1, 2, 3}) junctions.push_back({map, angle, lanes});
  return junctions;
}

TEST(BuiltinJunctionAngle, TheCrossingRoadsLanesHeadAtTheAngle) {
  for (const AngledJunction& junction : angled_junctions()) {
    SCOPED_TRACE(describe(junction));
    MapDescription map = generate_angled_junction(junction);
    const bool crossroads = junction.map == "crossroads";
    for (int k = 0; k < junction.lanes; ++k) {
      const std::string lane = std::to_string(k);
      // South arm `angle` counter-clockwise from the west arm: its traffic heads at `angle`.
      expect_heading(start_heading(lane_of(map, "south_in_" + lane)), junction.angle, 1e-9,
                     "south_in");
      expect_heading(end_heading(lane_of(map, "south_in_" + lane)), junction.angle, 1e-9,
                     "south_in");
      expect_heading(start_heading(lane_of(map, "south_out_" + lane)), junction.angle + 180, 1e-9,
                     "south_out");
      expect_heading(start_heading(lane_of(map, "west_in_" + lane)), 0, 1e-9, "west_in");
      expect_heading(start_heading(lane_of(map, "east_in_" + lane)), 180, 1e-9, "east_in");
      EXPECT_NEAR(centre_line(lane_of(map, "south_in_" + lane)).length(), 150, 1e-9);
      if (crossroads) {
        expect_heading(start_heading(lane_of(map, "north_out_" + lane)), junction.angle, 1e-9,
                       "north_out");
        // Straight over: one line from the south arm into the north arm.
        const LaneDescription& over = lane_of(map, "south_north_" + lane);
        EXPECT_EQ(over.turn, LaneTurn::none);
        EXPECT_EQ(over.centre_line.size(), 2u);
        expect_heading(start_heading(over), junction.angle, 1e-9, "south_north");
      }
    }
    // The turns keep their sides: from the west arm, south is a right turn by 180° - angle,
    // from the south arm, east is a right turn by the angle (within the half chord by which an
    // arc's first and last chords turn less than its tangents).
    const LaneDescription& west_south = lane_of(map, "west_south_0");
    EXPECT_EQ(west_south.turn, LaneTurn::right);
    EXPECT_NEAR(degrees(angle_difference(end_heading(west_south), start_heading(west_south))),
                junction.angle - 180, 0.6);
    const LaneDescription& south_east = lane_of(map, "south_east_0");
    EXPECT_EQ(south_east.turn, LaneTurn::right);
    EXPECT_NEAR(degrees(angle_difference(end_heading(south_east), start_heading(south_east))),
                -junction.angle, 0.6);
    const LaneDescription& south_west =
        lane_of(map, "south_west_" + std::to_string(junction.lanes - 1));
    EXPECT_EQ(south_west.turn, LaneTurn::left);
    EXPECT_NEAR(degrees(angle_difference(end_heading(south_west), start_heading(south_west))),
                180 - junction.angle, 0.6);
  }
}

MapPoint arm_direction(const std::string& arm, double angle) {
  if (arm == "west") return {-1, 0};
  if (arm == "east") return {1, 0};
  return direction_of(arm == "north" ? angle : angle + 180);
}

TEST(BuiltinJunctionAngle, ArmsBeginWhereTheyClearTheCrossingRoadAndConnectorsStayInside) {
  for (const AngledJunction& junction : angled_junctions()) {
    SCOPED_TRACE(describe(junction));
    MapDescription map = generate_angled_junction(junction);
    const bool crossroads = junction.map == "crossroads";
    const double half_size = junction.lanes * 3.5 + 3;  // road and pavements, from the axis
    ASSERT_EQ(map.junctions.size(), 1u);
    const std::vector<MapPoint>& outline = map.junctions[0].outline;
    EXPECT_GT(signed_area(outline), 0) << "counter-clockwise";
    for (std::size_t i = 0; i < outline.size(); ++i)
      EXPECT_GT(distance(outline[i], outline[(i + 1) % outline.size()]), 1e-6) << "repeated";

    const std::vector<std::string> arms =
        crossroads ? ids({"north", "east", "south", "west"}) : ids({"west", "east", "south"});
    // Where each arm begins: all its lanes begin (or end) there, on the junction's outline.
    std::map<std::string, double> starts;
    for (const std::string& arm : arms) {
      const MapPoint outward = arm_direction(arm, junction.angle);
      starts[arm] = along(lane_of(map, arm + "_in_0").centre_line.back(), outward);
      for (int k = 0; k < junction.lanes; ++k)
        for (const std::string& way : {std::string("_in_"), std::string("_out_")}) {
          const LaneDescription& lane = lane_of(map, arm + way + std::to_string(k));
          const MapPoint at_junction =
              way == "_in_" ? lane.centre_line.back() : lane.centre_line.front();
          EXPECT_NEAR(along(at_junction, outward), starts[arm], 1e-9) << lane.id;
          EXPECT_LT(distance_to_outline(at_junction, outline), 1e-9) << lane.id;
        }
    }
    // Each arm's start, pavements included, is clear of every arm of the other road (at least
    // half_size from its axis where it lies on that arm's side), touching it at the acute corner.
    double closest = std::numeric_limits<double>::infinity();
    for (const std::string& arm : arms) {
      const MapPoint outward = arm_direction(arm, junction.angle);
      for (double side : {-1.0, 1.0}) {
        const MapPoint edge{starts[arm] * outward.x - side * half_size * outward.y,
                            starts[arm] * outward.y + side * half_size * outward.x};
        for (const std::string& other : arms) {
          const MapPoint other_outward = arm_direction(other, junction.angle);
          if (std::abs(along(other_outward, outward)) > 0.99) continue;  // the same road
          if (along(edge, other_outward) <= 1e-9) continue;
          EXPECT_GE(off_axis(edge, other_outward), half_size - 1e-9) << arm << " on " << other;
          closest = std::min(closest, off_axis(edge, other_outward));
        }
      }
    }
    EXPECT_NEAR(closest, half_size, 1e-9);
    // The acute corner's arms begin half_size / tan(acute / 2) out; on the T's main road the arm
    // at the obtuse corner begins at half_size.
    const double acute = radians(std::min(junction.angle, 180 - junction.angle));
    const double acute_start = half_size / std::tan(acute / 2);
    EXPECT_NEAR(starts["south"], acute_start, 1e-9);
    EXPECT_NEAR(starts[junction.angle <= 90 ? "west" : "east"], acute_start, 1e-9);
    EXPECT_NEAR(starts[junction.angle <= 90 ? "east" : "west"],
                crossroads ? acute_start : half_size, 1e-9);

    for (const LaneDescription& lane : map.lanes) {
      if (lane.junction.empty()) continue;
      for (MapPoint point : lane.centre_line)
        EXPECT_TRUE(inside_or_on(point, outline))
            << lane.id << " leaves the junction at (" << point.x << ", " << point.y << ")";
    }

    // Stop lines 6 m and crosswalks 1 to 5 m outside their arm's start, across their arm.
    auto expect_stop_line = [&](const std::vector<MapPoint>& line, const std::string& arm) {
      for (MapPoint point : line)
        EXPECT_NEAR(along(point, arm_direction(arm, junction.angle)), starts[arm] + 6, 1e-9);
    };
    if (crossroads) {
      for (const std::string& arm : arms)
        expect_stop_line(light_of(map, "light_" + arm).stop_lines.at(0), arm);
    } else {
      expect_stop_line(sign_of(map, "stop_south").stop_lines.at(0), "south");
      double north_edge = -std::numeric_limits<double>::infinity();
      for (MapPoint corner : outline) north_edge = std::max(north_edge, corner.y);
      EXPECT_NEAR(north_edge, junction.lanes * 3.5, 1e-9) << "the north pavement runs on";
    }
    EXPECT_NEAR(along(centre_line(lane_of(map, "south_in_0")).point_at(144),
                      arm_direction("south", junction.angle)),
                starts["south"] + 6, 1e-9);
    for (const CrosswalkDescription& crosswalk : map.crosswalks) {
      SCOPED_TRACE(crosswalk.id);
      const std::string arm = crosswalk.id.substr(std::string("crosswalk_").size());
      const MapPoint outward = arm_direction(arm, junction.angle);
      double near = std::numeric_limits<double>::infinity(), far = 0;
      for (MapPoint corner : crosswalk.outline) {
        near = std::min(near, along(corner, outward));
        far = std::max(far, along(corner, outward));
      }
      EXPECT_NEAR(near, starts[arm] + 1, 1e-9);
      EXPECT_NEAR(far, starts[arm] + 5, 1e-9);
      for (const CrosswalkDescription& other : map.crosswalks) {
        if (other.id == crosswalk.id) continue;
        for (MapPoint corner : other.outline)
          EXPECT_FALSE(inside_or_on(corner, crosswalk.outline, 0)) << other.id << " overlaps";
      }
    }
  }
}

TEST(BuiltinJunctionAngle, TurnsCircleTheKerbCornerStraightOnFirstAtTheObtuseOne) {
  // At 60°: the west arm meets the south arm at 60° (acute) and the north arm at 120°
  // (obtuse). Half-size 10, so the acute corner lies 10 / tan 30° = 17.32 m along both arms,
  // where they begin, and the obtuse one 10 / tan 60° = 5.77 m along.
  MapDescription map = generate_builtin_map("crossroads", {{"angle", 60}});
  const double acute = 10 / std::tan(radians(30));
  const double obtuse = 10 / std::tan(radians(60));
  EXPECT_NEAR(-lane_of(map, "west_in_0").centre_line.back().x, acute, 1e-9);

  // Right into the south arm: all arc, radius 10 - 5.25 about the corner (-17.32, -10).
  const LaneDescription& right = lane_of(map, "west_south_0");
  for (MapPoint point : right.centre_line) EXPECT_NEAR(distance(point, {-acute, -10}), 4.75, 1e-9);
  EXPECT_NEAR(centre_line(right).length(), 4.75 * radians(120), 2e-3);

  // Left into the north arm: straight along y = -1.75 to x = -5.77, a 60° arc of radius
  // 10 + 1.75 about the corner (-5.77, 10), then straight along the north out lane.
  const LaneDescription& left = lane_of(map, "west_north_1");
  const MapPoint corner{-obtuse, 10};
  const MapPoint north = direction_of(60);
  int straight_in = 0, on_arc = 0, straight_out = 0;
  for (MapPoint point : left.centre_line) {
    if (std::abs(point.y + 1.75) < 1e-9 && point.x <= -obtuse + 1e-9) {
      ++straight_in;
    } else if (std::abs(distance(point, corner) - 11.75) < 1e-9) {
      ++on_arc;
    } else {
      // On the north out lane's line: 1.75 m right of the north axis.
      EXPECT_NEAR(point.x * north.y - point.y * north.x, 1.75, 1e-9) << point.x << ", " << point.y;
      ++straight_out;
    }
  }
  EXPECT_GE(straight_in, 2);
  EXPECT_GT(on_arc, 10);
  EXPECT_GE(straight_out, 1);
  EXPECT_NEAR(centre_line(left).length(), 2 * (acute - obtuse) + 11.75 * radians(60), 2e-3);
}

TEST(BuiltinJunctionAngle, ARightAngleIsTheDefaultMapExactly) {
  for (std::string name : {"crossroads", "t_junction"}) {
    SCOPED_TRACE(name);
    MapDescription given = generate_builtin_map(name, {{"angle", 90}});
    MapDescription by_default = generate_builtin_map(name, {});
    ASSERT_EQ(given.lanes.size(), by_default.lanes.size());
    for (std::size_t i = 0; i < given.lanes.size(); ++i)
      EXPECT_EQ(given.lanes[i].centre_line, by_default.lanes[i].centre_line);
    EXPECT_EQ(given.junctions[0].outline, by_default.junctions[0].outline);
    EXPECT_EQ(given.junctions[0].outline.size(), 4u);
  }
}

TEST(BuiltinJunctionAngle, RoutesThroughAnObliqueJunctionFindTheLightAhead) {
  RoadMap map = build_road_map(generate_builtin_map("crossroads", {{"angle", 70}}));
  auto from = map.find_lane("south_in_0");
  auto to = map.find_lane("east_out_0");
  ASSERT_TRUE(from && to);
  auto route = find_route(map, LanePosition{*from, 100, 0}, LanePosition{*to, 50, 0});
  ASSERT_TRUE(route);
  ASSERT_EQ(route->segments.size(), 3u);
  EXPECT_EQ(map.lane(route->segments[1].lane).id, "south_east_0");
  auto light = next_feature_ahead(map, *route, 0, FeatureKind::traffic_light);
  ASSERT_TRUE(light);
  EXPECT_EQ(map.traffic_lights()[light->index].id, "light_south");
  EXPECT_NEAR(light->distance, 44, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// curve

TEST(BuiltinCurve, LanesMatchTheContract) {
  MapDescription map = generate_builtin_map("curve", {});
  EXPECT_EQ(map.name, "curve");
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"fwd_0", "fwd_1", "bwd_0", "bwd_1"}));
  struct CurveRow {
    std::string id;
    MapPoint start;
    MapPoint end;
    double start_heading = 0;
    double end_heading = 0;
    double radius = 0;
    double length = 0;
    double bend_end = 0;
    MapPoint arc_centre{100, 100};
  };
  const std::vector<CurveRow> rows = {
      {"fwd_0", {0, -5.25}, {205.25, 200}, 0, 90, 105.25, 365.33, 265.33},
      {"fwd_1", {0, -1.75}, {201.75, 200}, 0, 90, 101.75, 359.83, 259.83},
      {"bwd_1", {198.25, 200}, {0, 1.75}, 270, 180, 98.25, 354.33, 254.33},
      {"bwd_0", {194.75, 200}, {0, 5.25}, 270, 180, 94.75, 348.83, 248.83}};
  for (const CurveRow& row : rows) {
    SCOPED_TRACE(row.id);
    const LaneDescription& lane = lane_of(map, row.id);
    Polyline line = centre_line(lane);
    expect_point(lane.centre_line.front(), row.start, kContractTolerance, "start");
    expect_point(lane.centre_line.back(), row.end, kContractTolerance, "end");
    expect_heading(start_heading(lane), row.start_heading, 1e-6, "start");
    expect_heading(end_heading(lane), row.end_heading, 1e-6, "end");
    EXPECT_NEAR(line.length(), row.length, kContractTolerance);
    // The bend, 100 < s < bend_end: straight before and after, on the circle in between.
    expect_heading(line.heading_at(99.5), row.start_heading, 1e-6, "before the bend");
    expect_heading(line.heading_at(row.bend_end + 0.5), row.end_heading, 1e-6, "after the bend");
    for (double s = 100; s <= row.bend_end; s += 5)
      EXPECT_NEAR(distance(line.point_at(s), row.arc_centre), row.radius, 2e-3) << "s = " << s;
    EXPECT_NEAR(distance(line.point_at(row.bend_end + 5), row.arc_centre), row.radius, 0.2);
    EXPECT_GT(distance(line.point_at(row.bend_end + 5), row.arc_centre), row.radius + 0.1);
  }
  EXPECT_EQ(lane_of(map, "fwd_0").left_forward_neighbours, ids({"fwd_1"}));
  EXPECT_EQ(lane_of(map, "fwd_1").left_reverse_neighbours, ids({"bwd_1"}));
  EXPECT_EQ(lane_of(map, "bwd_1").left_reverse_neighbours, ids({"fwd_1"}));
  EXPECT_EQ(lane_of(map, "fwd_1").left_boundary_type, BoundaryType::double_yellow);
  EXPECT_DOUBLE_EQ(lane_of(map, "fwd_0").speed_limit, 22.2);
  EXPECT_TRUE(map.junctions.empty());
}

TEST(BuiltinCurve, ARightBendPutsTheForwardLanesInside) {
  MapDescription map = generate_builtin_map(
      "curve", {{"angle", -90}, {"radius", 50}, {"straight_before", 20}, {"straight_after", 30}});
  // Centre line: (0, 0) -> (20, 0), arc about (20, -50) to (70, -50), then south to (70, -80).
  const LaneDescription& fwd_0 = lane_of(map, "fwd_0");
  expect_point(fwd_0.centre_line.front(), {0, -5.25}, 1e-9, "start");
  expect_point(fwd_0.centre_line.back(), {64.75, -80}, 1e-9, "end");
  expect_heading(end_heading(fwd_0), 270, 1e-6, "end");
  EXPECT_NEAR(centre_line(fwd_0).length(), 20 + 44.75 * std::numbers::pi / 2 + 30, 2e-3);
  const LaneDescription& bwd_0 = lane_of(map, "bwd_0");
  expect_point(bwd_0.centre_line.front(), {75.25, -80}, 1e-9, "bwd start");
  expect_heading(start_heading(bwd_0), 90, 1e-6, "bwd start");
}

TEST(BuiltinCurve, QueriesOnTheBuiltMap) {
  RoadMap map = build_road_map(generate_builtin_map("curve", {}));
  auto fwd_0 = map.find_lane("fwd_0");
  ASSERT_TRUE(fwd_0);
  // Half-way round the bend: 45° on the circle of radius 105.25 about (100, 100).
  double s = 100 + 105.25 * std::numbers::pi / 4;
  auto pose = lane_pose_at(map, *fwd_0, s);
  ASSERT_TRUE(pose);
  expect_point(pose->position,
               {100 + 105.25 * std::sin(std::numbers::pi / 4),
                100 - 105.25 * std::cos(std::numbers::pi / 4)},
               kContractTolerance, "mid-bend");
  expect_heading(pose->heading, 45, 0.6, "mid-bend");
  auto projection = project_to_lane(map, {205.25, 150}, std::numbers::pi / 2);
  ASSERT_TRUE(projection);
  EXPECT_EQ(projection->lane, *fwd_0);
  EXPECT_NEAR(projection->s, 265.33 + 50, kContractTolerance);
}

// ---------------------------------------------------------------------------------------------
// roundabout

TEST(BuiltinRoundabout, RingLaneIsAClosedLoopWithSEqualToRadiusTimesAngle) {
  MapDescription map = generate_builtin_map("roundabout", {});
  const LaneDescription& ring = lane_of(map, "ring_0");
  Polyline line = centre_line(ring);
  EXPECT_NEAR(line.length(), 125.66, kContractTolerance);
  EXPECT_EQ(ring.centre_line.front(), (MapPoint{20, 0}));
  EXPECT_EQ(ring.centre_line.back(), ring.centre_line.front());
  EXPECT_TRUE(contains(ring.successors, "ring_0"));
  EXPECT_TRUE(contains(ring.predecessors, "ring_0"));
  EXPECT_DOUBLE_EQ(ring.speed_limit, 8.3);
  EXPECT_EQ(ring.left_boundary_type, BoundaryType::curb);
  for (MapPoint point : ring.centre_line) EXPECT_NEAR(distance(point, {0, 0}), 20, 1e-9);
  expect_point(line.point_at(31.42), {0, 20}, kContractTolerance, "north");
  expect_point(line.point_at(62.83), {-20, 0}, kContractTolerance, "west");
  expect_point(line.point_at(94.25), {0, -20}, kContractTolerance, "south");
  expect_heading(line.heading_at(0), 90, 0.6, "counter-clockwise");
}

TEST(BuiltinRoundabout, ArmLanesMatchTheContract) {
  MapDescription map = generate_builtin_map("roundabout", {});
  expect_straight_lanes(map, {{"north_in_0", {-1.75, 125}, {-1.75, 25}, 270, 100},
                              {"north_out_0", {1.75, 25}, {1.75, 125}, 90, 100},
                              {"east_in_0", {125, 1.75}, {25, 1.75}, 180, 100},
                              {"east_out_0", {25, -1.75}, {125, -1.75}, 0, 100},
                              {"south_in_0", {1.75, -125}, {1.75, -25}, 90, 100},
                              {"south_out_0", {-1.75, -25}, {-1.75, -125}, 270, 100},
                              {"west_in_0", {-125, -1.75}, {-25, -1.75}, 0, 100},
                              {"west_out_0", {-25, 1.75}, {-125, 1.75}, 180, 100}});
  EXPECT_EQ(lane_of(map, "north_in_0").left_reverse_neighbours, ids({"north_out_0"}));
  EXPECT_DOUBLE_EQ(lane_of(map, "north_in_0").speed_limit, 13.9);
  EXPECT_EQ(map.lanes.size(), 8u + 1u + 8u);
}

TEST(BuiltinRoundabout, EntriesAndExitsMeetTheRingAtTheTabulatedS) {
  MapDescription map = generate_builtin_map("roundabout", {});
  Polyline ring = centre_line(lane_of(map, "ring_0"));
  struct JoinRow {
    std::string arm;
    double entry_s = 0;
    double exit_s = 0;
  };
  for (const JoinRow& row : std::vector<JoinRow>{{"east", 5.24, 120.43},
                                                 {"north", 36.65, 26.18},
                                                 {"west", 68.07, 57.60},
                                                 {"south", 99.48, 89.01}}) {
    SCOPED_TRACE(row.arm);
    const LaneDescription& entry = lane_of(map, row.arm + "_entry");
    const LaneDescription& exit = lane_of(map, row.arm + "_exit");
    EXPECT_EQ(entry.predecessors, ids({row.arm + "_in_0"}));
    EXPECT_EQ(entry.successors, ids({"ring_0"}));
    EXPECT_EQ(exit.predecessors, ids({"ring_0"}));
    EXPECT_EQ(exit.successors, ids({row.arm + "_out_0"}));
    EXPECT_EQ(entry.turn, LaneTurn::right);
    EXPECT_EQ(entry.junction, "roundabout");
    PolylineProjection joins = ring.project(entry.centre_line.back());
    EXPECT_NEAR(joins.s, row.entry_s, kContractTolerance);
    EXPECT_LT(joins.distance, 1e-3);
    expect_point(entry.centre_line.back(), ring.point_at(row.entry_s), kContractTolerance,
                 "entry end");
    PolylineProjection leaves = ring.project(exit.centre_line.front());
    EXPECT_NEAR(leaves.s, row.exit_s, kContractTolerance);
    EXPECT_LT(leaves.distance, 1e-3);
    // Tangent to the ring where they meet it.
    expect_heading(end_heading(entry), degrees(ring.heading_at(joins.s)), 0.6, "entry");
    expect_heading(start_heading(exit), degrees(ring.heading_at(leaves.s)), 0.6, "exit");
  }
}

TEST(BuiltinRoundabout, YieldSignsEndEveryInLane) {
  MapDescription map = generate_builtin_map("roundabout", {});
  EXPECT_TRUE(map.traffic_lights.empty());
  ASSERT_EQ(map.signs.size(), 4u);
  for (std::string arm : {"north", "east", "south", "west"}) {
    const SignDescription& yield = sign_of(map, "yield_" + arm);
    EXPECT_EQ(yield.kind, SignKind::yield);
    ASSERT_EQ(yield.lanes.size(), 1u);
    EXPECT_EQ(yield.lanes[0].lane, arm + "_in_0");
    EXPECT_DOUBLE_EQ(yield.lanes[0].s_begin, 100);
    EXPECT_DOUBLE_EQ(yield.lanes[0].s_end, 100);
  }
  RoadMap road_map = build_road_map(std::move(map));
  EXPECT_EQ(road_map.yield_sign_count(), 4u);
  auto ring = road_map.find_lane("ring_0");
  ASSERT_TRUE(ring);
  // "ring_0" -> s is at radius 20, angle s / 20.
  auto pose = lane_pose_at(road_map, *ring, 110);
  ASSERT_TRUE(pose);
  expect_point(pose->position, {20 * std::cos(110.0 / 20), 20 * std::sin(110.0 / 20)},
               kContractTolerance, "ring_0 -> 110");
}

TEST(BuiltinRoundabout, LargerRingsPushTheArmsOutWhereTheEntryCurveNeedsIt) {
  MapDescription map =
      generate_builtin_map("roundabout", {{"ring_radius", 60}, {"entry_angle", 30}});
  Polyline ring = centre_line(lane_of(map, "ring_0"));
  EXPECT_NEAR(ring.length(), 120 * std::numbers::pi, 2e-3);
  // The east entry joins at 30°: s = 60 * pi / 6.
  PolylineProjection joins = ring.project(lane_of(map, "east_entry").centre_line.back());
  EXPECT_NEAR(joins.s, 10 * std::numbers::pi, kContractTolerance);
  const LaneDescription& east_in = lane_of(map, "east_in_0");
  EXPECT_GT(east_in.centre_line.back().x, 65);
  EXPECT_NEAR(centre_line(east_in).length(), 100, 1e-9);
}

// Whether segments ab and cd cross at a point inside both (touching or running along each other
// does not count).
bool segments_cross(MapPoint a, MapPoint b, MapPoint c, MapPoint d) {
  auto side = [](MapPoint p, MapPoint q, MapPoint r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  const double c_side = side(a, b, c), d_side = side(a, b, d);
  const double a_side = side(c, d, a), b_side = side(c, d, b);
  return ((c_side > 0 && d_side < 0) || (c_side < 0 && d_side > 0)) &&
         ((a_side > 0 && b_side < 0) || (a_side < 0 && b_side > 0));
}

bool centre_lines_cross(const LaneDescription& first, const LaneDescription& second) {
  for (std::size_t i = 0; i + 1 < first.centre_line.size(); ++i)
    for (std::size_t j = 0; j + 1 < second.centre_line.size(); ++j)
      if (segments_cross(first.centre_line[i], first.centre_line[i + 1], second.centre_line[j],
                         second.centre_line[j + 1]))
        return true;
  return false;
}

// The tightest radius along a centre line: the circle through three neighbouring points.
double tightest_radius(const LaneDescription& lane) {
  double tightest = std::numeric_limits<double>::infinity();
  const std::vector<MapPoint>& points = lane.centre_line;
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const MapPoint a = points[i - 1], b = points[i], c = points[i + 1];
    const double twice_area = std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    if (twice_area < 1e-12) continue;
    tightest =
        std::min(tightest, distance(a, b) * distance(b, c) * distance(c, a) / (2 * twice_area));
  }
  return tightest;
}

// The polar angle, in degrees from +x, at which a connector meets the ring.
double ring_angle_at(MapPoint point) { return degrees(std::atan2(point.y, point.x)); }

struct RingSize {
  double ring_radius = 0;
  double lane_width = 3.5;
};

std::string describe(const RingSize& size) {
  return "ring_radius=" + std::to_string(size.ring_radius) +
         " lane_width=" + std::to_string(size.lane_width);
}

TEST(BuiltinRoundabout, MiniToLargeRingsAreClosedUncrossedAndEveryExitIsReachable) {
  // Mini (10 m diameter, the smallest), compact, normal and large (200 m) roundabouts.
  for (const RingSize& size : std::vector<RingSize>{
           {5, 3.5}, {5, 3.75}, {6.5, 2.75}, {12.5, 3.25}, {16, 3.5}, {50, 3.5}, {100, 3.75}}) {
    SCOPED_TRACE(describe(size));
    const double r = size.ring_radius;
    MapDescription map =
        generate_builtin_map("roundabout", {{"ring_radius", r}, {"lane_width", size.lane_width}});
    const LaneDescription& ring = lane_of(map, "ring_0");
    EXPECT_EQ(ring.centre_line.front(), ring.centre_line.back()) << "closed";
    for (MapPoint point : ring.centre_line) EXPECT_NEAR(distance(point, {0, 0}), r, 1e-9);
    EXPECT_NEAR(centre_line(ring).length(), 2 * std::numbers::pi * r, 2e-3 * r);
    EXPECT_GT(r - size.lane_width / 2, 3) << "a central island";

    const std::vector<std::string> arms = {"east", "north", "west", "south"};
    for (std::size_t a = 0; a < arms.size(); ++a) {
      SCOPED_TRACE(arms[a]);
      const LaneDescription& entry = lane_of(map, arms[a] + "_entry");
      const LaneDescription& exit = lane_of(map, arms[a] + "_exit");
      const double axis = 90.0 * static_cast<double>(a);
      // Joins after the arm's axis and before the next arm's exit leaves (90° on, mirrored).
      const double joins = degrees(
          angle_difference(radians(ring_angle_at(entry.centre_line.back())), radians(axis)));
      const double leaves = degrees(
          angle_difference(radians(axis), radians(ring_angle_at(exit.centre_line.front()))));
      EXPECT_GE(joins, 15 - 1e-9);
      EXPECT_LE(joins, 42 + 1e-9);
      EXPECT_NEAR(leaves, joins, 1e-6);
      // Curves a car can drive, which never reach inside the ring's centre line.
      EXPECT_GE(tightest_radius(entry), 4.25 * 0.999);
      EXPECT_GE(tightest_radius(exit), 4.25 * 0.999);
      for (const LaneDescription* connector : {&entry, &exit})
        for (MapPoint point : connector->centre_line)
          EXPECT_GE(distance(point, {0, 0}), r - 1e-9) << connector->id;
      // Arm lanes begin outside the ring, clear of the neighbouring arms.
      MapPoint arm_end = lane_of(map, arms[a] + "_in_0").centre_line.back();
      EXPECT_GE(distance(arm_end, {0, 0}), r + 5 - 1e-9);
    }
    // No two lanes off the ring cross (entries and exits touch the ring only where they join it).
    for (const LaneDescription& first : map.lanes)
      for (const LaneDescription& second : map.lanes) {
        if (first.id >= second.id || first.id == "ring_0" || second.id == "ring_0") continue;
        EXPECT_FALSE(centre_lines_cross(first, second)) << first.id << " x " << second.id;
      }

    RoadMap road_map = build_road_map(std::move(map));
    EXPECT_TRUE(road_map.warnings().empty());
    for (const std::string& from : arms)
      for (const std::string& to : arms) {
        auto in = road_map.find_lane(from + "_in_0");
        auto out = road_map.find_lane(to + "_out_0");
        ASSERT_TRUE(in && out);
        auto route = find_route(road_map, LanePosition{*in, 10, 0}, LanePosition{*out, 10, 0});
        ASSERT_TRUE(route) << from << " -> " << to;
        EXPECT_EQ(road_map.lane(route->segments[1].lane).id, from + "_entry");
      }
  }
}

TEST(BuiltinRoundabout, ASmallRingMovesTheEntriesRoundSoThatTheirCurvesStayDrivable) {
  // A 5 m ring with 3.5 m lanes: at 15° the entry curve would have to be negative; it joins at
  // asin((4.25 + 1.75) / (5 + 4.25)) = 40.4° with a curve of 4.25 m.
  MapDescription map = generate_builtin_map("roundabout", {{"ring_radius", 5}});
  const LaneDescription& entry = lane_of(map, "east_entry");
  EXPECT_NEAR(ring_angle_at(entry.centre_line.back()), degrees(std::asin(6.0 / 9.25)), 1e-6);
  EXPECT_NEAR(tightest_radius(entry), 4.25, 0.01);
  // A ring with room enough keeps the angle it is given.
  MapDescription roomy =
      generate_builtin_map("roundabout", {{"ring_radius", 8}, {"entry_angle", 30}});
  EXPECT_NEAR(ring_angle_at(lane_of(roomy, "east_entry").centre_line.back()), 30, 1e-6);
}

TEST(BuiltinRoundabout, LargeRingOf200MetresDiameter) {
  MapDescription map = generate_builtin_map("roundabout", {{"ring_radius", 100}});
  EXPECT_NEAR(centre_line(lane_of(map, "ring_0")).length(), 200 * std::numbers::pi, 0.2);
  PolylineProjection joins =
      centre_line(lane_of(map, "ring_0")).project(lane_of(map, "north_entry").centre_line.back());
  EXPECT_NEAR(joins.s, 100 * radians(90 + 15), 0.01);
  EXPECT_GT(lane_of(map, "north_in_0").centre_line.back().y, 105);
}

// ---------------------------------------------------------------------------------------------
// merge

TEST(BuiltinMerge, LaneIdsAndGeometry) {
  MapDescription map = generate_builtin_map("merge", {});
  EXPECT_EQ(lane_ids(map), (std::set<std::string>{"main_0", "main_1", "ramp_0", "accel_0"}));
  expect_straight_lanes(map, {{"main_0", {0, 1.75}, {500, 1.75}, 0, 500},
                              {"main_1", {0, 5.25}, {500, 5.25}, 0, 500},
                              {"accel_0", {200, -1.75}, {350, -1.75}, 0, 150}});
  const LaneDescription& ramp = lane_of(map, "ramp_0");
  // 100 m straight at 15°, then a 200 m radius bend to the right into accel_0.
  double bend = 200 * radians(15);
  MapPoint bend_start{200 - 200 * std::sin(radians(15)), -1.75 - 200 * (1 - std::cos(radians(15)))};
  MapPoint start = {bend_start.x - 100 * std::cos(radians(15)),
                    bend_start.y - 100 * std::sin(radians(15))};
  expect_point(ramp.centre_line.front(), start, 1e-9, "ramp start");
  expect_point(ramp.centre_line.front(), {51.64, -34.45}, kContractTolerance, "ramp start");
  expect_point(ramp.centre_line.back(), {200, -1.75}, 1e-9, "ramp end");
  expect_heading(start_heading(ramp), 15, 1e-6, "ramp start");
  expect_heading(end_heading(ramp), 0, 0.6, "ramp end");
  Polyline ramp_line = centre_line(ramp);
  EXPECT_NEAR(ramp_line.length(), 100 + bend, 2e-3);
  expect_point(ramp_line.point_at(100), bend_start, 1e-6, "bend start");

  EXPECT_EQ(ramp.successors, ids({"accel_0"}));
  const LaneDescription& accel = lane_of(map, "accel_0");
  EXPECT_EQ(accel.predecessors, ids({"ramp_0"}));
  EXPECT_TRUE(accel.successors.empty()) << "the acceleration lane ends";
  EXPECT_EQ(accel.left_forward_neighbours, ids({"main_0"}));
  EXPECT_EQ(lane_of(map, "main_0").right_forward_neighbours, ids({"accel_0"}));
  EXPECT_EQ(lane_of(map, "main_0").left_forward_neighbours, ids({"main_1"}));
  EXPECT_EQ(accel.left_boundary_type, BoundaryType::dotted_white);
  EXPECT_EQ(lane_of(map, "main_1").left_boundary_type, BoundaryType::curb);
  EXPECT_DOUBLE_EQ(ramp.speed_limit, 16.7);
  EXPECT_DOUBLE_EQ(accel.speed_limit, 22.2);
}

TEST(BuiltinMerge, FromTheRampIntoTheMainRoadByChangingLane) {
  RoadMap map = build_road_map(generate_builtin_map("merge", {}));
  auto ramp = map.find_lane("ramp_0");
  auto accel = map.find_lane("accel_0");
  auto main_0 = map.find_lane("main_0");
  auto main_1 = map.find_lane("main_1");
  ASSERT_TRUE(ramp && accel && main_0 && main_1);
  EXPECT_TRUE(lane_change_allowed(map, *accel, *main_0));
  EXPECT_TRUE(lane_change_allowed(map, *main_0, *main_1));
  auto route = find_route(map, LanePosition{*ramp, 0, 0}, LanePosition{*main_1, 450, 0});
  ASSERT_TRUE(route);
  EXPECT_EQ(route->segments.front().lane, *ramp);
  EXPECT_EQ(route->segments.back().lane, *main_1);
  EXPECT_EQ(route->lane_changes, 2);
}

TEST(BuiltinMerge, ParametersScaleTheRampAndRoad) {
  MapDescription map = generate_builtin_map("merge", {{"lanes", 3},
                                                      {"approach_length", 100},
                                                      {"accel_length", 80},
                                                      {"after_length", 20},
                                                      {"merge_angle", 30},
                                                      {"ramp_radius", 100},
                                                      {"ramp_length", 50}});
  EXPECT_EQ(lane_ids(map),
            (std::set<std::string>{"main_0", "main_1", "main_2", "ramp_0", "accel_0"}));
  expect_straight_lanes(map, {{"main_2", {0, 8.75}, {200, 8.75}, 0, 200},
                              {"accel_0", {100, -1.75}, {180, -1.75}, 0, 80}});
  const LaneDescription& ramp = lane_of(map, "ramp_0");
  expect_heading(start_heading(ramp), 30, 1e-6, "ramp start");
  EXPECT_NEAR(centre_line(ramp).length(), 50 + 100 * radians(30), 2e-3);
}

}  // namespace
}  // namespace scenfuzz

// The scenery to a built-in parametric map (docs/wmg-semantics.md, "Map"): which generator, its
// parameters from the roads' ranges, and how `Rn.Lk` names that map's lanes. Every range of the
// scenery becomes a parameter, also those the generators have no knob for (all but one junction
// angle, structure positions), so that a finding still replaces every range of the file.
#include <algorithm>
#include <array>
#include <string>

#include "lang/wmg/junction_arms.hpp"
#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {

namespace {

constexpr double kKilometresPerHour = 3.6;

int traffic_lane_count(const Road& road) {
  int count = 0;
  for (const LaneName& lane : road.lanes)
    if (lane.lane.name.starts_with("L")) ++count;
  return count;
}

void add_map_parameter(Translation& translation, const std::string& name, Value value,
                       SourceLocation location) {
  translation.scenario.map.parameters.push_back(NamedValue{name, std::move(value), location});
}

void add_attribute(Translation& translation, const std::string& key, const Label& label) {
  translation.scenario.map.attributes.push_back(Attribute{key, label.text, label.location});
}

// The values of one road's ranges; those no generator reads (structure positions, the widths and
// radii of later segments) are parameters all the same.
struct RoadValues {
  std::optional<Value> lane_width;  // the whole road's width
  Value length;
  std::optional<Value> speed_limit;  // m/s
  std::optional<Value> radius;       // the first curvature radius given
};

RoadValues translate_road_values(const Road& road, Translation& translation) {
  const std::string prefix = road.id.name + ".";
  RoadValues values;
  if (road.lane_width.whole_road)
    values.lane_width = translation.number(*road.lane_width.whole_road, prefix + "lane_width", "m");
  for (const SegmentRange& segment : road.lane_width.segments)
    if (segment.range)
      translation.number(*segment.range, prefix + "lane_width." + segment.segment.name, "m");
  values.length = translation.number(road.length, prefix + "length", "m");
  if (road.speed_limit)
    values.speed_limit =
        translation.number(*road.speed_limit, prefix + "speed_limit", "km/h", kKilometresPerHour);
  if (road.curvature_radius)
    for (const SegmentRange& segment : road.curvature_radius->segments) {
      if (!segment.range) continue;
      Value radius = translation.number(*segment.range,
                                        prefix + "curvature_radius." + segment.segment.name, "m");
      if (!values.radius) values.radius = radius;
    }
  for (const SpecialRoadStructure& structure : road.special_structures) {
    translation.number(structure.distance_from_start, prefix + structure.id.name + ".distance",
                       "m");
    translation.elements.insert(structure.id.name);
  }
  for (const RoadSign& sign : road.road_signs) {
    translation.number(sign.distance_from_start, prefix + sign.id.name + ".distance", "m");
    translation.elements.insert(sign.id.name);
  }
  for (const FixedRoadStructure& structure : road.fixed_structures) {
    if (!structure.street_lights) continue;
    translation.number(structure.street_lights->spacing, prefix + "street_lights.spacing", "m");
    translation.number(structure.street_lights->height, prefix + "street_lights.height", "m");
  }
  return values;
}

bool is_curved(const Road& road) {
  if (road.horizontal_geometry.whole_road)
    return road.horizontal_geometry.whole_road->text == "Curved";
  for (const SegmentLabel& segment : road.horizontal_geometry.segments)
    if (segment.value.text == "Curved") return true;
  return false;
}

// False, with the place and the word, when a road's geometry is neither Straight nor Curved.
bool has_known_geometry(const Road& road, SourceLocation& where, std::string& written) {
  auto known = [](const Label& label) {
    return !label.is_string && (label.text == "Straight" || label.text == "Curved");
  };
  if (road.horizontal_geometry.whole_road) {
    where = road.horizontal_geometry.whole_road->location;
    written = road.horizontal_geometry.whole_road->text;
    return known(*road.horizontal_geometry.whole_road);
  }
  for (const SegmentLabel& segment : road.horizontal_geometry.segments)
    if (!known(segment.value)) {
      where = segment.value.location;
      written = segment.value.text;
      return false;
    }
  return true;
}

// The road's values as the map parameters the generator of `map.name` takes.
void add_road_map_parameters(const Road& road, const RoadValues& values, bool with_speed_limit,
                             Translation& translation) {
  const std::string& map = translation.scenario.map.name;
  if (values.lane_width)
    add_map_parameter(translation, "lane_width", *values.lane_width, road.lane_width.location);
  if (map == "straight") {
    add_map_parameter(translation, "length", values.length, road.length.location);
  } else if (map == "curve") {
    Value third =
        binary_value(ValueOp::divide, values.length, constant_value(3.0), road.length.location);
    add_map_parameter(translation, "straight_before", third, road.length.location);
    add_map_parameter(translation, "straight_after", third, road.length.location);
    if (values.radius) {
      add_map_parameter(translation, "radius", *values.radius, road.curvature_radius->location);
      // The bend is the middle third of the road's length: it turns by that arc over the radius
      // (degrees), so a large radius gives a gentle bend, not a 90-degree one kilometres long.
      const SourceLocation where = road.curvature_radius->location;
      Value turn = binary_value(ValueOp::divide, third, *values.radius, where);
      turn =
          binary_value(ValueOp::multiply, turn, constant_value(180.0 / 3.141592653589793), where);
      add_map_parameter(translation, "angle", turn, where);
    }
  } else {
    add_map_parameter(translation, "arm_length", values.length, road.length.location);
  }
  if (values.speed_limit && with_speed_limit)
    add_map_parameter(translation, "speed_limit", *values.speed_limit, road.speed_limit->location);
}

void declare_lanes(const Road& road, const std::string& prefix, int traffic_lanes,
                   Translation& translation) {
  RoadLanes lanes;
  lanes.lane_prefix = prefix;
  lanes.traffic_lanes = traffic_lanes;
  for (const LaneName& lane : road.lanes)
    lanes.declared.insert(lane.road.name + "." + lane.lane.name);
  translation.roads[road.id.name] = lanes;
}

void translate_single_road(const Road& road, Translation& translation) {
  SourceLocation where = road.horizontal_geometry.location;
  std::string written;
  if (!has_known_geometry(road, where, written)) {
    translation.diagnostics.error(where, "horizontal road geometry '" + written +
                                             "' has no map generator yet (Straight or Curved)");
    return;
  }
  const int lanes = traffic_lane_count(road);
  if (lanes == 0) {
    translation.diagnostics.error(road.lane_count.location,
                                  "road '" + road.id.name + "' has no traffic lane (L1, L2, ...)");
    return;
  }
  const bool curved = is_curved(road);
  translation.scenario.map.name = curved ? "curve" : "straight";
  add_map_parameter(translation, "lanes", constant_value(static_cast<double>(lanes)),
                    road.lane_count.location);
  if (!curved) add_map_parameter(translation, "two_way", constant_value(0.0), road.location);
  add_road_map_parameters(road, translate_road_values(road, translation), true, translation);
  declare_lanes(road, curved ? "fwd_" : "east_", lanes, translation);
  translation.scenario.map.attributes.push_back(Attribute{
      "road " + road.id.name, curved ? "the road (fwd_*)" : "the road (east_*)", road.id.location});
}

struct JunctionMap {
  std::string name;
  std::size_t arms = 0;
};

std::optional<JunctionMap> junction_map(const Junction& junction) {
  const std::string& type = junction.type.text;
  if (junction.type.is_string) return std::nullopt;
  if (type == "Crossroads") return JunctionMap{"crossroads", 4};
  if (type == "T-Junction") return JunctionMap{"t_junction", 3};
  if (type == "Normal roundabout" || type == "Large roundabout" || type == "Compact roundabout" ||
      type == "Mini roundabout")
    return JunctionMap{"roundabout", 4};
  return std::nullopt;
}

// The generator's `angle` (counter-clockwise from the west arm to the south arm) from the stated
// pair the arm layout chose, or its supplement.
void add_crossing_angle(const Junction& junction, const ArmLayout& layout,
                        const std::vector<Value>& angles, Translation& translation) {
  if (!layout.angle_pair || *layout.angle_pair >= angles.size()) return;
  const std::size_t k = *layout.angle_pair;
  const SourceLocation where = junction.angles[k].location;
  add_map_parameter(translation, "angle",
                    layout.supplement ? binary_value(ValueOp::subtract,
                                                     constant_value(180.0, where), angles[k], where)
                                      : angles[k],
                    where);
}

// Which arm each road became and which map lane each of its lanes, for `scenfuzz map FILE` to
// say: "the west arm (R1.L1 west_in_0, R1.L2 west_out_0)".
void add_arm_notes(const Junction& junction, const std::vector<std::string>& arms,
                   Translation& translation) {
  for (std::size_t i = 0; i < junction.connected_roads.size() && i < arms.size(); ++i) {
    const Identifier& road = junction.connected_roads[i];
    std::string names;
    for (const auto& [written, id] : translation.roads.at(road.name).ids)
      names += (names.empty() ? "" : ", ") + written + " " + id;
    translation.scenario.map.attributes.push_back(
        Attribute{"road " + road.name, "the " + arms[i] + " arm (" + names + ")", road.location});
  }
}

void translate_junction(const Junction& junction, const std::vector<Road>& roads,
                        const Initialisation& initialisation, Translation& translation) {
  const std::string prefix = junction.id.name + ".";
  translation.elements.insert(junction.id.name);
  std::vector<Value> angles;
  for (std::size_t i = 0; i < junction.angles.size(); ++i) {
    std::string pair = std::to_string(i + 1);
    if (i < junction.angle_pairs.size())
      pair = junction.angle_pairs[i].from.name + "_" + junction.angle_pairs[i].to.name;
    angles.push_back(translation.number(junction.angles[i], prefix + "angle." + pair, "deg", 1.0,
                                        ParameterKind::angle));
  }
  std::optional<Value> ring_radius;
  if (junction.dimensions.width)
    translation.number(*junction.dimensions.width, prefix + "width", "m");
  if (junction.dimensions.depth)
    translation.number(*junction.dimensions.depth, prefix + "depth", "m");
  if (junction.dimensions.diameter)
    ring_radius = translation.number(*junction.dimensions.diameter, prefix + "diameter", "m", 2.0);

  const std::optional<JunctionMap> map = junction_map(junction);
  if (!map) {
    translation.diagnostics.error(
        junction.type.location,
        "junction type '" + junction.type.text +
            "' has no map generator yet (there are generators for Crossroads, T-Junction and the "
            "Mini, Compact, Normal and Large roundabouts; a Y-junction's fork, a staggered "
            "junction's two offset T-junctions and a double roundabout are not built)");
    return;
  }
  translation.scenario.map.name = map->name;
  if (junction.connected_roads.size() > map->arms) {
    translation.diagnostics.error(junction.connected_roads[map->arms].location,
                                  "the " + map->name + " map has " + std::to_string(map->arms) +
                                      " arms; road '" + junction.connected_roads[map->arms].name +
                                      "' has none to become");
    return;
  }
  const std::optional<ArmLayout> layout =
      lay_out_arms(junction, map->name, initialisation, translation.diagnostics);
  if (!layout) return;
  std::vector<const Road*> arm_roads;
  for (std::size_t i = 0; i < junction.connected_roads.size(); ++i) {
    const Identifier& id = junction.connected_roads[i];
    const Road* road = nullptr;
    for (const Road& candidate : roads)
      if (candidate.id.name == id.name) road = &candidate;
    arm_roads.push_back(road);
    if (!road) {
      translation.diagnostics.error(id.location, "junction '" + junction.id.name +
                                                     "' connects road '" + id.name +
                                                     "', which is not in the scenery");
      continue;
    }
    // Which way each lane runs, and so how many lanes the arm has, name_junction_lanes says.
    declare_lanes(*road, layout->arms[i] + "_in_", traffic_lane_count(*road), translation);
  }
  for (const Road& road : roads)
    if (!translation.roads.contains(road.id.name))
      translation.diagnostics.error(
          road.id.location,
          "road '" + road.id.name + "' is not connected to junction '" + junction.id.name + "'");
  if (translation.diagnostics.has_errors()) return;
  const int lanes = name_junction_lanes(junction, arm_roads, layout->arms, translation);
  add_arm_notes(junction, layout->arms, translation);
  // Every lane a connection names is one its road lists (the ego's exit reads them), and each
  // connection between traffic lanes is a way the map must have (physics/simulation/lane_links).
  for (const LaneConnection& connection : junction.lane_connections) {
    const std::optional<std::string> from = translation.lane_id(connection.from);
    for (const LaneName& to : connection.to) {
      const std::optional<std::string> id = translation.lane_id(to);
      if (from && id && connection.from.lane.name.starts_with("L") && to.lane.name.starts_with("L"))
        translation.scenario.map.links.push_back(LaneLink{*from, *id, to.location});
    }
  }
  if (translation.diagnostics.has_errors()) return;
  if (map->name == "roundabout" && lanes > 1) {
    translation.diagnostics.error(junction.lane_connections.front().location,
                                  "the roundabout map has one lane each way on every arm, but "
                                  "these connections and the roads' lanes need " +
                                      std::to_string(lanes) + " lanes one way");
    return;
  }

  // The first road stands for every arm: the generators give all arms one width and length.
  const bool roundabout = map->name == "roundabout";
  if (!roundabout)
    add_map_parameter(translation, "lanes", constant_value(static_cast<double>(lanes)),
                      junction.location);
  for (std::size_t i = 0; i < roads.size(); ++i) {
    const RoadValues values = translate_road_values(roads[i], translation);
    if (i == 0) add_road_map_parameters(roads[i], values, !roundabout, translation);
  }
  if (roundabout && ring_radius)
    add_map_parameter(translation, "ring_radius", *ring_radius,
                      junction.dimensions.diameter->location);
  // The roundabout's arms are a quarter turn apart whatever the file says.
  if (!roundabout) add_crossing_angle(junction, *layout, angles, translation);

  // The generated junction has one signal per approach, `light_<arm>`, with its own signal plan:
  // a light placed on a road (or one of its lanes) is that arm's signal. No TrafficLightSetting is
  // written, since the file gives no initial colour and the map's plan decides.
  if (junction.traffic_lights) {
    for (const TrafficLightPlacement& placement : junction.traffic_lights->lights) {
      std::size_t arm = junction.connected_roads.size();
      for (std::size_t i = 0; i < junction.connected_roads.size(); ++i)
        if (junction.connected_roads[i].name == placement.road.name) arm = i;
      if (arm == junction.connected_roads.size()) {
        translation.diagnostics.error(placement.road.location,
                                      "traffic light '" + placement.light.name +
                                          "' is placed on road '" + placement.road.name +
                                          "', which junction '" + junction.id.name +
                                          "' does not connect");
        continue;
      }
      if (placement.lane)
        translation.lane_id(LaneName{placement.road, *placement.lane, placement.location});
      translation.traffic_lights[placement.light.name] = "light_" + layout->arms[arm];
    }
  }
}

}  // namespace

void translate_scenery(const Scenery& scenery, const Initialisation& initialisation,
                       Translation& translation) {
  MapReference& map = translation.scenario.map;
  map.location = scenery.location;
  if (scenery.roads.empty()) {
    translation.diagnostics.error(scenery.location, "the scenery has no road");
    return;
  }
  const Road& first = scenery.roads.front();
  add_attribute(translation, "road_type", first.road_type);
  // The generated roads are right-handed; the written direction is kept as a note.
  add_attribute(translation, "traffic_direction", first.traffic_direction);
  if (first.surface_condition)
    add_attribute(translation, "surface_condition", *first.surface_condition);

  if (scenery.junctions.size() > 1) {
    translation.diagnostics.error(scenery.junctions[1].location,
                                  "more than one junction has no map generator yet");
    return;
  }
  if (scenery.junctions.empty()) {
    if (scenery.roads.size() > 1) {
      translation.diagnostics.error(scenery.roads[1].location,
                                    "more than one road without a junction has no map generator "
                                    "yet");
      return;
    }
    translate_single_road(first, translation);
    return;
  }
  translate_junction(scenery.junctions.front(), scenery.roads, initialisation, translation);
}

}  // namespace scenfuzz::wmg

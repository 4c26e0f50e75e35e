// Level 1 to level 2, the scenery: junctions (type, angles, lane connections, size, traffic
// lights), roads (everything the road type stands for, the features) and the background traffic
// that "with heavy traffic" asks for.
#include <algorithm>

#include "lang/wmg/level1_convert_parts.hpp"

namespace scenfuzz::wmg::detail {

namespace {

Identifier id(std::string name, SourceLocation where = {}) {
  return Identifier{std::move(name), where};
}

LaneName lane(const std::string& road, const std::string& lane_id, SourceLocation where = {}) {
  return LaneName{id(road, where), id(lane_id, where), where};
}

// The junction type's words in the table: a STRING type gets the "named junction" rows.
std::string junction_words(const JunctionSentence& junction) {
  return junction.type.is_string ? "named junction" : junction.type.text;
}

bool has_feature(const RoadPlan& road, std::string_view feature) {
  return std::any_of(road.features.begin(), road.features.end(),
                     [&](const Label& label) { return !label.is_string && label.text == feature; });
}

// Into the junction by a road's L1, out of it by L2 where the road has two lanes or more (level
// 2 reads a lane's direction from the connections, lane_directions.cpp).
std::string exit_lane(const ConversionPlan& plan, const std::string& road) {
  const RoadPlan* found = plan.road(road);
  return found && found->lane_count >= 2 ? "L2" : "L1";
}

std::vector<LaneConnection> lane_connections(const ConversionPlan& plan,
                                             const JunctionSentence& junction) {
  std::vector<LaneConnection> connections;
  auto connect = [&](const Identifier& from, const Identifier& to, SourceLocation where) {
    LaneName exit = lane(to.name, exit_lane(plan, to.name), to.location);
    for (LaneConnection& existing : connections)
      if (existing.from.road.name == from.name) {
        existing.to.push_back(exit);
        return;
      }
    connections.push_back(LaneConnection{lane(from.name, "L1", from.location), {exit}, where});
  };
  for (const ConnectionSentence& connection : junction.connections)
    connect(connection.from, connection.to, connection.location);
  if (!connections.empty()) return connections;
  // Nothing said: every road leads to every other road.
  for (const Identifier& from : junction.roads)
    for (const Identifier& to : junction.roads)
      if (from.name != to.name || junction.roads.size() == 1) connect(from, to, junction.location);
  return connections;
}

Junction convert_junction(const ConversionPlan& plan, const JunctionSentence& sentence) {
  Junction junction;
  std::string words = junction_words(sentence);
  junction.id = sentence.id;
  junction.type = converted_label(sentence.type, Quality::junction_type, "named junction");
  junction.named_as = sentence.id;
  bool signalised = plan.signalised_junctions.count(sentence.id.name) > 0;
  junction.connection_control = table_label(
      default_for(Quality::junction_control, signalised ? "traffic lights" : "no traffic lights",
                  "no traffic lights")
          .label,
      sentence.type.location);
  junction.connection_count =
      WholeNumber{static_cast<std::int64_t>(sentence.roads.size()), sentence.location};
  junction.connected_roads = sentence.roads;
  // Neighbouring roads in the order written, round the junction.
  const QualitativeDefault& angle = default_for(Quality::junction_angle, words, "named junction");
  std::size_t count = sentence.roads.size();
  std::size_t pairs = count == 0 ? 0 : count <= 2 ? 1 : count;
  for (std::size_t i = 0; i < pairs; ++i) {
    const Identifier& from = sentence.roads[i % count];
    const Identifier& to = sentence.roads[(i + 1) % count];
    junction.angle_pairs.push_back(RoadPair{from, to, from.location});
    junction.angles.push_back(table_range(angle, sentence.type.location));
  }
  junction.lane_connections = lane_connections(plan, sentence);
  const QualitativeDefault& size = default_for(Quality::junction_size, words, "named junction");
  NumberRange extent = table_range(size, sentence.type.location);
  if (size.label == "Diameter") {
    junction.dimensions.diameter = extent;
  } else {
    junction.dimensions.width = extent;
    junction.dimensions.depth = extent;
  }
  junction.dimensions.location = sentence.type.location;
  if (signalised) {
    JunctionTrafficLights lights;
    bool crossing = false;
    for (const Identifier& road : sentence.roads) {
      lights.lights.push_back(
          TrafficLightPlacement{id(traffic_light_name(road.name), road.location), road,
                                id("L1", road.location), road.location});
      if (const RoadPlan* plan_road = plan.road(road.name))
        crossing = crossing || has_feature(*plan_road, "pedestrian crossing");
    }
    lights.type = table_label(crossing ? "With pedestrian crossing" : "Without pedestrian crossing",
                              sentence.location);
    lights.location = sentence.location;
    junction.traffic_lights = lights;
  }
  junction.location = sentence.location;
  return junction;
}

void add_feature(Road& road, const RoadPlan& plan, const Label& feature, std::size_t& crossings) {
  SourceLocation where = feature.location;
  if (feature.is_string) {
    road.fixed_structures.push_back(FixedRoadStructure{feature, std::nullopt, {}, where});
    return;
  }
  if (const QualitativeDefault* row = find_default(Quality::lane_marking_feature, feature.text)) {
    road.lane_markings = table_label(row->label, where);
  } else if (const QualitativeDefault* edge = find_default(Quality::edge_feature, feature.text)) {
    road.edge_feature = table_label(edge->label, where);
  } else if (const QualitativeDefault* fixed = find_default(Quality::fixed_feature, feature.text)) {
    FixedRoadStructure structure{table_label(fixed->label, where), std::nullopt, {}, where};
    if (fixed->label == "Street lights")
      structure.street_lights =
          StreetLights{table_range(setting("street light spacing"), where),
                       table_range(setting("street light height"), where), where};
    road.fixed_structures.push_back(structure);
  } else if (const QualitativeDefault* special =
                 find_default(Quality::special_feature, feature.text)) {
    double at = setting("pedestrian crossing position").low * plan.length.low;
    road.special_structures.push_back(SpecialRoadStructure{
        table_label(special->label, where), id("Crossing" + std::to_string(++crossings), where),
        NumberRange{at, at, false, where}, where});
  }
}

Road convert_road(const RoadPlan& plan, const std::string& surface, std::size_t& crossings) {
  const RoadSentence& sentence = *plan.sentence;
  SourceLocation where = sentence.road_type.location;
  auto text_setting = [&](std::string_view name) {
    return table_label(setting(name).label, where);
  };
  Road road;
  road.id = plan.id;
  if (plan.junctions.size() >= 2) road.start_junction = id(plan.junctions[1], where);
  if (!plan.junctions.empty()) road.end_junction = id(plan.junctions[0], where);
  road.road_type = converted_label(sentence.road_type, Quality::road_type, plan.type_words);
  road.named_as = plan.id;
  road.zone = text_setting("zone");
  road.speed_limit = NumberRange{plan.speed_limit, plan.speed_limit, false, where};
  road.environment = table_label(
      default_for(Quality::road_environment, plan.type_words, "minor road").label, where);
  road.lane_count = WholeNumber{plan.lane_count, where};
  for (std::int64_t i = 1; i <= plan.lane_count; ++i)
    road.lanes.push_back(lane(plan.id.name, "L" + std::to_string(i), plan.id.location));
  road.traffic_direction = text_setting("traffic direction");
  road.lane_type = text_setting("lane type");
  road.lane_markings = text_setting("lane markings");
  road.surface_type = text_setting("surface type");
  road.surface_condition =
      table_label(default_for(Quality::surface_condition, surface, "dry").label, where);
  road.horizontal_geometry.whole_road =
      converted_label(sentence.horizontal_geometry, Quality::horizontal_geometry, "straight");
  road.horizontal_geometry.location = sentence.horizontal_geometry.location;
  if (!sentence.horizontal_geometry.is_string && sentence.horizontal_geometry.text == "curved") {
    CurvatureRadius radius;
    radius.segments.push_back(SegmentRange{
        id("S1", sentence.horizontal_geometry.location),
        table_range(default_for(Quality::curvature_radius, plan.type_words, "minor road"),
                    sentence.horizontal_geometry.location),
        sentence.horizontal_geometry.location});
    radius.location = sentence.horizontal_geometry.location;
    road.curvature_radius = radius;
  }
  road.vertical_geometry = text_setting("vertical geometry");
  road.transverse_geometry.push_back(
      table_label(default_for(Quality::road_division, plan.type_words, "minor road").label, where));
  road.banking_angle = text_setting("banking angle");
  road.roadside_feature = text_setting("roadside feature");
  for (const Label& feature : plan.features) add_feature(road, plan, feature, crossings);
  road.length = plan.length;
  road.lane_width.whole_road =
      table_range(default_for(Quality::lane_width, plan.type_words, "minor road"), where);
  road.lane_width.location = where;
  road.location = sentence.location;
  return road;
}

}  // namespace

Scenery convert_scenery(const ConversionPlan& plan) {
  Scenery scenery;
  scenery.description = Text{"Converted from WMG SDL level 1", {}};
  scenery.id = id("Scenery1");
  for (const JunctionSentence& junction : plan.file->junctions)
    scenery.junctions.push_back(convert_junction(plan, junction));
  std::string surface = surface_weather(*plan.file);
  std::size_t crossings = 0;
  for (const RoadPlan& road : plan.roads)
    scenery.roads.push_back(convert_road(road, surface, crossings));
  return scenery;
}

std::optional<TrafficModel> convert_traffic(const ConversionPlan& plan) {
  TrafficModel model;
  for (const RoadPlan& road : plan.roads) {
    const std::optional<Label>& traffic = road.sentence->traffic;
    if (!traffic) continue;
    const QualitativeDefault* flow = find_default(Quality::traffic_flow, traffic->text);
    const QualitativeDefault* speed = find_default(Quality::traffic_speed, traffic->text);
    if (!flow || !speed) continue;  // "no traffic"
    SourceLocation where = traffic->location;
    // Traffic enters and leaves the road near its junction, or near the ego when it has none.
    Identifier reference = road.junctions.empty() ? id(plan.ego().name.name, where)
                                                  : id(road.junctions.front(), where);
    NumberRange distance = table_range(setting("traffic centroid distance"), where);
    Identifier origin = id("Origin_" + road.id.name, where);
    Identifier destination = id("Destination_" + road.id.name, where);
    model.centroids.push_back(Centroid{origin, road.id, distance, reference, where});
    model.centroids.push_back(Centroid{destination, road.id, distance, reference, where});
    model.flows.push_back(TrafficFlow{id("Traffic_" + road.id.name, where), origin,
                                      lane(road.id.name, "L1", where), destination,
                                      lane(road.id.name, "L1", where), table_range(*flow, where),
                                      speed_range(*speed, road.speed_limit, where), where});
  }
  if (model.flows.empty()) return std::nullopt;
  return model;
}

}  // namespace scenfuzz::wmg::detail

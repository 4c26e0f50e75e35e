// Prints SCENERY_ELEMENTS: junctions and roads, one keyword phrase per line.
#include <string>

#include "lang/wmg/printer_parts.hpp"
#include "lang/wmg/syntax_printer.hpp"

namespace scenfuzz::wmg::detail {

namespace {

template <typename Item, typename Text>
std::string list_text(const std::vector<Item>& items, Text text,
                      const std::string& separator = ", ") {
  std::vector<std::string> texts;
  for (const Item& item : items) texts.push_back(text(item));
  return joined(texts, separator);
}

std::string junction_text(const Junction& junction) {
  std::string out = junction.id.name + ": Junction type " + bracketed(label_text(junction.type)) +
                    " as " + bracketed(junction.named_as.name) + "\n";
  out += "  which has " + bracketed(label_text(junction.connection_control)) +
         " connection control and " + bracketed(std::to_string(junction.connection_count.value)) +
         (junction.connection_count.value == 1 ? " connection\n" : " connections\n");
  out += "  with " +
         bracketed(list_text(junction.connected_roads,
                             [](const Identifier& road) { return road.name; })) +
         "\n";
  out += "  Angles between roads " +
         bracketed(list_text(
             junction.angle_pairs,
             [](const RoadPair& pair) { return pair.from.name + " -> " + pair.to.name; })) +
         "\n";
  out += "  " + bracketed(list_text(junction.angles, range_text)) + "\n";
  out += "  Road lane connections " +
         bracketed(list_text(junction.lane_connections,
                             [](const LaneConnection& connection) {
                               return lane_text(connection.from) + " -> " +
                                      list_text(connection.to, lane_text, " + ");
                             })) +
         "\n";
  const JunctionDimensions& dimensions = junction.dimensions;
  if (dimensions.diameter) {
    out += "  Dimensions " + bracketed("Diameter: " + range_text(*dimensions.diameter)) + "\n";
  } else {
    out += "  Dimensions " +
           bracketed("Width: " + range_text(dimensions.width.value_or(NumberRange{})) +
                     ", Depth: " + range_text(dimensions.depth.value_or(NumberRange{}))) +
           "\n";
  }
  if (junction.road_signs)
    out += "  Road signs " + bracketed(list_text(junction.road_signs->signs, label_text)) + " at " +
           bracketed(list_text(junction.road_signs->lanes, lane_text)) + "\n";
  if (junction.traffic_lights)
    out += "  Traffic light " + bracketed(label_text(junction.traffic_lights->type)) + " as " +
           bracketed(list_text(junction.traffic_lights->lights,
                               [](const TrafficLightPlacement& light) {
                                 return light.light.name + " -> " + light.road.name +
                                        (light.lane ? "." + light.lane->name : "");
                               })) +
           "\n";
  return out;
}

std::string segment_range_text(const SegmentRange& segment) {
  return segment.segment.name + ": " + (segment.range ? range_text(*segment.range) : "N/A");
}

std::string fixed_structure_text(const FixedRoadStructure& structure) {
  std::string out =
      structure.street_lights
          ? "Street lights: {spacing: " + range_text(structure.street_lights->spacing) +
                ", height: " + range_text(structure.street_lights->height) + "}"
          : label_text(structure.type);
  if (!structure.at.empty())
    out +=
        " at " + bracketed(list_text(structure.at, [](const Identifier& id) { return id.name; }));
  return out;
}

std::string road_text(const Road& road) {
  std::string out = road.id.name + ": START";
  if (road.start_junction) out += ": " + bracketed(road.start_junction->name);
  out += "\n  Road type " + bracketed(label_text(road.road_type)) + " as " +
         bracketed(road.named_as.name) + "\n";
  out += "  with zone as " + bracketed(label_text(road.zone)) + "\n";
  out += "  AND speed limit of " +
         bracketed(road.speed_limit ? range_text(*road.speed_limit) : "N/A") + "\n";
  // "a" or "an" as English wants it: the parser reads either.
  const std::string& environment = road.environment.text;
  bool vowel = !road.environment.is_string && !environment.empty() &&
               std::string("AEIOUaeiou").find(environment[0]) != std::string::npos;
  out += std::string("  in ") + (vowel ? "an " : "a ") + bracketed(label_text(road.environment)) +
         " environment\n";
  out += "  with Number of lanes " + bracketed(std::to_string(road.lane_count.value)) + " as " +
         bracketed(list_text(road.lanes, lane_text)) + "\n";
  out += "  Road traffic direction " + bracketed(label_text(road.traffic_direction)) + "\n";
  out += "  Lane type " + bracketed(label_text(road.lane_type)) + "\n";
  out += "  Lane markings " + bracketed(label_text(road.lane_markings)) + "\n";
  if (road.surface_type)
    out += "  Road surface type " + bracketed(label_text(*road.surface_type)) + "\n";
  if (road.surface_condition)
    out += "  with surface condition " + bracketed(label_text(*road.surface_condition)) + "\n";
  if (road.surface_feature)
    out += "  AND surface feature " + bracketed(label_text(*road.surface_feature)) + "\n";
  const HorizontalGeometry& horizontal = road.horizontal_geometry;
  out += "  Horizontal road geometry " +
         bracketed(horizontal.whole_road
                       ? label_text(*horizontal.whole_road)
                       : list_text(horizontal.segments,
                                   [](const SegmentLabel& segment) {
                                     return segment.segment.name + ": " + label_text(segment.value);
                                   })) +
         "\n";
  if (road.curvature_radius)
    out += "  with curvature radius of " +
           bracketed(road.curvature_radius->not_applicable
                         ? "N/A"
                         : list_text(road.curvature_radius->segments, segment_range_text)) +
           "\n";
  out += "  Vertical road geometry " + bracketed(label_text(road.vertical_geometry)) + "\n";
  out += "  Transverse road geometry " +
         bracketed(list_text(road.transverse_geometry, label_text)) + "\n";
  out += "  Road banking angle " + bracketed(label_text(road.banking_angle)) + "\n";
  out += "  with " + bracketed(label_text(road.roadside_feature)) + " roadside feature\n";
  if (road.edge_feature)
    out += "  Roadway edge features " + bracketed(label_text(*road.edge_feature)) + "\n";
  for (const SpecialRoadStructure& structure : road.special_structures)
    out += "  Special road structures " + bracketed(label_text(structure.type)) + " as " +
           bracketed(structure.id.name) + " at " +
           bracketed(range_text(structure.distance_from_start)) + " distance from START\n";
  if (!road.fixed_structures.empty())
    out += "  Fixed road structures " +
           bracketed(list_text(road.fixed_structures, fixed_structure_text)) + "\n";
  for (const TemporaryRoadStructures& structures : road.temporary_structures)
    out += "  Temporary road structures " + bracketed(list_text(structures.types, label_text)) +
           " at " + bracketed(lane_text(structures.lane)) + "\n";
  for (const RoadSign& sign : road.road_signs)
    out += "  Road sign " + bracketed(label_text(sign.type)) + " as " + bracketed(sign.id.name) +
           " at " + bracketed(range_text(sign.distance_from_start)) + " distance from START\n";
  out += "  Length " + bracketed(range_text(road.length)) + "\n";
  out += "  AND Lane width " +
         bracketed(road.lane_width.whole_road
                       ? range_text(*road.lane_width.whole_road)
                       : list_text(road.lane_width.segments, segment_range_text)) +
         "\n";
  out += "END";
  if (road.end_junction) out += ": " + bracketed(road.end_junction->name);
  return out + "\n";
}

}  // namespace

std::string print_scenery(const Scenery& scenery) {
  std::string out = "SCENERY ELEMENTS:\nDO: '" + scenery.description.text + "' " +
                    bracketed(scenery.id.name) + " as:\n";
  out += "Junctions:";
  if (scenery.junctions.empty()) out += " None";
  out += "\n";
  for (const Junction& junction : scenery.junctions) out += junction_text(junction);
  out += "Roads:";
  if (scenery.roads.empty()) out += " None";
  out += "\n";
  for (const Road& road : scenery.roads) out += road_text(road);
  return out;
}

}  // namespace scenfuzz::wmg::detail

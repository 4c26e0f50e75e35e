// JUNCTION_ELEMENT: a junction's type, connections, angles, lane connections, dimensions, signs
// and traffic lights.
#include <string>

#include "lang/wmg/parse_sections.hpp"

namespace scenfuzz::wmg::detail {

namespace {

constexpr TokenKind kComma = TokenKind::comma;
constexpr TokenKind kOpen = TokenKind::left_bracket;
constexpr TokenKind kClose = TokenKind::right_bracket;

RoadPair parse_road_pair(Cursor& cursor) {
  RoadPair pair;
  pair.from = cursor.road_id("an angle between roads");
  cursor.expect(TokenKind::arrow, "between the two roads of an angle (R1 -> R2)");
  pair.to = cursor.road_id("an angle between roads");
  pair.location = cursor.span_from(pair.from.location);
  return pair;
}

LaneConnection parse_lane_connection(Cursor& cursor) {
  LaneConnection connection;
  connection.from = cursor.lane_name("a road lane connection");
  cursor.expect(TokenKind::arrow, "after the lane a connection starts from (R1.L1 -> R2.L1)");
  connection.to.push_back(cursor.lane_name("a road lane connection"));
  while (cursor.at(TokenKind::plus)) {
    cursor.take();
    connection.to.push_back(cursor.lane_name("a road lane connection"));
  }
  connection.location = cursor.span_from(connection.from.location);
  return connection;
}

JunctionDimensions parse_dimensions(Cursor& cursor) {
  JunctionDimensions dimensions;
  SourceLocation first = cursor.expect(kOpen, "before the junction's dimensions").location;
  if (cursor.at_phrase("Width")) {
    cursor.take();
    cursor.expect(TokenKind::colon, "after 'Width'");
    dimensions.width = cursor.range(kComma, "the junction's width");
    cursor.expect(kComma, "after the junction's width");
    cursor.expect_phrase("Depth", "after the junction's width");
    cursor.expect(TokenKind::colon, "after 'Depth'");
    dimensions.depth = cursor.range(kClose, "the junction's depth");
  } else if (cursor.at_phrase("Diameter")) {
    cursor.take();
    cursor.expect(TokenKind::colon, "after 'Diameter'");
    dimensions.diameter = cursor.range(kClose, "the junction's diameter");
  } else {
    cursor.fail(cursor.peek().location,
                "expected 'Width: ..., Depth: ...' or 'Diameter: ...' in the junction's "
                "dimensions, found " +
                    describe(cursor.peek()));
  }
  cursor.close(kClose, "after the junction's dimensions");
  dimensions.location = cursor.span_from(first);
  return dimensions;
}

JunctionRoadSigns parse_junction_road_signs(Cursor& cursor) {
  JunctionRoadSigns signs;
  SourceLocation first = cursor.expect_phrase("Road signs", "");
  signs.signs = bracketed_list<Label>(
      cursor, "the road signs", [&] { return cursor.label(vocabulary::junction_road_sign()); });
  cursor.expect_phrase("at", "after the junction's road signs");
  signs.lanes = bracketed_list<LaneName>(cursor, "the lanes of the road signs",
                                         [&] { return cursor.lane_name("a road sign's lane"); });
  signs.location = cursor.span_from(first);
  return signs;
}

TrafficLightPlacement parse_traffic_light_placement(Cursor& cursor) {
  TrafficLightPlacement placement;
  placement.light = cursor.id("a traffic light");
  cursor.expect(TokenKind::arrow, "after the traffic light's ID (TL1 -> R1.L1)");
  placement.road = cursor.road_id("the traffic light's road");
  if (cursor.at(TokenKind::dot)) {
    cursor.take();
    placement.lane = cursor.lane_id("the traffic light's lane");
  }
  placement.location = cursor.span_from(placement.light.location);
  return placement;
}

JunctionTrafficLights parse_junction_traffic_lights(Cursor& cursor) {
  JunctionTrafficLights lights;
  SourceLocation first = cursor.expect_phrase("Traffic light", "");
  lights.type = cursor.bracketed_label(vocabulary::traffic_light_type());
  cursor.expect_phrase("as", "after the traffic light type");
  lights.lights = bracketed_list<TrafficLightPlacement>(
      cursor, "the traffic lights", [&] { return parse_traffic_light_placement(cursor); });
  lights.location = cursor.span_from(first);
  return lights;
}

}  // namespace

Junction parse_junction(Cursor& cursor) {
  Junction junction;
  junction.id = cursor.id("the junction");
  cursor.expect(TokenKind::colon, "after the junction's ID");
  cursor.expect_phrase("Junction type", "after '" + junction.id.name + ":'");
  junction.type = cursor.bracketed_label(vocabulary::junction_type());
  cursor.expect_phrase("as", "after the junction type");
  junction.named_as = cursor.bracketed_id("the junction's name");
  cursor.expect_phrase("which has", "after the junction's name");
  junction.connection_control = cursor.bracketed_label(vocabulary::connection_control());
  cursor.expect_phrase("connection control and", "after the connection control type");
  cursor.expect(kOpen, "before the number of connections");
  junction.connection_count = cursor.whole_number("the number of connections");
  cursor.close(kClose, "after the number of connections");
  if (cursor.at_word("connection") || cursor.at_word("connections")) {
    cursor.take();
  } else {
    cursor.fail(
        cursor.peek().location,
        "expected 'connections' after the number of connections, found " + describe(cursor.peek()));
  }
  cursor.expect_phrase("with", "after 'connections'");
  SourceLocation roads_location;
  junction.connected_roads = bracketed_list<Identifier>(
      cursor, "the connected roads", [&] { return cursor.road_id("a connected road"); },
      &roads_location);
  check_count(cursor, junction.connection_count, junction.connected_roads.size(), roads_location,
              "connection");
  cursor.expect_phrase("Angles between roads", "after the connected roads");
  junction.angle_pairs =
      bracketed_list<RoadPair>(cursor, "the road pairs", [&] { return parse_road_pair(cursor); });
  SourceLocation angles_location;
  junction.angles = bracketed_list<NumberRange>(
      cursor, "the angles between roads",
      [&] {
        return cursor.range({kComma, kClose}, "an angle between roads");
      },
      &angles_location);
  if (junction.angles.size() != junction.angle_pairs.size())
    cursor.error(angles_location,
                 "the junction has " + counted(junction.angle_pairs.size(), "road pair") + " but " +
                     counted(junction.angles.size(), "angle") + ": give one angle per pair");
  cursor.expect_phrase("Road lane connections", "after the angles between roads");
  junction.lane_connections = bracketed_list<LaneConnection>(
      cursor, "the road lane connections", [&] { return parse_lane_connection(cursor); });
  cursor.expect_phrase("Dimensions", "after the road lane connections");
  junction.dimensions = parse_dimensions(cursor);
  if (cursor.at_phrase("Road signs")) junction.road_signs = parse_junction_road_signs(cursor);
  if (cursor.at_phrase("Traffic light"))
    junction.traffic_lights = parse_junction_traffic_lights(cursor);
  junction.location = cursor.span_from(junction.id.location);
  return junction;
}

}  // namespace scenfuzz::wmg::detail

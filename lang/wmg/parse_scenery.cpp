// SCENERY_ELEMENTS and its roads (the junctions are parsed in parse_junction.cpp). A junction or
// road with an error is reported and the parser resumes at the next one.
#include <string>

#include "lang/wmg/parse_sections.hpp"

namespace scenfuzz::wmg::detail {

namespace {

constexpr TokenKind kComma = TokenKind::comma;
constexpr TokenKind kOpen = TokenKind::left_bracket;
constexpr TokenKind kClose = TokenKind::right_bracket;

// `J1: Junction type`: the start of the next junction.
bool at_junction_start(const Cursor& cursor) {
  return cursor.at(TokenKind::word) && cursor.at(TokenKind::colon, 1) &&
         cursor.at_phrase("Junction type", 2);
}

// `R1: START`: the start of the next road.
bool at_road_start(const Cursor& cursor) {
  return cursor.at_road_id() && cursor.at(TokenKind::colon, 1) && cursor.at_word("START", 2);
}

HorizontalGeometry parse_horizontal_geometry(Cursor& cursor) {
  HorizontalGeometry geometry;
  SourceLocation first = cursor.expect(kOpen, "before the horizontal geometry").location;
  if (cursor.at(TokenKind::word) && cursor.at(TokenKind::colon, 1)) {
    geometry.segments = comma_list<SegmentLabel>(cursor, [&] {
      SegmentLabel segment;
      segment.segment = cursor.id("a road segment");
      cursor.expect(TokenKind::colon, "after the segment's ID");
      segment.value = cursor.label(vocabulary::horizontal_geometry());
      segment.location = cursor.span_from(segment.segment.location);
      return segment;
    });
  } else {
    geometry.whole_road = cursor.label(vocabulary::horizontal_geometry());
  }
  cursor.close(kClose, "after the horizontal geometry");
  geometry.location = cursor.span_from(first);
  return geometry;
}

// `S1: 500 to 900` (or `S1: N/A` where allowed).
SegmentRange parse_segment_range(Cursor& cursor, const std::string& what, bool allow_none) {
  SegmentRange segment;
  segment.segment = cursor.id("a road segment");
  cursor.expect(TokenKind::colon, "after the segment's ID");
  if (allow_none && cursor.at_phrase("N/A")) {
    cursor.expect_phrase("N/A", "");
  } else {
    segment.range = cursor.range({kComma, kClose}, what);
  }
  segment.location = cursor.span_from(segment.segment.location);
  return segment;
}

CurvatureRadius parse_curvature_radius(Cursor& cursor) {
  CurvatureRadius radius;
  SourceLocation first = cursor.expect(kOpen, "before the curvature radius").location;
  if (cursor.at_phrase("N/A")) {
    cursor.expect_phrase("N/A", "");
    radius.not_applicable = true;
  } else {
    radius.segments = comma_list<SegmentRange>(
        cursor, [&] { return parse_segment_range(cursor, "the curvature radius", true); });
  }
  cursor.close(kClose, "after the curvature radius");
  radius.location = cursor.span_from(first);
  return radius;
}

LaneWidth parse_lane_width(Cursor& cursor) {
  LaneWidth width;
  SourceLocation first = cursor.expect(kOpen, "before the lane width").location;
  if (cursor.at(TokenKind::word) && cursor.at(TokenKind::colon, 1)) {
    width.segments = comma_list<SegmentRange>(
        cursor, [&] { return parse_segment_range(cursor, "the lane width", false); });
  } else {
    width.whole_road = cursor.range(kClose, "the lane width");
  }
  cursor.close(kClose, "after the lane width");
  width.location = cursor.span_from(first);
  return width;
}

FixedRoadStructure parse_fixed_structure(Cursor& cursor) {
  FixedRoadStructure structure;
  SourceLocation first = cursor.peek().location;
  if (cursor.at_phrase("Street lights")) {
    StreetLights lights;
    structure.type = Label{"Street lights", false, cursor.expect_phrase("Street lights", "")};
    cursor.expect(TokenKind::colon,
                  "after 'Street lights' (Street lights: {spacing: ..., "
                  "height: ...})");
    cursor.expect(TokenKind::left_brace, "after 'Street lights:'");
    cursor.expect_phrase("spacing", "after 'Street lights: {'");
    cursor.expect(TokenKind::colon, "after 'spacing'");
    lights.spacing = cursor.range(kComma, "the street lights' spacing");
    cursor.expect(kComma, "after the street lights' spacing");
    cursor.expect_phrase("height", "after the street lights' spacing");
    cursor.expect(TokenKind::colon, "after 'height'");
    lights.height = cursor.range(TokenKind::right_brace, "the street lights' height");
    cursor.close(TokenKind::right_brace, "after the street lights' height");
    lights.location = cursor.span_from(first);
    structure.street_lights = lights;
  } else {
    structure.type = cursor.label(vocabulary::fixed_structure());
  }
  if (cursor.at_word("at")) {
    cursor.take();
    structure.at = bracketed_list<Identifier>(cursor, "the places of the fixed road structure",
                                              [&] { return cursor.id("a place on the road"); });
  }
  structure.location = cursor.span_from(first);
  return structure;
}

// "Special road structures [Bridge] as [B1] at [200] distance from START" and
// "Road sign [Speed limit] as [S1] at [150] distance from START" share their tail.
template <typename Placed>
Placed parse_placed_structure(Cursor& cursor, const std::string& keyword,
                              const Vocabulary& vocabulary) {
  Placed placed;
  SourceLocation first = cursor.expect_phrase(keyword, "");
  placed.type = cursor.bracketed_label(vocabulary);
  cursor.expect_phrase("as", "after the " + vocabulary.what);
  placed.id = cursor.bracketed_id("the " + vocabulary.what + "'s ID");
  cursor.expect_phrase("at", "after the " + vocabulary.what + "'s ID");
  placed.distance_from_start = cursor.bracketed_number("the distance from the road's start");
  cursor.expect_phrase("distance from START", "after the distance");
  placed.location = cursor.span_from(first);
  return placed;
}

TemporaryRoadStructures parse_temporary_structures(Cursor& cursor) {
  TemporaryRoadStructures structures;
  SourceLocation first = cursor.expect_phrase("Temporary road structures", "");
  structures.types = bracketed_list<Label>(cursor, "the temporary road structures", [&] {
    return cursor.label(vocabulary::temporary_structure());
  });
  cursor.expect_phrase("at", "after the temporary road structures");
  // The grammar document writes this lane without brackets, unlike every other; both are read.
  if (cursor.at(kOpen)) {
    structures.lane = cursor.bracketed_lane_name("the temporary road structures' lane");
  } else {
    structures.lane = cursor.lane_name("the temporary road structures' lane");
  }
  structures.location = cursor.span_from(first);
  return structures;
}

Road parse_road(Cursor& cursor) {
  Road road;
  road.id = cursor.road_id("the road");
  cursor.expect(TokenKind::colon, "after the road id");
  cursor.expect_phrase("START", "after '" + road.id.name + ":'");
  if (cursor.at(TokenKind::colon)) {
    cursor.take();
    road.start_junction = cursor.bracketed_id("the junction the road starts at");
  }
  cursor.expect_phrase("Road type", "after 'START'");
  road.road_type = cursor.bracketed_label(vocabulary::road_type());
  cursor.expect_phrase("as", "after the road type");
  cursor.expect(kOpen, "before the road id after 'as'");
  road.named_as = cursor.road_id("the road type's road");
  cursor.close(kClose, "after the road id");
  cursor.expect_phrase("with zone as", "after the road id");
  road.zone = cursor.bracketed_label(vocabulary::zone_type());
  cursor.expect_phrase("AND speed limit of", "after the zone");
  cursor.expect(kOpen, "before the speed limit");
  if (cursor.at_phrase("N/A")) {
    cursor.expect_phrase("N/A", "");
  } else {
    road.speed_limit = cursor.number("the speed limit");
  }
  cursor.close(kClose, "after the speed limit");
  cursor.expect_phrase("in", "after the speed limit");
  if (!cursor.at_word("a") && !cursor.at_word("an"))
    cursor.fail(cursor.peek().location,
                "expected 'a' or 'an' after 'in', found " + describe(cursor.peek()));
  cursor.take();
  road.environment = cursor.bracketed_label(vocabulary::environment_type());
  cursor.expect_phrase("environment", "after the environment type");
  cursor.expect_phrase("with Number of lanes", "after 'environment'");
  cursor.expect(kOpen, "before the number of lanes");
  road.lane_count = cursor.whole_number("the number of lanes");
  cursor.close(kClose, "after the number of lanes");
  cursor.expect_phrase("as", "after the number of lanes");
  SourceLocation lanes_location;
  road.lanes = bracketed_list<LaneName>(
      cursor, "the road's lanes", [&] { return cursor.lane_name("one of the road's lanes"); },
      &lanes_location);
  check_count(cursor, road.lane_count, road.lanes.size(), lanes_location, "lane");
  cursor.expect_phrase("Road traffic direction", "after the road's lanes");
  road.traffic_direction = cursor.bracketed_label(vocabulary::traffic_direction());
  cursor.expect_phrase("Lane type", "after the traffic direction");
  road.lane_type = cursor.bracketed_label(vocabulary::lane_type());
  cursor.expect_phrase("Lane markings", "after the lane type");
  road.lane_markings = cursor.bracketed_label(vocabulary::lane_marking());
  if (cursor.at_phrase("Road surface type")) {
    cursor.expect_phrase("Road surface type", "");
    road.surface_type = cursor.bracketed_label(vocabulary::surface_type());
  }
  if (cursor.at_phrase("with surface condition")) {
    cursor.expect_phrase("with surface condition", "");
    road.surface_condition = cursor.bracketed_label(vocabulary::surface_condition());
  }
  if (cursor.at_phrase("AND surface feature")) {
    cursor.expect_phrase("AND surface feature", "");
    road.surface_feature = cursor.bracketed_label(vocabulary::surface_feature());
  }
  cursor.expect_phrase("Horizontal road geometry", "after the lane markings and surface");
  road.horizontal_geometry = parse_horizontal_geometry(cursor);
  if (cursor.at_phrase("with curvature radius of")) {
    cursor.expect_phrase("with curvature radius of", "");
    road.curvature_radius = parse_curvature_radius(cursor);
  }
  cursor.expect_phrase("Vertical road geometry", "after the horizontal road geometry");
  road.vertical_geometry = cursor.bracketed_label(vocabulary::vertical_geometry());
  cursor.expect_phrase("Transverse road geometry", "after the vertical road geometry");
  road.transverse_geometry = bracketed_list<Label>(cursor, "the transverse road geometry", [&] {
    return cursor.label(vocabulary::transverse_geometry());
  });
  cursor.expect_phrase("Road banking angle", "after the transverse road geometry");
  road.banking_angle = cursor.bracketed_label(vocabulary::banking_angle());
  cursor.expect_phrase("with", "after the road banking angle");
  road.roadside_feature = cursor.bracketed_label(vocabulary::roadside_feature());
  cursor.expect_phrase("roadside feature", "after the roadside feature");
  if (cursor.at_phrase("Roadway edge features")) {
    cursor.expect_phrase("Roadway edge features", "");
    road.edge_feature = cursor.bracketed_label(vocabulary::edge_feature());
  }
  // The four kinds of structure may each be given any number of times, in any order.
  while (true) {
    if (cursor.at_phrase("Special road structures")) {
      road.special_structures.push_back(parse_placed_structure<SpecialRoadStructure>(
          cursor, "Special road structures", vocabulary::special_structure()));
    } else if (cursor.at_phrase("Fixed road structures")) {
      cursor.expect_phrase("Fixed road structures", "");
      for (FixedRoadStructure& structure : bracketed_list<FixedRoadStructure>(
               cursor, "the fixed road structures", [&] { return parse_fixed_structure(cursor); }))
        road.fixed_structures.push_back(std::move(structure));
    } else if (cursor.at_phrase("Temporary road structures")) {
      road.temporary_structures.push_back(parse_temporary_structures(cursor));
    } else if (cursor.at_phrase("Road sign")) {
      road.road_signs.push_back(
          parse_placed_structure<RoadSign>(cursor, "Road sign", vocabulary::road_sign()));
    } else {
      break;
    }
  }
  cursor.expect_phrase("Length", "after the roadside and road structures");
  road.length = cursor.bracketed_range("the road's length");
  cursor.expect_phrase("AND Lane width", "after the road's length");
  road.lane_width = parse_lane_width(cursor);
  cursor.expect_phrase("END", "after the lane width, to end road " + road.id.name);
  if (cursor.at(TokenKind::colon)) {
    cursor.take();
    road.end_junction = cursor.bracketed_id("the junction the road ends at");
  }
  road.location = cursor.span_from(road.id.location);
  return road;
}

}  // namespace

Scenery parse_scenery(Cursor& cursor) {
  Scenery scenery;
  SourceLocation first = cursor.expect_phrase("SCENERY ELEMENTS", "after the header");
  cursor.expect(TokenKind::colon, "after 'SCENERY ELEMENTS'");
  cursor.expect_phrase("DO", "after 'SCENERY ELEMENTS:'");
  cursor.expect(TokenKind::colon, "after 'DO'");
  scenery.description = cursor.string("the scenery's description");
  scenery.id = cursor.bracketed_id("the scenery");
  cursor.expect_phrase("as", "after the scenery's ID");
  cursor.expect(TokenKind::colon, "after 'as'");

  cursor.expect_phrase("Junctions", "after the scenery's 'as:'");
  cursor.expect(TokenKind::colon, "after 'Junctions'");
  if (cursor.at_phrase("None")) {
    cursor.take();
  } else {
    if (cursor.at_phrase("Roads"))
      cursor.fail(cursor.peek().location,
                  "expected 'None' or a junction (J1: Junction type [...] ...) after "
                  "'Junctions:', found 'Roads'");
    do {
      std::size_t start = cursor.position();
      try {
        scenery.junctions.push_back(parse_junction(cursor));
      } catch (const SyntaxError&) {
        cursor.resync(start,
                      [&] { return at_junction_start(cursor) || cursor.at_phrase("Roads"); });
      }
    } while (at_junction_start(cursor));
  }

  cursor.expect_phrase("Roads", "after the junctions");
  cursor.expect(TokenKind::colon, "after 'Roads'");
  if (cursor.at_phrase("None")) {
    cursor.take();
  } else {
    if (!at_road_start(cursor))
      cursor.fail(cursor.peek().location,
                  "expected 'None' or a road (R1: START ...) after 'Roads:', found " +
                      describe(cursor.peek()));
    do {
      std::size_t start = cursor.position();
      try {
        scenery.roads.push_back(parse_road(cursor));
      } catch (const SyntaxError&) {
        cursor.resync(start, [&] { return at_road_start(cursor); });
      }
    } while (at_road_start(cursor));
  }
  scenery.location = cursor.span_from(first);
  return scenery;
}

}  // namespace scenfuzz::wmg::detail

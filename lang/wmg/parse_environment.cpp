// ENVIRONMENT_ELEMENTS (weather, time of day, light, connectivity) and the optional
// TRAFFIC_MODEL (centroids and flows between them).
#include <string>

#include "lang/wmg/parse_sections.hpp"

namespace scenfuzz::wmg::detail {

namespace {

constexpr TokenKind kComma = TokenKind::comma;
constexpr TokenKind kOpen = TokenKind::left_bracket;
constexpr TokenKind kClose = TokenKind::right_bracket;

// INT ':' INT as seconds since midnight.
double parse_time_of_day(Cursor& cursor, SourceLocation& where) {
  SourceLocation first = cursor.peek().location;
  auto whole = [&](const char* what) {
    if (!cursor.at(TokenKind::number) || cursor.peek().text.find('.') != std::string::npos)
      cursor.fail(cursor.peek().location, std::string("expected ") + what +
                                              " of a time of day such as 08:00, found " +
                                              describe(cursor.peek()));
    return cursor.take().number;
  };
  double hours = whole("the hours");
  cursor.expect(TokenKind::colon, "between the hours and minutes of a time of day (08:00)");
  double minutes = whole("the minutes");
  where = cursor.span_from(first);
  if (hours > 24 || minutes > 59 || (hours == 24 && minutes > 0))
    cursor.error(where, "invalid time of day '" + std::string(cursor.text_of(where)) +
                            "': expected hours 0-24 and minutes 00-59");
  return hours * 3600 + minutes * 60;
}

// TIME_RANGE `08:00 to 18:00`, or one time of day.
NumberRange parse_time_range(Cursor& cursor) {
  NumberRange range;
  SourceLocation low_location;
  range.low = range.high = parse_time_of_day(cursor, low_location);
  range.location = low_location;
  if (cursor.at_word("to")) {
    cursor.take();
    SourceLocation high_location;
    range.high = parse_time_of_day(cursor, high_location);
    range.is_range = true;
    range.location = span(low_location, high_location);
    if (range.low > range.high)
      cursor.error(range.location,
                   "inverted range: the lower bound " + std::string(cursor.text_of(low_location)) +
                       " is above the upper bound " + std::string(cursor.text_of(high_location)) +
                       " (a time range cannot wrap past midnight)");
  } else if (!cursor.at(kClose)) {
    cursor.fail(cursor.peek().location, "expected 'to' or ']' after the time of day " +
                                            std::string(cursor.text_of(low_location)) + ", found " +
                                            describe(cursor.peek()));
  }
  return range;
}

Connectivity parse_connectivity(Cursor& cursor) {
  Connectivity connectivity;
  SourceLocation first = cursor.expect(kOpen, "before the connectivity").location;
  if (cursor.at_phrase("None")) {
    cursor.take();
    connectivity.none = true;
  } else {
    cursor.expect_phrase("Communication", "(or 'None') in the connectivity");
    cursor.expect(TokenKind::colon, "after 'Communication'");
    connectivity.link = cursor.label(vocabulary::communication_link());
    cursor.expect(TokenKind::colon, "after '" + connectivity.link->text + "'");
    connectivity.technology =
        cursor.label(connectivity.link->text == "V2V" ? vocabulary::v2v_technology()
                                                      : vocabulary::v2i_technology());
    cursor.expect(kComma, "after the communication technology");
    cursor.expect_phrase("Positioning", "after the communication");
    cursor.expect(TokenKind::colon, "after 'Positioning'");
    connectivity.positioning = cursor.label(vocabulary::positioning());
  }
  cursor.close(kClose, "after the connectivity");
  connectivity.location = cursor.span_from(first);
  return connectivity;
}

Centroid parse_centroid(Cursor& cursor) {
  Centroid centroid;
  SourceLocation first = cursor.expect_phrase("CENTROID", "");
  centroid.id = cursor.bracketed_id("the centroid");
  cursor.expect_phrase("in", "after the centroid");
  cursor.expect(kOpen, "before the centroid's road");
  centroid.road = cursor.road_id("the centroid's road");
  cursor.close(kClose, "after the centroid's road");
  cursor.expect_phrase("at", "after the centroid's road");
  centroid.distance = cursor.bracketed_range("the centroid's distance");
  cursor.expect_phrase("to", "after the centroid's distance");
  centroid.reference = cursor.bracketed_id("the scenery element the distance is measured to");
  centroid.location = cursor.span_from(first);
  return centroid;
}

TrafficFlow parse_flow(Cursor& cursor) {
  TrafficFlow flow;
  SourceLocation first = cursor.expect_phrase("TRAFFIC", "");
  flow.id = cursor.bracketed_id("the traffic flow");
  cursor.expect(TokenKind::colon, "after the traffic flow's ID");
  cursor.expect(kOpen, "before the flow's source and destination");
  flow.source = cursor.id("the source centroid");
  cursor.expect(TokenKind::colon, "after the source centroid");
  flow.source_lane = cursor.lane_name("the source lane");
  cursor.expect(kComma, "between the source and the destination");
  flow.destination = cursor.id("the destination centroid");
  cursor.expect(TokenKind::colon, "after the destination centroid");
  flow.destination_lane = cursor.lane_name("the destination lane");
  cursor.close(kClose, "after the destination lane");
  cursor.expect_phrase("at", "after the flow's source and destination");
  cursor.expect(kOpen, "before the flow's parameters");
  flow.first = cursor.range(kComma, "the flow's first parameter");
  cursor.expect(kComma, "after the flow's first parameter");
  flow.second = cursor.range(kClose, "the flow's second parameter");
  cursor.close(kClose, "after the flow's parameters");
  flow.location = cursor.span_from(first);
  return flow;
}

bool at_flow_start(const Cursor& cursor) {
  return cursor.at_word("TRAFFIC") && cursor.at(kOpen, 1);
}

}  // namespace

Environment parse_environment(Cursor& cursor) {
  Environment environment;
  SourceLocation first = cursor.expect_phrase("ENVIRONMENT ELEMENTS", "after the dynamic elements");
  cursor.expect(TokenKind::colon, "after 'ENVIRONMENT ELEMENTS'");
  cursor.expect_phrase("DO", "after 'ENVIRONMENT ELEMENTS:'");
  cursor.expect(TokenKind::colon, "after 'DO'");
  environment.id = cursor.bracketed_id("the environment");
  if (cursor.at_phrase("Wind")) {
    cursor.take();
    environment.wind = cursor.bracketed_range("the wind");
  }
  cursor.expect_phrase("Cloudiness", "after the environment's ID and wind");
  environment.cloudiness = cursor.bracketed_range("the cloudiness");
  if (cursor.at_phrase("Particulates")) {
    cursor.take();
    environment.particulates = cursor.bracketed_label(vocabulary::particulates());
  }
  cursor.expect_phrase("Rainfall", "after the cloudiness and particulates");
  SourceLocation rain_first = cursor.expect(kOpen, "before the rainfall").location;
  environment.rainfall.type = cursor.label(vocabulary::rainfall());
  cursor.expect(TokenKind::colon, "after the rainfall type");
  environment.rainfall.intensity = cursor.range(kClose, "the rainfall");
  cursor.close(kClose, "after the rainfall");
  environment.rainfall.location = cursor.span_from(rain_first);
  if (cursor.at_phrase("Snowfall")) {
    cursor.take();
    Snowfall snowfall;
    SourceLocation snow_first = cursor.expect(kOpen, "before the snowfall").location;
    snowfall.type = cursor.label(vocabulary::snowfall());
    cursor.expect(TokenKind::left_paren, "after the snowfall type (Light Snow (visibility: ...))");
    cursor.expect_phrase("visibility", "after '('");
    cursor.expect(TokenKind::colon, "after 'visibility'");
    snowfall.visibility = cursor.range(TokenKind::right_paren, "the visibility");
    cursor.close(TokenKind::right_paren, "after the visibility");
    cursor.close(kClose, "after the snowfall");
    snowfall.location = cursor.span_from(snow_first);
    environment.snowfall = snowfall;
  }
  cursor.expect_phrase("Time of the day", "after the rainfall and snowfall");
  cursor.expect(kOpen, "before the time of day");
  if (cursor.at_phrase("Any")) {
    cursor.take();
  } else {
    environment.time_of_day = parse_time_range(cursor);
  }
  cursor.close(kClose, "after the time of day");
  cursor.expect_phrase("Illumination", "after the time of day");
  environment.illumination = cursor.bracketed_label(vocabulary::light_type());
  cursor.expect_phrase("with", "after the illumination");
  environment.light_source = cursor.bracketed_label(vocabulary::light_source());
  cursor.expect_phrase("as light source", "after the light source");
  if (cursor.at_word("at") && cursor.at(kOpen, 1)) {
    LightSourcePosition position;
    SourceLocation position_first = cursor.take().location;
    position.elevation = cursor.bracketed_range("the light source's elevation");
    cursor.expect_phrase("degree elevation AND", "after the light source's elevation");
    position.position =
        cursor.bracketed_enumerated<RelativeLocation>(vocabulary::relative_location());
    cursor.expect_phrase("position", "after the light source's position");
    position.location = cursor.span_from(position_first);
    environment.light_source_position = position;
  }
  if (cursor.at_phrase("Connectivity")) {
    cursor.take();
    environment.connectivity = parse_connectivity(cursor);
  }
  environment.location = cursor.span_from(first);
  return environment;
}

TrafficModel parse_traffic_model(Cursor& cursor) {
  TrafficModel traffic;
  SourceLocation first = cursor.expect_phrase("TRAFFIC ELEMENTS", "after the environment");
  cursor.expect(TokenKind::colon, "after 'TRAFFIC ELEMENTS'");
  cursor.expect_phrase("INITIAL", "after 'TRAFFIC ELEMENTS:'");
  // The grammar document writes no ':' after this INITIAL, unlike the dynamic one; both are read.
  if (cursor.at(TokenKind::colon)) cursor.take();
  traffic.centroids.push_back(parse_centroid(cursor));
  while (cursor.at_word("AND")) {
    cursor.take();
    traffic.centroids.push_back(parse_centroid(cursor));
  }
  cursor.expect_phrase("DO", "after the centroids");
  cursor.expect(TokenKind::colon, "after 'DO'");
  if (!at_flow_start(cursor))
    cursor.fail(cursor.peek().location,
                "expected a traffic flow 'TRAFFIC [F1]: ...' after 'DO:', found " +
                    describe(cursor.peek()));
  do {
    std::size_t start = cursor.position();
    try {
      traffic.flows.push_back(parse_flow(cursor));
    } catch (const SyntaxError&) {
      cursor.resync(start, [&] { return at_flow_start(cursor); });
    }
  } while (at_flow_start(cursor));
  traffic.location = cursor.span_from(first);
  return traffic;
}

}  // namespace scenfuzz::wmg::detail

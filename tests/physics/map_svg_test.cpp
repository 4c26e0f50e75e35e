// render_map_svg on small hand-made maps: a standalone, well-formed document; one drawing
// element per lane and per piece of road furniture, each with its class; labels only when asked
// and XML-escaped; every drawn point inside the viewBox, north up. render_map_svg_layer on the
// built-in crossroads: a fragment with only what reaches its frame.
#include "physics/map/map_svg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {
namespace {

constexpr std::string_view awkward_id = "b<&>\"'";

// Two eastbound lanes side by side (a: y = 0, the other: y = 3.5, x 0..100) running into a
// junction with a crosswalk; a signal stops both at x = 95.
MapDescription small_map() {
  MapDescription map;
  map.name = "small <map> & co";
  map.source = "test";
  LaneDescription a;
  a.id = "lane_a";
  a.centre_line = {{0, 0}, {50, 0}, {100, 0}};
  a.left_boundary_type = BoundaryType::dotted_white;
  a.right_boundary_type = BoundaryType::curb;
  a.left_forward_neighbours = {std::string(awkward_id)};
  LaneDescription b;
  b.id = std::string(awkward_id);
  b.centre_line = {{0, 3.5}, {100, 3.5}};
  b.right_boundary_type = BoundaryType::dotted_white;
  b.left_boundary_type = BoundaryType::double_yellow;
  b.right_forward_neighbours = {"lane_a"};
  map.lanes = {a, b};
  map.junctions = {{"junction_1", {{100, -5}, {120, -5}, {120, 10}, {100, 10}}}};
  TrafficLightDescription light;
  light.id = "signal_1";
  light.heads = {{96, 8}};
  light.stop_lines = {{{95, -1.75}, {95, 5.25}}};
  light.lanes = {{"lane_a", 95, 95}, {std::string(awkward_id), 95, 95}};
  map.traffic_lights = {light};
  CrosswalkDescription crosswalk;
  crosswalk.id = "crosswalk_1";
  crosswalk.outline = {{103, -2}, {107, -2}, {107, 6}, {103, 6}};
  map.crosswalks = {crosswalk};
  return map;
}

std::size_t count(std::string_view text, std::string_view needle) {
  std::size_t found = 0;
  for (std::size_t at = text.find(needle); at != std::string_view::npos;
       at = text.find(needle, at + needle.size()))
    ++found;
  return found;
}

std::size_t count_class(std::string_view svg, std::string_view css_class) {
  return count(svg, "class=\"" + std::string(css_class) + "\"");
}

// Entity references are the only '&' XML allows in text and attribute values.
bool valid_entities(std::string_view text) {
  for (std::size_t at = text.find('&'); at != std::string_view::npos; at = text.find('&', at + 1)) {
    const std::size_t end = text.find(';', at);
    if (end == std::string_view::npos) return false;
    const std::string_view entity = text.substr(at + 1, end - at - 1);
    if (entity != "amp" && entity != "lt" && entity != "gt" && entity != "quot" &&
        entity != "apos" && !entity.starts_with('#'))
      return false;
  }
  return true;
}

// A small XML checker: balanced and properly nested tags, quoted attribute values, no stray '<'
// or '&', and a single root element. An empty string means well formed.
std::string xml_error(std::string_view xml) {
  std::vector<std::string_view> open;
  bool had_root = false;
  std::size_t at = 0;
  while (at < xml.size()) {
    const std::size_t tag = xml.find('<', at);
    const std::string_view text =
        xml.substr(at, tag == std::string_view::npos ? xml.npos : tag - at);
    if (!valid_entities(text)) return "bad '&' in text near " + std::to_string(at);
    if (open.empty() && text.find_first_not_of(" \t\r\n") != std::string_view::npos)
      return "text outside the root element at " + std::to_string(at);
    if (tag == std::string_view::npos) break;
    if (xml.substr(tag).starts_with("<?")) {
      if (had_root || !open.empty()) return "processing instruction inside the document";
      const std::size_t end = xml.find("?>", tag);
      if (end == std::string_view::npos) return "unterminated <?";
      at = end + 2;
      continue;
    }
    if (xml.substr(tag).starts_with("<!--")) {
      const std::size_t end = xml.find("-->", tag);
      if (end == std::string_view::npos) return "unterminated comment";
      at = end + 3;
      continue;
    }
    const bool closing = xml.substr(tag).starts_with("</");
    std::size_t cursor = tag + (closing ? 2 : 1);
    const std::size_t name_end = xml.find_first_of(" \t\r\n/>", cursor);
    if (name_end == std::string_view::npos || name_end == cursor) return "bad tag name";
    const std::string_view name = xml.substr(cursor, name_end - cursor);
    cursor = name_end;
    bool self_closing = false;
    while (true) {
      cursor = xml.find_first_not_of(" \t\r\n", cursor);
      if (cursor == std::string_view::npos) return "unterminated tag " + std::string(name);
      if (xml[cursor] == '>') break;
      if (xml.substr(cursor).starts_with("/>")) {
        self_closing = true;
        ++cursor;
        break;
      }
      if (closing) return "attributes on a closing tag";
      const std::size_t equals = xml.find('=', cursor);
      if (equals == std::string_view::npos || xml.find_first_of(" \t\r\n<>", cursor) < equals)
        return "attribute without value in " + std::string(name);
      const char quote = xml[equals + 1];
      if (quote != '"' && quote != '\'') return "unquoted attribute in " + std::string(name);
      const std::size_t value_end = xml.find(quote, equals + 2);
      if (value_end == std::string_view::npos) return "unterminated attribute";
      const std::string_view value = xml.substr(equals + 2, value_end - equals - 2);
      if (value.find('<') != std::string_view::npos || !valid_entities(value))
        return "bad character in attribute of " + std::string(name);
      cursor = value_end + 1;
    }
    at = cursor + 1;
    if (closing) {
      if (open.empty() || open.back() != name)
        return "</" + std::string(name) + "> does not close the open element";
      open.pop_back();
    } else if (!self_closing) {
      if (open.empty() && had_root) return "second root element";
      had_root = true;
      open.push_back(name);
    } else if (open.empty()) {
      return "self-closing root";
    }
  }
  if (!open.empty()) return "<" + std::string(open.back()) + "> is never closed";
  if (!had_root) return "no root element";
  return "";
}

// The values of every `attribute="..."` in `svg`.
std::vector<std::string_view> attribute_values(std::string_view svg, std::string_view attribute) {
  std::vector<std::string_view> values;
  const std::string needle = " " + std::string(attribute) + "=\"";
  for (std::size_t at = svg.find(needle); at != std::string_view::npos;
       at = svg.find(needle, at + 1)) {
    const std::size_t begin = at + needle.size();
    values.push_back(svg.substr(begin, svg.find('"', begin) - begin));
  }
  return values;
}

std::vector<double> numbers_in(std::string_view text) {
  std::vector<double> numbers;
  std::string buffer(text);
  const char* cursor = buffer.c_str();
  while (*cursor != '\0') {
    char* end = nullptr;
    const double value = std::strtod(cursor, &end);
    if (end == cursor) {
      ++cursor;
    } else {
      numbers.push_back(value);
      cursor = end;
    }
  }
  return numbers;
}

struct ViewBox {
  double x = 0, y = 0, width = 0, height = 0;
};

ViewBox view_box(std::string_view svg) {
  const auto values = attribute_values(svg, "viewBox");
  EXPECT_FALSE(values.empty());
  if (values.empty()) return {};
  const auto numbers = numbers_in(values.front());
  EXPECT_EQ(numbers.size(), 4u);
  if (numbers.size() != 4) return {};
  return {numbers[0], numbers[1], numbers[2], numbers[3]};
}

// The drawing before the legend (whose coordinates are in its own scaled frame).
std::string_view map_part(std::string_view svg) {
  return svg.substr(0, svg.find("<g class=\"legend\""));
}

// Every x,y pair drawn: polygon/polyline points, path data, circle centres and label anchors.
std::vector<MapPoint> drawn_points(std::string_view svg) {
  std::vector<MapPoint> points;
  auto add_pairs = [&points](std::string_view text) {
    const auto numbers = numbers_in(text);
    EXPECT_EQ(numbers.size() % 2, 0u) << text;
    for (std::size_t i = 0; i + 1 < numbers.size(); i += 2)
      points.push_back({numbers[i], numbers[i + 1]});
  };
  for (const auto value : attribute_values(svg, "points")) add_pairs(value);
  for (const auto value : attribute_values(svg, "d")) add_pairs(value);
  const auto xs = attribute_values(svg, "cx");
  const auto ys = attribute_values(svg, "cy");
  EXPECT_EQ(xs.size(), ys.size());
  for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i)
    points.push_back({numbers_in(xs[i]).at(0), numbers_in(ys[i]).at(0)});
  for (const auto value : attribute_values(svg, "transform")) {
    const std::size_t translate = value.find("translate(");
    if (translate == std::string_view::npos) continue;
    const auto numbers =
        numbers_in(value.substr(translate, value.find(')', translate) - translate));
    EXPECT_EQ(numbers.size(), 2u) << value;
    if (numbers.size() == 2) points.push_back({numbers[0], numbers[1]});
  }
  return points;
}

std::string_view without_declaration(std::string_view svg) {
  if (svg.starts_with("<?xml")) svg.remove_prefix(svg.find("?>") + 2);
  while (!svg.empty() && (svg.front() == '\n' || svg.front() == ' ')) svg.remove_prefix(1);
  return svg;
}

TEST(MapSvg, XmlCheckerCatchesMalformedDocuments) {
  EXPECT_EQ(xml_error("<?xml version=\"1.0\"?>\n<svg a=\"1\"><g><p/></g><!-- c --></svg>\n"), "");
  EXPECT_NE(xml_error("<svg><g></svg></g>"), "");
  EXPECT_NE(xml_error("<svg><g></svg>"), "");
  EXPECT_NE(xml_error("<svg></svg><svg></svg>"), "");
  EXPECT_NE(xml_error("<svg a=1></svg>"), "");
  EXPECT_NE(xml_error("<svg a=\"<\"></svg>"), "");
  EXPECT_NE(xml_error("<svg><text>a & b</text></svg>"), "");
  EXPECT_NE(xml_error("<svg><text>a</text>"), "");
  EXPECT_NE(xml_error(""), "");
}

TEST(MapSvg, IsAStandaloneWellFormedDocument) {
  const RoadMap map = build_road_map(small_map());
  for (const bool labels : {false, true}) {
    SCOPED_TRACE(labels ? "with labels" : "without labels");
    const std::string svg = render_map_svg(map, {.labels = labels});
    EXPECT_TRUE(without_declaration(svg).starts_with("<svg")) << svg.substr(0, 200);
    EXPECT_TRUE(svg.ends_with("</svg>\n"));
    EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_EQ(xml_error(svg), "") << svg;
    // The stylesheet is shared; elements carry classes, not style attributes.
    EXPECT_EQ(count(svg, "<style>"), 1u);
    EXPECT_EQ(count(svg, " style=\""), 0u);
  }
}

TEST(MapSvg, DrawsEveryLaneAndEveryPieceOfFurniture) {
  const std::string svg = render_map_svg(build_road_map(small_map()));
  EXPECT_EQ(count_class(svg, "lane"), 2u);
  EXPECT_EQ(count_class(svg, "centre"), 2u);
  EXPECT_EQ(count_class(svg, "arrow"), 2u);
  EXPECT_EQ(count_class(svg, "junction"), 1u);
  EXPECT_EQ(count_class(svg, "crosswalk"), 1u);
  EXPECT_EQ(count_class(svg, "stop-line"), 1u);
  EXPECT_EQ(count_class(svg, "signal"), 1u);
  EXPECT_EQ(count(svg, "<circle class=\"signal\""), 1u);
  // The dotted line between the lanes is listed by both, and drawn once.
  EXPECT_EQ(count_class(svg, "boundary-dotted-white"), 1u);
  EXPECT_EQ(count_class(svg, "boundary-curb"), 1u);
  EXPECT_EQ(count_class(svg, "boundary-double-yellow"), 1u);
  EXPECT_EQ(count_class(svg, "boundary-double-yellow-gap"), 1u);
  EXPECT_EQ(count_class(svg, "legend"), 1u);
  EXPECT_EQ(count_class(svg, "scale-bar"), 1u);
  EXPECT_NE(svg.find("url(#crosswalk-stripes)"), std::string::npos);
  EXPECT_NE(svg.find("id=\"crosswalk-stripes\""), std::string::npos);
}

TEST(MapSvg, DrawsOnlyCurbsInsideJunctions) {
  MapDescription description = small_map();
  LaneDescription turn;
  turn.id = "turn";
  turn.centre_line = {{100, 0}, {110, 0}, {115, 5}};
  turn.junction = "junction_1";
  turn.left_boundary_type = BoundaryType::dotted_white;
  turn.right_boundary_type = BoundaryType::curb;
  description.lanes.push_back(turn);
  // Some maps leave junction lanes without a junction id; its middle lies in the outline, which
  // (as in the san_francisco sample) is traced twice.
  std::vector<MapPoint>& outline = description.junctions.front().outline;
  const std::vector<MapPoint> once = outline;
  outline.insert(outline.end(), once.begin(), once.end());
  LaneDescription through;
  through.id = "through";
  through.centre_line = {{100, 3.5}, {120, 3.5}};
  through.left_boundary_type = BoundaryType::dotted_white;
  through.right_boundary_type = BoundaryType::solid_white;
  description.lanes.push_back(through);
  const std::string svg = render_map_svg(build_road_map(std::move(description)));
  EXPECT_EQ(count_class(svg, "lane"), 4u);
  EXPECT_EQ(count_class(svg, "boundary-solid-white"), 0u);
  EXPECT_EQ(count_class(svg, "boundary-dotted-white"), 1u);  // only the one between the lanes
  EXPECT_EQ(count_class(svg, "boundary-curb"), 2u);
}

// Opposite lanes either side of a median list each other as neighbours, but each side has its
// own line; a double yellow line the two share is drawn once.
TEST(MapSvg, SharedBoundariesOnceAndMediansOnBothSides) {
  auto opposite_pair = [](double gap) {
    MapDescription description;
    description.source = "test";
    LaneDescription east;
    east.id = "east";
    east.centre_line = {{0, 0}, {60, 0}};
    east.left_boundary_type = BoundaryType::double_yellow;
    east.left_reverse_neighbours = {"west"};
    LaneDescription west;
    west.id = "west";
    west.centre_line = {{60, 3.5 + gap}, {0, 3.5 + gap}};
    west.left_boundary_type = BoundaryType::double_yellow;
    west.left_reverse_neighbours = {"east"};
    description.lanes = {east, west};
    return build_road_map(std::move(description));
  };
  EXPECT_EQ(count_class(render_map_svg(opposite_pair(0)), "boundary-double-yellow"), 1u);
  EXPECT_EQ(count_class(render_map_svg(opposite_pair(2)), "boundary-double-yellow"), 2u);
}

TEST(MapSvg, DrawsSignStopLines) {
  MapDescription description = small_map();
  SignDescription stop;
  stop.id = "stop_1";
  stop.kind = SignKind::stop;
  stop.stop_lines = {{{40, -1.75}, {40, 1.75}}};
  stop.lanes = {{"lane_a", 40, 40}};
  SignDescription yield;
  yield.id = "yield_1";
  yield.kind = SignKind::yield;
  yield.stop_lines = {{{60, 1.75}, {60, 5.25}}};
  description.signs = {stop, yield};
  const std::string svg = render_map_svg(build_road_map(std::move(description)));
  EXPECT_EQ(count_class(svg, "stop-sign-line"), 1u);
  EXPECT_EQ(count_class(svg, "yield-line"), 1u);
  EXPECT_EQ(xml_error(svg), "");
}

TEST(MapSvg, LabelsOnlyWhenAskedAndEscaped) {
  const RoadMap map = build_road_map(small_map());
  const std::string plain = render_map_svg(map);
  EXPECT_EQ(count_class(plain, "label"), 0u);
  EXPECT_EQ(plain.find("lane_a"), std::string::npos);

  const std::string labelled = render_map_svg(map, {.labels = true});
  EXPECT_EQ(count_class(labelled, "label"), 2u);
  EXPECT_NE(labelled.find(">lane_a</text>"), std::string::npos);
  EXPECT_NE(labelled.find(">b&lt;&amp;&gt;&quot;&apos;</text>"), std::string::npos);
  EXPECT_EQ(labelled.find(awkward_id), std::string::npos);
  EXPECT_EQ(labelled.find("<&>"), std::string::npos);
  // The map's name is escaped in the title too.
  EXPECT_NE(labelled.find("<title>small &lt;map&gt; &amp; co</title>"), std::string::npos);
  EXPECT_EQ(xml_error(labelled), "");
}

TEST(MapSvg, LabelsFollowTheLaneAndFitIt) {
  MapDescription description = small_map();
  // A northbound lane: its label turns a quarter.
  LaneDescription north;
  north.id = "north";
  north.centre_line = {{130, 0}, {130, 40}};
  description.lanes.push_back(north);
  const std::string svg = render_map_svg(build_road_map(std::move(description)), {.labels = true});
  const std::size_t label = svg.find(">north</text>");
  ASSERT_NE(label, std::string::npos);
  const std::size_t start = svg.rfind("<text", label);
  const std::string_view element(svg.data() + start, label - start);
  EXPECT_NE(element.find("rotate(-90)"), std::string_view::npos) << element;
  // Eastbound lanes read left to right.
  const std::size_t east = svg.find(">lane_a</text>");
  ASSERT_NE(east, std::string::npos);
  const std::string_view east_element(svg.data() + svg.rfind("<text", east),
                                      east - svg.rfind("<text", east));
  EXPECT_NE(east_element.find("rotate(0)"), std::string_view::npos) << east_element;
  // Sized in metres to stay within a 3.5 m lane yet be readable when zoomed in.
  for (const auto size : attribute_values(svg, "font-size")) {
    const double metres = numbers_in(size).at(0);
    EXPECT_GE(metres, 0.5) << size;
    EXPECT_LE(metres, 3.5) << size;
  }
}

TEST(MapSvg, ViewBoxContainsEveryDrawnPoint) {
  const RoadMap map = build_road_map(small_map());
  const std::string svg = render_map_svg(map, {.labels = true});
  const ViewBox box = view_box(svg);
  EXPECT_EQ(box.x, 0);
  EXPECT_EQ(box.y, 0);
  const auto points = drawn_points(map_part(svg));
  // 2 lane surfaces, 3 boundaries and a gap line, 2 centre lines, arrows, junction, crosswalk,
  // stop line, signal head, 2 labels.
  EXPECT_GT(points.size(), 30u);
  for (const MapPoint point : points) {
    EXPECT_GE(point.x, box.x);
    EXPECT_LE(point.x, box.x + box.width);
    EXPECT_GE(point.y, box.y);
    EXPECT_LE(point.y, box.y + box.height);
  }
  // With a margin: nothing touches the edge.
  double min_x = box.width, max_x = 0;
  for (const MapPoint point : points) {
    min_x = std::min(min_x, point.x);
    max_x = std::max(max_x, point.x);
  }
  EXPECT_GT(min_x, 0);
  EXPECT_LT(max_x, box.width);
  // The map spans x 0..120 (lanes to the junction's far side).
  EXPECT_NEAR(max_x - min_x, 120, 0.02);
}

TEST(MapSvg, NorthIsUp) {
  const std::string svg = render_map_svg(build_road_map(small_map()));
  // The lanes' surfaces, in order: lane_a (y -1.75..1.75), then the one north of it.
  const auto surfaces = attribute_values(svg, "points");
  ASSERT_GE(surfaces.size(), 2u);
  auto mean_y = [](std::string_view points) {
    const auto numbers = numbers_in(points);
    double sum = 0;
    for (std::size_t i = 1; i < numbers.size(); i += 2) sum += numbers[i];
    return sum / static_cast<double>(numbers.size() / 2);
  };
  EXPECT_NEAR(mean_y(surfaces[0]) - mean_y(surfaces[1]), 3.5, 0.02);
}

TEST(MapSvg, ImageSizeFollowsTheScale) {
  const RoadMap map = build_road_map(small_map());
  const std::string fitted = render_map_svg(map);
  const ViewBox box = view_box(fitted);
  const double width = numbers_in(attribute_values(fitted, "width").at(0)).at(0);
  const double height = numbers_in(attribute_values(fitted, "height").at(0)).at(0);
  // The map is wider than tall: its width is fitted to 2000 pixels.
  EXPECT_NEAR(width, 2000, 1);
  EXPECT_NEAR(height / width, box.height / box.width, 0.01);

  const std::string scaled = render_map_svg(map, {.pixels_per_metre = 4});
  const ViewBox scaled_box = view_box(scaled);
  EXPECT_NEAR(numbers_in(attribute_values(scaled, "width").at(0)).at(0), scaled_box.width * 4, 1);
  EXPECT_NEAR(numbers_in(attribute_values(scaled, "height").at(0)).at(0), scaled_box.height * 4, 1);
}

// A city-sized map (1600 lanes of 60 m, points every 2 m) stays a few MB: coordinates are
// rounded to centimetres and styles are shared.
TEST(MapSvg, CityMapStaysReasonablySized) {
  MapDescription description;
  description.name = "grid";
  description.source = "test";
  for (int row = 0; row < 40; ++row) {
    for (int column = 0; column < 40; ++column) {
      LaneDescription lane;
      lane.id = "lane_" + std::to_string(row) + "_" + std::to_string(column);
      for (int step = 0; step <= 30; ++step)
        lane.centre_line.push_back({column * 70.0 + step * 2.0, row * 20.0 + 0.001 * step * step});
      lane.left_boundary_type = BoundaryType::dotted_white;
      lane.right_boundary_type = BoundaryType::solid_white;
      description.lanes.push_back(std::move(lane));
    }
  }
  const std::string svg = render_map_svg(build_road_map(std::move(description)), {.labels = true});
  EXPECT_EQ(count_class(svg, "lane"), 1600u);
  EXPECT_EQ(count_class(svg, "label"), 1600u);
  EXPECT_LT(svg.size(), 8'000'000u);
  EXPECT_EQ(xml_error(svg), "");
}

// The bounding box of each `<polygon class="lane"` in `svg`, in drawing coordinates.
std::vector<MapBounds> lane_boxes(std::string_view svg) {
  std::vector<MapBounds> boxes;
  constexpr std::string_view lane = "<polygon class=\"lane\" points=\"";
  for (std::size_t at = svg.find(lane); at != std::string_view::npos; at = svg.find(lane, at + 1)) {
    const std::size_t begin = at + lane.size();
    const auto numbers = numbers_in(svg.substr(begin, svg.find('"', begin) - begin));
    MapBounds& box = boxes.emplace_back();
    for (std::size_t i = 0; i + 1 < numbers.size(); i += 2)
      box.include({numbers[i], numbers[i + 1]});
  }
  return boxes;
}

// A frame on the crossroads' west arm, far from the junction, draws that arm's lanes only.
TEST(MapSvg, LayerDrawsOnlyWhatReachesItsFrame) {
  const RoadMap map = build_road_map(generate_builtin_map("crossroads", {}));
  MapBounds region;
  region.include({-130, -20});
  region.include({-110, 20});
  const SvgFrame frame = map_svg_frame(region, 5, 0, 800);
  EXPECT_DOUBLE_EQ(frame.origin.x, -135);
  EXPECT_DOUBLE_EQ(frame.origin.y, 25);
  EXPECT_DOUBLE_EQ(frame.width, 30);
  EXPECT_DOUBLE_EQ(frame.height, 50);
  EXPECT_DOUBLE_EQ(frame.metres_per_pixel, 50.0 / 800);

  const std::string layer = render_map_svg_layer(map, frame, {.labels = true});
  EXPECT_EQ(layer.find("<svg"), std::string::npos);
  EXPECT_EQ(layer.find("<?xml"), std::string::npos);
  EXPECT_EQ(layer.find("legend"), std::string::npos);
  EXPECT_EQ(layer.find("key-"), std::string::npos);
  EXPECT_EQ(xml_error("<svg>" + layer + "</svg>"), "");

  const std::vector<MapBounds> boxes = lane_boxes(layer);
  EXPECT_EQ(boxes.size(), 4u);  // two lanes each way
  EXPECT_EQ(count_class(layer, "label"), boxes.size());
  for (const MapBounds& box : boxes) {
    EXPECT_LE(box.min.x, frame.width);
    EXPECT_GE(box.max.x, 0);
    EXPECT_LE(box.min.y, frame.height);
    EXPECT_GE(box.max.y, 0);
  }
  EXPECT_EQ(count_class(layer, "junction"), 0u);
  EXPECT_EQ(count_class(layer, "signal"), 0u);
  EXPECT_EQ(count_class(render_map_svg(map), "lane"), map.lanes().size());
}

// Framed on the whole map, the layer is the standalone drawing without its document and legend.
TEST(MapSvg, LayerOfTheWholeMapMatchesTheDocument) {
  const RoadMap map = build_road_map(small_map());
  const std::string document = render_map_svg(map, {.labels = true});
  const ViewBox box = view_box(document);
  const std::size_t origin = document.find("map x = ");
  ASSERT_NE(origin, std::string::npos);
  const auto numbers = numbers_in(document.substr(origin, document.find("</desc>") - origin));
  ASSERT_EQ(numbers.size(), 2u);
  MapBounds region;
  region.include({numbers[0], numbers[1]});
  const std::string layer =
      render_map_svg_layer(map, map_svg_frame(region, 0, 1, 0), {.labels = true});
  // A frame of no size at the drawing's corner, in its margin, reaches nothing; one around the
  // map reaches everything, drawn exactly as in the document.
  EXPECT_EQ(count_class(layer, "lane"), 0u);
  region.include({numbers[0] + box.width, numbers[1] - box.height});
  const std::string whole =
      render_map_svg_layer(map, map_svg_frame(region, 0, 1, 0), {.labels = true});
  for (const std::string_view css_class :
       {"lane", "junction", "crosswalk", "centre", "arrow", "stop-line", "signal", "label"})
    EXPECT_EQ(count_class(whole, css_class), count_class(document, css_class)) << css_class;
  const std::string_view drawing = map_part(document);
  EXPECT_NE(drawing.find(whole.substr(whole.find("<g class=\"map\">"))), std::string_view::npos);
}

}  // namespace
}  // namespace scenfuzz

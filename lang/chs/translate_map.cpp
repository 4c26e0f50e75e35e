// The CH-Scenario map (translation.hpp): `map: NAME` is looked up as any map name is; a blank map
// carries its roads as outlines, which physics/map/outline_map.hpp turns into lanes. Every road
// point must lie on the blank rectangle, [0, length] x [0, width], as the grammar's example lays
// its 400 m by 50 m map. The grammar gives no speed limits: a road takes the defaults of China's
// road traffic law, whose scenarios CH-Scenario describes (docs/ch-scenario.md, "Speed limits").
#include "lang/chs/translation.hpp"
#include "lang/number_format.hpp"

namespace scenfuzz::chs {

namespace {

// The name the IR gives a blank map: what reports and pictures call it.
constexpr const char* kBlankMapName = "blank";

scenfuzz::Point outline_point(const Point& point) {
  return {constant_value(point.x, point.x_at), constant_value(point.y, point.y_at)};
}

std::vector<scenfuzz::Point> outline(const std::vector<Point>& points) {
  std::vector<scenfuzz::Point> result;
  for (const Point& point : points) result.push_back(outline_point(point));
  return result;
}

// Art. 45 of the Regulation on the Implementation of the Road Traffic Safety Law: 50 km/h on a
// road with a lane each way and no sign; Art. 46: 30 km/h on icy or muddy roads, going down a
// steep slope, and in fog, rain, sand or hail that leaves 50 m of sight (the storms, here).
double speed_limit(const File& file) {
  constexpr double kUsual = 50 / 3.6, kHazardous = 30 / 3.6;
  const SpecialHighRisk& h = file.high_risk;
  const NaturalDisaster& d = file.disaster;
  const bool hazardous = h.ice_road.value || h.muddy.value || h.wade.value ||
                         h.steep_descent_ahead.value || d.rainstorm.value || d.typhoon.value ||
                         d.sandstorm.value || d.tornado.value;
  return hazardous ? kHazardous : kUsual;
}

void check_on_map(const Road& road, const MapSource& map, Diagnostics& diagnostics) {
  for (const auto* line : {&road.left_boundary, &road.centre_lines, &road.right_boundary})
    for (const Point& point : *line)
      if (point.x < 0 || point.x > map.length.value || point.y < 0 || point.y > map.width.value) {
        diagnostics.error(point.location,
                          "this point of road " + road.name.text + " lies off the map, which is " +
                              format_number(map.length.value) + " m long (x) and " +
                              format_number(map.width.value) + " m wide (y) from (0, 0)");
        return;  // one error a road
      }
}

}  // namespace

void translate_map(Translation& translation) {
  const File& file = translation.file;
  MapReference& map = translation.scenario.map;
  map.location = file.map.location;
  if (file.map.kind == MapSource::Kind::named) {
    map.name = file.map.name.text;
    return;
  }
  map.name = kBlankMapName;
  const Value limit = constant_value(speed_limit(file));
  for (const Road& road : file.roads) {
    check_on_map(road, file.map, translation.diagnostics);
    map.roads.push_back({road.name.text, outline(road.left_boundary), outline(road.centre_lines),
                         outline(road.right_boundary), limit, road.location});
  }
}

}  // namespace scenfuzz::chs

// render_map_svg and render_map_svg_layer. Drawing is in metres (one user unit is a metre) with the
// y axis flipped so north is up; every element carries a class and the styles live once in a
// <style> sheet, which keeps a city map of a few thousand lanes to a few MB. A layer leaves out
// what lies outside its frame, so that a small part of a city map stays small and quick to draw.
#include "physics/map/map_svg.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <tuple>
#include <vector>

#include "physics/map/svg_writing.hpp"

namespace scenfuzz {
namespace {

constexpr double default_image_pixels = 2000;  // the longer side, when no scale is asked for
constexpr double arrow_spacing = 20;           // metres between direction chevrons
constexpr double arrow_wing = 0.9;             // metres
constexpr double signal_head_radius = 0.6;     // metres
constexpr double max_label_size = 1.2;         // metres: about a third of a lane's width
constexpr double min_label_size = 0.25;
constexpr double label_advance = 0.6;  // width of one character, in font sizes

// The legend is drawn in its own units, each a metre scaled so that its text is readable
// whatever the map's scale; the road-marking samples then share the map's stroke styles.
constexpr double legend_pixels_per_unit = 8;
constexpr double legend_font_size = 1.6;
constexpr double legend_row_height = 4.5;
constexpr double legend_key_length = 12;
constexpr double legend_entry_width = 30;
constexpr double legend_padding = 1.5;

struct Style {
  std::string_view name;
  std::string_view declarations;
};

// Each class also styles "key-<class>", its sample in the legend, so that counting class="lane"
// counts lanes only.
constexpr std::array styles{
    // The stroke closes the slivers left where neighbours' boundaries were digitised apart.
    Style{"lane", "fill:#a0a0a0;stroke:#a0a0a0;stroke-width:.2;stroke-linejoin:round"},
    Style{"junction",
          "fill:#f0b040;fill-opacity:.3;stroke:#c08020;stroke-width:.2;stroke-dasharray:1 1"},
    Style{"crosswalk", "fill:url(#crosswalk-stripes);stroke:#fff;stroke-width:.1"},
    Style{"boundary-unknown", "stroke:#c8c8c8;stroke-width:.08"},
    Style{"boundary-dotted-white", "stroke:#fff;stroke-width:.15;stroke-dasharray:3 6"},
    Style{"boundary-dotted-yellow", "stroke:#f2c200;stroke-width:.15;stroke-dasharray:3 6"},
    Style{"boundary-solid-white", "stroke:#fff;stroke-width:.15"},
    Style{"boundary-solid-yellow", "stroke:#f2c200;stroke-width:.15"},
    // A wide yellow line with a lane-coloured line over its middle reads as two lines.
    Style{"boundary-double-yellow", "stroke:#f2c200;stroke-width:.45"},
    Style{"boundary-double-yellow-gap", "stroke:#a0a0a0;stroke-width:.15"},
    Style{"boundary-curb", "stroke:#505050;stroke-width:.3"},
    Style{"centre", "stroke:#2050b0;stroke-width:.08;stroke-opacity:.6"},
    Style{"arrow", "stroke:#2050b0;stroke-width:.15"},
    Style{"stop-line", "stroke:#d01010;stroke-width:.5"},
    Style{"signal", "fill:#d01010;stroke:#202020;stroke-width:.1"},
    Style{"stop-sign-line", "stroke:#9020c0;stroke-width:.5"},
    Style{"yield-line", "stroke:#ff8c00;stroke-width:.5;stroke-dasharray:.8 .4"},
    Style{"label",
          "font-family:sans-serif;fill:#0a1a40;text-anchor:middle;"
          "dominant-baseline:central"},
    Style{"mark-body", "fill:#e05a20;fill-opacity:.85;stroke:#401000;stroke-width:.15"},
    Style{"mark-front", "stroke:#401000;stroke-width:.25"},
    Style{"mark-text",
          "font-family:sans-serif;font-weight:bold;fill:#401000;dominant-baseline:central;"
          "paint-order:stroke;stroke:#fff;stroke-width:.4"},
};

std::string_view boundary_class(BoundaryType type) {
  switch (type) {
    case BoundaryType::dotted_white: return "boundary-dotted-white";
    case BoundaryType::dotted_yellow: return "boundary-dotted-yellow";
    case BoundaryType::solid_white: return "boundary-solid-white";
    case BoundaryType::solid_yellow: return "boundary-solid-yellow";
    case BoundaryType::double_yellow: return "boundary-double-yellow";
    case BoundaryType::curb: return "boundary-curb";
    case BoundaryType::unknown: break;
  }
  return "boundary-unknown";
}

void append_point(std::string& out, const SvgFrame& frame, MapPoint point) {
  append_number(out, point.x - frame.origin.x, 2);
  out += ',';
  append_number(out, frame.origin.y - point.y, 2);
}

void append_points_attribute(std::string& out, const SvgFrame& frame,
                             std::span<const MapPoint> points) {
  out += " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out += ' ';
    append_point(out, frame, points[i]);
  }
  out += '"';
}

void append_shape(std::string& out, const SvgFrame& frame, std::string_view element,
                  std::string_view css_class, std::span<const MapPoint> points) {
  if (points.size() < 2) return;
  out += '<';
  out += element;
  out += " class=\"";
  out += css_class;
  out += '"';
  append_points_attribute(out, frame, points);
  out += "/>\n";
}

void append_polyline(std::string& out, const SvgFrame& frame, std::string_view css_class,
                     std::span<const MapPoint> points) {
  append_shape(out, frame, "polyline", css_class, points);
}

void append_polygon(std::string& out, const SvgFrame& frame, std::string_view css_class,
                    std::span<const MapPoint> points) {
  append_shape(out, frame, "polygon", css_class, points);
}

MapPoint offset(MapPoint point, double heading, double distance_ahead, double distance_left) {
  return {point.x + distance_ahead * std::cos(heading) - distance_left * std::sin(heading),
          point.y + distance_ahead * std::sin(heading) + distance_left * std::cos(heading)};
}

struct LaneLabel {
  double size = 0;    // font size, metres
  double length = 0;  // along the lane, metres
};

// As large as fits the lane's width and length, so that short lanes keep readable labels that
// do not spill onto their neighbours.
LaneLabel lane_label(const Lane& lane) {
  const double middle = lane.length() / 2;
  const double lane_width = width_at(lane.left_width, middle) + width_at(lane.right_width, middle);
  const double characters = static_cast<double>(std::max<std::size_t>(1, lane.id.size()));
  double size = std::min(
      {max_label_size, 0.7 * lane_width, 0.9 * lane.length() / (label_advance * characters)});
  size = std::max(size, min_label_size);
  return {size, size * label_advance * characters};
}

// Chevrons every arrow_spacing metres, at least one per lane, kept clear of the label.
std::vector<double> arrow_positions(const Lane& lane, const std::optional<LaneLabel>& label) {
  const double length = lane.length();
  const int count = std::max(1, static_cast<int>(std::lround(length / arrow_spacing)));
  std::vector<double> positions;
  const double clearance = label ? label->length / 2 + arrow_wing : 0;
  for (int i = 0; i < count; ++i) {
    const double s = (i + 0.5) * length / count;
    if (!label || std::abs(s - length / 2) >= clearance) positions.push_back(s);
  }
  if (positions.empty()) positions.push_back(std::min(length, length / 2 + clearance));
  return positions;
}

void append_arrows(std::string& out, const SvgFrame& frame, const Lane& lane,
                   const std::optional<LaneLabel>& label) {
  out += "<path class=\"arrow\" d=\"";
  bool first = true;
  for (const double s : arrow_positions(lane, label)) {
    const MapPoint tip = lane.centre_line.point_at(s);
    const double heading = lane.centre_line.heading_at(s);
    const double back = -arrow_wing * std::cos(std::numbers::pi / 6);
    const double side = arrow_wing * std::sin(std::numbers::pi / 6);
    out += first ? "M" : " M";
    first = false;
    append_point(out, frame, offset(tip, heading, back, side));
    out += " L";
    append_point(out, frame, tip);
    out += " L";
    append_point(out, frame, offset(tip, heading, back, -side));
  }
  out += "\"/>\n";
}

void append_label(std::string& out, const SvgFrame& frame, const Lane& lane,
                  const LaneLabel& label) {
  const double middle = lane.length() / 2;
  // SVG rotates clockwise with y down; the lane's heading is counter-clockwise with y up.
  double degrees = -lane.centre_line.heading_at(middle) * 180 / std::numbers::pi;
  degrees = std::remainder(degrees, 360.0);
  if (degrees > 90) degrees -= 180;  // keep the text upright
  if (degrees < -90) degrees += 180;
  out += "<text class=\"label\" font-size=\"";
  append_number(out, label.size, 2);
  out += "\" transform=\"translate(";
  const MapPoint at = lane.centre_line.point_at(middle);
  append_number(out, at.x - frame.origin.x, 2);
  out += ' ';
  append_number(out, frame.origin.y - at.y, 2);
  out += ") rotate(";
  append_number(out, degrees, 2);
  out += ")\">";
  append_escaped(out, lane.id);
  out += "</text>\n";
}

void append_circle(std::string& out, const SvgFrame& frame, std::string_view css_class,
                   MapPoint centre, double radius) {
  out += "<circle class=\"";
  out += css_class;
  out += "\" cx=\"";
  append_number(out, centre.x - frame.origin.x, 2);
  out += "\" cy=\"";
  append_number(out, frame.origin.y - centre.y, 2);
  out += "\" r=\"";
  append_number(out, radius, 2);
  out += "\"/>\n";
}

MapPoint halfway_along(const std::vector<MapPoint>& points) {
  double length = 0;
  for (std::size_t i = 1; i < points.size(); ++i) length += distance(points[i - 1], points[i]);
  double remaining = length / 2;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double segment = distance(points[i - 1], points[i]);
    if (segment > 0 && remaining <= segment) {
      const double t = remaining / segment;
      return {points[i - 1].x + t * (points[i].x - points[i - 1].x),
              points[i - 1].y + t * (points[i].y - points[i - 1].y)};
    }
    remaining -= segment;
  }
  return points.empty() ? MapPoint{} : points.back();
}

double distance_to_polyline(MapPoint point, const std::vector<MapPoint>& points) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < points.size(); ++i) {
    const MapPoint a = points[i - 1];
    const MapPoint b = points[i];
    const double length_squared = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
    double t =
        length_squared > 0
            ? ((point.x - a.x) * (b.x - a.x) + (point.y - a.y) * (b.y - a.y)) / length_squared
            : 0;
    t = std::clamp(t, 0.0, 1.0);
    nearest = std::min(nearest, distance(point, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}));
  }
  return nearest;
}

// Neighbouring lanes that touch share a boundary and both list it, often digitised twice with
// dashes out of step; drawing it once keeps the markings readable and the file smaller. A lane
// always draws its right boundary, so its left one is left to a forward neighbour whose right
// boundary lies on it, or, between opposite directions, to the lane that comes first. Lanes
// either side of a median are neighbours too, but their boundaries do not coincide. Only a
// neighbour that is itself drawn (`drawn`, by lane index) can take the boundary over.
bool left_boundary_drawn_by_neighbour(const RoadMap& map, LaneIndex index,
                                      const std::vector<bool>& drawn) {
  constexpr double coincident = 0.3;  // metres
  const Lane& lane = map.lane(index);
  if (lane.left_boundary.size() < 2) return false;
  const MapPoint middle = halfway_along(lane.left_boundary);
  for (const LaneIndex neighbour : lane.left_forward_neighbours)
    if (drawn[neighbour] &&
        distance_to_polyline(middle, map.lane(neighbour).right_boundary) < coincident)
      return true;
  for (const LaneIndex neighbour : lane.left_reverse_neighbours)
    if (neighbour < index && drawn[neighbour] &&
        distance_to_polyline(middle, map.lane(neighbour).left_boundary) < coincident)
      return true;
  return false;
}

// Copies that neighbour links do not explain are caught by their end points.
using BoundaryKey = std::tuple<BoundaryType, long long, long long, long long, long long>;

BoundaryKey boundary_key(BoundaryType type, const std::vector<MapPoint>& points) {
  auto centimetres = [](double value) { return std::llround(value * 100); };
  auto first = std::pair{centimetres(points.front().x), centimetres(points.front().y)};
  auto last = std::pair{centimetres(points.back().x), centimetres(points.back().y)};
  if (last < first) std::swap(first, last);
  return {type, first.first, first.second, last.first, last.second};
}

// By winding number (SVG's nonzero rule) rather than crossing parity: some maps trace their
// junction outlines twice, which parity would read as outside.
bool inside_polygon(MapPoint point, const std::vector<MapPoint>& polygon) {
  int winding = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const MapPoint a = polygon[i];
    const MapPoint b = polygon[(i + 1) % polygon.size()];
    const double side = (b.x - a.x) * (point.y - a.y) - (point.x - a.x) * (b.y - a.y);
    if (a.y <= point.y && b.y > point.y && side > 0) ++winding;
    if (a.y > point.y && b.y <= point.y && side < 0) --winding;
  }
  return winding != 0;
}

// Some maps (LGSVL's exports among them) leave junction lanes without a junction id, so a lane
// whose middle lies in a junction's outline counts as a junction lane too.
bool in_junction(const RoadMap& map, const Lane& lane) {
  if (lane.junction) return true;
  const MapPoint middle = lane.centre_line.point_at(lane.length() / 2);
  return std::ranges::any_of(map.junctions(), [middle](const Junction& junction) {
    return junction.outline.size() >= 3 && inside_polygon(middle, junction.outline);
  });
}

// Inside a junction only curbs are drawn: intersections carry no painted lane lines, and the
// criss-crossing boundaries of the turning lanes would hide everything else there.
void append_boundary(std::string& out, const SvgFrame& frame, std::set<BoundaryKey>& drawn,
                     bool junction_lane, BoundaryType type, const std::vector<MapPoint>& points) {
  if (junction_lane && type != BoundaryType::curb) return;
  if (points.size() < 2 || !drawn.insert(boundary_key(type, points)).second) return;
  append_polyline(out, frame, boundary_class(type), points);
  if (type == BoundaryType::double_yellow)
    append_polyline(out, frame, "boundary-double-yellow-gap", points);
}

MapBounds drawing_bounds(const RoadMap& map) {
  MapBounds bounds = map.bounds();
  for (const TrafficLight& light : map.traffic_lights()) {
    for (const MapPoint head : light.heads) bounds.include(head);
    for (const auto& line : light.stop_lines)
      for (const MapPoint point : line) bounds.include(point);
  }
  for (const Sign& sign : map.signs())
    for (const auto& line : sign.stop_lines)
      for (const MapPoint point : line) bounds.include(point);
  if (bounds.empty()) bounds.include({0, 0});
  return bounds;
}

// A round length (1, 2 or 5 times a power of ten) about `target` long.
double round_length(double target) {
  const double power = std::pow(10.0, std::floor(std::log10(target)));
  for (const double step : {1.0, 2.0, 5.0})
    if (step * power * 1.5 >= target) return step * power;
  return 10 * power;
}

struct LegendEntry {
  std::string_view text;
  std::string_view key_class;
  enum class Shape { area, line, dot } shape;
};

constexpr std::array legend_entries{
    LegendEntry{"lane", "key-lane", LegendEntry::Shape::area},
    LegendEntry{"junction", "key-junction", LegendEntry::Shape::area},
    LegendEntry{"crosswalk", "key-crosswalk", LegendEntry::Shape::area},
    LegendEntry{"centre line", "key-centre", LegendEntry::Shape::line},
    LegendEntry{"dotted white", "key-boundary-dotted-white", LegendEntry::Shape::line},
    LegendEntry{"dotted yellow", "key-boundary-dotted-yellow", LegendEntry::Shape::line},
    LegendEntry{"solid white", "key-boundary-solid-white", LegendEntry::Shape::line},
    LegendEntry{"solid yellow", "key-boundary-solid-yellow", LegendEntry::Shape::line},
    LegendEntry{"double yellow", "key-boundary-double-yellow", LegendEntry::Shape::line},
    LegendEntry{"curb", "key-boundary-curb", LegendEntry::Shape::line},
    LegendEntry{"other boundary", "key-boundary-unknown", LegendEntry::Shape::line},
    LegendEntry{"signal stop line", "key-stop-line", LegendEntry::Shape::line},
    LegendEntry{"signal head", "key-signal", LegendEntry::Shape::dot},
    LegendEntry{"stop sign line", "key-stop-sign-line", LegendEntry::Shape::line},
    LegendEntry{"yield line", "key-yield-line", LegendEntry::Shape::line},
};

struct LegendLayout {
  double metres_per_unit = 1;
  int columns = 1;
  int rows = 1;  // entry rows, then one for the scale bar
  double height_in_metres() const {
    return ((rows + 1) * legend_row_height + 2 * legend_padding) * metres_per_unit;
  }
};

LegendLayout legend_layout(double map_width, double metres_per_pixel) {
  LegendLayout layout;
  layout.metres_per_unit = metres_per_pixel * legend_pixels_per_unit;
  const double width_in_units = map_width / layout.metres_per_unit - 2 * legend_padding;
  layout.columns = std::max(1, static_cast<int>(width_in_units / legend_entry_width));
  const int entries = static_cast<int>(legend_entries.size());
  layout.rows = (entries + layout.columns - 1) / layout.columns;
  return layout;
}

// Legend coordinates are plain SVG coordinates inside the legend's own transform.
void append_legend_number_pair(std::string& out, double x, double y) {
  append_number(out, x, 2);
  out += ',';
  append_number(out, y, 2);
}

void append_legend_text(std::string& out, double x, double y, std::string_view text) {
  out += "<text class=\"legend-text\" x=\"";
  append_number(out, x, 2);
  out += "\" y=\"";
  append_number(out, y, 2);
  out += "\">";
  append_escaped(out, text);
  out += "</text>\n";
}

void append_key_patch(std::string& out, std::string_view css_class, double x, double x_end,
                      double y) {
  out += "<polygon class=\"";
  out += css_class;
  out += "\" points=\"";
  append_legend_number_pair(out, x, y - 1.75);
  out += ' ';
  append_legend_number_pair(out, x_end, y - 1.75);
  out += ' ';
  append_legend_number_pair(out, x_end, y + 1.75);
  out += ' ';
  append_legend_number_pair(out, x, y + 1.75);
  out += "\"/>\n";
}

void append_key_line(std::string& out, std::string_view css_class, double x, double x_end,
                     double y) {
  out += "<polyline class=\"";
  out += css_class;
  out += "\" points=\"";
  append_legend_number_pair(out, x, y);
  out += ' ';
  append_legend_number_pair(out, x_end, y);
  out += "\"/>\n";
}

void append_legend(std::string& out, const SvgFrame& frame, const LegendLayout& layout) {
  const double scale = layout.metres_per_unit;
  out += "<g class=\"legend\" transform=\"translate(0 ";
  append_number(out, frame.height, 2);
  out += ") scale(";
  // Six significant digits: the scale can be far below a centimetre per unit.
  std::array<char, 32> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), scale,
                                          std::chars_format::general, 6);
  if (error == std::errc())
    out.append(buffer.data(), end);
  else
    out += '1';
  out += ")\">\n<rect class=\"legend-background\" x=\"0\" y=\"0\" width=\"";
  append_number(out, frame.width / scale, 2);
  out += "\" height=\"";
  append_number(out, (layout.rows + 1) * legend_row_height + 2 * legend_padding, 2);
  out += "\"/>\n";
  for (std::size_t i = 0; i < legend_entries.size(); ++i) {
    const LegendEntry& entry = legend_entries[i];
    const int column = static_cast<int>(i) % layout.columns;
    const int row = static_cast<int>(i) / layout.columns;
    const double x = legend_padding + column * legend_entry_width;
    const double y = legend_padding + (row + 0.5) * legend_row_height;
    const double key_end = x + legend_key_length;
    // Markings are shown on a patch of road, as on the map: white ones vanish on the legend's
    // white.
    const bool on_road = entry.key_class != "key-lane" && entry.key_class != "key-junction";
    if (on_road || entry.shape == LegendEntry::Shape::area)
      append_key_patch(out, on_road ? "key-lane" : entry.key_class, x, key_end, y);
    switch (entry.shape) {
      case LegendEntry::Shape::area:
        if (on_road) append_key_patch(out, entry.key_class, x, key_end, y);
        break;
      case LegendEntry::Shape::line:
        append_key_line(out, entry.key_class, x, key_end, y);
        if (entry.key_class == "key-boundary-double-yellow")
          append_key_line(out, "key-boundary-double-yellow-gap", x, key_end, y);
        break;
      case LegendEntry::Shape::dot:
        out += "<circle class=\"";
        out += entry.key_class;
        out += "\" cx=\"";
        append_number(out, x + legend_key_length / 2, 2);
        out += "\" cy=\"";
        append_number(out, y, 2);
        out += "\" r=\"";
        append_number(out, signal_head_radius * 1.5, 2);
        out += "\"/>\n";
        break;
    }
    append_legend_text(out, key_end + 1, y, entry.text);
  }

  // Scale bar: a round length near 150 pixels, drawn in map metres.
  const double bar_metres = round_length(150 * frame.metres_per_pixel);
  const double bar_units = bar_metres / scale;
  const double x = legend_padding;
  const double y = legend_padding + (layout.rows + 0.5) * legend_row_height;
  out += "<polyline class=\"scale-bar\" points=\"";
  append_legend_number_pair(out, x, y - 1);
  out += ' ';
  append_legend_number_pair(out, x, y);
  out += ' ';
  append_legend_number_pair(out, x + bar_units, y);
  out += ' ';
  append_legend_number_pair(out, x + bar_units, y - 1);
  out += "\"/>\n";
  std::string bar_text;
  if (bar_metres >= 1000) {
    append_number(bar_text, bar_metres / 1000);
    bar_text += " km";
  } else {
    append_number(bar_text, bar_metres);
    bar_text += " m";
  }
  append_legend_text(out, x + bar_units + 1, y, bar_text);
  out += "</g>\n";
}

// The crosswalk pattern and the style sheet; with `legend`, also the styles of the legend and of
// its samples.
void append_defs(std::string& out, bool legend) {
  out += "<defs>\n";
  out +=
      "<pattern id=\"crosswalk-stripes\" patternUnits=\"userSpaceOnUse\" width=\"1.2\" "
      "height=\"1.2\" patternTransform=\"rotate(45)\"><rect width=\"0.6\" height=\"1.2\" "
      "fill=\"#fff\"/></pattern>\n";
  out += "<style>\n";
  out += "polyline,path{fill:none;stroke-linejoin:round}\n";
  for (const Style& style : styles) {
    out += '.';
    out += style.name;
    if (legend) {
      out += ",.key-";
      out += style.name;
    }
    out += '{';
    out += style.declarations;
    out += "}\n";
  }
  out += ".background{fill:#f2f2ee}\n";
  if (legend) {
    out += ".legend-background{fill:#fff;fill-opacity:.9;stroke:#808080;stroke-width:.1}\n";
    out += ".legend-text{font-family:sans-serif;font-size:";
    append_number(out, legend_font_size, 2);
    out += "px;fill:#000;dominant-baseline:central}\n";
    out += ".scale-bar{stroke:#000;stroke-width:.2}\n";
  }
  out += "</style>\n</defs>\n";
}

void append_background(std::string& out, const SvgFrame& frame) {
  out += "<rect class=\"background\" x=\"0\" y=\"0\" width=\"";
  append_number(out, frame.width, 2);
  out += "\" height=\"";
  append_number(out, frame.height, 2);
  out += "\"/>\n";
}

void append_header(std::string& out, const RoadMap& map, const SvgFrame& frame,
                   double total_height) {
  const double pixels_per_metre = 1 / frame.metres_per_pixel;
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  out += std::to_string(std::max(1L, std::lround(frame.width * pixels_per_metre)));
  out += "\" height=\"";
  out += std::to_string(std::max(1L, std::lround(total_height * pixels_per_metre)));
  out += "\" viewBox=\"0 0 ";
  append_number(out, frame.width, 2);
  out += ' ';
  append_number(out, total_height, 2);
  out += "\">\n<title>";
  append_escaped(out, map.name().empty() ? std::string_view("road map") : map.name());
  out += "</title>\n<desc>";
  append_escaped(out, map.source());
  out += ": one unit is a metre; map x = ";
  append_number(out, frame.origin.x, 2);
  out += " + svg x, map y = ";
  append_number(out, frame.origin.y, 2);
  out += " - svg y</desc>\n";
}

// Whether something with these bounds may show in `region`, judged by bounding box; without a
// region, everything is drawn.
bool reaches(const std::optional<MapBounds>& region, const MapBounds& bounds) {
  if (!region) return true;
  return !bounds.empty() && bounds.min.x <= region->max.x && bounds.max.x >= region->min.x &&
         bounds.min.y <= region->max.y && bounds.max.y >= region->min.y;
}

void include_all(MapBounds& bounds, std::span<const MapPoint> points) {
  for (const MapPoint point : points) bounds.include(point);
}

bool reaches(const std::optional<MapBounds>& region, std::span<const MapPoint> points) {
  MapBounds bounds;
  include_all(bounds, points);
  return reaches(region, bounds);
}

// A lane's surface spans both its boundaries, so it is judged by their common bounding box.
bool lane_reaches(const std::optional<MapBounds>& region, const Lane& lane) {
  MapBounds bounds;
  include_all(bounds, lane.left_boundary);
  include_all(bounds, lane.right_boundary);
  include_all(bounds, lane.centre_line.points());
  return reaches(region, bounds);
}

// The lanes and road furniture that reach `region` (all of them without one), as a <g> element.
void append_map_drawing(std::string& out, const RoadMap& map, const SvgFrame& frame, bool labels,
                        const std::optional<MapBounds>& region) {
  const std::vector<Lane>& lanes = map.lanes();
  std::vector<bool> drawn(lanes.size());
  for (std::size_t i = 0; i < lanes.size(); ++i) drawn[i] = lane_reaches(region, lanes[i]);

  // Painter's order: areas first, markings over them, text last.
  out += "<g class=\"map\">\n";
  std::vector<MapPoint> surface;
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    if (!drawn[i]) continue;
    surface.assign(lanes[i].left_boundary.begin(), lanes[i].left_boundary.end());
    surface.insert(surface.end(), lanes[i].right_boundary.rbegin(), lanes[i].right_boundary.rend());
    append_polygon(out, frame, "lane", surface);
  }
  for (const Junction& junction : map.junctions())
    if (reaches(region, junction.outline)) append_polygon(out, frame, "junction", junction.outline);
  for (const Crosswalk& crosswalk : map.crosswalks())
    if (reaches(region, crosswalk.outline))
      append_polygon(out, frame, "crosswalk", crosswalk.outline);

  std::set<BoundaryKey> drawn_boundaries;
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    if (!drawn[i]) continue;
    const Lane& lane = lanes[i];
    const bool junction_lane = in_junction(map, lane);
    if (!left_boundary_drawn_by_neighbour(map, static_cast<LaneIndex>(i), drawn))
      append_boundary(out, frame, drawn_boundaries, junction_lane, lane.left_boundary_type,
                      lane.left_boundary);
    append_boundary(out, frame, drawn_boundaries, junction_lane, lane.right_boundary_type,
                    lane.right_boundary);
  }

  std::vector<std::optional<LaneLabel>> lane_labels(lanes.size());
  if (labels)
    for (std::size_t i = 0; i < lanes.size(); ++i)
      if (drawn[i]) lane_labels[i] = lane_label(lanes[i]);
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    if (!drawn[i]) continue;
    append_polyline(out, frame, "centre", lanes[i].centre_line.points());
    append_arrows(out, frame, lanes[i], lane_labels[i]);
  }

  for (const Sign& sign : map.signs())
    for (const auto& line : sign.stop_lines)
      if (reaches(region, line))
        append_polyline(out, frame, sign.kind == SignKind::stop ? "stop-sign-line" : "yield-line",
                        line);
  for (const TrafficLight& light : map.traffic_lights()) {
    for (const auto& line : light.stop_lines)
      if (reaches(region, line)) append_polyline(out, frame, "stop-line", line);
    for (const MapPoint head : light.heads)
      if (reaches(region, std::span(&head, 1)))
        append_circle(out, frame, "signal", head, signal_head_radius);
  }

  for (std::size_t i = 0; i < lanes.size(); ++i)
    if (lane_labels[i]) append_label(out, frame, lanes[i], *lane_labels[i]);
  out += "</g>\n";
}

// Each mark's body (a box at its pose with a tick from its centre to its front) and its text,
// 14 pixels high, to the body's right as drawn or centred on a mark without a body.
void append_marks(std::string& out, const SvgFrame& frame, std::span<const SvgMark> marks) {
  const double font = 14 * frame.metres_per_pixel;
  for (const SvgMark& mark : marks) {
    const MapPoint centre = mark.pose.position;
    const double heading = mark.pose.heading;
    double text_x = centre.x - frame.origin.x;
    if (mark.length > 0) {
      const double half_length = mark.length / 2;
      const double half_width = mark.width / 2;
      const std::vector<MapPoint> corners = {offset(centre, heading, half_length, half_width),
                                             offset(centre, heading, -half_length, half_width),
                                             offset(centre, heading, -half_length, -half_width),
                                             offset(centre, heading, half_length, -half_width)};
      append_polygon(out, frame, "mark-body", corners);
      const std::vector<MapPoint> tick = {centre, offset(centre, heading, half_length, 0)};
      append_polyline(out, frame, "mark-front", tick);
      text_x += std::max(mark.length, mark.width) / 2 + font / 2;
    }
    out += "<text class=\"mark-text\" font-size=\"";
    append_number(out, font, 2);
    out += mark.length > 0 ? "\" x=\"" : "\" text-anchor=\"middle\" x=\"";
    append_number(out, text_x, 2);
    out += "\" y=\"";
    append_number(out, frame.origin.y - centre.y, 2);
    out += "\">";
    append_escaped(out, mark.text);
    out += "</text>\n";
  }
}

}  // namespace

MapBounds SvgFrame::region() const {
  MapBounds bounds;
  bounds.include({origin.x, origin.y - height});
  bounds.include({origin.x + width, origin.y});
  return bounds;
}

SvgFrame map_svg_frame(const MapBounds& region, double margin, double pixels_per_metre,
                       double fit_pixels) {
  MapBounds bounds = region;
  if (bounds.empty()) bounds.include({0, 0});
  SvgFrame frame;
  frame.origin = {bounds.min.x - margin, bounds.max.y + margin};
  frame.width = bounds.max.x - bounds.min.x + 2 * margin;
  frame.height = bounds.max.y - bounds.min.y + 2 * margin;
  const double longer_side = std::max(frame.width, frame.height);
  if (pixels_per_metre > 0)
    frame.metres_per_pixel = 1 / pixels_per_metre;
  else if (longer_side > 0 && fit_pixels > 0)
    frame.metres_per_pixel = longer_side / fit_pixels;
  return frame;
}

std::string render_map_svg(const RoadMap& map, const SvgOptions& options,
                           std::span<const SvgMark> marks) {
  const MapBounds bounds = drawing_bounds(map);
  const double extent = std::max({bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y, 1.0});
  const SvgFrame frame = map_svg_frame(bounds, std::max(5.0, 0.03 * extent),
                                       options.pixels_per_metre, default_image_pixels);
  const LegendLayout legend = legend_layout(frame.width, frame.metres_per_pixel);

  std::string out;
  out.reserve(1024 + map.lanes().size() * 2048);
  append_header(out, map, frame, frame.height + legend.height_in_metres());
  append_defs(out, true);
  append_background(out, frame);
  append_map_drawing(out, map, frame, options.labels, std::nullopt);
  append_marks(out, frame, marks);
  append_legend(out, frame, legend);
  out += "</svg>\n";
  return out;
}

std::string render_map_svg_layer(const RoadMap& map, const SvgFrame& frame,
                                 const SvgOptions& options) {
  std::string out;
  append_defs(out, false);
  append_background(out, frame);
  append_map_drawing(out, map, frame, options.labels, frame.region());
  return out;
}

}  // namespace scenfuzz

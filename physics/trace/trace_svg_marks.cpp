// The marks of a trace's picture, drawn in a view's metres: paths, bodies, speed arrows,
// collision stars, the target, the lights at the event and the perception range. Line widths
// are given in pixels of the view and converted, so that both views read alike.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>

#include "physics/map/svg_writing.hpp"
#include "physics/trace/picture_regions.hpp"
#include "physics/trace/trace_svg_parts.hpp"

namespace scenfuzz {
namespace {

constexpr int path_shades = 12;  // time slices per path, light to dark
constexpr std::size_t max_listed_others = 9;
constexpr std::string_view obstacle_colour = "#505050";
constexpr std::array other_colours{
    std::string_view("#e65100"), std::string_view("#2a9d3a"), std::string_view("#8e44ad"),
    std::string_view("#8b5a2b"), std::string_view("#0097a7"), std::string_view("#c2185b"),
    std::string_view("#7f8c00"), std::string_view("#d4a017"), std::string_view("#5d4037")};

MapPoint position(const TraceActor& actor, std::size_t i) { return {actor.x[i], actor.y[i]}; }

void append_point(std::string& out, const Panel& panel, MapPoint p) {
  append_number(out, panel.u(p));
  out += ',';
  append_number(out, panel.v(p));
}

MapPoint offset(MapPoint point, double heading, double ahead, double left) {
  return {point.x + ahead * std::cos(heading) - left * std::sin(heading),
          point.y + ahead * std::sin(heading) + left * std::cos(heading)};
}

bool round_body(const TraceActor& actor) {
  return actor.kind == TraceActorKind::pedestrian ||
         (actor.kind == TraceActorKind::obstacle && actor.shape != BodyShape::box);
}

double elapsed_fraction(const Trace& trace, double time) {
  if (trace.time.size() < 2) return 1;
  const double span = trace.time.back() - trace.time.front();
  return span > 0 ? std::clamp((time - trace.time.front()) / span, 0.0, 1.0) : 1;
}

// A path's slices: the pale casings go under every coloured line, or each slice's casing would
// cut into the end of the one before.
struct PathDrawing {
  std::string casings;
  std::string lines;
};

void append_points(std::string& out, const Panel& panel, std::span<const MapPoint> points) {
  out += " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out += ' ';
    append_point(out, panel, points[i]);
  }
  out += "\"/>\n";
}

void flush_path(PathDrawing& drawing, const Panel& panel, std::vector<MapPoint>& points,
                std::string_view colour, double opacity, double width) {
  if (points.size() >= 2) {
    drawing.casings += "<polyline class=\"trace-path-casing\"";
    append_attribute(drawing.casings, "stroke-width", width + panel.metres(3));
    append_points(drawing.casings, panel, points);
    drawing.lines += "<polyline class=\"trace-path\"";
    append_attribute(drawing.lines, "stroke", colour);
    append_attribute(drawing.lines, "stroke-opacity", number_text(opacity, 2));
    append_attribute(drawing.lines, "stroke-width", width);
    append_points(drawing.lines, panel, points);
  }
  points.clear();
}

void append_path(PathDrawing& drawing, const Panel& panel, const Trace& trace, std::size_t id,
                 const ActorStyle& style, double width) {
  const TraceActor& actor = trace.actors[id];
  constexpr double min_step = 0.01;  // metres: a standing actor adds no points
  std::vector<MapPoint> points;
  int shade = 0;
  const double faint = style.listed ? 1.0 : 0.5;
  const auto opacity = [&](int slice) { return faint * (0.3 + 0.7 * (slice + 1) / path_shades); };
  for (std::size_t i = 0; i < actor.x.size() && i < trace.time.size(); ++i) {
    if (!drawn_at(trace, id, i)) {
      flush_path(drawing, panel, points, style.colour, opacity(shade), width);
      continue;
    }
    const MapPoint point = position(actor, i);
    const int slice = std::min(
        path_shades - 1, static_cast<int>(elapsed_fraction(trace, trace.time[i]) * path_shades));
    if (slice != shade) {
      if (!points.empty()) points.push_back(point);
      flush_path(drawing, panel, points, style.colour, opacity(shade), width);
      shade = slice;
    }
    if (points.empty() || distance(points.back(), point) >= min_step) points.push_back(point);
  }
  flush_path(drawing, panel, points, style.colour, opacity(shade), width);
}

std::string_view light_colour(SignalColour colour) {
  switch (colour) {
    case SignalColour::red: return "#e00000";
    case SignalColour::yellow: return "#ffc400";
    case SignalColour::green: return "#00b050";
  }
  return "#808080";
}

void append_circle(std::string& out, const Panel& panel, std::string_view css_class, MapPoint at,
                   double radius) {
  out += "<circle class=\"";
  out += css_class;
  out += '"';
  append_attribute(out, "cx", panel.u(at));
  append_attribute(out, "cy", panel.v(at));
  append_attribute(out, "r", radius);
}

}  // namespace

std::vector<ActorStyle> actor_styles(const Trace& trace, const std::optional<TraceMoment>& moment,
                                     const MapBounds& region) {
  std::vector<ActorStyle> styles(trace.actors.size());
  for (std::size_t id = 0; id < trace.actors.size(); ++id)
    for (std::size_t i = 0; i < trace.sample_count() && !styles[id].ever_drawn; ++i)
      styles[id].ever_drawn = drawn_at(trace, id, i);
  if (styles.empty()) return styles;
  styles[kEgo] = {kEgoColour, true, styles[kEgo].ever_drawn, styles[kEgo].ever_drawn};
  // The others by how near the ego they were at the event (the other party first); without an
  // event, in actor order.
  std::vector<std::pair<double, std::size_t>> candidates;
  const auto inside = [&](MapPoint at) {
    return region.min.x <= at.x && at.x <= region.max.x && region.min.y <= at.y &&
           at.y <= region.max.y;
  };
  for (std::size_t id = 1; id < trace.actors.size(); ++id) {
    // Only actors the main view shows get an entry of their own (the other party always).
    for (std::size_t i = 0; i < trace.sample_count() && !styles[id].in_view; ++i)
      styles[id].in_view = drawn_at(trace, id, i) && inside(position(trace.actors[id], i));
    if (!styles[id].in_view && !(moment && moment->other == id)) continue;
    double rank = static_cast<double>(id);
    if (moment) {
      const std::size_t i = moment->sample;
      if (moment->other == id) {
        rank = -1;
      } else if (drawn_at(trace, id, i) && drawn_at(trace, kEgo, i)) {
        const MapPoint at = position(trace.actors[id], i);
        rank = inside(at) ? distance(at, position(trace.actors[kEgo], i))
                          : 1e9 + static_cast<double>(id);
      } else {
        rank = 1e9 + static_cast<double>(id);
      }
    }
    candidates.emplace_back(rank, id);
  }
  std::sort(candidates.begin(), candidates.end());
  std::size_t next_colour = 0;
  for (std::size_t k = 0; k < candidates.size() && k < max_listed_others; ++k) {
    ActorStyle& style = styles[candidates[k].second];
    style.listed = true;
    style.colour = trace.actors[candidates[k].second].kind == TraceActorKind::obstacle
                       ? obstacle_colour
                       : other_colours[next_colour++ % other_colours.size()];
  }
  return styles;
}

void append_paths(std::string& out, const Panel& panel, const Trace& trace,
                  const std::vector<ActorStyle>& styles, double width_pixels) {
  PathDrawing drawing;
  // Background actors first, so that the listed ones' paths lie over theirs.
  for (const bool listed : {false, true})
    for (std::size_t id = 0; id < trace.actors.size(); ++id)
      if (styles[id].listed == listed)
        append_path(drawing, panel, trace, id, styles[id],
                    panel.metres(listed ? width_pixels : width_pixels * 0.6));
  out += "<g class=\"trace-paths\">\n";
  out += drawing.casings;
  out += drawing.lines;
  out += "</g>\n";
}

void append_body(std::string& out, const Panel& panel, const TraceActor& actor, std::size_t sample,
                 std::string_view colour, BodyEmphasis emphasis) {
  if (sample >= actor.x.size()) return;
  const MapPoint centre = position(actor, sample);
  if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) return;
  const double heading = sample < actor.heading.size() && std::isfinite(actor.heading[sample])
                             ? actor.heading[sample]
                             : 0;
  const double fill_opacity = emphasis == BodyEmphasis::faint ? 0.12 : 0.45;
  const double stroke_pixels = emphasis == BodyEmphasis::colliding ? 2.5
                               : emphasis == BodyEmphasis::event   ? 2
                                                                   : 1.2;
  const auto append_paint = [&] {
    out += emphasis == BodyEmphasis::colliding ? "<g class=\"trace-box trace-box-collision\""
                                               : "<g class=\"trace-box\"";
    append_attribute(out, "fill", colour);
    append_attribute(out, "stroke", emphasis == BodyEmphasis::colliding ? "#d00000" : colour);
    append_attribute(out, "fill-opacity", number_text(fill_opacity, 2));
    if (emphasis == BodyEmphasis::faint) append_attribute(out, "stroke-opacity", "0.6");
    append_attribute(out, "stroke-width", panel.metres(stroke_pixels));
    out += ">\n";
  };
  append_paint();
  if (round_body(actor)) {
    // A pedestrian is a dot of a few pixels at least, or it vanishes in a street's view.
    append_circle(out, panel, "trace-body", centre,
                  std::max(std::max(actor.length, actor.width) / 2, panel.metres(4)));
    out += "/>\n</g>\n";
    return;
  }
  const double half_length = actor.length / 2, half_width = actor.width / 2;
  out += "<polygon class=\"trace-body\" points=\"";
  append_point(out, panel, offset(centre, heading, half_length, half_width));
  out += ' ';
  append_point(out, panel, offset(centre, heading, -half_length, half_width));
  out += ' ';
  append_point(out, panel, offset(centre, heading, -half_length, -half_width));
  out += ' ';
  append_point(out, panel, offset(centre, heading, half_length, -half_width));
  out += "\"/>\n";
  // A tick from the centre to the front says which way the body faces.
  out += "<polyline class=\"trace-front\" points=\"";
  append_point(out, panel, centre);
  out += ' ';
  append_point(out, panel, offset(centre, heading, half_length, 0));
  out += "\"/>\n</g>\n";
}

void append_arrow(std::string& out, const Panel& panel, MapPoint from, MapPoint to,
                  std::string_view colour) {
  const double length = distance(from, to);
  if (!(length > 0)) return;
  const double heading = std::atan2(to.y - from.y, to.x - from.x);
  const double head = std::min(panel.metres(11), length * 0.6);
  const MapPoint base = offset(to, heading, -head, 0);
  out += "<g class=\"trace-speed\"";
  append_attribute(out, "stroke", colour);
  append_attribute(out, "fill", colour);
  out += ">\n<polyline class=\"trace-speed-casing\"";
  append_attribute(out, "stroke-width", panel.metres(5.5));
  out += " points=\"";
  append_point(out, panel, from);
  out += ' ';
  append_point(out, panel, base);
  out += "\"/>\n<polyline class=\"trace-speed-shaft\"";
  append_attribute(out, "stroke-width", panel.metres(2.5));
  out += " points=\"";
  append_point(out, panel, from);
  out += ' ';
  append_point(out, panel, base);
  out += "\"/>\n<polygon class=\"trace-speed-head\"";
  append_attribute(out, "stroke-width", panel.metres(1));
  out += " points=\"";
  append_point(out, panel, to);
  out += ' ';
  append_point(out, panel, offset(base, heading, 0, head * 0.45));
  out += ' ';
  append_point(out, panel, offset(base, heading, 0, -head * 0.45));
  out += "\"/>\n</g>\n";
}

void append_star(std::string& out, double x, double y, double radius) {
  out += "<polygon class=\"trace-collision\"";
  append_attribute(out, "stroke-width", radius / 9);
  out += " points=\"";
  for (int i = 0; i < 10; ++i) {
    const double reach = i % 2 == 0 ? radius : radius * 0.45;
    const double angle = -std::numbers::pi / 2 + i * std::numbers::pi / 5;
    if (i > 0) out += ' ';
    append_number(out, x + reach * std::cos(angle));
    out += ',';
    append_number(out, y + reach * std::sin(angle));
  }
  out += "\"/>\n";
}

void append_target(std::string& out, const Panel& panel, MapPoint at) {
  const double r = std::max(1.5, panel.metres(8));
  out += "<g class=\"trace-target\"";
  append_attribute(out, "stroke-width", panel.metres(2.5));
  out += ">\n";
  append_circle(out, panel, "trace-target-ring", at, r);
  out += "/>\n";
  append_circle(out, panel, "trace-target-ring", at, r * 0.45);
  out += "/>\n<polyline points=\"";
  append_point(out, panel, {at.x - r * 1.3, at.y});
  out += ' ';
  append_point(out, panel, {at.x + r * 1.3, at.y});
  out += "\"/>\n<polyline points=\"";
  append_point(out, panel, {at.x, at.y - r * 1.3});
  out += ' ';
  append_point(out, panel, {at.x, at.y + r * 1.3});
  out += "\"/>\n</g>\n";
}

void append_lights(std::string& out, const Panel& panel, const RoadMap& map, const Trace& trace,
                   std::size_t sample) {
  const double r = std::max(0.9, panel.metres(5));
  out += "<g class=\"trace-lights\"";
  append_attribute(out, "stroke-width", panel.metres(1.2));
  out += ">\n";
  for (const TrafficLight& light : map.traffic_lights()) {
    std::string_view colour = "#808080";
    for (const TraceLight& traced : trace.lights)
      if (traced.id == light.id && sample < traced.colour.size())
        colour = light_colour(traced.colour[sample]);
    for (const MapPoint head : light.heads) {
      if (!panel.shows(head)) continue;
      append_circle(out, panel, "trace-light", head, r);
      append_attribute(out, "fill", colour);
      out += "/>\n";
    }
  }
  out += "</g>\n";
}

void append_perception(std::string& out, const Panel& panel, const TraceSensing& sensing,
                       MapPoint centre) {
  out += "<g class=\"trace-perception\"";
  append_attribute(out, "stroke-width", panel.metres(1.5));
  out += ">\n";
  append_circle(out, panel, "trace-perception-vehicles", centre, sensing.vehicle_range);
  append_attribute(out, "stroke-dasharray",
                   number_text(panel.metres(8), 3) + " " + number_text(panel.metres(5), 3));
  out += "/>\n";
  if (std::abs(sensing.pedestrian_range - sensing.vehicle_range) > 0.5) {
    append_circle(out, panel, "trace-perception-pedestrians", centre, sensing.pedestrian_range);
    append_attribute(out, "stroke-dasharray",
                     number_text(panel.metres(2), 3) + " " + number_text(panel.metres(4), 3));
    out += "/>\n";
  }
  out += "</g>\n";
}

}  // namespace scenfuzz

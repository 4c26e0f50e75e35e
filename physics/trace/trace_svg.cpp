// render_trace_svg. The roads are render_map_svg_layer's drawing of the map in the picture's own
// frame, and the trace is drawn over them in the same coordinates. Sizes of marks and text are
// given in pixels and converted to metres, so they read the same at any scale.
#include "physics/trace/trace_svg.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <span>
#include <string_view>
#include <vector>

#include "physics/collision/body_side.hpp"
#include "physics/map/map_svg.hpp"

namespace scenfuzz {
namespace {

constexpr double default_image_pixels = 1600;  // the longer side, when no scale is asked for
constexpr double min_margin = 10;              // metres around the actors
constexpr double margin_fraction = 0.1;        // of the region's longer side
constexpr int path_shades = 12;                // time slices per path, light to dark

// Pixel sizes, converted to metres with the drawing's scale.
constexpr double path_width_pixels = 3.5;
constexpr double box_stroke_pixels = 1.2;
constexpr double name_font_pixels = 13;
constexpr double time_font_pixels = 10;
constexpr double collision_font_pixels = 12;
constexpr double collision_star_pixels = 9;
constexpr double halo_pixels = 3;

// The legend strip below the drawing is laid out directly in pixels.
constexpr double legend_padding = 8;
constexpr double legend_title_height = 22;
constexpr double legend_row_height = 20;
constexpr double legend_key_length = 24;
constexpr double legend_character_width = 7;  // of the 12 px legend font, roughly

constexpr std::string_view ego_colour = "#1565c0";
constexpr std::string_view obstacle_colour = "#505050";
constexpr std::array other_colours{std::string_view("#e07000"), std::string_view("#2a9d3a"),
                                   std::string_view("#8e44ad"), std::string_view("#8b5a2b"),
                                   std::string_view("#0097a7"), std::string_view("#c2185b"),
                                   std::string_view("#7f8c00"), std::string_view("#d4a017")};

// `count` pixels in metres, the drawing's unit.
double pixels(const SvgFrame& frame, double count) { return count * frame.metres_per_pixel; }

void append_escaped(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
}

// Millimetres, without trailing zeros.
void append_number(std::string& out, double value, int decimals = 3) {
  if (!std::isfinite(value)) {
    out += '0';
    return;
  }
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  std::array<char, 48> buffer{};
  const auto [end, error] =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), rounded == 0 ? 0.0 : rounded,
                    std::chars_format::fixed, decimals);
  if (error != std::errc()) {
    out += '0';
    return;
  }
  std::string_view text(buffer.data(), static_cast<std::size_t>(end - buffer.data()));
  if (text.find('.') != std::string_view::npos) {
    while (text.ends_with('0')) text.remove_suffix(1);
    if (text.ends_with('.')) text.remove_suffix(1);
  }
  out += text;
}

// With its trailing zeros, as people write times: "7.00 s".
std::string fixed_text(double value, int decimals) {
  std::array<char, 48> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                          std::chars_format::fixed, decimals);
  return error == std::errc() ? std::string(buffer.data(), end) : std::string("?");
}

std::string number_text(double value, int decimals) {
  std::string text;
  append_number(text, value, decimals);
  return text;
}

void append_point(std::string& out, const SvgFrame& frame, MapPoint point) {
  append_number(out, point.x - frame.origin.x);
  out += ',';
  append_number(out, frame.origin.y - point.y);
}

void append_attribute(std::string& out, std::string_view name, double value) {
  out += ' ';
  out += name;
  out += "=\"";
  append_number(out, value);
  out += '"';
}

// A five-pointed star centred at (x, y) in drawing coordinates (y down).
void append_star(std::string& out, double x, double y, double radius) {
  out += "<polygon class=\"trace-collision\" points=\"";
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

bool finite(MapPoint point) { return std::isfinite(point.x) && std::isfinite(point.y); }

MapPoint position(const TraceActor& actor, std::size_t sample) {
  return {actor.x[sample], actor.y[sample]};
}

// Whether sample i of the actor is drawn: it is on the map then (background traffic comes and
// goes) at a finite position.
bool drawn(const TraceActor& actor, std::size_t i) {
  return present_at(actor, i) && finite(position(actor, i));
}

bool round_body(const TraceActor& actor) {
  return actor.kind == TraceActorKind::pedestrian ||
         (actor.kind == TraceActorKind::obstacle && actor.shape != BodyShape::box);
}

std::string_view actor_colour(const Trace& trace, std::size_t id) {
  if (trace.actors[id].kind == TraceActorKind::ego) return ego_colour;
  if (trace.actors[id].kind == TraceActorKind::obstacle) return obstacle_colour;
  return other_colours[(id - 1) % other_colours.size()];
}

// ---- the region ----

MapBounds visited_region(const RoadMap& map, const Trace& trace) {
  MapBounds bounds;
  double largest_body = 0;
  for (const TraceActor& actor : trace.actors) {
    bool seen = false;
    for (std::size_t i = 0; i < actor.x.size(); ++i) {
      if (!drawn(actor, i)) continue;
      bounds.include(position(actor, i));
      seen = true;
    }
    if (seen) largest_body = std::max(largest_body, std::hypot(actor.length, actor.width));
  }
  for (const Collision& collision : trace.collisions)
    if (finite(collision.point)) bounds.include(collision.point);
  if (bounds.empty()) bounds = map.bounds();
  if (bounds.empty()) bounds.include({0, 0});
  const double extent = std::max(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y);
  const double margin = std::max(min_margin, margin_fraction * extent) + largest_body / 2;
  bounds.include({bounds.min.x - margin, bounds.min.y - margin});
  bounds.include({bounds.max.x + margin, bounds.max.y + margin});
  return bounds;
}

// ---- the legend's layout, in pixels ----

struct LegendEntry {
  std::string text;
  std::string_view colour;  // empty: the collision star
};

struct LegendLayout {
  std::vector<std::pair<double, double>> positions;  // left and middle of each entry
  double height = 0;
};

double entry_width(const LegendEntry& entry) {
  return legend_key_length + 6 + static_cast<double>(entry.text.size()) * legend_character_width +
         16;
}

LegendLayout legend_layout(const std::vector<LegendEntry>& entries, double width_pixels) {
  LegendLayout layout;
  double x = legend_padding;
  double row = 0;
  for (const LegendEntry& entry : entries) {
    const double width = entry_width(entry);
    if (x > legend_padding && x + width > width_pixels - legend_padding) {
      x = legend_padding;
      ++row;
    }
    layout.positions.emplace_back(
        x, legend_padding + legend_title_height + (row + 0.5) * legend_row_height);
    x += width;
  }
  layout.height = 2 * legend_padding + legend_title_height + (row + 1) * legend_row_height;
  return layout;
}

std::string duration_text(const Trace& trace) {
  const double duration = trace.time.empty() ? 0 : trace.time.back();
  return fixed_text(duration, 2) + " s";
}

std::string title_text(const Trace& trace) {
  std::string title = "Trace on " + (trace.map_name.empty() ? "a map" : trace.map_name) +
                      " (seed " + std::to_string(trace.seed) + "): ended by " +
                      std::string(end_reason_name(trace.end)) + " after " + duration_text(trace);
  return title;
}

void append_legend(std::string& out, const SvgFrame& frame, const std::vector<LegendEntry>& entries,
                   const LegendLayout& layout, const std::string& title) {
  out += "<g class=\"trace-legend\" transform=\"translate(0 ";
  append_number(out, frame.height);
  out += ") scale(";
  std::array<char, 32> buffer{};
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                                          frame.metres_per_pixel, std::chars_format::general, 6);
  out += error == std::errc() ? std::string_view(buffer.data(), end) : std::string_view("1");
  out += ")\">\n<rect class=\"trace-legend-background\" x=\"0\" y=\"0\"";
  append_attribute(out, "width", frame.width / frame.metres_per_pixel);
  append_attribute(out, "height", layout.height);
  out += "/>\n<text class=\"trace-legend-title\"";
  append_attribute(out, "x", legend_padding);
  append_attribute(out, "y", legend_padding + legend_title_height / 2);
  out += '>';
  append_escaped(out, title);
  out += "</text>\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto [x, y] = layout.positions[i];
    if (entries[i].colour.empty()) {
      append_star(out, x + legend_key_length / 2, y, 7);
    } else {
      out += "<line class=\"trace-legend-key\" stroke=\"";
      out += entries[i].colour;
      out += '"';
      append_attribute(out, "x1", x);
      append_attribute(out, "y1", y);
      append_attribute(out, "x2", x + legend_key_length);
      append_attribute(out, "y2", y);
      out += "/>\n";
    }
    out += "<text class=\"trace-legend-text\"";
    append_attribute(out, "x", x + legend_key_length + 6);
    append_attribute(out, "y", y);
    out += '>';
    append_escaped(out, entries[i].text);
    out += "</text>\n";
  }
  out += "</g>\n";
}

// ---- the actors ----

// Light early, dark late: the fraction of the run elapsed at `time`.
double elapsed_fraction(const Trace& trace, double time) {
  if (trace.time.size() < 2) return 1;
  const double span = trace.time.back() - trace.time.front();
  return span > 0 ? std::clamp((time - trace.time.front()) / span, 0.0, 1.0) : 1;
}

// The casings of all paths go below all the coloured lines, or each slice's casing would cut
// into the end of the slice before it.
struct PathDrawing {
  std::string casings;
  std::string lines;
};

void append_path_points(std::string& out, const SvgFrame& frame, std::span<const MapPoint> points) {
  out += " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out += ' ';
    append_point(out, frame, points[i]);
  }
  out += "\"/>\n";
}

void flush_path(PathDrawing& drawing, const SvgFrame& frame, std::vector<MapPoint>& points,
                std::string_view colour, double opacity) {
  if (points.size() >= 2) {
    // A pale casing keeps the path visible over lane lines of its own colour.
    drawing.casings += "<polyline class=\"trace-path-casing\"";
    append_path_points(drawing.casings, frame, points);
    drawing.lines += "<polyline class=\"trace-path\" stroke=\"";
    drawing.lines += colour;
    drawing.lines += "\" stroke-opacity=\"";
    append_number(drawing.lines, opacity, 2);
    drawing.lines += '"';
    append_path_points(drawing.lines, frame, points);
  }
  points.clear();
}

// The path in path_shades slices of the run's time, each one more opaque; a gap in the samples
// (NaN, or the actor off the map) breaks it.
void append_path(PathDrawing& drawing, const SvgFrame& frame, const Trace& trace, std::size_t id) {
  const TraceActor& actor = trace.actors[id];
  const std::string_view colour = actor_colour(trace, id);
  constexpr double min_step = 0.01;  // metres: a standing actor adds no points
  std::vector<MapPoint> points;
  int shade = 0;
  auto opacity = [](int slice) { return 0.3 + 0.7 * (slice + 1) / path_shades; };
  for (std::size_t i = 0; i < actor.x.size() && i < trace.time.size(); ++i) {
    const MapPoint point = position(actor, i);
    if (!drawn(actor, i)) {
      flush_path(drawing, frame, points, colour, opacity(shade));
      continue;
    }
    const int slice = std::min(
        path_shades - 1, static_cast<int>(elapsed_fraction(trace, trace.time[i]) * path_shades));
    if (slice != shade) {
      if (!points.empty()) points.push_back(point);
      flush_path(drawing, frame, points, colour, opacity(shade));
      shade = slice;
    }
    if (points.empty() || distance(points.back(), point) >= min_step) points.push_back(point);
  }
  flush_path(drawing, frame, points, colour, opacity(shade));
}

// Where bodies are drawn: the first and last samples, one every `interval` seconds, and the
// sample at or just after each collision.
std::size_t sample_at(const Trace& trace, double time) {
  const auto at = std::lower_bound(trace.time.begin(), trace.time.end(), time - 1e-9);
  return std::min(static_cast<std::size_t>(at - trace.time.begin()), trace.time.size() - 1);
}

std::vector<std::size_t> snapshot_samples(const Trace& trace, double interval) {
  const std::vector<double>& time = trace.time;
  if (time.empty()) return {};
  std::set<std::size_t> samples{0, time.size() - 1};
  if (interval > 0)
    for (double next = time.front() + interval; next < time.back(); next += interval)
      samples.insert(sample_at(trace, next));
  for (const Collision& collision : trace.collisions)
    samples.insert(sample_at(trace, collision.time));
  return {samples.begin(), samples.end()};
}

MapPoint offset(MapPoint point, double heading, double ahead, double left) {
  return {point.x + ahead * std::cos(heading) - left * std::sin(heading),
          point.y + ahead * std::sin(heading) + left * std::cos(heading)};
}

void append_body(std::string& out, const SvgFrame& frame, const TraceActor& actor,
                 std::size_t sample, std::string_view colour, double fraction, bool colliding) {
  const MapPoint centre = position(actor, sample);
  if (!finite(centre)) return;
  const double heading = sample < actor.heading.size() && std::isfinite(actor.heading[sample])
                             ? actor.heading[sample]
                             : 0;
  const std::string_view css_class = colliding ? "trace-box trace-box-collision" : "trace-box";
  const auto append_paint = [&] {
    out += " fill=\"";
    out += colour;
    out += "\" stroke=\"";
    out += colour;
    out += "\" fill-opacity=\"";
    append_number(out, 0.15 + 0.35 * fraction, 2);
    out += '"';
  };
  if (round_body(actor)) {
    out += "<circle class=\"";
    out += css_class;
    out += '"';
    append_paint();
    append_attribute(out, "cx", centre.x - frame.origin.x);
    append_attribute(out, "cy", frame.origin.y - centre.y);
    append_attribute(out, "r", std::max(actor.length, actor.width) / 2);
    out += "/>\n";
    return;
  }
  const double half_length = actor.length / 2;
  const double half_width = actor.width / 2;
  out += "<polygon class=\"";
  out += css_class;
  out += '"';
  append_paint();
  out += " points=\"";
  append_point(out, frame, offset(centre, heading, half_length, half_width));
  out += ' ';
  append_point(out, frame, offset(centre, heading, -half_length, half_width));
  out += ' ';
  append_point(out, frame, offset(centre, heading, -half_length, -half_width));
  out += ' ';
  append_point(out, frame, offset(centre, heading, half_length, -half_width));
  out += "\"/>\n";
  // A tick from the centre to the front says which way the body faces.
  out += "<polyline class=\"trace-front\" stroke=\"";
  out += colour;
  out += "\" points=\"";
  append_point(out, frame, centre);
  out += ' ';
  append_point(out, frame, offset(centre, heading, half_length, 0));
  out += "\"/>\n";
}

void append_text(std::string& out, const SvgFrame& frame, std::string_view css_class, MapPoint at,
                 double dx_pixels, double dy_pixels, std::string_view text,
                 std::string_view colour = {}) {
  out += "<text class=\"";
  out += css_class;
  out += '"';
  if (!colour.empty()) {
    out += " fill=\"";
    out += colour;
    out += '"';
  }
  append_attribute(out, "x", at.x - frame.origin.x + pixels(frame, dx_pixels));
  append_attribute(out, "y", frame.origin.y - at.y + pixels(frame, dy_pixels));
  out += '>';
  append_escaped(out, text);
  out += "</text>\n";
}

std::string actor_name(const Trace& trace, ActorId id) {
  return id < trace.actors.size() ? trace.actors[id].name : "actor " + std::to_string(id);
}

std::string collision_label(const Trace& trace, const Collision& collision) {
  return "t=" + fixed_text(collision.time, 2) + " s " + actor_name(trace, collision.first) + " " +
         std::string(body_side_name(collision.first_side)) + " / " +
         actor_name(trace, collision.second) + " " +
         std::string(body_side_name(collision.second_side));
}

void append_collisions(std::string& out, const SvgFrame& frame, const Trace& trace) {
  const double line_height = pixels(frame, collision_font_pixels * 1.3);
  for (std::size_t i = 0; i < trace.collisions.size(); ++i) {
    const Collision& collision = trace.collisions[i];
    if (!finite(collision.point)) continue;
    append_star(out, collision.point.x - frame.origin.x, frame.origin.y - collision.point.y,
                pixels(frame, collision_star_pixels));
    // Labels of collisions at nearly the same place stack instead of overprinting.
    int earlier_nearby = 0;
    for (std::size_t j = 0; j < i; ++j)
      if (distance(trace.collisions[j].point, collision.point) < pixels(frame, 40))
        ++earlier_nearby;
    append_text(out, frame, "trace-collision-label", collision.point, collision_star_pixels + 3,
                collision_font_pixels / 2 + earlier_nearby * line_height / frame.metres_per_pixel,
                collision_label(trace, collision));
  }
}

void append_style(std::string& out, const SvgFrame& frame) {
  const auto metres = [&](double pixel_count) {
    return number_text(pixels(frame, pixel_count), 4);
  };
  const std::string halo =
      "paint-order:stroke;stroke:#fff;stroke-linejoin:round;stroke-width:" + metres(halo_pixels) +
      "px";
  out += "<defs>\n<style>\n";
  out += ".trace-path{fill:none;stroke-linecap:butt;stroke-linejoin:round;stroke-width:" +
         metres(path_width_pixels) + "}\n";
  out +=
      ".trace-path-casing{fill:none;stroke:#fff;stroke-opacity:.6;stroke-linecap:round;"
      "stroke-linejoin:round;stroke-width:" +
      metres(path_width_pixels + 3) + "}\n";
  out += ".trace-box{stroke-width:" + metres(box_stroke_pixels) + "}\n";
  out +=
      ".trace-box-collision{stroke:#d00000;stroke-width:" + metres(2 * box_stroke_pixels) + "}\n";
  out += ".trace-front{fill:none;stroke-width:" + metres(box_stroke_pixels) + "}\n";
  out +=
      ".trace-name{font-family:sans-serif;font-weight:bold;font-size:" + metres(name_font_pixels) +
      "px;" + halo + "}\n";
  out += ".trace-time{font-family:sans-serif;fill:#303030;font-size:" + metres(time_font_pixels) +
         "px;" + halo + "}\n";
  out += ".trace-collision{fill:#e00000;stroke:#600000;stroke-width:" + metres(1) + "}\n";
  out += ".trace-collision-label{font-family:sans-serif;font-weight:bold;fill:#a00000;font-size:" +
         metres(collision_font_pixels) + "px;" + halo + "}\n";
  // The legend is drawn in pixels (its group scales them to metres).
  out += ".trace-legend-background{fill:#fff;stroke:#808080;stroke-width:1}\n";
  out +=
      ".trace-legend-title{font-family:sans-serif;font-weight:bold;font-size:15px;"
      "dominant-baseline:central}\n";
  out += ".trace-legend-text{font-family:sans-serif;font-size:12px;dominant-baseline:central}\n";
  out += ".trace-legend-key{stroke-width:4}\n";
  out += "</style>\n</defs>\n";
}

}  // namespace

std::string render_trace_svg(const RoadMap& map, const Trace& trace,
                             const TraceSvgOptions& options) {
  const SvgFrame frame =
      map_svg_frame(visited_region(map, trace), 0, options.pixels_per_metre, default_image_pixels);

  std::vector<LegendEntry> entries;
  for (std::size_t id = 0; id < trace.actors.size(); ++id) {
    // A flow vehicle that never got onto the map is not drawn, so it has no entry either.
    if (trace.actors[id].present_from >=
            std::min(trace.actors[id].present_until, trace.sample_count()) &&
        trace.sample_count() > 0)
      continue;
    entries.push_back({trace.actors[id].name + " (" +
                           std::string(trace_actor_kind_name(trace.actors[id].kind)) + ")",
                       actor_colour(trace, id)});
  }
  if (!trace.collisions.empty()) entries.push_back({"collision", {}});
  entries.push_back(
      {"paths darken with time; bodies every " + number_text(options.snapshot_interval, 2) + " s",
       "#b0b0b0"});
  const LegendLayout legend = legend_layout(entries, frame.width / frame.metres_per_pixel);
  const double total_height = frame.height + pixels(frame, legend.height);
  const std::string title = title_text(trace);

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  out += std::to_string(std::max(1L, std::lround(frame.width / frame.metres_per_pixel)));
  out += "\" height=\"";
  out += std::to_string(std::max(1L, std::lround(total_height / frame.metres_per_pixel)));
  out += "\" viewBox=\"0 0 ";
  append_number(out, frame.width);
  out += ' ';
  append_number(out, total_height);
  out += "\">\n<title>";
  append_escaped(out, title);
  out += "</title>\n<desc>scenfuzz trace: one unit is a metre; map x = ";
  append_number(out, frame.origin.x);
  out += " + svg x, map y = ";
  append_number(out, frame.origin.y);
  out += " - svg y</desc>\n";
  append_style(out, frame);
  out += render_map_svg_layer(map, frame, {.labels = options.lane_labels});

  // Painter's order: paths, then bodies over them, then collisions and text on top.
  out += "<g class=\"trace-paths\">\n";
  PathDrawing paths;
  for (std::size_t id = 0; id < trace.actors.size(); ++id) append_path(paths, frame, trace, id);
  out += paths.casings;
  out += paths.lines;
  out += "</g>\n<g class=\"trace-bodies\">\n";
  // (sample, actor) pairs whose body is drawn as in a collision.
  std::set<std::pair<std::size_t, std::size_t>> colliding;
  if (!trace.time.empty())
    for (const Collision& collision : trace.collisions) {
      colliding.emplace(sample_at(trace, collision.time), collision.first);
      colliding.emplace(sample_at(trace, collision.time), collision.second);
    }
  const std::vector<std::size_t> snapshots = snapshot_samples(trace, options.snapshot_interval);
  std::string time_labels;
  for (std::size_t id = 0; id < trace.actors.size(); ++id) {
    const TraceActor& actor = trace.actors[id];
    for (const std::size_t sample : snapshots) {
      if (sample >= actor.x.size() || !present_at(actor, sample)) continue;
      append_body(out, frame, actor, sample, actor_colour(trace, id),
                  elapsed_fraction(trace, trace.time[sample]), colliding.contains({sample, id}));
      if (sample > 0 && finite(position(actor, sample)))
        append_text(time_labels, frame, "trace-time", position(actor, sample), 6, -6,
                    number_text(trace.time[sample], 1) + " s");
    }
  }
  out += "</g>\n<g class=\"trace-labels\">\n";
  out += time_labels;
  for (std::size_t id = 0; id < trace.actors.size(); ++id) {
    const TraceActor& actor = trace.actors[id];
    std::size_t first = 0;
    while (first < actor.x.size() && !drawn(actor, first)) ++first;
    if (first == actor.x.size()) continue;
    append_text(out, frame, "trace-name", position(actor, first), -8, -10, actor.name,
                actor_colour(trace, id));
  }
  out += "</g>\n<g class=\"trace-collisions\">\n";
  append_collisions(out, frame, trace);
  out += "</g>\n";
  append_legend(out, frame, entries, legend, title);
  out += "</svg>\n";
  return out;
}

}  // namespace scenfuzz

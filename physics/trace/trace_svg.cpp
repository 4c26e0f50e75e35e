// render_trace_svg: lays the picture out in pixels (title block, main view, inset with its
// caption, legend), then draws each view as a nested <svg> in map metres over one shared drawing
// of the roads, and places every label with a LabelPlacer so that none clips or overlaps.
#include "physics/trace/trace_svg.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string_view>
#include <vector>

#include "physics/collision/body_side.hpp"
#include "physics/map/map_svg.hpp"
#include "physics/map/svg_writing.hpp"
#include "physics/trace/picture_regions.hpp"
#include "physics/trace/trace_moment.hpp"
#include "physics/trace/trace_svg_parts.hpp"

namespace scenfuzz {
namespace {

constexpr double main_fit_pixels = 1000;  // the main view's longer side, without a scale
constexpr double inset_fit_pixels = 440;  // the inset's longer side
constexpr double padding = 14;
constexpr double gap = 18;
constexpr double legend_row = 22;
constexpr double legend_key = 26;
constexpr double max_picture_aspect = 3;
constexpr double min_legend_width = 300;  // the narrowest room beside the inset it goes into
constexpr std::size_t max_collision_labels = 4;
constexpr double min_time_label_spacing = 14;  // pixels between the times along one path
constexpr double min_ghost_movement = 0.3;     // m an actor must move for a faint body of its own

constexpr TextFont title_font{17, true};
constexpr TextFont summary_font{13, false};
constexpr TextFont emphasis_font{13, true};
constexpr TextFont detail_font{12, false};
constexpr TextFont name_font{13, true};
constexpr TextFont time_font{11, false};
constexpr TextFont speed_font{12, true};
constexpr TextFont legend_font{12, false};

constexpr std::string_view text_colour = "#000";
constexpr std::string_view detail_colour = "#404040";
constexpr std::string_view collision_colour = "#b00000";

std::string seconds(double t) { return fixed_text(t, 2) + " s"; }

std::string actor_name(const Trace& trace, std::size_t id) {
  return id < trace.actors.size() ? trace.actors[id].name : "actor " + std::to_string(id);
}

MapPoint position(const TraceActor& actor, std::size_t i) { return {actor.x[i], actor.y[i]}; }

double speed_at(const TraceActor& actor, std::size_t i) {
  const MapPoint v = velocity_at(actor, i);
  return std::hypot(v.x, v.y);
}

// The sample `seconds` before sample i, if the run had started by then.
std::optional<std::size_t> sample_before(const Trace& trace, std::size_t i, double seconds) {
  const double steps = std::round(seconds / std::max(trace.dt, 1e-6));
  if (steps > static_cast<double>(i)) return std::nullopt;
  return i - static_cast<std::size_t>(steps);
}

// ---- what the title block says ----

struct TextLine {
  std::string text;
  TextFont font;
  std::string_view colour = text_colour;
};

std::string title_line(const Trace& trace, const TraceCaption& caption) {
  if (!caption.headline.empty()) return caption.headline;
  if (caption.spec.empty())
    return "Trace on " + (trace.map_name.empty() ? std::string("a map") : trace.map_name) +
           " (seed " + std::to_string(trace.seed) + ")";
  std::string title = "Spec " + caption.spec;
  if (caption.robustness) {
    title += *caption.robustness < 0 ? " violated" : " satisfied";
    title += ", robustness " + number_text(*caption.robustness, 4);
  }
  if (caption.time) title += " at " + seconds(*caption.time);
  return title;
}

std::string event_line(const Trace& trace, const TraceMoment& moment) {
  const TraceActor& ego = trace.actors[kEgo];
  const std::size_t i = moment.sample;
  const auto speeds = [&](ActorId other) {
    const TraceActor& them = trace.actors[other];
    const MapPoint a = velocity_at(ego, i), b = velocity_at(them, i);
    return "; " + ego.name + " at " + number_text(speed_at(ego, i), 1) + " m/s, " + them.name +
           " at " + number_text(speed_at(them, i), 1) + " m/s (closing " +
           number_text(std::hypot(a.x - b.x, a.y - b.y), 1) + " m/s)";
  };
  if (moment.collision) {
    const Collision& c = trace.collisions[*moment.collision];
    const bool ego_first = c.first == kEgo;
    const ActorId other = ego_first ? c.second : c.first;
    return "Collision at " + seconds(c.time) + ": " + ego.name + "'s " +
           std::string(body_side_name(ego_first ? c.first_side : c.second_side)) + " with " +
           actor_name(trace, other) + "'s " +
           std::string(body_side_name(ego_first ? c.second_side : c.first_side)) + speeds(other);
  }
  std::string when = moment.kind == MomentKind::verdict            ? "the verdict's time"
                     : moment.kind == MomentKind::nearest_approach ? "the nearest approach"
                                                                   : "the end of the run";
  if (!moment.other)
    return "No collision with " + ego.name + "; shown at " + when + ", " + seconds(moment.time);
  const double gap_metres = std::max(0.0, gap_to_ego(trace, *moment.other, i));
  return "No collision with " + ego.name + "; at " + when + ", " + seconds(moment.time) + ", " +
         trace.actors[*moment.other].name + " is nearest (about " + number_text(gap_metres, 1) +
         " m between bodies)" + speeds(*moment.other);
}

std::vector<TextLine> title_block(const Trace& trace, const std::optional<TraceMoment>& moment,
                                  const TraceCaption& caption) {
  std::vector<TextLine> lines{{title_line(trace, caption), title_font}};
  if (moment) lines.push_back({event_line(trace, *moment), summary_font});
  if (!caption.responsibility.empty())
    lines.push_back({"Responsibility: " + caption.responsibility +
                         (caption.reason.empty() ? "" : " - " + caption.reason),
                     emphasis_font});
  else if (!caption.reason.empty())
    lines.push_back({"Reason: " + caption.reason, emphasis_font});
  std::string details = (trace.map_name.empty() ? std::string("map") : trace.map_name) + ", seed " +
                        std::to_string(trace.seed) + "; ended by " +
                        std::string(end_reason_name(trace.end)) + " after " +
                        seconds(trace.time.empty() ? 0 : trace.time.back());
  if (!caption.atom.empty()) details += "; atom " + caption.atom;
  lines.push_back({details, detail_font, detail_colour});
  return lines;
}

// The lines wrapped to `width`, each keeping its font.
std::vector<TextLine> wrapped_lines(const std::vector<TextLine>& lines, double width) {
  std::vector<TextLine> out;
  for (const TextLine& line : lines)
    for (std::string& part : wrapped(line.text, line.font, width))
      out.push_back({std::move(part), line.font, line.colour});
  return out;
}

// One line's height: its text's box (with the halo) and a pixel between lines.
double line_height(const TextFont& font) { return label_at(0, 0, "", font).box.height() + 1; }

double lines_height(const std::vector<TextLine>& lines) {
  double height = 0;
  for (const TextLine& line : lines) height += line_height(line.font);
  return height;
}

// Each line's text from its top-left corner down.
void append_lines(std::string& out, const std::vector<TextLine>& lines, double left, double top) {
  for (const TextLine& line : lines) {
    const PlacedLabel label = label_at(left, top, line.text, line.font);
    append_text(out, label, line.text, line.font, line.colour);
    top += line_height(line.font);
  }
}

std::string inset_caption(const Trace& trace, const TraceMoment& moment) {
  std::string what = moment.collision                     ? "the collision"
                     : moment.kind == MomentKind::verdict ? "the verdict's time"
                     : moment.kind == MomentKind::nearest_approach
                         ? "the nearest approach to " + actor_name(trace, *moment.other)
                         : "the end";
  return "Zoomed on " + what + " at " + seconds(moment.time) +
         ": bodies then (bold) and 1, 2, 3 s before (faint); arrows show speed, 1 s of travel";
}

// ---- the legend ----

enum class LegendKey { line, star, target, lights, perception_vehicles, perception_pedestrians };

struct LegendEntry {
  std::string text;
  LegendKey key = LegendKey::line;
  std::string_view colour;
};

struct LegendPlace {
  double left = 0;
  double middle = 0;  // of its row
};

double legend_entry_width(const LegendEntry& entry, double available) {
  return legend_key + 6 +
         std::min(estimated_text_width(entry.text, legend_font), available - legend_key - 10) + 18;
}

// Rows of entries within `width`; the legend's height.
double legend_places(const std::vector<LegendEntry>& entries, double width,
                     std::vector<LegendPlace>& places) {
  double x = 0;
  int row = 0;
  for (const LegendEntry& entry : entries) {
    const double entry_width = legend_entry_width(entry, width);
    if (x > 0 && x + entry_width > width) {
      x = 0;
      ++row;
    }
    places.push_back({x, (row + 0.5) * legend_row});
    x += entry_width;
  }
  return entries.empty() ? 0 : (row + 1) * legend_row;
}

void append_legend_key(std::string& out, const LegendEntry& entry, double x, double y) {
  switch (entry.key) {
    case LegendKey::line:
      out += "<line class=\"trace-legend-key\"";
      append_attribute(out, "stroke", entry.colour);
      append_attribute(out, "x1", x);
      append_attribute(out, "y1", y);
      append_attribute(out, "x2", x + legend_key);
      append_attribute(out, "y2", y);
      out += "/>\n";
      return;
    case LegendKey::star: append_star(out, x + legend_key / 2, y, 8); return;
    case LegendKey::target:
      out += "<g class=\"trace-target\" stroke-width=\"2\"><circle class=\"trace-target-ring\"";
      append_attribute(out, "cx", x + legend_key / 2);
      append_attribute(out, "cy", y);
      out += " r=\"7\"/><circle class=\"trace-target-ring\"";
      append_attribute(out, "cx", x + legend_key / 2);
      append_attribute(out, "cy", y);
      out += " r=\"3\"/></g>\n";
      return;
    case LegendKey::lights:
      for (int k = 0; k < 3; ++k) {
        out += "<circle class=\"trace-light\" stroke-width=\"1\" r=\"4\"";
        append_attribute(out, "cx", x + 4 + 9 * k);
        append_attribute(out, "cy", y);
        append_attribute(out, "fill", k == 0 ? "#e00000" : k == 1 ? "#ffc400" : "#00b050");
        out += "/>\n";
      }
      return;
    case LegendKey::perception_vehicles:
    case LegendKey::perception_pedestrians:
      out += "<line class=\"trace-perception\" stroke-width=\"2\"";
      append_attribute(out, "stroke-dasharray",
                       entry.key == LegendKey::perception_vehicles ? "8 5" : "2 4");
      append_attribute(out, "x1", x);
      append_attribute(out, "y1", y);
      append_attribute(out, "x2", x + legend_key);
      append_attribute(out, "y2", y);
      out += "/>\n";
      return;
  }
}

void append_legend(std::string& out, const std::vector<LegendEntry>& entries,
                   const std::vector<LegendPlace>& places, double left, double top, double width) {
  out += "<g class=\"trace-legend\">\n";
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const double x = left + places[k].left, y = top + places[k].middle;
    append_legend_key(out, entries[k], x, y);
    const std::string text = fitted(entries[k].text, legend_font, width - legend_key - 10);
    const PlacedLabel probe = label_at(0, 0, text, legend_font);
    append_text(out, label_at(x + legend_key + 6, y - probe.box.height() / 2, text, legend_font),
                text, legend_font, text_colour);
  }
  out += "</g>\n";
}

// ---- the views ----

struct Picture {
  const RoadMap& map;
  const Trace& trace;
  const TraceSvgOptions& options;
  std::optional<TraceMoment> moment;
  std::vector<ActorStyle> styles;
};

// The sample where an actor's body is drawn as in the event: the moment's, for everyone.
BodyEmphasis emphasis_at(const Picture& picture, std::size_t id, std::size_t sample) {
  for (const Collision& c : picture.trace.collisions)
    if ((c.first == id || c.second == id) && sample_at(picture.trace, c.time) == sample)
      return BodyEmphasis::colliding;
  if (picture.moment && sample == picture.moment->sample) return BodyEmphasis::event;
  return BodyEmphasis::normal;
}

// Bodies along the paths: the first and last samples, one every interval, each collision's and
// the event's.
std::vector<std::size_t> snapshot_samples(const Picture& picture) {
  const Trace& trace = picture.trace;
  if (trace.time.empty()) return {};
  std::set<std::size_t> samples{0, trace.time.size() - 1};
  const double interval = picture.options.snapshot_interval;
  if (interval > 0)
    for (double next = trace.time.front() + interval; next < trace.time.back(); next += interval)
      samples.insert(sample_at(trace, next));
  for (const Collision& collision : trace.collisions)
    samples.insert(sample_at(trace, collision.time));
  if (picture.moment) samples.insert(picture.moment->sample);
  return {samples.begin(), samples.end()};
}

void open_view(std::string& out, std::string_view id, const Panel& panel) {
  out += "<svg class=\"trace-view\"";
  append_attribute(out, "id", id);
  append_attribute(out, "x", panel.box.left);
  append_attribute(out, "y", panel.box.top);
  append_attribute(out, "width", panel.box.width());
  append_attribute(out, "height", panel.box.height());
  out += " viewBox=\"";
  append_number(out, panel.u(panel.region.min));
  out += ' ';
  append_number(out, panel.v(panel.region.max));
  out += ' ';
  append_number(out, panel.region.max.x - panel.region.min.x);
  out += ' ';
  append_number(out, panel.region.max.y - panel.region.min.y);
  out += "\" preserveAspectRatio=\"none\">\n<use xlink:href=\"#trace-roads\"/>\n";
}

void close_view(std::string& out, const Panel& panel) {
  out += "</svg>\n<rect class=\"trace-view-frame\"";
  append_attribute(out, "x", panel.box.left);
  append_attribute(out, "y", panel.box.top);
  append_attribute(out, "width", panel.box.width());
  append_attribute(out, "height", panel.box.height());
  out += "/>\n";
}

// The picture's pixels a body covers (its bounding circle's box), so labels keep off it.
PixelBox body_pixels(const Panel& panel, const TraceActor& actor, MapPoint at) {
  const auto [x, y] = panel.pixel(at);
  const double r =
      std::max(std::hypot(actor.length, actor.width) / 2 / panel.metres_per_pixel, 3.0);
  return {x - r, y - r, x + r, y + r};
}

double body_clearance(const Panel& panel, const TraceActor& actor) {
  return std::max(std::hypot(actor.length, actor.width) / 2 / panel.metres_per_pixel, 4.0);
}

// A label for something at `at` in the panel, when a free place is found; with a leader line
// when it had to go far.
void place_label(std::string& labels, LabelPlacer& placer, const Panel& panel, MapPoint at,
                 double clearance, const std::string& text, const TextFont& font,
                 std::string_view colour) {
  if (!panel.shows(at)) return;
  const auto [x, y] = panel.pixel(at);
  const std::optional<PlacedLabel> label = placer.place(x, y, clearance, text, font);
  if (!label) return;
  append_leader(labels, x, y, label->box);
  append_text(labels, *label, text, font, colour);
}

void append_collision_marks(std::string& out, std::string& labels, LabelPlacer& placer,
                            const Panel& panel, const Trace& trace) {
  std::size_t labelled = 0;
  for (const Collision& collision : trace.collisions) {
    if (!std::isfinite(collision.point.x) || !std::isfinite(collision.point.y) ||
        !panel.shows(collision.point))
      continue;
    append_star(out, panel.u(collision.point), panel.v(collision.point), panel.metres(10));
    const auto [x, y] = panel.pixel(collision.point);
    placer.block({x - 10, y - 10, x + 10, y + 10});
    if (labelled++ < max_collision_labels)
      place_label(labels, placer, panel, collision.point, 10,
                  "collision " + seconds(collision.time), speed_font, collision_colour);
  }
}

// Where an actor's name goes: at its body at the event, else where it first shows in the view.
std::optional<MapPoint> name_anchor(const Picture& picture, const Panel& panel, std::size_t id) {
  const Trace& trace = picture.trace;
  if (picture.moment && drawn_at(trace, id, picture.moment->sample) &&
      panel.shows(position(trace.actors[id], picture.moment->sample)))
    return position(trace.actors[id], picture.moment->sample);
  for (std::size_t i = 0; i < trace.sample_count(); ++i)
    if (drawn_at(trace, id, i) && panel.shows(position(trace.actors[id], i)))
      return position(trace.actors[id], i);
  return std::nullopt;
}

// The listed actors, the ego and the other party first.
std::vector<std::size_t> label_order(const Picture& picture) {
  std::vector<std::size_t> order;
  if (!picture.styles.empty() && picture.styles[kEgo].ever_drawn) order.push_back(kEgo);
  if (picture.moment && picture.moment->other) order.push_back(*picture.moment->other);
  for (std::size_t id = 1; id < picture.styles.size(); ++id)
    if (picture.styles[id].listed && std::find(order.begin(), order.end(), id) == order.end())
      order.push_back(id);
  return order;
}

void append_main_view(std::string& out, std::string& labels, const Picture& picture,
                      const Panel& panel, const std::optional<Panel>& inset) {
  const Trace& trace = picture.trace;
  open_view(out, "main-view", panel);
  const std::size_t event_sample =
      picture.moment ? picture.moment->sample : (trace.time.empty() ? 0 : trace.time.size() - 1);
  append_lights(out, panel, picture.map, trace, event_sample);
  if (picture.moment && trace.sensing.limited)
    append_perception(out, panel, trace.sensing, position(trace.actors[kEgo], event_sample));
  append_paths(out, panel, trace, picture.styles, 3.5);

  LabelPlacer placer(
      {panel.box.left + 1, panel.box.top + 1, panel.box.right - 1, panel.box.bottom - 1});
  out += "<g class=\"trace-bodies\">\n";
  const std::vector<std::size_t> snapshots = snapshot_samples(picture);
  for (std::size_t id = 0; id < trace.actors.size(); ++id)
    for (const std::size_t sample : snapshots) {
      if (!drawn_at(trace, id, sample)) continue;
      const BodyEmphasis emphasis = emphasis_at(picture, id, sample);
      append_body(out, panel, trace.actors[id], sample, picture.styles[id].colour,
                  picture.styles[id].listed ? emphasis : BodyEmphasis::faint);
      if (emphasis != BodyEmphasis::normal && panel.shows(position(trace.actors[id], sample)))
        placer.block(body_pixels(panel, trace.actors[id], position(trace.actors[id], sample)));
    }
  out += "</g>\n";
  if (trace.ego_target && panel.shows(*trace.ego_target)) {
    append_target(out, panel, *trace.ego_target);
    const auto [x, y] = panel.pixel(*trace.ego_target);
    placer.block({x - 9, y - 9, x + 9, y + 9});
  }
  append_collision_marks(out, labels, placer, panel, trace);
  if (inset) {
    out += "<rect class=\"trace-inset-outline\"";
    append_attribute(out, "x", panel.u(inset->region.min));
    append_attribute(out, "y", panel.v(inset->region.max));
    append_attribute(out, "width", inset->region.max.x - inset->region.min.x);
    append_attribute(out, "height", inset->region.max.y - inset->region.min.y);
    append_attribute(out, "stroke-width", panel.metres(1.5));
    append_attribute(out, "stroke-dasharray",
                     number_text(panel.metres(6), 3) + " " + number_text(panel.metres(4), 3));
    out += "/>\n";
  }
  close_view(out, panel);

  for (const std::size_t id : label_order(picture))
    if (const std::optional<MapPoint> at = name_anchor(picture, panel, id))
      place_label(labels, placer, panel, *at, body_clearance(panel, trace.actors[id]),
                  trace.actors[id].name, name_font, picture.styles[id].colour);
  if (trace.ego_target)
    place_label(labels, placer, panel, *trace.ego_target, 9, "target", name_font, text_colour);
  // Times beside the bodies of the ego and the other party, as room allows; one for a body
  // that stood where an earlier labelled one is (a standing car would pile them up).
  for (const std::size_t id : label_order(picture)) {
    if (id != kEgo && !(picture.moment && picture.moment->other == id)) continue;
    std::vector<std::pair<double, double>> labelled;
    for (const std::size_t sample : snapshots) {
      if (sample == 0 || !drawn_at(trace, id, sample)) continue;
      const MapPoint at = position(trace.actors[id], sample);
      const auto [x, y] = panel.pixel(at);
      if (std::any_of(labelled.begin(), labelled.end(), [&](const auto& p) {
            return std::hypot(p.first - x, p.second - y) < min_time_label_spacing;
          }))
        continue;
      labelled.emplace_back(x, y);
      place_label(labels, placer, panel, at, body_clearance(panel, trace.actors[id]),
                  number_text(trace.time[sample], 1) + " s", time_font, detail_colour);
    }
  }
}

// Whether actor id stood still from sample `earlier` to `later` (its faint body would lie under
// the later one, saying nothing).
bool stood_still(const Trace& trace, std::size_t id, std::size_t earlier, std::size_t later) {
  return drawn_at(trace, id, later) &&
         distance(position(trace.actors[id], earlier), position(trace.actors[id], later)) <
             min_ghost_movement;
}

void append_inset_view(std::string& out, std::string& labels, const Picture& picture,
                       const Panel& panel) {
  const Trace& trace = picture.trace;
  const TraceMoment& moment = *picture.moment;
  open_view(out, "inset-view", panel);
  append_lights(out, panel, picture.map, trace, moment.sample);
  if (trace.sensing.limited)
    append_perception(out, panel, trace.sensing, position(trace.actors[kEgo], moment.sample));
  append_paths(out, panel, trace, picture.styles, 2);
  LabelPlacer placer(
      {panel.box.left + 1, panel.box.top + 1, panel.box.right - 1, panel.box.bottom - 1});
  // Which actors show: those whose body at the event or in the seconds before is in the view.
  // The faint bodies first, then the collision's star, then the bodies at the event over it.
  std::vector<std::size_t> shown;
  std::string event_bodies;
  out += "<g class=\"trace-bodies\">\n";
  for (std::size_t id = 0; id < trace.actors.size(); ++id) {
    bool any = false;
    for (int back = static_cast<int>(kInsetLookBack); back >= 0; --back) {
      const std::optional<std::size_t> sample = sample_before(trace, moment.sample, back);
      if (!sample || !drawn_at(trace, id, *sample) ||
          !panel.shows(position(trace.actors[id], *sample)))
        continue;
      if (back > 0 &&
          stood_still(trace, id, *sample, *sample_before(trace, moment.sample, back - 1)))
        continue;
      any = true;
      append_body(back > 0 ? out : event_bodies, panel, trace.actors[id], *sample,
                  picture.styles[id].colour,
                  back > 0 ? BodyEmphasis::faint : emphasis_at(picture, id, *sample));
      placer.block(body_pixels(panel, trace.actors[id], position(trace.actors[id], *sample)));
    }
    if (any) shown.push_back(id);
  }
  append_collision_marks(out, labels, placer, panel, trace);
  out += event_bodies;
  out += "</g>\n";
  // Speed arrows at the event, one second of travel long.
  for (const std::size_t id : shown) {
    if (!drawn_at(trace, id, moment.sample)) continue;
    const MapPoint from = position(trace.actors[id], moment.sample);
    const MapPoint v = velocity_at(trace.actors[id], moment.sample);
    if (std::hypot(v.x, v.y) < 0.2) continue;
    const MapPoint tip{from.x + v.x, from.y + v.y};
    append_arrow(out, panel, from, tip, picture.styles[id].colour);
    const auto [x, y] = panel.pixel(tip);
    placer.block({x - 8, y - 8, x + 8, y + 8});
  }
  if (trace.ego_target && panel.shows(*trace.ego_target))
    append_target(out, panel, *trace.ego_target);
  close_view(out, panel);

  // Names and speeds of the ego and the other party first, then of the others shown.
  std::vector<std::size_t> order;
  for (const std::size_t id : label_order(picture))
    if (std::find(shown.begin(), shown.end(), id) != shown.end()) order.push_back(id);
  for (const std::size_t id : order) {
    if (!drawn_at(trace, id, moment.sample)) continue;
    const TraceActor& actor = trace.actors[id];
    const MapPoint at = position(actor, moment.sample);
    const double speed = speed_at(actor, moment.sample);
    place_label(labels, placer, panel, at, body_clearance(panel, actor),
                actor.name + ", " + number_text(speed, 1) + " m/s", name_font,
                picture.styles[id].colour);
  }
  // When each faint body was, for the ego and the other party.
  for (const std::size_t id : order) {
    if (id != kEgo && moment.other != id) continue;
    for (int back = 1; back <= static_cast<int>(kInsetLookBack); ++back) {
      const std::optional<std::size_t> sample = sample_before(trace, moment.sample, back);
      if (sample && drawn_at(trace, id, *sample) &&
          !stood_still(trace, id, *sample, *sample_before(trace, moment.sample, back - 1)))
        place_label(labels, placer, panel, position(trace.actors[id], *sample),
                    body_clearance(panel, trace.actors[id]), "-" + std::to_string(back) + " s",
                    time_font, detail_colour);
    }
  }
}

std::vector<LegendEntry> legend_entries(const Picture& picture, bool lights_shown) {
  const Trace& trace = picture.trace;
  std::vector<LegendEntry> entries;
  bool background = false;
  for (const std::size_t id : label_order(picture))
    entries.push_back({trace.actors[id].name + " (" +
                           std::string(trace_actor_kind_name(trace.actors[id].kind)) + ")",
                       LegendKey::line, picture.styles[id].colour});
  for (const ActorStyle& style : picture.styles)
    background = background || (style.in_view && !style.listed);
  if (background) entries.push_back({"other road users", LegendKey::line, kBackgroundColour});
  if (!trace.collisions.empty()) entries.push_back({"collision", LegendKey::star, {}});
  if (trace.ego_target) entries.push_back({"the ego's target", LegendKey::target, {}});
  if (lights_shown)
    entries.push_back({"traffic lights as they were at the event", LegendKey::lights, {}});
  if (picture.moment && trace.sensing.limited) {
    entries.push_back({"ego's perception range (weather, darkness): vehicles " +
                           number_text(trace.sensing.vehicle_range, 0) + " m",
                       LegendKey::perception_vehicles,
                       {}});
    if (std::abs(trace.sensing.pedestrian_range - trace.sensing.vehicle_range) > 0.5)
      entries.push_back({"pedestrians " + number_text(trace.sensing.pedestrian_range, 0) + " m",
                         LegendKey::perception_pedestrians,
                         {}});
  }
  entries.push_back({"paths darken with time; bodies every " +
                         number_text(picture.options.snapshot_interval, 2) + " s and at the event",
                     LegendKey::line, "#b0b0b0"});
  return entries;
}

bool shows_a_light(const RoadMap& map, const Panel& panel) {
  for (const TrafficLight& light : map.traffic_lights())
    for (const MapPoint head : light.heads)
      if (panel.shows(head)) return true;
  return false;
}

void append_style(std::string& out) {
  out += "<defs>\n<style>\n";
  out +=
      ".trace-text{font-family:'DejaVu Sans',Verdana,sans-serif;paint-order:stroke;stroke:#fff;"
      "stroke-width:3px;stroke-linejoin:round}\n"
      ".trace-background{fill:#fff}\n"
      ".trace-view-frame{fill:none;stroke:#707070;stroke-width:1}\n"
      ".trace-path{fill:none;stroke-linecap:butt;stroke-linejoin:round}\n"
      ".trace-path-casing{fill:none;stroke:#fff;stroke-opacity:.6;stroke-linecap:round;"
      "stroke-linejoin:round}\n"
      ".trace-front{fill:none}\n"
      ".trace-collision{fill:#e00000;stroke:#600000}\n"
      ".trace-speed polyline{fill:none;stroke-linecap:round}\n"
      ".trace-speed-casing{stroke:#fff;stroke-opacity:.85}\n"
      ".trace-target{fill:none;stroke:#111}\n"
      ".trace-target-ring{fill:#fff;fill-opacity:.4}\n"
      ".trace-light{stroke:#202020}\n"
      ".trace-perception{fill:none;stroke:#7b1fa2;stroke-opacity:.85}\n"
      ".trace-inset-outline{fill:none;stroke:#000}\n"
      ".trace-leader{stroke:#505050;stroke-width:.8}\n"
      ".trace-legend-key{stroke-width:4}\n";
  out += "</style>\n";
}

// Pixel sizes of the views and where they go.
struct Layout {
  double width = 0, height = 0;
  double header_top = padding;
  std::vector<TextLine> header;
  Panel main;
  std::optional<Panel> inset;
  std::vector<TextLine> inset_caption;
  double inset_caption_top = 0;
  std::vector<LegendEntry> legend;
  std::vector<LegendPlace> legend_places;
  double legend_left = 0, legend_top = 0, legend_width = 0;
};

Panel sized_panel(const MapBounds& region, MapPoint origin, double metres_per_pixel) {
  Panel panel;
  panel.origin = origin;
  panel.region = region;
  panel.metres_per_pixel = metres_per_pixel;
  panel.box = {0, 0, (region.max.x - region.min.x) / metres_per_pixel,
               (region.max.y - region.min.y) / metres_per_pixel};
  return panel;
}

void move_to(Panel& panel, double left, double top) {
  const double width = panel.box.width(), height = panel.box.height();
  panel.box = {left, top, left + width, top + height};
}

double aspect_distance(double width, double height) { return std::abs(std::log(width / height)); }

Layout lay_out(Picture& picture) {
  const Trace& trace = picture.trace;
  Layout layout;
  std::optional<MapBounds> inset_bounds;
  if (picture.moment) inset_bounds = inset_region(trace, *picture.moment);
  const MapBounds main_bounds = main_region(picture.map, trace, picture.moment, inset_bounds);
  picture.styles = actor_styles(trace, picture.moment, main_bounds);
  const MapPoint origin{main_bounds.min.x, main_bounds.max.y};
  const double longer =
      std::max(main_bounds.max.x - main_bounds.min.x, main_bounds.max.y - main_bounds.min.y);
  const double main_scale = picture.options.pixels_per_metre > 0
                                ? 1 / picture.options.pixels_per_metre
                                : std::max(longer, 1.0) / main_fit_pixels;
  layout.main = sized_panel(main_bounds, origin, main_scale);
  const double main_width = layout.main.box.width(), main_height = layout.main.box.height();

  double inset_width = 0, inset_height = 0, caption_height = 0;
  if (inset_bounds) {
    const double inset_longer = std::max(inset_bounds->max.x - inset_bounds->min.x,
                                         inset_bounds->max.y - inset_bounds->min.y);
    layout.inset = sized_panel(*inset_bounds, origin, inset_longer / inset_fit_pixels);
    inset_width = layout.inset->box.width();
    inset_height = layout.inset->box.height();
    layout.inset_caption = wrapped_lines(
        {{inset_caption(trace, *picture.moment), detail_font, detail_colour}}, inset_width);
    caption_height = lines_height(layout.inset_caption) + 4;
  }
  // The inset beside the main view or below it, whichever makes the picture squarer.
  const double side_width = main_width + (inset_bounds ? gap + inset_width : 0);
  const double side_height = std::max(main_height, caption_height + inset_height);
  const double below_width = std::max(main_width, inset_width);
  const double below_height =
      main_height + (inset_bounds ? gap + caption_height + inset_height : 0);
  const bool beside =
      aspect_distance(side_width, side_height) <= aspect_distance(below_width, below_height);
  const double content_width = beside ? side_width : below_width;
  const double content_height = beside ? side_height : below_height;

  layout.width = std::max(content_width + 2 * padding, 480.0);
  const double text_width = layout.width - 2 * padding;
  layout.header =
      wrapped_lines(title_block(trace, picture.moment, picture.options.caption), text_width);
  const double content_top = padding + lines_height(layout.header) + gap / 2;
  move_to(layout.main, padding, content_top);
  if (layout.inset) {
    const double left = beside ? padding + main_width + gap : padding;
    layout.inset_caption_top = beside ? content_top : content_top + main_height + gap;
    move_to(*layout.inset, left, layout.inset_caption_top + caption_height);
  }
  layout.legend = legend_entries(picture, shows_a_light(picture.map, layout.main));
  // The legend goes into the room the inset leaves beside or under it when it fits there, else
  // below everything.
  PixelBox room;
  if (layout.inset && beside)
    room = {layout.inset->box.left, layout.inset->box.bottom + gap, layout.inset->box.right,
            content_top + content_height};
  else if (layout.inset)
    room = {layout.inset->box.right + gap, layout.inset_caption_top, padding + content_width,
            content_top + content_height};
  std::vector<LegendPlace> in_room;
  if (room.width() >= min_legend_width &&
      legend_places(layout.legend, room.width(), in_room) <= room.height()) {
    layout.legend_places = std::move(in_room);
    layout.legend_left = room.left;
    layout.legend_width = room.width();
    layout.legend_top = room.top;
    layout.height = content_top + content_height + padding;
  } else {
    layout.legend_left = padding;
    layout.legend_width = text_width;
    layout.legend_top = content_top + content_height + gap;
    layout.height = layout.legend_top +
                    legend_places(layout.legend, text_width, layout.legend_places) + padding;
  }
  // Whitespace keeps the sides within 1:3 should the text ever make the picture a strip.
  layout.height = std::max(layout.height, layout.width / max_picture_aspect);
  layout.width = std::max(layout.width, layout.height / max_picture_aspect);
  return layout;
}

std::string document_title(const Trace& trace, const TraceCaption& caption) {
  std::string title =
      "Trace on " + (trace.map_name.empty() ? std::string("a map") : trace.map_name) + " (seed " +
      std::to_string(trace.seed) + "): ended by " + std::string(end_reason_name(trace.end)) +
      " after " + seconds(trace.time.empty() ? 0 : trace.time.back());
  if (!caption.spec.empty() || !caption.headline.empty())
    title += "; " + title_line(trace, caption);
  return title;
}

}  // namespace

std::string render_trace_svg(const RoadMap& map, const Trace& trace,
                             const TraceSvgOptions& options) {
  Picture picture{map, trace, options, key_moment(trace, options.caption.time), {}};
  const Layout layout = lay_out(picture);
  const Panel& main = layout.main;
  SvgFrame frame;
  frame.origin = main.origin;
  frame.width = main.region.max.x - main.region.min.x;
  frame.height = main.region.max.y - main.region.min.y;
  frame.metres_per_pixel = main.metres_per_pixel;

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out +=
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"";
  const long width = std::lround(std::ceil(layout.width));
  const long height = std::lround(std::ceil(layout.height));
  out += std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
         std::to_string(width) + " " + std::to_string(height) + "\">\n<title>";
  append_escaped(out, document_title(trace, options.caption));
  out +=
      "</title>\n<desc>scenfuzz trace picture, in pixels; its views are nested svg elements in "
      "map metres: map x = ";
  append_number(out, frame.origin.x);
  out += " + u, map y = ";
  append_number(out, frame.origin.y);
  out += " - v for their viewBox coordinates (u, v)</desc>\n";
  append_style(out);
  // The roads once, in the main view's coordinates; both views show them through <use>.
  out += "<g id=\"trace-roads\">\n";
  out += render_map_svg_layer(map, frame, {.labels = options.lane_labels});
  out +=
      "</g>\n</defs>\n<rect class=\"trace-background\" x=\"0\" y=\"0\" width=\"100%\" "
      "height=\"100%\"/>\n";

  std::string labels;
  append_lines(out, layout.header, padding, layout.header_top);
  append_main_view(out, labels, picture, main, layout.inset);
  if (layout.inset) {
    append_lines(out, layout.inset_caption, layout.inset->box.left, layout.inset_caption_top);
    append_inset_view(out, labels, picture, *layout.inset);
  }
  out += "<g class=\"trace-labels\">\n" + labels + "</g>\n";
  append_legend(out, layout.legend, layout.legend_places, layout.legend_left, layout.legend_top,
                layout.legend_width);
  out += "</svg>\n";
  return out;
}

}  // namespace scenfuzz

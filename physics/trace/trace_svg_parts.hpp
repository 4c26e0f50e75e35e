// The pieces render_trace_svg assembles, shared between its files: a view of the map placed in
// the picture (Panel), how each actor is coloured, the marks drawn in map metres inside a view,
// and text drawn in the picture's pixels.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "physics/map/road_map.hpp"
#include "physics/trace/label_placement.hpp"
#include "physics/trace/trace.hpp"
#include "physics/trace/trace_moment.hpp"

namespace scenfuzz {

// A view of the map: a nested <svg> whose viewBox is `region` in the main view's coordinates
// (u = x - origin.x, v = origin.y - y, metres), drawn into `box` of the picture.
struct Panel {
  MapPoint origin;
  MapBounds region;
  double metres_per_pixel = 1;
  PixelBox box;

  // `count` pixels of this view in metres.
  double metres(double count) const { return count * metres_per_pixel; }
  double u(MapPoint p) const { return p.x - origin.x; }
  double v(MapPoint p) const { return origin.y - p.y; }
  // Where a map point lands in the picture, pixels.
  std::pair<double, double> pixel(MapPoint p) const {
    return {box.left + (p.x - region.min.x) / metres_per_pixel,
            box.top + (region.max.y - p.y) / metres_per_pixel};
  }
  bool shows(MapPoint p) const {
    return p.x >= region.min.x && p.x <= region.max.x && p.y >= region.min.y && p.y <= region.max.y;
  }
};

inline constexpr std::string_view kEgoColour = "#1565c0";
inline constexpr std::string_view kBackgroundColour = "#9a9a9a";  // actors not in the legend

// How each actor is drawn: a colour of its own and a legend entry for the ego, the other party
// and the few actors nearest the ego at the event; the rest grey, as background.
struct ActorStyle {
  std::string_view colour = kBackgroundColour;
  bool listed = false;
  bool ever_drawn = false;
  bool in_view = false;  // drawn inside the main view at some sample
};

std::vector<ActorStyle> actor_styles(const Trace& trace, const std::optional<TraceMoment>& moment,
                                     const MapBounds& region);

// ---- marks, in a panel's metres ----

void append_paths(std::string& out, const Panel& panel, const Trace& trace,
                  const std::vector<ActorStyle>& styles, double width_pixels);

enum class BodyEmphasis { faint, normal, event, colliding };

void append_body(std::string& out, const Panel& panel, const TraceActor& actor, std::size_t sample,
                 std::string_view colour, BodyEmphasis emphasis);

// An arrow from `from` to `to`, for a velocity.
void append_arrow(std::string& out, const Panel& panel, MapPoint from, MapPoint to,
                  std::string_view colour);

// A five-pointed star of `radius` centred at (x, y), in whatever units the element is in.
void append_star(std::string& out, double x, double y, double radius);

// The ego's target: a chequered flag's ring and cross.
void append_target(std::string& out, const Panel& panel, MapPoint at);

// Every signal head in the view in its light's colour at `sample` (grey where not recorded).
void append_lights(std::string& out, const Panel& panel, const RoadMap& map, const Trace& trace,
                   std::size_t sample);

// The ego's perception range about `centre`: vehicles dashed, pedestrians dotted.
void append_perception(std::string& out, const Panel& panel, const TraceSensing& sensing,
                       MapPoint centre);

// ---- text, in the picture's pixels ----

// A <text> at the label's place; `colour` its fill; the halo class outlines it in white.
void append_text(std::string& out, const PlacedLabel& label, std::string_view text,
                 const TextFont& font, std::string_view colour);

// A thin line from a label to what it names, when the label had to go further away.
void append_leader(std::string& out, double x, double y, const PixelBox& label);

// `text` broken at spaces into lines no wider than `width` pixels (a word longer than that is
// cut with an ellipsis, so that nothing overflows).
std::vector<std::string> wrapped(std::string_view text, const TextFont& font, double width);

// `text`, cut with an ellipsis when it is wider than `width` pixels.
std::string fitted(std::string_view text, const TextFont& font, double width);

}  // namespace scenfuzz

// Draws a trace as a bird's-eye SVG picture, for a person deciding what went wrong in a run: a
// title saying which spec failed, how badly and (when known) whose fault it was; the roads around
// the ego's path with each light in its state at the event, every actor's path darkening with
// time, the ego's target and perception range; an inset zoomed on the event (the ego's first
// collision, else the spec's verdict or the nearest approach) with the bodies then and 1, 2 and
// 3 s before and their speeds; labels that never leave the picture or cover each other.
#pragma once

#include <optional>
#include <string>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// What the picture's title says about the verdict; callers fill what they know. Every field may
// stay empty.
struct TraceCaption {
  std::string spec;  // the violated (or judged) spec's name
  std::optional<double> robustness;
  std::optional<double> time;  // s: when the verdict was decided; the event without a collision
  std::string atom;            // the responsible atom as written
  std::string responsibility;  // of the collision: "ego", "other" or "shared"
  std::string reason;          // why, in one sentence
  // The title's first line in the caller's words, in place of a spec's verdict (an accident's
  // reconstruction); empty: the spec's.
  std::string headline;
};

struct TraceSvgOptions {
  double pixels_per_metre = 0;   // the main view's scale; 0: fit it into about 1000 pixels
  double snapshot_interval = 5;  // seconds between the bodies drawn along each path
  bool lane_labels = false;      // write each lane's id, as render_map_svg does
  TraceCaption caption;
};

// One standalone SVG document in pixels. The main view and the inset are nested <svg> elements
// in map metres; the <desc> says how the main view's coordinates map to the map's.
std::string render_trace_svg(const RoadMap& map, const Trace& trace,
                             const TraceSvgOptions& options = {});

}  // namespace scenfuzz

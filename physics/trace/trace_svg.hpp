// Draws a trace as a bird's-eye SVG picture, for a person looking at what happened in a run: the
// roads around the actors, each actor's path darkening with time, its body at a few instants,
// every collision marked and labelled, and a legend with how and when the run ended.
#pragma once

#include <string>

#include "physics/map/road_map.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

struct TraceSvgOptions {
  double pixels_per_metre = 0;   // 0: fit the drawing into about 1600 pixels
  double snapshot_interval = 5;  // seconds between the bodies drawn along each path
  bool lane_labels = false;      // write each lane's id, as render_map_svg does
};

// One standalone SVG document, cropped to the region the actors visit (with a margin). The
// document's <desc> says how its coordinates map to the map's: map x = X + svg x,
// map y = Y - svg y, one unit a metre.
std::string render_trace_svg(const RoadMap& map, const Trace& trace,
                             const TraceSvgOptions& options = {});

}  // namespace scenfuzz

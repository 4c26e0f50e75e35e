// Draws a road map as SVG, for a user who looks at a map before writing lane ids into a scenario:
// lane surfaces and boundaries, centre lines with direction arrows, junction areas, stop lines,
// signal heads, crosswalks and signs; optionally every lane's id. Either a standalone document
// of the whole map with a legend, or a layer of another picture (a trace's) showing part of it.
#pragma once

#include <span>
#include <string>

#include "physics/map/road_map.hpp"

namespace scenfuzz {

// Something placed on a standalone map: a body's outline with a tick towards its front (an actor
// where a scenario starts it), or with no body only the text (a road's name).
struct SvgMark {
  MapPose pose;
  double length = 0;  // m; 0: no body
  double width = 0;   // m
  std::string text;   // written beside the body, or at the pose
};

struct SvgOptions {
  bool labels = false;          // write each lane's id at its middle
  double pixels_per_metre = 0;  // 0: fit the map into about 2000 pixels (unused by a layer)
};

// Where a drawing lies on the map. Its coordinates are relative to its top-left corner, because
// SVG viewers hold coordinates as 32-bit floats, which at UTM magnitudes (4e6 m) would snap
// points to half a metre: svg x = map x - origin.x, svg y = origin.y - map y, one unit a metre.
struct SvgFrame {
  MapPoint origin;    // map coordinates of the drawing's top-left corner
  double width = 0;   // metres
  double height = 0;  // metres
  double metres_per_pixel = 1;

  MapBounds region() const;  // the part of the map the frame shows
};

// The frame showing `region` (the origin when empty) with `margin` metres around it, at
// `pixels_per_metre`, or when that is 0 with its longer side about `fit_pixels` long.
SvgFrame map_svg_frame(const MapBounds& region, double margin, double pixels_per_metre,
                       double fit_pixels);

// `marks` are drawn over the map.
std::string render_map_svg(const RoadMap& map, const SvgOptions& options = {},
                           std::span<const SvgMark> marks = {});

// The roads in `frame`, to draw other things over in the same coordinates: a <defs> block with
// the styles, the frame's background, then every lane and piece of road furniture whose
// bounding box reaches the frame's region, whole. No root element and no legend; the caller's
// document clips what spills over the frame's edges.
std::string render_map_svg_layer(const RoadMap& map, const SvgFrame& frame,
                                 const SvgOptions& options = {});

}  // namespace scenfuzz

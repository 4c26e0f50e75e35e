// Draws a road map as SVG, for a user who looks at a map before writing lane ids into a scenario:
// lane surfaces and boundaries, centre lines with direction arrows, junction areas, stop lines,
// signal heads, crosswalks and signs; optionally every lane's id.
#pragma once

#include <string>

#include "physics/map/road_map.hpp"

namespace scenfuzz {

struct SvgOptions {
  bool labels = false;          // write each lane's id at its middle
  double pixels_per_metre = 0;  // 0: fit the map into about 2000 pixels
};

std::string render_map_svg(const RoadMap& map, const SvgOptions& options = {});

}  // namespace scenfuzz

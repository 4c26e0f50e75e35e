// Point-in-polygon queries on the map's outlines (crosswalks, junctions), with a margin.
#pragma once

#include <vector>

#include "physics/map/map_point.hpp"

namespace scenfuzz {

// The distance from p to the segment ab.
double distance_to_segment(MapPoint p, MapPoint a, MapPoint b);

// Whether p lies inside the polygon or within `margin` of its outline (false for fewer than three
// points).
bool near_polygon(MapPoint p, const std::vector<MapPoint>& polygon, double margin);

}  // namespace scenfuzz

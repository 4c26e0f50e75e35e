// Internal to outline_map.cpp: the lanes of an outline network's junction that turn from one road
// into another, and the junction's outline (outline_map.hpp, rule 9). Straight on through a
// junction is the road's own lane, cut there, which outline_map.cpp makes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "physics/map/map_description.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz::outline {

// Where a road leaves a junction: its lanes coming in and going out there, each counted from the
// centre line (k = 0 first), and the road's two edges there.
struct JunctionArm {
  std::string road;
  MapPoint outward;  // unit, from the junction along the road
  std::vector<std::string> in_lanes, out_lanes;
  std::array<MapPoint, 2> edges;
};

// Adds junction `id` to `map`, outlined by the convex hull of its arms' edges, with a connector
// for every turn between two arms: a left turn from the in lane next to the centre line into the
// out lane next to the centre line, a right turn from kerb lane to kerb lane. A turn is left or
// right by the side the arm it leads to lies on, seen coming in; an arm within 30 degrees of
// straight on or of straight back gets none. A connector is the cubic Bezier curve tangent to
// both lanes that draws a quarter circle at a right angle, `<in lane>_to_<out lane>`, of the in
// lane's speed limit and widths changing linearly into the out lane's. The arms' lanes must be
// in `map`.
void add_junction(MapDescription& map, const std::string& id, const std::vector<JunctionArm>& arms);

}  // namespace scenfuzz::outline

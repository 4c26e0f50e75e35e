// A written point read as a place in a lane of the blank map's roads, and back. A vehicle's
// `position: (x, y)` becomes its lane, how far along it and how far off its centre, so that the
// search moves the vehicle along its lane and a little across it, never into the oncoming half or
// off the road; a concrete finding writes the place back as a point. The lanes are the map
// layer's (physics/map/outline_map.hpp, rules 1-4), whose lane count this repeats; the arc length
// along a lane is read on the road's centre line, exact on straight roads and within centimetres
// on the gentle bends a road outline draws (docs/ch-scenario.md, "Written positions").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lang/chs/syntax.hpp"

namespace scenfuzz::chs {

struct LanePlace {
  const Road* road = nullptr;
  bool forward = true;  // the right half, driving in the point order
  int lane = 0;         // k of <road>_f<k> / <road>_b<k>, counted from the centre line
  double s = 0;         // metres along the lane in its driving direction
  double lateral = 0;   // metres left of the lane's centre, facing its driving direction
};

// The place of (x, y) in the lane of `roads` it lies in: the road whose centre line is nearest
// among those between whose boundaries the point lies, abreast of the centre line. None for a
// point off every road's lanes (it stays a point).
std::optional<LanePlace> lane_place_at(const std::vector<Road>& roads, double x, double y);

struct PlanePoint {
  double x = 0, y = 0;
};

// The point of a place: the inverse of lane_place_at for a point it reads.
PlanePoint point_of(const LanePlace& place);

// <road>_f<k> or <road>_b<k>, the map layer's lane id.
std::string lane_id(const Road& road, bool forward, int lane);

// The number of lanes of a half (outline_map.hpp, rules 2-3): 0 when it is narrower than a metre
// everywhere.
int lane_count(const Road& road, bool forward);

}  // namespace scenfuzz::chs

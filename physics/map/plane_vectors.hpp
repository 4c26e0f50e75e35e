// Internal to the map builders (built-in generators, drawn road networks): plane vectors as
// MapPoints, and looking up a lane of a map description being built. The operators live in
// namespace `plane` only, so that they cannot clash with anyone else's; a builder brings them in
// with `using namespace plane;`.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "lang/demand.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz::plane {

inline MapPoint operator+(MapPoint a, MapPoint b) { return {a.x + b.x, a.y + b.y}; }
inline MapPoint operator-(MapPoint a, MapPoint b) { return {a.x - b.x, a.y - b.y}; }
inline MapPoint operator*(double factor, MapPoint a) { return {factor * a.x, factor * a.y}; }
inline double dot(MapPoint a, MapPoint b) { return a.x * b.x + a.y * b.y; }
inline double cross(MapPoint a, MapPoint b) { return a.x * b.y - a.y * b.x; }
inline double norm(MapPoint a) { return std::sqrt(dot(a, a)); }

inline MapPoint unit_vector(double heading) { return {std::cos(heading), std::sin(heading)}; }
inline double heading_of(MapPoint direction) { return std::atan2(direction.y, direction.x); }
inline MapPoint left_normal(MapPoint direction) { return {-direction.y, direction.x}; }
inline MapPoint right_normal(MapPoint direction) { return {direction.y, -direction.x}; }

// The length of a polyline given as its points.
inline double length_of(const std::vector<MapPoint>& line) {
  double length = 0;
  for (std::size_t i = 1; i < line.size(); ++i) length += distance(line[i - 1], line[i]);
  return length;
}

// A lane the builder itself put into `map`: its absence is a bug in the builder.
template <typename Description>
auto& lane_named(Description& map, const std::string& id) {
  for (auto& lane : map.lanes)
    if (lane.id == id) return lane;
  demand_failed("a map builder's lane is in the map", __FILE__, __LINE__);
}

}  // namespace scenfuzz::plane

// Internal to the built-in map generators: the resolved parameters a generator reads, the
// generators' entry points (registered in builtin_maps.cpp), and the plane geometry they share
// (straight and circular centre lines, lateral offsets, fillets, polygons).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "physics/map/builtin_maps.hpp"
#include "physics/map/map_description.hpp"
#include "physics/map/plane_vectors.hpp"

namespace scenfuzz::builtin {

// Every parameter of one map with its final value: defaults filled in, ranges checked. Asking
// for a parameter the map does not declare is a bug in a generator, hence logic_error.
struct MapParameters {
  std::string map;
  std::vector<MapParameterValue> values;

  double value(std::string_view name) const {
    for (const MapParameterValue& parameter : values)
      if (parameter.name == name) return parameter.value;
    throw std::logic_error("built-in map '" + map + "' has no parameter '" + std::string(name) +
                           "'");
  }
  // Counts and flags are checked to be whole numbers before a generator sees them.
  int count(std::string_view name) const { return static_cast<int>(std::lround(value(name))); }
  bool flag(std::string_view name) const { return count(name) != 0; }
};

MapDescription generate_straight(const MapParameters& parameters);
MapDescription generate_curve(const MapParameters& parameters);
MapDescription generate_t_junction(const MapParameters& parameters);
MapDescription generate_crossroads(const MapParameters& parameters);
MapDescription generate_roundabout(const MapParameters& parameters);
MapDescription generate_merge(const MapParameters& parameters);

// Plane vectors reuse MapPoint (plane_vectors.hpp).
using namespace plane;

inline double radians(double degrees) { return degrees * std::numbers::pi / 180; }

// Arcs are sampled finely enough that a centre line's polyline length is within a millimetre or
// so of the true arc length (the contract gives lengths and s values to the centimetre): segments
// of at most 1 m and at most 0.01 rad, so the chord shortfall stays below 5 ppm.
constexpr double kArcSampleSpacing = 1.0;
constexpr double kArcSampleAngle = 0.01;

inline std::size_t arc_segment_count(double radius, double sweep) {
  double by_length = std::abs(sweep) * radius / kArcSampleSpacing;
  double by_angle = std::abs(sweep) / kArcSampleAngle;
  return std::max<std::size_t>(1,
                               static_cast<std::size_t>(std::ceil(std::max(by_length, by_angle))));
}

// The circle about `centre` from `start` to `end` (both on it), counter-clockwise when the sweep
// is positive. The end points are copied, not recomputed, so lanes that meet there meet exactly.
inline std::vector<MapPoint> arc_between(MapPoint start, MapPoint end, MapPoint centre,
                                         bool counter_clockwise) {
  double radius = distance(start, centre);
  double start_angle = std::atan2(start.y - centre.y, start.x - centre.x);
  double end_angle = std::atan2(end.y - centre.y, end.x - centre.x);
  double sweep = end_angle - start_angle;
  if (counter_clockwise && sweep <= 0) sweep += 2 * std::numbers::pi;
  if (!counter_clockwise && sweep >= 0) sweep -= 2 * std::numbers::pi;
  std::size_t segments = arc_segment_count(radius, sweep);
  std::vector<MapPoint> points{start};
  for (std::size_t i = 1; i < segments; ++i) {
    double angle = start_angle + sweep * static_cast<double>(i) / static_cast<double>(segments);
    points.push_back(centre + radius * unit_vector(angle));
  }
  points.push_back(end);
  return points;
}

// Appends a piece that starts where `line` ends, without repeating the shared point.
inline void append_continuation(std::vector<MapPoint>& line, const std::vector<MapPoint>& piece) {
  auto first = piece.begin();
  if (!line.empty() && first != piece.end()) ++first;
  line.insert(line.end(), first, piece.end());
}

// A road's reference line: from a start pose, straights and circular arcs one after the other.
struct PathPiece {
  double length = 0;  // a straight's length; unused for an arc
  double radius = 0;  // an arc's radius; 0 for a straight
  double sweep = 0;   // an arc's turn in radians, positive to the left
};

inline PathPiece straight_piece(double length) { return {length, 0, 0}; }
inline PathPiece arc_piece(double radius, double sweep) { return {0, radius, sweep}; }

// The line `lateral_offset` metres to the left (negative: right) of a reference path, in the
// path's direction. Offsetting an arc keeps its centre and changes its radius, so an offset
// line is again straights and arcs.
inline std::vector<MapPoint> offset_path(MapPose start, const std::vector<PathPiece>& pieces,
                                         double lateral_offset) {
  MapPoint position = start.position;
  double heading = start.heading;
  std::vector<MapPoint> points{position + lateral_offset * left_normal(unit_vector(heading))};
  for (const PathPiece& piece : pieces) {
    if (piece.radius == 0) {
      if (piece.length <= 0) continue;
      position = position + piece.length * unit_vector(heading);
      points.push_back(position + lateral_offset * left_normal(unit_vector(heading)));
      continue;
    }
    if (piece.sweep == 0) continue;
    double turn_side = piece.sweep > 0 ? 1 : -1;
    MapPoint centre = position + turn_side * piece.radius * left_normal(unit_vector(heading));
    double offset_radius = piece.radius - turn_side * lateral_offset;
    std::size_t segments = arc_segment_count(offset_radius, piece.sweep);
    for (std::size_t i = 1; i <= segments; ++i) {
      double turned =
          heading + piece.sweep * static_cast<double>(i) / static_cast<double>(segments);
      // The centre seen from the path, rotated with it: -turn_side * left normal.
      MapPoint on_path = centre - turn_side * piece.radius * left_normal(unit_vector(turned));
      points.push_back(on_path + lateral_offset * left_normal(unit_vector(turned)));
    }
    heading += piece.sweep;
    position = centre - turn_side * piece.radius * left_normal(unit_vector(heading));
  }
  return points;
}

// A connector from a straight line into a circular arc that ends at `end` with `end`'s heading:
// the straight part runs along the line through `line_point` with `line_heading` up to
// `tangent_point`, where an arc of `radius` about `centre` takes over. `line_point` only fixes
// the line; the straight part may begin before or after it.
struct LineArcFit {
  MapPoint tangent_point;
  MapPoint centre;
  double radius = 0;
  bool turns_left = false;
};

inline LineArcFit fit_line_then_arc(MapPoint line_point, double line_heading, MapPose end) {
  MapPoint line_direction = unit_vector(line_heading);
  MapPoint end_direction = unit_vector(end.heading);
  LineArcFit fit;
  fit.turns_left = cross(line_direction, end_direction) > 0;
  double side = fit.turns_left ? 1 : -1;
  // Normals towards the centre of the turn, at the line and at the end.
  MapPoint line_normal = side * left_normal(line_direction);
  MapPoint end_normal = side * left_normal(end_direction);
  // The centre lies `radius` from the end along its normal and `radius` from the line.
  fit.radius = dot(end.position - line_point, line_normal) / (1 - dot(end_normal, line_normal));
  fit.centre = end.position + fit.radius * end_normal;
  fit.tangent_point = fit.centre - fit.radius * line_normal;
  return fit;
}

inline double polygon_signed_area(const std::vector<MapPoint>& polygon) {
  double twice_area = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    twice_area += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return twice_area / 2;
}

// Outlines are stored counter-clockwise, whichever way a generator walked round them.
inline std::vector<MapPoint> counter_clockwise(std::vector<MapPoint> polygon) {
  if (polygon_signed_area(polygon) < 0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

// Boundary types of lane k of n lanes that drive one way side by side, k = 0 at the kerb.
inline BoundaryType right_boundary_of(int k) {
  return k == 0 ? BoundaryType::curb : BoundaryType::dotted_white;
}
inline BoundaryType left_boundary_of(int k, int lane_count, BoundaryType outermost) {
  return k == lane_count - 1 ? outermost : BoundaryType::dotted_white;
}

// Lane ids: prefix + k.
inline std::string lane_id(std::string_view prefix, int k) {
  return std::string(prefix) + std::to_string(k);
}

}  // namespace scenfuzz::builtin

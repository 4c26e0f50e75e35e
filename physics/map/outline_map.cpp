// describe_outline_map (outline_map.hpp): checks each road outline, makes the lanes of its two
// halves with their ids, neighbours and boundary types, then connects lanes whose ends meet.
#include "physics/map/outline_map.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "lang/number_format.hpp"
#include "physics/map/outline_half_road.hpp"
#include "physics/map/polyline.hpp"
#include "physics/map/road_map.hpp"

namespace scenfuzz {

namespace {

using outline::CentreSample;
using outline::HalfSide;

constexpr const char* kSource = "CH-Scenario road network";
// A boundary point this close to the wrong side of the centre line is drawing noise, not a
// crossing (a one-way road's left boundary is its centre line, drawn with other points).
constexpr double kSideTolerance = 0.01;
constexpr double kConnectionReach = 1.5;
constexpr double kConnectionAngle = 60 * std::numbers::pi / 180;

[[noreturn]] void fail(const std::string& road, const std::string& message) {
  throw MapError("road '" + road + "': " + message);
}

// Rounded to the centimetre: error messages name places, not bits.
std::string metres(double value) { return format_number(std::round(value * 100) / 100); }

std::string point_text(std::size_t index, MapPoint point) {
  return "point " + std::to_string(index + 1) + " (" + metres(point.x) + ", " + metres(point.y) +
         ")";
}

void check_points(const std::string& road, const char* line, const std::vector<MapPoint>& points) {
  if (points.size() < 2)
    fail(road, std::string("the ") + line + " needs at least two points, it has " +
                   std::to_string(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      fail(road, "point " + std::to_string(i + 1) + " of the " + line + " is not finite (" +
                     format_number(points[i].x) + ", " + format_number(points[i].y) + ")");
}

Polyline centre_polyline(const RoadOutlineGeometry& road) {
  try {
    return Polyline(road.centre_line);
  } catch (const std::invalid_argument&) {
    fail(road.name, "the centre line has zero length (all its points are at (" +
                        metres(road.centre_line[0].x) + ", " + metres(road.centre_line[0].y) +
                        "))");
  }
}

// Every point of a boundary on its own side of the centre line: `side` +1 left, -1 right.
void check_side(const std::string& road, const Polyline& centre, const char* line,
                const std::vector<MapPoint>& boundary, double side) {
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const double wrong_way = -side * outline::side_of_centre_line(centre, boundary[i]);
    if (wrong_way > kSideTolerance)
      fail(road, point_text(i, boundary[i]) + " of the " + line + " lies " + metres(wrong_way) +
                     " m " + (side > 0 ? "right" : "left") +
                     " of the centre line: the boundary crosses to the other side");
  }
}

std::string lane_id(const std::string& road, HalfSide side, int k) {
  return road + (side == HalfSide::right ? "_f" : "_b") + std::to_string(k);
}

HalfSide other(HalfSide side) { return side == HalfSide::right ? HalfSide::left : HalfSide::right; }

// The lanes of one half with their ids, neighbours and boundary types. `opposite_lanes` says
// whether the other half has lanes, across the centre line.
void add_half(std::vector<LaneDescription>& lanes, const std::string& road,
              const std::vector<CentreSample>& samples, const std::vector<double>& widths,
              HalfSide side, int lane_count, bool opposite_lanes) {
  for (int k = 0; k < lane_count; ++k) {
    LaneDescription lane = outline::half_lane(samples, widths, side, lane_count, k);
    lane.id = lane_id(road, side, k);
    if (k > 0) lane.left_forward_neighbours = {lane_id(road, side, k - 1)};
    if (k + 1 < lane_count) lane.right_forward_neighbours = {lane_id(road, side, k + 1)};
    if (k == 0 && opposite_lanes) lane.left_reverse_neighbours = {lane_id(road, other(side), 0)};
    const BoundaryType centre = opposite_lanes ? BoundaryType::dotted_yellow : BoundaryType::curb;
    lane.left_boundary_type = k == 0 ? centre : BoundaryType::dotted_white;
    lane.right_boundary_type =
        k + 1 == lane_count ? BoundaryType::curb : BoundaryType::dotted_white;
    lanes.push_back(std::move(lane));
  }
}

void add_road(std::vector<LaneDescription>& lanes, const RoadOutlineGeometry& road) {
  check_points(road.name, "left boundary", road.left_boundary);
  check_points(road.name, "centre line", road.centre_line);
  check_points(road.name, "right boundary", road.right_boundary);
  const Polyline centre = centre_polyline(road);
  check_side(road.name, centre, "left boundary", road.left_boundary, +1);
  check_side(road.name, centre, "right boundary", road.right_boundary, -1);

  const std::vector<CentreSample> samples = outline::sample_centre_line(centre);
  const std::vector<double> right = outline::half_widths(samples, road.right_boundary);
  const std::vector<double> left = outline::half_widths(samples, road.left_boundary);
  const int forward = outline::half_lane_count(samples, right);
  const int backward = outline::half_lane_count(samples, left);
  if (forward == 0 && backward == 0)
    fail(road.name, "the road has no lanes: both halves are narrower than " +
                        metres(outline::kMinimumHalfWidth) +
                        " m everywhere (the boundaries lie on the centre line?)");
  add_half(lanes, road.name, samples, right, HalfSide::right, forward, backward > 0);
  add_half(lanes, road.name, samples, left, HalfSide::left, backward, forward > 0);
}

// The heading of a line's first (or last) segment of positive length; none when it has none.
std::optional<double> end_heading(const std::vector<MapPoint>& points, bool at_start) {
  const std::size_t n = points.size();
  for (std::size_t step = 1; step < n; ++step) {
    const MapPoint a = at_start ? points[0] : points[n - 1 - step];
    const MapPoint b = at_start ? points[step] : points[n - 1];
    if (distance(a, b) > 1e-6) return std::atan2(b.y - a.y, b.x - a.x);
  }
  return std::nullopt;
}

bool continues_into(const LaneDescription& from, const LaneDescription& to) {
  if (distance(from.centre_line.back(), to.centre_line.front()) > kConnectionReach) return false;
  const std::optional<double> out = end_heading(from.centre_line, false);
  const std::optional<double> in = end_heading(to.centre_line, true);
  return out && in && std::abs(angle_difference(*in, *out)) < kConnectionAngle;
}

void connect_lanes(std::vector<LaneDescription>& lanes) {
  for (LaneDescription& from : lanes)
    for (LaneDescription& to : lanes)
      if (&from != &to && continues_into(from, to)) {
        from.successors.push_back(to.id);
        to.predecessors.push_back(from.id);
      }
}

void check_names(const std::string& map, const std::vector<RoadOutlineGeometry>& roads) {
  if (roads.empty()) throw MapError("map '" + map + "': the road network has no roads");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < roads.size(); ++i) {
    if (roads[i].name.empty())
      throw MapError("map '" + map + "': road " + std::to_string(i + 1) +
                     " of the road network has no name");
    if (!seen.insert(roads[i].name).second) fail(roads[i].name, "two roads have this name");
  }
}

}  // namespace

MapDescription describe_outline_map(std::string name,
                                    const std::vector<RoadOutlineGeometry>& roads) {
  check_names(name, roads);
  MapDescription map;
  map.name = std::move(name);
  map.source = kSource;
  map.default_lane_width = outline::kNominalLaneWidth;
  for (const RoadOutlineGeometry& road : roads) {
    const std::size_t first = map.lanes.size();
    add_road(map.lanes, road);
    for (std::size_t i = first; i < map.lanes.size(); ++i)
      map.lanes[i].speed_limit = road.speed_limit;
  }
  connect_lanes(map.lanes);
  return map;
}

}  // namespace scenfuzz

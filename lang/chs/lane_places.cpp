// Written points to lane places and back (lane_places.hpp).
#include "lang/chs/lane_places.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lang/chs/road_stations.hpp"

namespace scenfuzz::chs {

namespace {

// outline_map.hpp's sampling and lane rules (physics/map/outline_half_road.hpp).
constexpr double kSampleSpacing = 5.0;
constexpr double kMinimumHalfWidth = 1.0;
constexpr double kNominalLaneWidth = 3.5;

// Where a point lies against a centre line: the arc length of its nearest point, its offset to
// the left of the line, and whether it lies abreast of the line rather than before its start or
// beyond its end.
struct Projection {
  double s = 0, offset = 0;
  bool abreast = false;
};

Projection project(const std::vector<Point>& line, double x, double y) {
  Projection best;
  double nearest = std::numeric_limits<double>::infinity();
  double walked = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double ax = line[i - 1].x, ay = line[i - 1].y;
    const double dx = line[i].x - ax, dy = line[i].y - ay;
    const double length = std::hypot(dx, dy);
    if (length == 0) continue;
    const double along = ((x - ax) * dx + (y - ay) * dy) / length;
    const double t = std::clamp(along / length, 0.0, 1.0);
    const double distance = std::hypot(ax + t * dx - x, ay + t * dy - y);
    if (distance < nearest) {
      nearest = distance;
      const bool first = walked == 0, last = i + 1 == line.size();
      best.s = walked + t * length;
      best.offset = (dx * (y - ay) - dy * (x - ax)) / length;
      best.abreast = !(first && along < 0) && !(last && along > length);
    }
    walked += length;
  }
  return best;
}

const std::vector<Point>& boundary_of(const Road& road, bool forward) {
  return forward ? road.right_boundary : road.left_boundary;
}

// The half's width at arc length `s` of the centre line.
double half_width_at(const Road& road, bool forward, double s) {
  const Station station = station_at(road.centre_lines, s);
  return distance_to(boundary_of(road, forward), station.x, station.y);
}

// Arc lengths of the centre line's vertices and of points at most kSampleSpacing between them.
std::vector<double> sample_stations(const std::vector<Point>& line) {
  std::vector<double> stations{0};
  double walked = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double length = std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    if (length == 0) continue;
    const double pieces = std::max(1.0, std::ceil(length / kSampleSpacing));
    for (double j = 1; j <= pieces; ++j) stations.push_back(walked + length * j / pieces);
    walked += length;
  }
  return stations;
}

}  // namespace

int lane_count(const Road& road, bool forward) {
  const std::vector<double> stations = sample_stations(road.centre_lines);
  std::vector<double> widths;
  for (double s : stations) widths.push_back(half_width_at(road, forward, s));
  if (stations.size() < 2 || *std::max_element(widths.begin(), widths.end()) < kMinimumHalfWidth)
    return 0;
  double area = 0;
  for (std::size_t i = 0; i + 1 < stations.size(); ++i)
    area += (stations[i + 1] - stations[i]) * (widths[i] + widths[i + 1]) / 2;
  return std::max(1, static_cast<int>(std::lround(area / stations.back() / kNominalLaneWidth)));
}

std::string lane_id(const Road& road, bool forward, int lane) {
  return road.name.text + (forward ? "_f" : "_b") + std::to_string(lane);
}

std::optional<LanePlace> lane_place_at(const std::vector<Road>& roads, double x, double y) {
  std::optional<LanePlace> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Road& road : roads) {
    const Projection at = project(road.centre_lines, x, y);
    const bool forward = at.offset <= 0;
    const double width = half_width_at(road, forward, at.s);
    const int lanes = lane_count(road, forward);
    if (!at.abreast || lanes == 0 || std::abs(at.offset) > width || width <= 0) continue;
    if (std::abs(at.offset) >= nearest) continue;
    nearest = std::abs(at.offset);
    const double lane_width = width / lanes;
    const int k = std::clamp(static_cast<int>(std::abs(at.offset) / lane_width), 0, lanes - 1);
    const double centre = (k + 0.5) * lane_width;
    const double length = polyline_length(road.centre_lines);
    best = forward ? LanePlace{&road, true, k, at.s, at.offset + centre}
                   : LanePlace{&road, false, k, length - at.s, centre - at.offset};
  }
  return best;
}

PlanePoint point_of(const LanePlace& place) {
  const Road& road = *place.road;
  const double length = polyline_length(road.centre_lines);
  const double s = place.forward ? place.s : length - place.s;
  const double lanes = lane_count(road, place.forward);
  const double centre = (place.lane + 0.5) * half_width_at(road, place.forward, s) / lanes;
  const double offset = place.forward ? place.lateral - centre : centre - place.lateral;
  // Beyond either end the centre line goes on straight, as a vehicle mutated past it would.
  const Station station = station_at(road.centre_lines, std::clamp(s, 0.0, length));
  const double beyond = s - std::clamp(s, 0.0, length);
  const Station moved = {station.x + beyond * std::cos(station.heading),
                         station.y + beyond * std::sin(station.heading), station.heading};
  const Station point = offset_station(moved, offset);
  return {point.x, point.y};
}

}  // namespace scenfuzz::chs

// Centre-line stations of a CH-Scenario road (road_stations.hpp).
#include "lang/chs/road_stations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scenfuzz::chs {

double polyline_length(const std::vector<Point>& line) {
  double length = 0;
  for (std::size_t i = 1; i < line.size(); ++i)
    length += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
  return length;
}

Station station_at(const std::vector<Point>& line, double s) {
  double walked = 0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double dx = line[i].x - line[i - 1].x, dy = line[i].y - line[i - 1].y;
    const double length = std::hypot(dx, dy);
    if (length == 0) continue;
    const bool last = i + 1 == line.size();
    if (s <= walked + length || last) {
      const double t = std::clamp((s - walked) / length, 0.0, 1.0);
      return {line[i - 1].x + t * dx, line[i - 1].y + t * dy, std::atan2(dy, dx)};
    }
    walked += length;
  }
  return {line.front().x, line.front().y, 0};
}

double distance_to(const std::vector<Point>& line, double x, double y) {
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double ax = line[i - 1].x, ay = line[i - 1].y;
    const double dx = line[i].x - ax, dy = line[i].y - ay;
    const double squared = dx * dx + dy * dy;
    const double t =
        squared > 0 ? std::clamp(((x - ax) * dx + (y - ay) * dy) / squared, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, std::hypot(ax + t * dx - x, ay + t * dy - y));
  }
  return nearest;
}

Station offset_station(const Station& station, double offset) {
  return {station.x - offset * std::sin(station.heading),
          station.y + offset * std::cos(station.heading), station.heading};
}

}  // namespace scenfuzz::chs

// A seeded random walk for pedestrians. Draws come from std::mt19937_64 (whose output the
// standard fixes) through our own mapping to [0, 1), because std::uniform_real_distribution
// differs between standard libraries and walks must replay anywhere.
#include "physics/actors/random_walk.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

namespace scenfuzz {

namespace {

constexpr double kShortestLegTime = 2;  // s
constexpr double kLongestLegTime = 5;   // s
constexpr double kLargestTurn = std::numbers::pi / 3;
// Turning back towards the start leaves this much freedom, so that walks do not bounce
// through the start every time.
constexpr double kLargestTurnBackDeviation = std::numbers::pi / 6;
constexpr double kMaximumLegs = 1e6;

double uniform(std::mt19937_64& random, double lower, double upper) {
  double unit = static_cast<double>(random() >> 11) * 0x1.0p-53;  // [0, 1), 53 random bits
  return lower + unit * (upper - lower);
}

// How far from `from` along `heading` the circle of `radius` about `centre` is (from inside it).
double distance_to_circle(MapPoint from, double heading, MapPoint centre, double radius) {
  double qx = from.x - centre.x;
  double qy = from.y - centre.y;
  double along = qx * std::cos(heading) + qy * std::sin(heading);
  double outside = qx * qx + qy * qy - radius * radius;
  return -along + std::sqrt(std::max(0.0, along * along - outside));
}

}  // namespace

Polyline random_walk_path(MapPose start, double speed, double duration, double radius,
                          std::uint64_t seed) {
  if (!(speed > 0) || !(duration > 0) || !(radius > 0) || !std::isfinite(speed) ||
      !std::isfinite(duration) || !std::isfinite(radius))
    throw std::invalid_argument("random walk needs a positive speed, duration and radius");
  const double walk_length = speed * duration;
  // Every leg is at least the shortest leg or most of the radius (a leg cut at the disc's edge
  // still crosses most of it), which bounds how many legs the walk takes.
  double shortest_leg = std::min(speed * kShortestLegTime, 0.8 * radius);
  if (walk_length / shortest_leg > kMaximumLegs)
    throw std::invalid_argument("random walk too long for its radius");

  std::mt19937_64 random(seed);
  const MapPoint centre = start.position;
  std::vector<MapPoint> points{centre};
  MapPoint here = centre;
  double heading = start.heading;
  double walked = 0;
  bool first = true;
  while (walked < walk_length) {
    double leg = speed * uniform(random, kShortestLegTime, kLongestLegTime);
    if (!first) heading += uniform(random, -kLargestTurn, kLargestTurn);
    first = false;
    double room = distance_to_circle(here, heading, centre, radius);
    if (leg > room) {
      if (distance(here, centre) > 1e-9) {
        double back = std::atan2(centre.y - here.y, centre.x - here.x);
        heading = back + uniform(random, -kLargestTurnBackDeviation, kLargestTurnBackDeviation);
      }
      leg = std::min(leg, distance_to_circle(here, heading, centre, radius));
    }
    heading = angle_difference(heading, 0);
    here = {here.x + leg * std::cos(heading), here.y + leg * std::sin(heading)};
    points.push_back(here);
    walked += leg;
  }
  return Polyline(points);
}

}  // namespace scenfuzz

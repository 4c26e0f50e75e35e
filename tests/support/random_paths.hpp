// Random polylines for the path-search tests: uneven segments (0.2 m to 3 m) at UTM-like
// coordinates, the heading turning up to `max_turn` radians a vertex (enough, at 0.5, to turn
// back on itself now and then, so far stretches of path come near again).
#pragma once

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include "physics/map/polyline.hpp"

namespace scenfuzz::test {

inline Polyline random_path(std::mt19937_64& random, std::size_t points, double max_turn) {
  std::uniform_real_distribution<double> step(0.2, 3.0), turn(-max_turn, max_turn);
  std::vector<MapPoint> vertices{{552000.5, 4182000.25}};
  double heading = 0.3;
  for (std::size_t i = 1; i < points; ++i) {
    heading += turn(random);
    double length = step(random);
    vertices.push_back({vertices.back().x + length * std::cos(heading),
                        vertices.back().y + length * std::sin(heading)});
  }
  return Polyline(vertices);
}

}  // namespace scenfuzz::test

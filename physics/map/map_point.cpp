// Angle arithmetic shared by the map queries.
#include "physics/map/map_point.hpp"

#include <numbers>

namespace scenfuzz {

double angle_difference(double a, double b) {
  double difference = std::remainder(a - b, 2 * std::numbers::pi);
  if (difference <= -std::numbers::pi) difference += 2 * std::numbers::pi;
  return difference;
}

}  // namespace scenfuzz

// Angle arithmetic shared by the map queries.
#include "physics/map/map_point.hpp"

#include <numbers>

namespace scenfuzz {

// remainder is exact, and rounds the half turn at +-pi to the even quotient 0: the result is in
// [-pi, pi], and -pi is turned into pi.
double wrapped_difference(double raw) {
  double difference = std::remainder(raw, 2 * std::numbers::pi);
  if (difference <= -std::numbers::pi) difference += 2 * std::numbers::pi;
  return difference;
}

}  // namespace scenfuzz

// Angle arithmetic shared by the map queries.
#include "physics/map/map_point.hpp"

#include <numbers>

namespace scenfuzz {

double angle_difference(double a, double b) {
  // Already in (-pi, pi]: remainder would return it unchanged (it is exact, and rounds the half
  // turn at +-pi to the even quotient 0), so skip glibc's slow remainder. Every scripted actor's
  // heading goes through here at every step.
  const double raw = a - b;
  if (raw > -std::numbers::pi && raw <= std::numbers::pi) return raw;
  double difference = std::remainder(raw, 2 * std::numbers::pi);
  if (difference <= -std::numbers::pi) difference += 2 * std::numbers::pi;
  return difference;
}

}  // namespace scenfuzz

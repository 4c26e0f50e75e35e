// The stopping-distance arithmetic behind the reference driver's sight limit.
#include "physics/ego/sight_distance.hpp"

#include <algorithm>
#include <cmath>

#include "lang/demand.hpp"

namespace scenfuzz {

double stopping_distance(double speed, double reaction_time, double deceleration) {
  SCENFUZZ_DEMAND(deceleration > 0);
  return speed * reaction_time + speed * speed / (2 * deceleration);
}

double speed_to_stop_within(double distance, double reaction_time, double deceleration) {
  SCENFUZZ_DEMAND(deceleration > 0);
  if (!(distance > 0)) return 0;
  if (std::isinf(distance)) return distance;
  // v = b (-t + sqrt(t^2 + 2 d / b)), written to stay accurate when t is 0.
  const double bt = deceleration * reaction_time;
  return 2 * deceleration * distance / (bt + std::sqrt(bt * bt + 2 * deceleration * distance));
}

double sight_distance(const PerceptionSettings& sensing) {
  return std::min(sensing.vehicle_range, sensing.pedestrian_range);
}

double planned_deceleration(const PerceptionSettings& sensing, double max_deceleration,
                            const SightSettings& settings) {
  SCENFUZZ_DEMAND(max_deceleration > 0 && settings.clear_sight > 0);
  const double comfortable = std::min(settings.comfortable_deceleration, max_deceleration);
  const double fraction = std::clamp(sight_distance(sensing) / settings.clear_sight, 0.0, 1.0);
  return comfortable + (max_deceleration - comfortable) * fraction * fraction;
}

double sight_speed(const PerceptionSettings& sensing, double front_overhang,
                   double max_deceleration, const SightSettings& settings) {
  const double room =
      sight_distance(sensing) - front_overhang - settings.object_extent - settings.margin;
  const double deceleration = planned_deceleration(sensing, max_deceleration, settings);
  return std::max(settings.minimum_speed,
                  speed_to_stop_within(room, settings.reaction_time, deceleration));
}

}  // namespace scenfuzz

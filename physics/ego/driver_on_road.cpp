// The reference driver's settings on a slippery road (driver_on_road.hpp).
#include "physics/ego/driver_on_road.hpp"

#include "lang/demand.hpp"
#include "physics/actors/road_friction.hpp"

namespace scenfuzz {

DriverSettings on_road(const DriverSettings& settings, double friction) {
  SCENFUZZ_DEMAND(is_road_friction(friction));
  if (friction == kDryRoad) return settings;
  DriverSettings careful = settings;
  careful.comfortable_acceleration = settings.comfortable_acceleration * friction;
  careful.comfortable_deceleration = settings.comfortable_deceleration * friction;
  careful.lateral_acceleration = settings.lateral_acceleration * friction;
  careful.sight_braking = settings.sight_braking * friction;
  careful.sight.comfortable_deceleration = settings.sight.comfortable_deceleration * friction;
  careful.left_turn.acceleration = settings.left_turn.acceleration * friction;
  careful.overtaking.rear_braking = settings.overtaking.rear_braking * friction;
  careful.time_gap = settings.time_gap / friction;
  return careful;
}

}  // namespace scenfuzz

// A vehicle's limits on a road with less grip than dry asphalt's (road_friction.hpp).
#include "physics/actors/road_friction.hpp"

#include <cmath>

#include "lang/demand.hpp"

namespace scenfuzz {

bool is_road_friction(double friction) {
  return std::isfinite(friction) && friction > 0 && friction <= kDryRoad;
}

ActorClass on_road(const ActorClass& body, double friction) {
  SCENFUZZ_DEMAND(is_road_friction(friction));
  // A dry road leaves the body as it is (x * 1 is exact anyway; this says so).
  if (friction == kDryRoad || body.category == ActorCategory::pedestrian) return body;
  ActorClass slippery = body;
  slippery.max_acceleration = body.max_acceleration * friction;
  slippery.max_deceleration = body.max_deceleration * friction;
  slippery.comfortable_deceleration = body.comfortable_deceleration * friction;
  slippery.comfortable_lateral_acceleration = body.comfortable_lateral_acceleration * friction;
  return slippery;
}

}  // namespace scenfuzz

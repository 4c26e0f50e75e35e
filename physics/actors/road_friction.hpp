// A vehicle on a slippery road (CH-Scenario's icy, muddy, flooded or wet roads): its tyres grip a
// share of what they grip on dry asphalt, and every limit that grip bounds shrinks with it.
#pragma once

#include "physics/actors/actor_class.hpp"

namespace scenfuzz {

// The friction of dry asphalt, which the actor class table's limits are for.
inline constexpr double kDryRoad = 1;

// Whether `friction` is a road's grip as a share of dry asphalt's: finite and in (0, 1].
bool is_road_friction(double friction);

// `body` on a road with `friction` (is_road_friction, demanded): a vehicle's full braking and
// acceleration, and the braking and cornering a calm driver of it takes, scaled by it, so that
// each keeps its share of the grip (the friction circle, friction_circle.hpp, is full braking, so
// it follows). Top speed, jerk and steering are not the tyres' grip; pedestrians walk as before.
ActorClass on_road(const ActorClass& body, double friction);

}  // namespace scenfuzz

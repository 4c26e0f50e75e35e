// The most sideways acceleration an actor class can corner with: one rule shared by the trace
// audit (which flags more) and the scripted motion (which keeps below it).
#pragma once

#include "physics/actors/actor_class.hpp"

namespace scenfuzz {

// Tyres grip about as well sideways as when braking (the friction circle), so full braking is
// also the most a class can corner with (of a body on a slippery road, road_friction.hpp, that
// road's grip). Pedestrians have no steering and turn on the spot: 0.
inline double grip_lateral_acceleration(const ActorClass& actor_class) {
  return actor_class.category == ActorCategory::pedestrian ? 0 : actor_class.max_deceleration;
}

// The share of that grip a scripted actor that must keep to a script (the fuzzer's adversaries)
// may corner with. The margin covers how a trace samples a bend: a step's yaw rate is its mean
// over the step and its speed the one at the step's end.
inline constexpr double kScriptedGripShare = 0.9;

}  // namespace scenfuzz

// What vehicles do after an impact, when a run asks for it (SimulationOptions::after_impact): an
// accident is often a chain of collisions (CarSim's worked example: a truck hits a car, which
// then skids into a tree), so a reconstruction needs the bodies to move on from the first. The
// model is Newton's planar impact without friction, as accident reconstruction's impulse method
// first approximates it: the impulse acts along the normal of the face struck (the side face a
// front hit, else the victim's face), with a coefficient of restitution, so that what each body
// carried along that face it keeps (a car hit on its side by a truck is pushed sideways and keeps
// going forward). Then each slides to a standstill, decelerating at its full braking on the
// road's grip (its tyres scrub sideways), without spinning: its body keeps its heading while it
// moves along its velocity. A vehicle that hits a static obstacle stops there. Pedestrians are
// not in it: nothing in the accident formalism hits one.
#pragma once

#include <utility>

#include "physics/actors/actor_class.hpp"
#include "physics/actors/kinematics.hpp"
#include "physics/collision/body_side.hpp"
#include "physics/map/map_point.hpp"

namespace scenfuzz {

// The mass (kg) an impact weighs a road user with: a typical loaded one of its category.
double impact_mass(ActorCategory category);

// A vehicle's velocity (m/s, map frame) from its state: `speed` along its heading, backwards when
// reversing.
MapPoint velocity_of(const KinematicState& state);

// How much of the closing speed along the normal two vehicles keep apart after an impact: car
// crashes at tens of km/h rebound little (0.1 to 0.3 in crash tests).
inline constexpr double kRestitution = 0.2;

// The outward unit normal of a body's face, heading `heading` (rad).
MapPoint face_normal(double heading, BodySide side);

struct ImpactBody {
  MapPoint velocity;  // m/s, map frame
  double mass = 0;    // kg
};

// The velocities of a and b after an impact whose normal `normal` (unit) points from a into b.
// Bodies already parting along it are left as they were.
std::pair<MapPoint, MapPoint> impact_velocities(const ImpactBody& a, const ImpactBody& b,
                                                MapPoint normal);

// A sliding vehicle one step of `dt` on: it moves along `velocity`, whose magnitude falls by
// `deceleration` * dt to no less than 0; its heading stays. Returns the new state; `velocity` is
// updated in place. The state's speed is the velocity's magnitude, its acceleration the fall.
KinematicState slide_step(const KinematicState& state, MapPoint& velocity, double deceleration,
                          double dt);

}  // namespace scenfuzz

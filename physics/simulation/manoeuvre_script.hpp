// A WMG SDL actor's manoeuvre phases resolved for one run (docs/wmg-semantics.md, "Manoeuvre
// phases"): each MP_TYPE mapped onto a motion primitive, its arguments evaluated at the point of
// the search space, its reference actor and conditions resolved. ManoeuvreDriver runs it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/actors/kinematics.hpp"
#include "physics/map/road_map.hpp"
#include "physics/simulation/manoeuvre_trigger.hpp"

namespace scenfuzz {

enum class MotionPrimitive {
  keep_lane,    // Drive_*, Misc_*: keep the lane, change speed to `speed` over `duration`
  lane_change,  // LaneChangeLeft/Right_* (not a cut-in), *_CutOut: to a neighbour lane
  cut_in,       // *_CutIn: into the reference's lane, ending `gap` ahead of it
  stop,         // Stop: brake to a standstill over `duration`
  stopped,      // Stopped: stand still
  turn_left,    // TurnLeft_*: the left connector at the next junction
  turn_right,   // TurnRight_*
  collide,      // Collide_*: head for the reference actor
  // Reverse_*: backwards at `speed`, facing the way it did.
  reverse_towards,  // Reverse_Towards: along the lane; ends early within `gap` of the reference
  reverse_away,     // Reverse_Away: along the lane; ends early `gap` away from the reference
  reverse_cut_in,   // Reverse_CutIn: into the reference's lane, as Drive_CutIn picks it
  reverse_cut_out,  // Reverse_CutOut: out of the lane, as Drive_CutOut
  walk,             // Walk/Run/Slide_* (pedestrians): straight on along the heading
  walk_cross,       // Walk/Run/Slide_Cross: straight across the lane
  walk_towards,     // Walk/Run/Slide_Towards: towards the reference
  walk_away,        // Walk/Run/Slide_Away: away from the reference
  // Overtake: one lane to the left, into the left neighbour lane; on a road with one lane each
  // way, out onto the oncoming lane while still driving its own way (LaneChangeRight brings it
  // back).
  overtake,
};

// Which neighbour lane a lane change goes to.
enum class LaneSide { towards_reference, left, right, left_else_right };

struct PrimitiveChoice {
  MotionPrimitive primitive = MotionPrimitive::keep_lane;
  LaneSide side = LaneSide::towards_reference;
};

// The primitive an MP_TYPE names ("Drive_CutIn", "LaneChangeLeft_CutOut", "Stop", "Walk_Cross",
// "turn_left"; case and underscores do not matter); nullopt for an unknown word.
std::optional<PrimitiveChoice> motion_primitive_named(std::string_view manoeuvre);

// Whether the primitive drives backwards (Reverse_*).
bool reverses(MotionPrimitive primitive);

struct PhaseMotion {
  std::string manoeuvre;  // as written, for messages
  PrimitiveChoice choice;
  std::optional<double> speed;        // m/s
  std::optional<double> duration;     // s
  std::optional<double> gap;          // m, front bumper of the reference to this actor's rear
  std::uint32_t reference = 0;        // actor id; the ego when the phase names none
  std::vector<LaneIndex> road_lanes;  // the road a crossing crosses; empty: the nearest lane's
  std::optional<TriggerCondition> start_when;
  std::optional<TriggerCondition> continue_while;
};

struct ManoeuvreScript {
  KinematicState initial;
  std::vector<PhaseMotion> phases;
  // Driven along the script without looking, as scripted NPC behaviour asks (an accident
  // reconstruction: the truck that rear-ends a stopped car must not brake for it): no holding
  // back for the traffic ahead in a phase, and between and after phases the speed is kept
  // instead of following the traffic and the lights; only bends and dead ends still slow it.
  bool heedless = false;
  // Its phases stop at red lights too: a CH-Scenario vehicle's manoeuvres are what it does in
  // traffic, where a WMG SDL phase is a script against the ego that may run a red on purpose.
  bool heeds_lights = false;
};

}  // namespace scenfuzz

// What an actor is seen doing at one instant, in the words of WMG SDL's conditions
// (`[Ego] is [Going Ahead]`): read off its state relative to the lane it is on, so that it works
// for every actor alike, whether it follows a script, a manoeuvre phase or a driver.
#pragma once

#include <optional>
#include <string_view>

#include "physics/actors/kinematics.hpp"
#include "physics/simulation/lane_tracker.hpp"

namespace scenfuzz {

enum class ObservedManoeuvre {
  going_ahead,
  stopped,
  lane_change_left,
  lane_change_right,
  turn_left,
  turn_right,
  reverse,
};

// Below this speed an actor is Stopped.
inline constexpr double kStoppedSpeed = 0.1;  // m/s
// Above this sideways speed relative to its lane an actor is changing lane.
inline constexpr double kLaneChangeLateralSpeed = 0.3;  // m/s

// Stopped below kStoppedSpeed; Reverse while it moves backwards (KinematicState::reversing, on a
// lane or off every lane) or against its lane's direction (a heading opposed to the lane's);
// TurnLeft/TurnRight on a junction connector of that turn; LaneChangeLeft/Right while its
// velocity across its lane exceeds kLaneChangeLateralSpeed; else GoingAhead, also off every
// lane.
ObservedManoeuvre observe_manoeuvre(const RoadMap& map, const KinematicState& state, LaneFix lane);

// The manoeuvre a condition's word names: "GoingAhead", "Going Ahead", "going_ahead", ... (case,
// spaces and underscores do not matter); nullopt for an unknown word.
std::optional<ObservedManoeuvre> observed_manoeuvre_named(std::string_view word);

}  // namespace scenfuzz

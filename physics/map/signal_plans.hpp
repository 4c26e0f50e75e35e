// The fixed-time plan of a junction whose two directions take turns, shared by the built-in
// crossroads and the junctions of drawn road networks (outline_signals.hpp): the defaults
// (25 s green, 3 s yellow, 2 s all red) and the plan of each direction.
#pragma once

#include "physics/map/map_description.hpp"

namespace scenfuzz {

inline constexpr double kDefaultGreen = 25;
inline constexpr double kDefaultYellow = 3;
inline constexpr double kDefaultAllRed = 2;

// Green, yellow, then red while the other direction has its green and yellow plus an all-red gap
// after each. The second direction runs half a cycle behind the first.
inline SignalPlan two_direction_plan(double green, double yellow, double all_red,
                                     bool second_direction) {
  const double half_cycle = green + yellow + all_red;
  SignalPlan plan;
  plan.phases = {{SignalColour::green, green},
                 {SignalColour::yellow, yellow},
                 {SignalColour::red, half_cycle + all_red}};
  plan.offset = second_direction ? half_cycle : 0;
  return plan;
}

}  // namespace scenfuzz

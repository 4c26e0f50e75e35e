// Which vehicle an `overtake` overtakes (docs/accident.md, "The vehicles"). CarSim's overtake
// event names no vehicle, yet "overtakes" means passing the vehicle ahead: without one, the
// translation let the overtaker start anywhere, and a reconstruction could have it "overtake"
// from in front. The rule picks the vehicle ahead from what the description says, so that the
// translation can start the overtaker behind it and faster than it.
#pragma once

#include "lang/accident/scene_layout.hpp"
#include "lang/accident/syntax.hpp"

namespace scenfuzz::accident {

// Whether the vehicle's chain has an overtake.
bool overtakes(const Vehicle& vehicle);

// The vehicle the overtaker's overtake passes: among the other vehicles that start heading its
// way in its start lane (or in a lane nothing fixes) and do not overtake themselves, the one
// written nearest to it in the DYNAMIC part (the earlier one of two as near). Null when the
// vehicle does not overtake or no vehicle qualifies.
const Vehicle* overtaken_vehicle(const File& file, const SceneLayout& layout,
                                 const Vehicle& overtaker);

// The first vehicle written whose overtake passes `vehicle`; null when none does.
const Vehicle* overtaker_of(const File& file, const SceneLayout& layout, const Vehicle& vehicle);

}  // namespace scenfuzz::accident

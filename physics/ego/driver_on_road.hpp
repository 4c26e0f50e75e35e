// What the reference driver makes of a slippery road. It knows the road's friction, as a careful
// driver who sees ice or a wet road does: besides its vehicle's lower limits (road_friction.hpp),
// which already lower the speed it can stop from within its sight and its emergency braking, it
// plans every comfortable acceleration and braking with the same share of the grip and keeps a
// longer time gap, so that on ice it drives slower, brakes earlier and follows farther back.
#pragma once

#include "physics/ego/reference_driver.hpp"

namespace scenfuzz {

// `settings` for a road with `friction` (is_road_friction, demanded): its comfortable
// accelerations and decelerations (IDM's a and b, the bends', the sight limit's, the left turn's,
// and what an overtake may ask of a car behind) scaled by the friction, and its following time
// gap divided by it: the UK Highway Code (rules 126 and 230) asks for at least double the gap on
// wet roads and up to ten times on icy ones, about as the stopping distance grows. A dry road (1)
// leaves the settings as they are.
DriverSettings on_road(const DriverSettings& settings, double friction);

}  // namespace scenfuzz

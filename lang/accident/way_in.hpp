// Where a described vehicle comes in (docs/accident.md, "The vehicles"): the heading its
// INITDIRECTION or STARTSIGN gives, and the lane its chain or its collisions fix. The translation
// of its start, the rule for which vehicle an overtake overtakes (overtaken.hpp) and where a stop
// aims (stop_place.hpp) all read them, so they live apart from any one of those.
#pragma once

#include <optional>

#include "lang/accident/scene_layout.hpp"
#include "lang/accident/syntax.hpp"

namespace scenfuzz::accident {

// The place a STARTSIGN or ENDSIGN gives, in the description's frame: a point as written, a light
// or tree by its coordinates; none for a name that is neither (the checks have said so).
std::optional<PlanePoint> sign_place(const File& file, const SignReference& sign);

// The heading the vehicle starts with: its INITDIRECTION when the road has that way in, else the
// way in whose line passes nearest its STARTSIGN; none when neither says (translate_vehicles.cpp
// reports it).
std::optional<Direction> way_in_heading(const File& file, const SceneLayout& layout,
                                        const Vehicle& vehicle);

// The lane (0 at the kerb) the description fixes for the vehicle's start: the one its chain
// needs, else the one a vehicle heading its way changes into to collide with it. None when the
// road has two lanes each way and nothing says which.
std::optional<int> fixed_start_lane(const File& file, const Vehicle& vehicle, int lanes);

}  // namespace scenfuzz::accident

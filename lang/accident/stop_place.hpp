// Where a `stop` event aims (docs/accident.md, "The vehicles"). A report's "stopped at the red
// light" names the place: the vehicle's ENDSIGN. A scripted Stop brakes from where it begins, so
// the place is reached by choosing when the stop begins; that needs the distance from the
// vehicle's start to the sign along its way, which holds only while nothing before the stop
// changed the vehicle's way or speed. This file decides which stop aims, and where.
#pragma once

#include <cstddef>
#include <optional>

#include "lang/accident/scene_layout.hpp"
#include "lang/accident/syntax.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::accident {

struct StopAim {
  std::size_t event = 0;  // the stop's index in the chain (from 0)
  double along = 0;       // m from the way in's entry to the sign's place, along the way
};

// The stop of the chain that aims at the vehicle's ENDSIGN: the chain's first stop, when the
// vehicle has an ENDSIGN whose place lies beside its way in's line (within the carriageway and
// 5 m of roadside) and every event before the stop keeps the start speed and the way (a first
// `driving_forward`, lane changes). None otherwise; a warning, at the ENDSIGN or the stop, says
// why a stop that could have aimed does not.
std::optional<StopAim> stop_aim(const File& file, const SceneLayout& layout, const Vehicle& vehicle,
                                Direction heading, Diagnostics& diagnostics);

}  // namespace scenfuzz::accident

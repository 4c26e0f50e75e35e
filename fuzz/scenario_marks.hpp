// What `scenfuzz map FILE --svg` marks on a scenario's map, so that its author can see at once
// whether the file's scenery and actors came out where they meant them: every actor's body where
// the scenario starts it (named, with the sector it was placed in), the ego's target, and each
// WMG road's name on the arm or road it became.
#pragma once

#include <span>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "physics/map/map_svg.hpp"

namespace scenfuzz {

// The marks for `scenario` at `values` on `map`, which it built there. Actors are left out after
// an error in `diagnostics` (an actor that cannot be placed): the roads are still drawn.
std::vector<SvgMark> scenario_marks(const ScenarioTemplate& scenario,
                                    std::span<const double> values, const RoadMap& map,
                                    Diagnostics& diagnostics);

}  // namespace scenfuzz

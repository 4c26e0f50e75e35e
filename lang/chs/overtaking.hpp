// A CH-Scenario track's `overtake` as manoeuvre phases (docs/ch-scenario.md, "Entities"). The
// grammar says only that the vehicle overtakes, not whom or when, so the phases say it as a driver
// decides it, from what is around the vehicle while it drives: it pulls out (`Overtake`) when it
// is close behind a road user slower than its own speed and the lane on its left is clear, and
// comes back (`LaneChangeRight`) once the lane on its right is clear of what it passed and of
// anything it would have to overtake again. Both are conditions over the simulation's signals
// (lateral_offset, longitudinal_offset, relative_heading, speed of each other road user), so that
// no time has to be guessed and a concrete file needs no search parameter for them.
#pragma once

#include <string>
#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz::chs {

// The two phases of `overtaker`'s overtake at `speed` (m/s, what it drives at), among the other
// road users named `others` (the ego and the other vehicles and cyclists: what it may overtake,
// meet or have beside it; demanded not empty), located at its track.
std::vector<ManoeuvrePhase> overtake_phases(const std::string& overtaker, const Value& speed,
                                            const std::vector<std::string>& others,
                                            SourceLocation at);

}  // namespace scenfuzz::chs

// scenest's `PriorityNPCAhead` and `PriorityPedsAhead`: whether a vehicle or a pedestrian the ego
// must give way to is near. LawBreaker's areas around the ego (reference section 1.6), with its
// quirks Q8-Q10 fixed: heading differences wrap, each sample is judged on its own poses, and
// the areas lie on the side they are named for. Private to the oracle.
#pragma once

#include <span>
#include <vector>

#include "oracle/law_manoeuvre.hpp"
#include "physics/trace/trace.hpp"

namespace scenfuzz {

// 1 or 0 at every sample. `vehicle_ahead` is `NPCAhead`'s distance at every sample.
std::vector<double> priority_vehicle_ahead(const Trace& trace, const EgoManoeuvre& manoeuvre,
                                           std::span<const double> vehicle_ahead);
std::vector<double> priority_pedestrian_ahead(const Trace& trace, const EgoManoeuvre& manoeuvre);

}  // namespace scenfuzz

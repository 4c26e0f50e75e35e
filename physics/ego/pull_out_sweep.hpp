// The swept path of a pull-out round something standing: before the reference driver commits to
// an overtaking plan that starts close behind a standing object, it rolls its own control (pure
// pursuit onto the plan, comfortable acceleration) forward on the kinematic bicycle model and
// checks that its body keeps a margin from the object's box until it is past it. A driver who
// stopped a few metres behind a parked car pulls out at full lock at walking pace; one who
// cannot clear it that way does not start (docs/simulation.md, "Overtaking").
#pragma once

#include "physics/ego/overtaking.hpp"

namespace scenfuzz {

// Whether the ego, following `plan` from its state in `context`, keeps at least `margin` from
// `blocker` (a standing object) until its rear is past the blocker's front.
bool pull_out_clears(const OvertakeContext& context, const OvertakePlan& plan,
                     const Blocker& blocker, double margin);

}  // namespace scenfuzz

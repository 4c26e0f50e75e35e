// The swept path of a pull-out round something standing: before the reference driver commits to
// an overtaking plan that starts close behind a standing object, it rolls its own control (pure
// pursuit onto the plan, comfortable acceleration) forward on the kinematic bicycle model and
// checks that its body keeps a margin from the object's box until it is past it. A driver who
// stopped a few metres behind a parked car pulls out at full lock at walking pace; one who
// cannot clear it that way does not start (docs/simulation.md, "Overtaking").
#pragma once

#include "physics/ego/overtaking.hpp"

namespace scenfuzz {

// The least distance (m, negative: contact) the ego keeps from `blocker` (a standing object),
// following `plan` from its state in `context`, until its rear is `margin` past the blocker's
// front; minus infinity when it does not get past within 20 s.
double pull_out_clearance(const OvertakeContext& context, const OvertakePlan& plan,
                          const Blocker& blocker, double margin);

}  // namespace scenfuzz

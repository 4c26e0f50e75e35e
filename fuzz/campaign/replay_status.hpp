// The regression replay's verdict on a known failure mode: its status for this run, from its
// status before and what replaying it with several perception seeds found (docs/campaigns.md,
// "Regression replay and CI outputs").
#pragma once

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/campaign/replay_outcome.hpp"

namespace scenfuzz {

// Every seed failed the same way: still_failing, or regressed when it was fixed (a fix that no
// longer holds). No seed failed: fixed. Some did: flaky (whether the ego fails depends on the
// perception noise). Nothing was tried, or the replay met an error: `before`, unchanged, since
// nothing was learnt about the ego.
FailureModeStatus replay_status(FailureModeStatus before, const ReplayOutcome& outcome);

}  // namespace scenfuzz

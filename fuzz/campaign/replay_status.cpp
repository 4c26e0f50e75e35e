// The regression replay's status rule (replay_status.hpp).
#include "fuzz/campaign/replay_status.hpp"

#include "lang/demand.hpp"

namespace scenfuzz {

FailureModeStatus replay_status(FailureModeStatus before, const ReplayOutcome& outcome) {
  SCENFUZZ_DEMAND(outcome.failing >= 0 && outcome.failing <= outcome.tried);
  if (!outcome.error.empty() || outcome.tried == 0) return before;
  if (outcome.failing == 0) return FailureModeStatus::fixed;
  if (outcome.failing < outcome.tried) return FailureModeStatus::flaky;
  return before == FailureModeStatus::fixed ? FailureModeStatus::regressed
                                            : FailureModeStatus::still_failing;
}

}  // namespace scenfuzz

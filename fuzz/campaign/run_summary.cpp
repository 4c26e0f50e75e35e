// What a run learnt about each failure mode (run_summary.hpp).
#include "fuzz/campaign/run_summary.hpp"

namespace scenfuzz {

RunEvidence run_evidence(const RunSummary& summary, const RunFailureMode& mode) {
  if (mode.mode.last_seen_run == summary.run.id) return RunEvidence::found;
  if (!mode.replay) return RunEvidence::none;
  if (!mode.replay->error.empty() || mode.replay->tried == 0) return RunEvidence::replay_failed;
  return RunEvidence::replayed;
}

}  // namespace scenfuzz

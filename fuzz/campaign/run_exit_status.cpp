// The campaign run's exit status rule (run_exit_status.hpp).
#include "fuzz/campaign/run_exit_status.hpp"

#include "fuzz/cli.hpp"

namespace scenfuzz {

namespace {

bool learnt_in_run(const RunSummary& summary, const RunFailureMode& mode) {
  const RunEvidence evidence = run_evidence(summary, mode);
  return evidence == RunEvidence::found || evidence == RunEvidence::replayed;
}

std::string counted(std::size_t count, const std::string& one, const std::string& many) {
  return std::to_string(count) + " " + (count == 1 ? one : many);
}

}  // namespace

bool new_in_run(const RunSummary& summary, const RunFailureMode& mode) {
  return mode.mode.status == FailureModeStatus::new_mode &&
         mode.mode.first_seen_run == summary.run.id;
}

bool regressed_in_run(const RunSummary& summary, const RunFailureMode& mode) {
  return mode.mode.status == FailureModeStatus::regressed && learnt_in_run(summary, mode);
}

int run_exit_status(const RunSummary& summary) {
  for (const RunFailureMode& mode : summary.failure_modes)
    if (new_in_run(summary, mode) || regressed_in_run(summary, mode)) return kExitViolated;
  return kExitSuccess;
}

std::string run_exit_reason(const RunSummary& summary) {
  std::size_t added = 0, regressed = 0;
  for (const RunFailureMode& mode : summary.failure_modes) {
    if (new_in_run(summary, mode)) ++added;
    if (regressed_in_run(summary, mode)) ++regressed;
  }
  if (added == 0 && regressed == 0) return "0: no new failure mode and no regression";
  return "1: " + counted(added, "new failure mode", "new failure modes") + ", " +
         counted(regressed, "regression", "regressions");
}

}  // namespace scenfuzz

// A campaign run's exit status for CI: 1 when the run found a new failure mode or a regression,
// else 0 (errors, exit status 2, are the run loop's). Only what this run learnt counts: a mode
// whose status is older (its replay failed, or it was not replayed) does not.
#pragma once

#include <string>

#include "fuzz/campaign/run_summary.hpp"

namespace scenfuzz {

// First found by this run.
bool new_in_run(const RunSummary& summary, const RunFailureMode& mode);
// Fixed before, and failing again in this run (found by a search, or failing every replay seed).
bool regressed_in_run(const RunSummary& summary, const RunFailureMode& mode);

// kExitViolated (1) when any mode is new or regressed in this run, else kExitSuccess (0).
int run_exit_status(const RunSummary& summary);

// The exit status in words: "1: 2 new failure modes, 1 regression" or "0: no new failure mode
// and no regression".
std::string run_exit_reason(const RunSummary& summary);

}  // namespace scenfuzz

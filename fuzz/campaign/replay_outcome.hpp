// What replaying one known failure mode against the current ego says (the regression replay at
// the start of every campaign run): how many perception seeds were tried and how many of them
// still fail. The campaign run turns it into the mode's status (campaign_run.hpp); the replay
// itself lives in regression_replay.*.
#pragma once

#include <string>

namespace scenfuzz {

struct ReplayOutcome {
  int tried = 0;      // perception seeds replayed; 0: not replayed (the status stays)
  int failing = 0;    // of those, how many still fail the same way
  std::string error;  // why the mode could not be replayed (its file is gone, ...); empty if it was
};

}  // namespace scenfuzz

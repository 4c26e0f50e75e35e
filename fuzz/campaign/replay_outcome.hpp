// What replaying one known failure mode against the current ego found: with how many perception
// seeds it was simulated, and with how many it failed the same way again; an error (the scenario
// no longer reads, the map is missing) leaves its status unchanged.
#pragma once

#include <string>

namespace scenfuzz {

struct ReplayOutcome {
  int tried = 0;
  int failing = 0;
  std::string error;
};

}  // namespace scenfuzz

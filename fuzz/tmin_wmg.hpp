// The reduction behind `scenfuzz tmin` for a WMG SDL finding: the same steps as for AVUnit
// (fuzz/tmin.hpp), made on the finding's level-2 syntax tree (lang/wmg/reduce.hpp) so that the
// result prints as WMG SDL: remove actors (binary halves first, then one at a time; never the
// ego; an actor placed relative to a removed one goes with it), then manoeuvre phases; make the
// weather neutral and the time of day noon; round every number to as few significant digits as
// keep the failure; cut the duration to just after the failure. Each change is kept only while
// the predicate says the candidate still fails the same way.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/tmin.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz {

// What is replayed: the level-2 file and how long to simulate it.
struct WmgTminCandidate {
  wmg::Level2File file;
  std::optional<double> duration;  // s, the replay's --duration; none: the scenario's own
};

using WmgTminPredicate = std::function<TminCheck(const WmgTminCandidate&)>;

struct WmgTminReduction {
  WmgTminCandidate result;
  std::vector<std::string> changes;  // what was removed or changed, in order, one line each
  std::size_t actors_removed = 0, phases_removed = 0, numbers_rounded = 0;
  std::size_t digits_before = 0, digits_after = 0;  // significant digits of the file's numbers
  std::size_t checks = 0;                           // predicate calls
};

// Reduces `start`, which fails as `start_check` says (same_failure must be true).
WmgTminReduction reduce_failing_wmg(WmgTminCandidate start, const TminCheck& start_check,
                                    const WmgTminPredicate& still_fails);

}  // namespace scenfuzz

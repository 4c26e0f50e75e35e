// The reduction behind `scenfuzz tmin`: a failing concrete scenario made smaller while a
// predicate says it still fails the same way (the same failure-mode signature). Steps, in order,
// each change kept only while the failure persists: remove actors (binary halves first, then one
// at a time; never the ego), then each actor's waypoints, then obstacles; clear the weather and
// set the time of day to noon; round every number to as few significant digits as keep the
// failure; cut the duration to just after the failure. Deterministic: the same predicate answers
// give the same reduction. The predicate knows nothing of files, so tests use fake ones.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lang/scenario.hpp"

namespace scenfuzz {

// What is replayed: the scenario and how long to simulate it.
struct TminCandidate {
  ScenarioTemplate scenario;
  std::optional<double> duration;  // s, the replay's --duration; none: the scenario's own
};

// What a replay of a candidate said.
struct TminCheck {
  bool same_failure = false;
  double failure_time = std::numeric_limits<double>::quiet_NaN();  // s; NaN: unknown
  double end_time = std::numeric_limits<double>::quiet_NaN();      // s, when the run ended
};

using TminPredicate = std::function<TminCheck(const TminCandidate&)>;

inline constexpr double kNoonSeconds = 12 * 3600;
// How long a cut run goes on after the failure, before rounding up to a whole second.
inline constexpr double kDurationMargin = 1;

struct TminReduction {
  TminCandidate result;
  std::vector<std::string> changes;  // what was removed or changed, in order, one line each
  std::size_t actors_removed = 0, waypoints_removed = 0, obstacles_removed = 0;
  std::size_t numbers_rounded = 0;
  std::size_t digits_before = 0, digits_after = 0;  // significant digits of the scenario's numbers
  std::size_t checks = 0;                           // predicate calls
};

// The state of a reduction in progress, for any language's candidates: the reduction so far, the
// predicate, and the last replay of the current result. `Reduction` has `result` (a `Candidate`)
// and `checks`.
template <typename Reduction, typename Candidate>
struct TminReducer {
  Reduction& reduction;
  const std::function<TminCheck(const Candidate&)>& still_fails;
  TminCheck check;  // the last replay of reduction.result

  // Replays `candidate` and adopts it when it still fails the same way.
  bool adopt_if_failing(Candidate candidate) {
    ++reduction.checks;
    const TminCheck replay = still_fails(candidate);
    if (!replay.same_failure) return false;
    reduction.result = std::move(candidate);
    check = replay;
    return true;
  }
};

// Reduces `start`, which fails as `start_check` says (same_failure must be true).
TminReduction reduce_failing_scenario(TminCandidate start, const TminCheck& start_check,
                                      const TminPredicate& still_fails);

// Which of `count` items to keep, as ddmin's complement step: remove the first half, the second
// half, then quarters, ..., then single items, each removal kept when `fails_with(kept)` (true
// for the items kept) says the candidate still fails. Never calls it with nothing removed.
std::vector<bool> reduce_list(std::size_t count,
                              const std::function<bool(const std::vector<bool>&)>& fails_with);

// Each of `numbers` rounded to the fewest significant digits that keep the failure, found by
// bisection (the failure is assumed to persist from some number of digits on); a rounding is kept
// when `fails_with(trial)` says the candidate with those numbers still fails. Returns how many
// numbers were rounded.
std::size_t round_each(std::vector<double>& numbers,
                       const std::function<bool(const std::vector<double>&)>& fails_with);

// The significant digits of all `numbers` together.
std::size_t total_digits(const std::vector<double>& numbers);

// Where a run that fails as `check` says is cut: kDurationMargin past the failure, rounded up to a
// whole second; none when either time is unknown or the cut would not be shorter.
std::optional<double> cut_duration(const TminCheck& check);

// The constant numbers of a template's scenario (its specs, events and end conditions apart: they
// say what the failure is; the time of day apart: seconds since midnight do not round to
// readable times), in a fixed walk order, and setting them back in that order.
std::vector<double> scenario_numbers(const ScenarioTemplate& scenario);
void set_scenario_numbers(ScenarioTemplate& scenario, const std::vector<double>& numbers);

}  // namespace scenfuzz

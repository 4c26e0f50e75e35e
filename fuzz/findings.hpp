// Findings: the evaluations with a negative robustness, and those in which the ego under test
// crashed, hung or returned an error, one per failure mode (oracle/failure_mode.hpp), numbered
// in the order their modes first appear (so the same seed numbers them the same way for any
// thread count). A mode's finding is its most violating evaluation, ties to the earliest; the
// others of the mode are counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/search.hpp"

namespace scenfuzz {

struct Finding {
  std::size_t number = 0;  // 1, 2, ...
  // A spec violation: the earliest violated objective; an ego failure: kNoObjective.
  std::size_t objective = 0;
  std::vector<std::size_t> violated;  // every violated objective, the earliest first
  std::string objective_name;         // the spec, or the ego failure's kind ("ego_crash")
  double robustness = 0;              // of `objective`; an ego failure: NaN
  std::size_t evaluation = 0;
  std::uint64_t seed = 0;
  UnitPoint point;
  std::string mode;     // the failure mode's key
  std::string failure;  // an ego failure: what happened
  // "stuck" when the spec was violated only because the run ended while the ego had stopped
  // making progress (oracle/judge.hpp); empty when the trace decided it.
  std::string ending;
  // The ego's first collision: whose fault and why; empty without one.
  std::string responsibility;
  std::string collision_reason;
  std::size_t count = 1;  // evaluations of this mode so far, this one included

  bool ego_failure() const { return objective == kNoObjective; }
  static constexpr std::size_t kNoObjective = static_cast<std::size_t>(-1);
};

// What one evaluation changed: a new mode's finding, or a known mode's with a more violating
// representative (`replaced`: its files are written again under the same number).
struct FindingUpdate {
  Finding finding;
  bool replaced = false;
};

class FindingLog {
 public:
  explicit FindingLog(std::vector<std::string> objectives);

  // The finding `record` makes or improves; nullopt when it violates nothing or repeats a known
  // mode without violating it more (it is counted).
  std::optional<FindingUpdate> add(const EvaluationRecord& record);

  const std::vector<Finding>& findings() const { return findings_; }
  // Evaluations that repeated a known mode.
  std::size_t duplicates() const { return duplicates_; }

 private:
  Finding make_finding(const EvaluationRecord& record, std::vector<std::size_t> violated) const;

  std::vector<std::string> objectives_;
  std::vector<Finding> findings_;
  std::map<std::string, std::size_t> by_mode_;  // mode key -> index into findings_
  std::size_t duplicates_ = 0;
};

}  // namespace scenfuzz

// Findings: the evaluations with a negative robustness, and those in which the ego under test
// crashed, hung or returned an error, de-duplicated and numbered in evaluation order (so the same
// seed numbers them the same way for any thread count).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/search.hpp"

namespace scenfuzz {

struct Finding {
  std::size_t number = 0;  // 1, 2, ...
  // A spec violation: the objective violated; an ego failure: kNoObjective.
  std::size_t objective = 0;
  std::string objective_name;  // the spec, or the ego failure's kind ("ego_crash")
  double robustness = 0;       // an ego failure: NaN
  std::size_t evaluation = 0;
  std::uint64_t seed = 0;
  UnitPoint point;
  std::string signature;
  std::string failure;  // an ego failure: what happened
  // "stuck" when the spec was violated only because the run ended while the ego had stopped
  // making progress (oracle/judge.hpp); empty when the trace decided it.
  std::string ending;

  bool ego_failure() const { return objective == kNoObjective; }
  static constexpr std::size_t kNoObjective = static_cast<std::size_t>(-1);
};

// Which evaluations are new findings. A violated objective is a duplicate of an earlier finding
// of the same objective when their points lie within `distance` of each other (Euclidean in the
// unit cube, divided by the square root of the dimension count, so the threshold means the same
// whatever the dimension), or when both carry the same non-empty signature (the same colliding
// pair and sides). An ego failure is a duplicate of an earlier one of the same kind and signal.
class FindingLog {
 public:
  FindingLog(std::vector<std::string> objectives, double distance = 0.05);

  // The new findings `record` makes: one per objective it violates that is not a duplicate, or
  // its ego failure when it is new.
  std::vector<Finding> add(const EvaluationRecord& record);

  const std::vector<Finding>& findings() const { return findings_; }
  std::size_t duplicates() const { return duplicates_; }

 private:
  bool is_duplicate(std::size_t objective, const EvaluationRecord& record) const;
  Finding make_finding(std::size_t objective, const EvaluationRecord& record) const;

  std::vector<std::string> objectives_;
  double distance_;
  std::vector<Finding> findings_;
  std::size_t duplicates_ = 0;
};

}  // namespace scenfuzz

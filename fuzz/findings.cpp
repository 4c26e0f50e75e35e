// One finding per failure mode, its most violating evaluation kept (findings.hpp).
#include "fuzz/findings.hpp"

#include <cmath>

namespace scenfuzz {

namespace {

// The violated objectives, the earliest first as the evaluator ordered them, else (an evaluator
// that orders none) in objective order.
std::vector<std::size_t> violated_objectives(const Evaluation& evaluation) {
  if (!evaluation.violated.empty()) return evaluation.violated;
  std::vector<std::size_t> violated;
  for (std::size_t k = 0; k < evaluation.robustness.size(); ++k)
    if (evaluation.robustness[k] < 0) violated.push_back(k);
  return violated;
}

}  // namespace

FindingLog::FindingLog(std::vector<std::string> objectives) : objectives_(std::move(objectives)) {}

Finding FindingLog::make_finding(const EvaluationRecord& record,
                                 std::vector<std::size_t> violated) const {
  const Evaluation& evaluation = record.evaluation;
  Finding finding;
  finding.evaluation = record.index;
  finding.seed = record.seed;
  finding.point = record.point;
  finding.mode = evaluation.signature;
  finding.responsibility = evaluation.responsibility;
  finding.collision_reason = evaluation.collision_reason;
  if (!evaluation.failure_kind.empty()) {
    finding.objective = Finding::kNoObjective;
    finding.objective_name = evaluation.failure_kind;
    finding.robustness = std::nan("");
    finding.failure = evaluation.failure;
    if (finding.mode.empty()) finding.mode = evaluation.failure_kind;
    return finding;
  }
  finding.violated = std::move(violated);
  finding.objective = finding.violated.front();
  finding.objective_name = objectives_[finding.objective];
  finding.robustness = evaluation.robustness[finding.objective];
  if (finding.objective < evaluation.endings.size())
    finding.ending = evaluation.endings[finding.objective];
  // An evaluator that names no modes: one finding per first violated objective.
  if (finding.mode.empty()) finding.mode = finding.objective_name;
  return finding;
}

std::optional<FindingUpdate> FindingLog::add(const EvaluationRecord& record) {
  const Evaluation& evaluation = record.evaluation;
  std::vector<std::size_t> violated;
  if (evaluation.failure_kind.empty()) {
    if (!evaluation.judged()) return std::nullopt;
    violated = violated_objectives(evaluation);
    if (violated.empty()) return std::nullopt;
  }
  Finding finding = make_finding(record, std::move(violated));
  const auto known = by_mode_.find(finding.mode);
  if (known == by_mode_.end()) {
    finding.number = findings_.size() + 1;
    by_mode_.emplace(finding.mode, findings_.size());
    findings_.push_back(finding);
    return FindingUpdate{std::move(finding), false};
  }
  ++duplicates_;
  Finding& kept = findings_[known->second];
  ++kept.count;
  // Ego failures have no measure of more or less: the first stays.
  if (finding.ego_failure() || !(finding.robustness < kept.robustness)) return std::nullopt;
  finding.number = kept.number;
  finding.count = kept.count;
  kept = finding;
  return FindingUpdate{std::move(finding), true};
}

}  // namespace scenfuzz

#include "fuzz/findings.hpp"

#include <cmath>

namespace scenfuzz {

namespace {

double normalised_distance(const UnitPoint& a, const UnitPoint& b) {
  if (a.empty()) return 0;
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

}  // namespace

FindingLog::FindingLog(std::vector<std::string> objectives, double distance)
    : objectives_(std::move(objectives)), distance_(distance) {}

bool FindingLog::is_duplicate(std::size_t objective, const EvaluationRecord& record) const {
  const std::string& signature = record.evaluation.signature;
  for (const Finding& finding : findings_) {
    if (finding.objective != objective) continue;
    if (!signature.empty() && finding.signature == signature) return true;
    if (objective != Finding::kNoObjective &&
        normalised_distance(finding.point, record.point) < distance_)
      return true;
  }
  return false;
}

Finding FindingLog::make_finding(std::size_t objective, const EvaluationRecord& record) const {
  Finding finding;
  finding.number = findings_.size() + 1;
  finding.objective = objective;
  finding.evaluation = record.index;
  finding.seed = record.seed;
  finding.point = record.point;
  finding.signature = record.evaluation.signature;
  if (objective == Finding::kNoObjective) {
    finding.objective_name = record.evaluation.failure_kind;
    finding.robustness = std::nan("");
    finding.failure = record.evaluation.failure;
  } else {
    finding.objective_name = objectives_[objective];
    finding.robustness = record.evaluation.robustness[objective];
    if (objective < record.evaluation.endings.size())
      finding.ending = record.evaluation.endings[objective];
  }
  return finding;
}

std::vector<Finding> FindingLog::add(const EvaluationRecord& record) {
  std::vector<std::size_t> violated;
  if (!record.evaluation.failure_kind.empty()) violated.push_back(Finding::kNoObjective);
  if (record.evaluation.judged())
    for (std::size_t k = 0; k < record.evaluation.robustness.size(); ++k)
      if (record.evaluation.robustness[k] < 0) violated.push_back(k);
  std::vector<Finding> added;
  for (std::size_t objective : violated) {
    if (is_duplicate(objective, record)) {
      ++duplicates_;
      continue;
    }
    findings_.push_back(make_finding(objective, record));
    added.push_back(findings_.back());
  }
  return added;
}

}  // namespace scenfuzz

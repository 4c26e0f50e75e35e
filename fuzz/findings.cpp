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
    if (normalised_distance(finding.point, record.point) < distance_) return true;
  }
  return false;
}

std::vector<Finding> FindingLog::add(const EvaluationRecord& record) {
  std::vector<Finding> added;
  if (!record.evaluation.judged()) return added;
  for (std::size_t objective = 0; objective < record.evaluation.robustness.size(); ++objective) {
    const double robustness = record.evaluation.robustness[objective];
    if (!(robustness < 0)) continue;
    if (is_duplicate(objective, record)) {
      ++duplicates_;
      continue;
    }
    Finding finding;
    finding.number = findings_.size() + 1;
    finding.objective = objective;
    finding.objective_name = objectives_[objective];
    finding.robustness = robustness;
    finding.evaluation = record.index;
    finding.seed = record.seed;
    finding.point = record.point;
    finding.signature = record.evaluation.signature;
    findings_.push_back(finding);
    added.push_back(std::move(finding));
  }
  return added;
}

}  // namespace scenfuzz

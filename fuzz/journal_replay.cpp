#include "fuzz/journal_replay.hpp"

#include <algorithm>
#include <string>

namespace scenfuzz {

JournalReplay::JournalReplay(const Evaluator& inner, std::vector<EvaluationRecord> journal)
    : inner_(inner), journal_(std::move(journal)) {
  for (std::size_t i = 0; i < journal_.size(); ++i) by_seed_.emplace(journal_[i].seed, i);
}

Evaluation JournalReplay::evaluate(std::span<const double> unit_point, std::uint64_t seed) const {
  const auto found = by_seed_.find(seed);
  if (found == by_seed_.end()) return inner_.evaluate(unit_point, seed);
  const EvaluationRecord& record = journal_[found->second];
  if (!std::equal(unit_point.begin(), unit_point.end(), record.point.begin(), record.point.end()))
    throw JournalMismatch("evaluation " + std::to_string(record.index) +
                          " of the journal was at another point than the search now proposes");
  return record.evaluation;
}

}  // namespace scenfuzz

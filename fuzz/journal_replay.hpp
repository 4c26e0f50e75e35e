// An evaluator that answers from a journal (evaluations.csv of a killed search) and simulates
// only what the journal does not hold: replaying the search's own loop over it restores every
// strategy to the state it had, since strategies are deterministic in what they are told
// (--resume; as libFuzzer's merge resumes from its control file).
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "fuzz/evaluator.hpp"
#include "fuzz/search.hpp"

namespace scenfuzz {

// The journal disagrees with the search replayed over it: another scenario, other options or
// another version of scenfuzz wrote it.
class JournalMismatch : public std::runtime_error {
 public:
  using runtime_error::runtime_error;
};

class JournalReplay : public Evaluator {
 public:
  // `inner` must outlive the replay.
  JournalReplay(const Evaluator& inner, std::vector<EvaluationRecord> journal);

  std::vector<SearchDimension> dimensions() const override { return inner_.dimensions(); }
  std::vector<std::string> objectives() const override { return inner_.objectives(); }
  std::optional<std::vector<double>> start_point() const override { return inner_.start_point(); }
  std::vector<SubTarget> sub_targets() const override { return inner_.sub_targets(); }
  // The journalled evaluation for `seed`, or a new one. Throws JournalMismatch when the journal
  // has `seed` at another point.
  Evaluation evaluate(std::span<const double> unit_point, std::uint64_t seed) const override;

  // Whether evaluation `index` comes from the journal (the journal is a prefix of the search).
  bool replayed(std::size_t index) const { return index < journal_.size(); }

 private:
  const Evaluator& inner_;
  std::vector<EvaluationRecord> journal_;
  std::unordered_map<std::uint64_t, std::size_t> by_seed_;
};

}  // namespace scenfuzz

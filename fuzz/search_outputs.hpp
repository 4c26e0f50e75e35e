// What a search writes into its output folder, each file atomically (temporary file, then
// rename): findings/NNN-<spec>.<ext> with their trace and picture, evaluations.csv and
// summary.json, rewritten as the search goes on.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"

namespace scenfuzz {

class SearchOutputs {
 public:
  // All arguments must outlive the object.
  SearchOutputs(const FuzzCommandOptions& options, const SourceFile& file,
                const ScenarioTemplate& scenario, const ScenarioEvaluator& evaluator);

  // Creates the folders and an empty evaluations.csv; an error message when it cannot.
  std::string prepare();

  // Adds an evaluation's row to evaluations.csv (written at the next flush) and its robustness
  // to the best so far.
  void record(const EvaluationRecord& record);

  // Writes `finding` (simulating its point again, which gives the same run) and returns the
  // path of its scenario file; a problem (a write failure, a replay that differs) goes into
  // `failure`.
  std::string write_finding(const Finding& finding, std::string& failure);

  nlohmann::json summary(const SearchSummary& search, const FindingLog& log, bool complete) const;

  // Rewrites evaluations.csv and summary.json; an error message when it cannot.
  std::string flush(const SearchSummary& search, const FindingLog& log, bool complete);

  // The lowest robustness seen per objective (empty before the first judged evaluation).
  const std::vector<double>& best() const { return best_; }

 private:
  const FuzzCommandOptions& options_;
  const SourceFile& file_;
  const ScenarioTemplate& scenario_;
  const ScenarioEvaluator& evaluator_;
  std::filesystem::path dir_;
  std::vector<std::string> objectives_;
  std::string header_;
  std::string rows_;
  std::vector<double> best_;
  std::vector<std::string> written_;
};

// "001", "012", "1234": finding numbers in file names.
std::string finding_number_text(std::size_t number);

}  // namespace scenfuzz

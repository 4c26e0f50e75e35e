// What a search writes into its output folder, so that what is on disk is consistent at every
// moment, even after kill -9: search.json (what is searched, once), evaluations.csv (the
// journal, appended batch by batch), findings/NNN-<name>.<ext> with their trace and picture (the
// scenario file last, so that its presence means the finding is whole), and summary.json
// (rewritten atomically after a batch with a new finding or a second after the last time, the
// journal flushed to disk first, and once more when the search ends).
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_journal.hpp"

namespace scenfuzz {

// The judged simulations in which the ego collided, by whose fault its first collision was
// (oracle/responsibility.hpp), and the first few not its fault.
inline constexpr std::size_t kListedOtherCollisions = 10;

struct CollisionCounts {
  std::size_t ego = 0, shared = 0, other = 0;
  // Without specs and --all-collisions, those not the ego's fault are not findings.
  bool not_counted = false;
  std::vector<std::pair<std::size_t, std::string>> first_others;  // evaluation, reason
};

class SearchOutputs {
 public:
  // All arguments must outlive the object.
  SearchOutputs(const FuzzCommandOptions& options, const SourceFile& file,
                const ScenarioTemplate& scenario, const ScenarioEvaluator& evaluator);

  // A new search: creates findings/ and writes search.json and the journal's header. An error
  // message naming the file when it cannot.
  std::string start();

  // Resuming: checks search.json against this search and reads the journal (dropping a row cut
  // short). An error message when there is nothing to resume or it belongs to another search.
  std::string resume(std::vector<EvaluationRecord>& journal);

  // Takes an evaluation: its row joins the next batch (unless it is `replayed` from the
  // journal), its robustness the best so far.
  void record(const EvaluationRecord& record, bool replayed);

  // Writes `finding`'s files (simulating its point again, which gives the same run) unless a
  // resumed search finds them in place already. Returns its scenario file's path; a problem (a
  // write failure, a replay that differs) goes into `failure` (`fatal` when a file could not be
  // written).
  std::string write_finding(const Finding& finding, std::string& failure, bool& fatal);

  // Appends the batch's rows to the journal, then rewrites summary.json when it is due. An error
  // message naming the file when it cannot.
  std::string end_batch(const SearchSummary& search, const FindingLog& log);

  // The final summary.json; `error` (a failed write) is recorded as the reason of stop "error".
  std::string finish(const SearchSummary& search, const FindingLog& log, const std::string& error);

  nlohmann::json summary(const SearchSummary& search, const FindingLog& log, bool complete,
                         const std::string& error = "") const;

  // --tmin's outcome for a finding: its minimised file, or why there is none. summary.json
  // lists it with the finding once rewrite_summary (or a later summary) writes it.
  void set_minimised(std::size_t number, const std::string& file, const std::string& reason);
  // The final summary.json written again, with what came after the search (--tmin).
  std::string rewrite_summary(const SearchSummary& search, const FindingLog& log);

  // The lowest robustness seen per objective (empty before the first judged evaluation).
  const std::vector<double>& best() const { return best_; }
  // Simulations whose trace audit found something, and the issues by AuditKind over the search.
  std::size_t audited_with_issues() const { return audited_with_issues_; }
  const std::vector<std::size_t>& audit_totals() const { return audit_totals_; }
  // Per objective: evaluations whose verdict was a time-out (not violations).
  const std::vector<std::size_t>& time_outs() const { return time_outs_; }
  // Per objective: evaluations whose verdict was start-state (not violations either).
  const std::vector<std::size_t>& start_states() const { return start_states_; }
  // Per objective: evaluations whose verdict was other-fault (not violations either).
  const std::vector<std::size_t>& other_faults() const { return other_faults_; }
  const CollisionCounts& collisions() const { return collisions_; }
  // The behaviour-coverage features of every evaluation so far (replayed ones included), as
  // summary.json's "coverage" reports them.
  const std::set<std::string>& coverage() const { return coverage_; }
  // The law specs' sub-violation coverage as the end-of-search text gives it (empty without law
  // specs); summary.json's "law_coverage" says the same.
  std::string law_coverage_lines() const;

  // Once the first design (EvaluationRecord::first_design) is over, or with `search_over`: a
  // warning for every spec violated at more than half of its judged points, naming the rate and
  // the responsible atom at the first of them (simulated again); empty after the first call
  // that had them, and before the design is over.
  std::vector<std::string> take_design_warnings(bool search_over);

  // Whether `finding`'s files could not be written (the search then stops): it is left out of
  // the summary, and a resumed search writes it.
  bool lost(const Finding& finding) const { return lost_.count(finding.number) > 0; }
  // Why no evaluation could be judged, with counts and the first reasons ("" once one was).
  std::string why_nothing_judged(const SearchSummary& search) const;

 private:
  std::filesystem::path finding_path(const Finding& finding, const std::string& extension) const;
  std::string write_summary(const SearchSummary& search, const FindingLog& log, bool complete,
                            const std::string& error);
  std::string finding_header(const Finding& finding, const ScenarioRun& run,
                             const std::filesystem::path& scenario_path) const;
  void record_collision(const Evaluation& evaluation, std::size_t index);
  std::string also_violated_lines(const Finding& finding, const ScenarioRun& run,
                                  const std::string& comment) const;
  void record_design(const EvaluationRecord& record);

  const FuzzCommandOptions& options_;
  const SourceFile& file_;
  const ScenarioTemplate& scenario_;
  const ScenarioEvaluator& evaluator_;
  std::filesystem::path dir_;
  std::vector<std::string> objectives_;
  SearchJournal journal_;
  std::string batch_rows_;
  std::vector<double> best_;
  std::map<std::size_t, std::string> written_;  // finding number -> scenario file
  std::set<std::size_t> lost_;                  // finding numbers whose files failed
  // --tmin: finding number -> {"minimised": file} or {"minimised": null, "not_minimised": why}.
  std::map<std::size_t, nlohmann::json> minimised_;
  std::string first_infeasible_;
  std::string first_failure_;
  std::size_t ego_failures_ = 0;
  std::size_t audited_with_issues_ = 0;
  std::vector<std::size_t> audit_totals_;
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_summary_ = Clock::now();
  std::size_t findings_in_summary_ = 0;
  // Per objective: evaluations whose verdict was a time-out, stuck ones and start-state ones.
  std::vector<std::size_t> time_outs_, stuck_, start_states_, other_faults_;
  CollisionCounts collisions_;
  std::set<std::string> coverage_;
  std::map<std::string, std::size_t> law_first_;  // law feature -> first evaluation reaching it
  // The first design: judged points, violations per objective and the first violating record.
  std::size_t design_points_ = 0;
  std::vector<std::size_t> design_violations_;
  std::vector<std::optional<EvaluationRecord>> design_first_violation_;
  bool design_over_ = false;
  bool design_warned_ = false;
};

// What summary.json and the --json finding events say of every finding: number, evaluation,
// kind ("violation" with spec and robustness, or an ego failure's kind with its reason).
nlohmann::json finding_json(const Finding& finding);

// "001", "012", "1234": finding numbers in file names.
std::string finding_number_text(std::size_t number);

}  // namespace scenfuzz

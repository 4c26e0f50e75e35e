// One search in its output folder, as `scenfuzz --out DIR FILE` runs it and as each search of a
// campaign runs: claim the folder (resume the search journalled there, replace it or refuse),
// run the search, write every finding and the summary. It prints nothing and installs no signal
// handler: what a caller shows and when it stops go through FolderSearchEvents, so that several
// searches can run side by side in one process.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"
#include "fuzz/findings.hpp"
#include "fuzz/output_folder.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/search.hpp"
#include "fuzz/search_outputs.hpp"

namespace scenfuzz {

class JournalReplay;

// What the caller hears of a search in progress; every member may be left empty. All are called
// on the thread that called FolderSearch::run.
struct FolderSearchEvents {
  // Asked between batches: true stops the search (a signal, a deadline). A failed write stops it
  // too, without asking.
  std::function<bool()> interrupted;
  // Every evaluation, in index order (those replayed from the journal included).
  std::function<void(const EvaluationRecord&)> evaluation;
  // A finding made or improved, with its scenario file ("" when it could not be written).
  std::function<void(const FindingUpdate&, const std::string& file)> finding;
  // Something the user should know that does not stop the search.
  std::function<void(const std::string&)> warning;
  // After each evaluation, and once more at the end with `final` set.
  std::function<void(std::size_t judged, const std::vector<double>& best, std::size_t findings,
                     bool final)>
      progress;
};

// Why a search ended without a complete result.
enum class FolderSearchProblem {
  none,
  write_failed,      // a file could not be written (message: why); what is on disk is consistent
  unjudgeable,       // a spec the oracle cannot judge (message: diagnostics against the scenario)
  journal_mismatch,  // the journal belongs to another search (message: why)
};

struct FolderSearchEnd {
  SearchSummary summary;
  FolderSearchProblem problem = FolderSearchProblem::none;
  std::string message;
};

class FolderSearch {
 public:
  // All arguments must outlive the object. options.out_dir is the folder; options.resume and
  // options.force say what happens to an earlier search there.
  FolderSearch(const FuzzCommandOptions& options, const ScenarioFile& input,
               const ScenarioEvaluator& evaluator, FolderSearchEvents events);

  // Locks the folder and starts, resumes or replaces the search there. An error message, empty
  // when the search may run; `nothing_to_resume` is set when --resume found no search.
  std::string claim(bool& nothing_to_resume);

  // Runs the claimed search to its end and writes the final summary.
  FolderSearchEnd run(const SearchOptions& search);

  const SearchOutputs& outputs() const { return outputs_; }
  SearchOutputs& outputs() { return outputs_; }  // after run(): what --tmin adds to the summary
  const FindingLog& log() const { return log_; }
  // The scenario file of every finding written, by finding number.
  const std::map<std::size_t, std::string>& finding_files() const { return files_; }

 private:
  void take(const EvaluationRecord& record);
  void write(const FindingUpdate& update);
  void end_batch();
  void warn_of_design(bool search_over);
  void warn(const std::string& warning);

  const FuzzCommandOptions& options_;
  const ScenarioFile& input_;
  const ScenarioEvaluator& evaluator_;
  FolderSearchEvents events_;
  OutputFolderLock lock_;
  SearchOutputs outputs_;
  std::vector<EvaluationRecord> journal_;
  FindingLog log_;
  std::map<std::size_t, std::string> files_;
  const JournalReplay* replay_ = nullptr;  // while run() runs
  SearchSummary so_far_;
  std::string write_failure_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The search loop's options as the command's options set them (algorithm, budget, time limit,
// seed, threads); the caller adds the targets.
SearchOptions search_plan(const FuzzCommandOptions& options);

}  // namespace scenfuzz

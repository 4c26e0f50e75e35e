// FolderSearch: the search's callbacks (journal, findings, summary) around run_search, as run_fuzz
// had them, with what it printed handed to the caller's events instead.
#include "fuzz/folder_search.hpp"

#include <chrono>
#include <filesystem>

#include "fuzz/journal_replay.hpp"
#include "fuzz/options.hpp"
#include "fuzz/report_format.hpp"
#include "lang/demand.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

FolderSearch::FolderSearch(const FuzzCommandOptions& options, const ScenarioFile& input,
                           const ScenarioEvaluator& evaluator, FolderSearchEvents events)
    : options_(options),
      input_(input),
      evaluator_(evaluator),
      events_(std::move(events)),
      outputs_(options, input.file, input.scenario, evaluator),
      log_(evaluator.objectives()) {}

std::string FolderSearch::claim(bool& nothing_to_resume) {
  nothing_to_resume = false;
  const fs::path dir = options_.out_dir;
  if (std::string failure = lock_.acquire(dir); !failure.empty()) return failure;
  remove_temporary_files(dir);
  if (holds_search(dir)) {
    if (options_.resume) return outputs_.resume(journal_);
    if (!options_.force)
      return "'" + dir.string() +
             "' holds an earlier search: continue it with --resume, write into another folder "
             "with --out DIR, or replace it with --force";
    if (std::string failure = remove_search(dir); !failure.empty()) return failure;
  } else {
    nothing_to_resume = options_.resume;
  }
  return outputs_.start();
}

FolderSearchEnd FolderSearch::run(const SearchOptions& search) {
  SCENFUZZ_DEMAND(lock_.held());  // claim() first
  const JournalReplay replay(evaluator_, std::move(journal_));
  replay_ = &replay;
  SearchCallbacks callbacks;
  callbacks.on_evaluation = [this](const EvaluationRecord& record) { take(record); };
  callbacks.on_batch_end = [this] { end_batch(); };
  callbacks.interrupted = [this] {
    return !write_failure_.empty() || (events_.interrupted && events_.interrupted());
  };
  FolderSearchEnd end;
  try {
    end.summary = run_search(replay, search, callbacks);
  } catch (const OracleError& error) {
    Diagnostics diagnostics;
    diagnostics.error(error.location(), error.what());
    end.problem = FolderSearchProblem::unjudgeable;
    end.message = format_diagnostics(input_.file, diagnostics);
    replay_ = nullptr;
    return end;
  } catch (const JournalMismatch& error) {
    end.problem = FolderSearchProblem::journal_mismatch;
    end.message = error.what();
    replay_ = nullptr;
    return end;
  }
  replay_ = nullptr;
  if (!write_failure_.empty()) end.summary.stop = StopReason::error;
  warn_of_design(true);
  if (events_.progress)
    events_.progress(end.summary.judged, outputs_.best(), log_.findings().size(), true);
  std::string failure = outputs_.finish(end.summary, log_, write_failure_);
  if (write_failure_.empty()) write_failure_ = failure;
  if (!write_failure_.empty()) {
    end.problem = FolderSearchProblem::write_failed;
    end.message = write_failure_;
  }
  return end;
}

void FolderSearch::take(const EvaluationRecord& record) {
  outputs_.record(record, replay_->replayed(record.index));
  ++so_far_.evaluations;
  if (!record.evaluation.feasible())
    ++so_far_.infeasible;
  else if (record.evaluation.judged())
    ++so_far_.judged;
  else
    ++so_far_.failed;
  if (events_.evaluation) events_.evaluation(record);
  if (const std::optional<FindingUpdate> update = log_.add(record)) write(*update);
  if (events_.progress)
    events_.progress(so_far_.judged, outputs_.best(), log_.findings().size(), false);
}

void FolderSearch::write(const FindingUpdate& update) {
  if (!write_failure_.empty()) return;
  std::string failure;
  bool fatal = false;
  const std::string path = outputs_.write_finding(update.finding, failure, fatal);
  if (!path.empty()) files_[update.finding.number] = path;
  if (fatal)
    write_failure_ = failure;
  else if (!failure.empty())
    warn(failure);
  if (events_.finding) events_.finding(update, path);
}

void FolderSearch::end_batch() {
  if (!write_failure_.empty()) return;
  so_far_.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  write_failure_ = outputs_.end_batch(so_far_, log_);
  warn_of_design(false);
}

void FolderSearch::warn_of_design(bool search_over) {
  for (const std::string& warning : outputs_.take_design_warnings(search_over)) warn(warning);
}

void FolderSearch::warn(const std::string& warning) {
  if (events_.warning) events_.warning(warning);
}

SearchOptions search_plan(const FuzzCommandOptions& options) {
  SearchOptions plan = budget_search_options(options);
  plan.sub_violation_targets = options.target == "sub-violations";
  return plan;
}

}  // namespace scenfuzz

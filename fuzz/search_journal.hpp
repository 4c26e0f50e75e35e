// evaluations.csv is the search's journal: one row per evaluation, appended batch by batch, with
// every number written exactly (shortest round-trip) so that a killed search can be replayed from
// it (--resume) to the very state it had. This file knows the columns, writes rows and reads them
// back.
//
// Columns: evaluation, seed, target, status (judged / failed / infeasible), kind (an ego
// failure's finding kind, else empty), every parameter by name, the point in the unit cube
// (u.<name>), robustness.<spec>, guide.<spec> (what the search minimised, when it differs from the
// robustness), audit (the trace audit's issues by kind, "off_road=1;npc_overlap=1"), endings (the
// specs whose verdict the run's end left open, "reach=time-out;clearance=stuck"), violated (the
// violated specs, the earliest first, "clearance;reach"), responsibility and collision_reason (of
// the ego's first collision), signature (the failure mode, which de-duplicates findings),
// wall_seconds, reason, coverage (the run's behaviour-coverage features, docs/coverage.md,
// "ego.following;light.day": journalled so that a resumed search reports the coverage of the
// evaluations it replays without simulating them again), sub_robustness (the robustness of each
// law sub-violation, "-3.2;0;-inf", in Evaluator::sub_targets() order: journalled so that a
// resumed --target sub-violations search replays what its strategies were told).
// The target column names an objective or a sub-violation's feature ("law.laws.07").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/search.hpp"
#include "sampler/parameter_space.hpp"

namespace scenfuzz {

class SearchJournal {
 public:
  // `sub_targets`: the names of the evaluator's sub-targets (Evaluator::sub_targets()).
  SearchJournal(const ParameterSpace& space, std::vector<std::string> objectives,
                std::vector<std::string> sub_targets = {});

  const std::string& header() const { return header_; }
  // One CSV row (ending in a line break) for `record`.
  std::string row(const EvaluationRecord& record) const;

  // Reads the journal at `path`: the records of every complete row, in order. A last row cut
  // short by a kill is removed from the file. nullopt with `error` set when the file cannot be
  // read, belongs to another search (its header differs) or a row cannot be parsed.
  std::optional<std::vector<EvaluationRecord>> read(const std::filesystem::path& path,
                                                    std::string& error) const;

 private:
  std::optional<EvaluationRecord> parse_row(const std::vector<std::string>& fields,
                                            std::string& error) const;

  const ParameterSpace& space_;
  std::vector<std::string> objectives_;
  std::vector<std::string> target_names_;  // the objectives, then the sub-targets
  std::string header_;
};

// Appends `text` to the file at `path` with one write: once it returns, a kill of the process
// cannot lose it (a power cut can, until sync_file). Returns an error message naming the file,
// empty on success.
std::string append_to_file(const std::filesystem::path& path, const std::string& text);

// Flushes the file at `path` to disk (fsync). An error message naming the file, or empty.
std::string sync_file(const std::filesystem::path& path);

}  // namespace scenfuzz

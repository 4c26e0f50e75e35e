// Replaying a finding's scenario with several perception seeds (scenario_replay.hpp).
#include "fuzz/campaign/scenario_replay.hpp"

#include <cctype>
#include <charconv>
#include <exception>
#include <optional>
#include <sstream>

#include "fuzz/findings.hpp"
#include "fuzz/options.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "lang/demand.hpp"
#include "oracle/robustness.hpp"
#include "sampler/random.hpp"

namespace scenfuzz {

namespace {

std::string trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

// read_scenario's message without the command line's "scenfuzz: error: ": the replay's error is
// shown inside the campaign's outputs.
std::string without_prefix(std::string text) {
  const std::string prefix = "scenfuzz: error: ";
  if (text.starts_with(prefix)) text.erase(0, prefix.size());
  return text;
}

// What one seed's run said: whether it failed as the target did, or why it could not be judged.
struct SeedVerdict {
  bool failing = false;
  std::string error;
};

// The search's own reading of one evaluation: a FindingLog of its objectives turns it into a
// finding, whose mode is the key the search grouped the target under.
SeedVerdict judge_seed(const ScenarioEvaluator& evaluator, const ReplayTarget& target,
                       std::uint64_t seed) {
  EvaluationRecord record;
  record.seed = seed;
  record.evaluation = evaluator.evaluate({}, seed);
  const Evaluation& evaluation = record.evaluation;
  const std::string which = "seed " + std::to_string(seed) + ": ";
  if (!evaluation.feasible()) return {false, which + "cannot be set up: " + evaluation.infeasible};
  // A run cut short without being a finding (an ego plugin that cannot start, an unplannable
  // path) says nothing about the target.
  if (!evaluation.judged() && evaluation.failure_kind.empty())
    return {false, which + "cannot be judged: " + evaluation.failure};
  FindingLog log(evaluator.objectives());
  const std::optional<FindingUpdate> update = log.add(record);
  if (!update) return {};  // violated nothing: the ego passed
  const Finding& finding = update->finding;
  // A spec's violation that now ends in a crash or hang was not judged this time.
  if (finding.ego_failure() && target.signature != finding.mode)
    return {false, which + "the ego failed before the spec could be judged (" + finding.mode +
                       "): " + finding.failure};
  const bool same_spec = finding.ego_failure() || finding.objective_name == target.spec;
  return {same_spec && finding.mode == target.signature, ""};
}

// The replay's evaluator, or the reason there is none (a map that cannot be loaded).
std::optional<ScenarioEvaluator> make_evaluator(const ScenarioFile& input,
                                                const SimulationCommandOptions& flags,
                                                std::string& error) {
  std::optional<ScenarioEvaluator> evaluator;
  try {
    std::vector<std::filesystem::path> map_paths(flags.map_paths.begin(), flags.map_paths.end());
    evaluator.emplace(input.file, input.scenario, map_search_path(map_paths),
                      simulation_options(flags));
    evaluator->set_judge_options(judge_options(flags));
  } catch (const MapError& failure) {
    error = input.file.path() + ": " + failure.what();
    return std::nullopt;
  }
  if (!evaluator->space().dimensions.empty()) {
    error = "'" + input.file.path() + "' is a logical scenario with " +
            std::to_string(evaluator->space().dimensions.size()) +
            " parameters, not a finding's concrete scenario";
    return std::nullopt;
  }
  return evaluator;
}

// Every seed in turn; the first that cannot be judged ends the replay as an error.
ReplayOutcome replay_seeds_of(const ScenarioFile& input, const ScenarioEvaluator& evaluator,
                              const ReplayTarget& target, int seeds) {
  ReplayOutcome outcome;
  for (std::uint64_t seed : replay_seeds(finding_seed(input.file.text()), seeds)) {
    SeedVerdict verdict;
    try {
      verdict = judge_seed(evaluator, target, seed);
    } catch (const OracleError& failure) {
      // A spec the trace cannot answer, placed in the file (file:line:column).
      Diagnostics diagnostics;
      diagnostics.error(failure.location(), failure.what());
      return {0, 0, trimmed(format_diagnostics(input.file, diagnostics))};
    } catch (const std::exception& failure) {
      verdict.error = "seed " + std::to_string(seed) + ": " + failure.what();
    }
    if (!verdict.error.empty()) return {0, 0, input.file.path() + ": " + verdict.error};
    ++outcome.tried;
    if (verdict.failing) ++outcome.failing;
  }
  return outcome;
}

}  // namespace

std::uint64_t finding_seed(std::string_view scenario_text) {
  std::istringstream lines{std::string(scenario_text)};
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t replay = line.find("replay: scenfuzz run ");
    if (replay == std::string::npos) continue;
    const std::string flag = " --seed ";
    const std::size_t at = line.find(flag, replay);
    if (at == std::string::npos) return 0;
    const char* first = line.data() + at + flag.size();
    std::uint64_t seed = 0;
    const auto [end, error] = std::from_chars(first, line.data() + line.size(), seed);
    return error == std::errc() ? seed : 0;
  }
  return 0;
}

std::vector<std::uint64_t> replay_seeds(std::uint64_t own, int count) {
  SCENFUZZ_DEMAND(count >= 0);
  std::vector<std::uint64_t> seeds;
  for (int k = 0; k < count; ++k)
    seeds.push_back(k == 0 ? own : derive_seed(own, static_cast<std::uint64_t>(k)));
  return seeds;
}

std::string finding_scenario(std::string_view scenario_text) {
  std::istringstream lines{std::string(scenario_text)};
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find("replay: scenfuzz run ") == std::string::npos) continue;
    const std::string flag = " --scenario ";
    const std::size_t at = line.find(flag);
    if (at == std::string::npos) return "";
    // A scenario's name is a variable's: no spaces; shell_quote may have quoted it.
    std::string name = line.substr(at + flag.size());
    name = name.substr(0, name.find(' '));
    if (name.size() >= 2 && name.front() == '\'' && name.back() == '\'')
      name = name.substr(1, name.size() - 2);
    return name;
  }
  return "";
}

ReplayOutcome replay_scenario(const ReplayTarget& target, const ReplaySettings& settings) {
  try {
    std::ostringstream diagnostics;
    std::optional<SourceFile> file = read_source_file(target.scenario.string());
    const ScenarioChoiceOptions choice{file ? finding_scenario(file->text()) : ""};
    std::optional<ScenarioFile> input =
        read_scenario(target.scenario.string(), "replay", diagnostics, choice);
    if (!input) return {0, 0, without_prefix(trimmed(diagnostics.str()))};
    apply_scenario_overrides(settings.simulation, input->scenario);
    std::string error;
    const std::optional<ScenarioEvaluator> evaluator =
        make_evaluator(*input, settings.simulation, error);
    if (!evaluator) return {0, 0, error};
    return replay_seeds_of(*input, *evaluator, target, settings.seeds);
  } catch (const std::exception& failure) {
    // Nothing above is expected to throw; a replay that cannot be made is still only an error.
    return {0, 0, target.scenario.string() + ": " + failure.what()};
  }
}

}  // namespace scenfuzz

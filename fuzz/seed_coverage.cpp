// A seed's behaviour coverage: the union of the features (oracle/behaviour_coverage,
// oracle/law_coverage) of the runs at its sample points, simulated as a search evaluates a point
// (ScenarioEvaluator). Every problem becomes SeedCoverage::error; nothing escapes as an exception.
#include "fuzz/seed_coverage.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "fuzz/options.hpp"
#include "fuzz/run_coverage.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "lang/number_format.hpp"
#include "oracle/robustness.hpp"
#include "sampler/point_samplers.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// What seed_coverage.hpp's sample of a logical seed is: the centre of its space and this many
// points of the scrambled Halton sequence of --seed (docs/coverage.md).
constexpr std::size_t kLogicalSamplePoints = 8;

std::vector<std::vector<double>> sample_points(std::size_t dimensions, std::uint64_t seed) {
  std::vector<std::vector<double>> points = {std::vector<double>(dimensions, 0.5)};
  if (dimensions == 0) return points;
  const HaltonSequence halton(dimensions, seed);
  for (std::uint64_t k = 0; k < kLogicalSamplePoints; ++k) points.push_back(halton.point(k));
  return points;
}

// `text` without its trailing newlines.
std::string trimmed(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

std::string located(const SourceFile& file, const OracleError& error) {
  if (!error.location().known()) return error.what();
  return file.path() + ":" + std::to_string(error.location().line) + ":" +
         std::to_string(error.location().column) + ": " + error.what();
}

// A run's features appended to `features`; false when the run left no trace to read.
bool cover_run(const ScenarioRun& run, const ScenarioTemplate& scenario,
               std::vector<std::string>& features, SeedCoverage& coverage) {
  if (!has_coverage(run)) return false;
  const std::vector<std::string> covered = run_coverage(run, scenario);
  features.insert(features.end(), covered.begin(), covered.end());
  ++coverage.simulations;
  coverage.simulated_steps += run.trace->sample_count();
  return true;
}

// Why no run of the seed could be covered, from the first point's reason.
std::string nothing_covered(const ScenarioRun& first, bool logical) {
  const std::string reason = !first.infeasible.empty() ? first.infeasible
                             : !first.failure.empty()  ? first.failure
                                                       : "the run left no trace";
  return logical ? "no point of its sample could be simulated; at its centre: " + reason
                 : "it cannot be simulated: " + reason;
}

// The scenario's own duration (none given on the command line) within the step limit.
std::optional<std::string> step_problem(const SeedCoverageOptions& options,
                                        const ScenarioEvaluator& evaluator) {
  if (options.simulation.duration) return std::nullopt;
  const SetupProbe probe =
      evaluator.probe(std::vector<double>(evaluator.space().dimensions.size(), 0.5));
  if (!probe.duration) return std::nullopt;
  return check_step_count(*probe.duration, options.simulation.dt,
                          "the scenario's duration of " + format_number(*probe.duration) + " s");
}

void cover_scenario(const ScenarioFile& input, const SeedCoverageOptions& options,
                    SeedCoverage& coverage) {
  std::vector<fs::path> map_paths(options.simulation.map_paths.begin(),
                                  options.simulation.map_paths.end());
  const ScenarioEvaluator evaluator(input.file, input.scenario, map_search_path(map_paths),
                                    simulation_options(options.simulation));
  coverage.logical = !evaluator.space().dimensions.empty();
  if (const std::optional<std::string> problem = step_problem(options, evaluator)) {
    coverage.error = *problem;
    return;
  }
  std::vector<std::string> features;
  std::optional<ScenarioRun> first;
  for (const std::vector<double>& point :
       sample_points(evaluator.space().dimensions.size(), options.seed)) {
    ScenarioRun run = evaluator.run(point, options.seed);
    cover_run(run, input.scenario, features, coverage);
    if (!first) first = std::move(run);
  }
  if (coverage.simulations == 0) {
    coverage.error = nothing_covered(*first, coverage.logical);
    return;
  }
  std::sort(features.begin(), features.end());
  features.erase(std::unique(features.begin(), features.end()), features.end());
  coverage.features = std::move(features);
}

}  // namespace

SeedCoverage cover_seed(const std::string& path, const SeedCoverageOptions& options) {
  SeedCoverage coverage;
  coverage.path = path;
  std::error_code size_error;
  const std::uintmax_t size = fs::file_size(path, size_error);
  coverage.file_size = size_error ? 0 : size;
  std::ostringstream diagnostics;
  std::optional<ScenarioFile> input = read_scenario(path, "cover", diagnostics);
  if (!input) {
    // The error stands on its own in coverage's and cmin's lists: without the command's prefix.
    std::string error = trimmed(diagnostics.str());
    const std::string prefix = "scenfuzz: error: ";
    if (error.starts_with(prefix)) error.erase(0, prefix.size());
    coverage.error = error;
    return coverage;
  }
  apply_scenario_overrides(options.simulation, input->scenario);
  try {
    cover_scenario(*input, options, coverage);
  } catch (const MapError& error) {
    coverage.error = error.what();
  } catch (const OracleError& error) {
    coverage.error = located(input->file, error);
  } catch (const std::exception& error) {
    // Anything else a simulation throws costs this seed, never the corpus.
    coverage.error = std::string("it cannot be covered: ") + error.what();
  }
  if (!coverage.error.empty()) coverage.features.clear();
  return coverage;
}

}  // namespace scenfuzz

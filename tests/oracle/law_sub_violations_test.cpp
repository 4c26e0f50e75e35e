// LawBreaker's 13-law specification, decomposed into its 81 sub-violations by the negation rule
// (oracle/sub_violations.*), evaluates whole on runs simulated on san_francisco: the shared
// traffic_rule_tests file and our own law files (tests/oracle/data/laws) read no signal the
// oracle lacks, and every sub-violation has a robustness, none an error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "oracle/robustness.hpp"
#include "oracle/spec_judgeable.hpp"
#include "oracle/sub_violations.hpp"
#include "oracle/trace_signals.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/scenario_setup.hpp"
#include "physics/simulation/simulation.hpp"
#include "sampler/parameter_space.hpp"
#include "tests/support/shared_dir.hpp"

namespace scenfuzz {
namespace {

namespace fs = std::filesystem;

// LawBreaker's count for laws.txt (reference section 3.2).
constexpr std::size_t kLawSubViolations = 81;

// A law file parsed and simulated on its map from the shared Apollo maps.
struct LawRun {
  ScenarioTemplate scenario;
  std::vector<double> parameters;
  std::optional<RoadMap> map;
  std::optional<Trace> trace;
  std::string errors;
};

LawRun simulate_law_file(const fs::path& path) {
  LawRun run;
  const std::optional<SourceFile> file = read_source_file(path.string());
  if (!file) {
    run.errors = "cannot read " + path.string();
    return run;
  }
  avunit::ParseResult parsed = avunit::parse(*file);
  run.errors = format_diagnostics(*file, parsed.diagnostics);
  if (!parsed.ok()) return run;
  run.scenario = std::move(parsed.scenario);
  const ParameterSpace space = parameter_space(run.scenario);
  const std::vector<double> middle(space.dimensions.size(), 0.5);
  run.parameters = decode(space, middle);
  run.map = load_scenario_map(
      run.scenario.map, map_search_path({test::shared_dir() / "maps" / "apollo"}), run.parameters);
  Diagnostics diagnostics;
  const auto setup = prepare_simulation(run.scenario, run.parameters, *run.map, 1, diagnostics);
  run.errors += format_diagnostics(*file, diagnostics);
  if (setup) run.trace = simulate(*run.map, *setup, SimulationOptions{});
  return run;
}

std::vector<fs::path> law_files() {
  std::vector<fs::path> files = {test::shared_dir() / "examples" / "scenest" /
                                 "lawbreaker__traffic_rule_tests__intersection_turn_left.scenest"};
  for (const char* name :
       {"intersection_straight.scenest", "lane_change_left.scenest", "night_fog.scenest"})
    files.push_back(fs::path(SCENFUZZ_TEST_DATA_DIR) / "laws" / name);
  return files;
}

TEST(LawSubViolationsTest, AllEightyOneSubViolationsOfTheThirteenLawsEvaluateOnSimulatedRuns) {
  SCENFUZZ_REQUIRE_SHARED_DIR();
  for (const fs::path& path : law_files()) {
    SCOPED_TRACE(path.string());
    const LawRun run = simulate_law_file(path);
    ASSERT_TRUE(run.trace) << run.errors;
    ASSERT_EQ(run.scenario.specs.size(), 1u) << "the 13 laws asserted together";
    EXPECT_TRUE(uncomputed_signals(run.scenario).empty()) << "a spec would not be judged";
    const Spec& laws = run.scenario.specs[0];
    const std::optional<std::vector<Formula>> subs = sub_violations(laws.formula);
    ASSERT_TRUE(subs);
    ASSERT_EQ(subs->size(), kLawSubViolations);
    const TraceSignals signals(*run.trace, run.scenario, run.parameters, *run.map);
    std::size_t found = 0;
    for (std::size_t k = 0; k < subs->size(); ++k) {
      double robustness = NAN;
      EXPECT_NO_THROW(robustness = robustness_signal((*subs)[k], signals.source()).at(0))
          << "sub-violation " << k + 1;
      EXPECT_FALSE(std::isnan(robustness)) << "sub-violation " << k + 1;
      if (robustness >= 0) ++found;
    }
    // The laws hold exactly when no sub-violation is found (LawBreaker's convention: >= 0).
    const double whole = robustness_signal(laws.formula, signals.source()).at(0);
    EXPECT_EQ(whole <= 0, found > 0) << whole << " with " << found << " found";
  }
}

}  // namespace
}  // namespace scenfuzz

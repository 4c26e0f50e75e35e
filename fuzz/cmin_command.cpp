// `scenfuzz cmin`: corpus minimisation with each seed's coverage from cover_seed, stopped
// cleanly by SIGINT or SIGTERM.
#include <nlohmann/json.hpp>
#include <optional>

#include "fuzz/cmin_table.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/corpus_minimize.hpp"
#include "fuzz/seed_coverage.hpp"
#include "fuzz/stop_signals.hpp"

namespace scenfuzz {

namespace {

template <typename T>
nlohmann::json option_json(const T& value) {
  return value;
}

template <typename T>
nlohmann::json option_json(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// Everything a seed's coverage depends on besides its bytes: the version (the feature set may
// change), the seed and every simulation option.
std::string coverage_identity(const CminCommandOptions& options) {
  nlohmann::json identity = {{"version", SCENFUZZ_VERSION}, {"seed", options.seed}};
#define SCENFUZZ_SIMULATION_OPTION(TYPE, FIELD, ...) \
  identity[#FIELD] = option_json(options.simulation.FIELD);
#include "fuzz/options.def"
  return identity.dump();
}

}  // namespace

int run_cmin(const CminCommandOptions& options, std::ostream& out, std::ostream& err) {
  const SeedCoverageOptions coverage{options.simulation, options.seed};
  const CminOptions cmin{options.inputs, options.out_dir, options.jobs, coverage_identity(options)};
  CminResult result;
  {
    StopSignalGuard guard;
    result = minimize_corpus(
        cmin, [&coverage](const std::string& path) { return cover_seed(path, coverage); },
        [] { return StopSignalGuard::stop_requested(); });
  }
  print_cmin_report(result, options.out_dir, out, err);
  return cmin_exit_status(result);
}

}  // namespace scenfuzz

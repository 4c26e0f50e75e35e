// cmin.json, the printed report and the exit status of `scenfuzz cmin`.
#include "fuzz/cmin_table.hpp"

#include <nlohmann/json.hpp>

#include "fuzz/cli.hpp"

namespace scenfuzz {

namespace {

using Json = nlohmann::ordered_json;

Json kept_json(const CminSeed& seed) {
  return {{"path", seed.path},
          {"output", seed.output},
          {"size", seed.coverage.file_size},
          {"simulated_steps", seed.coverage.simulated_steps},
          {"logical", seed.coverage.logical},
          {"features", seed.coverage.features},
          {"new_features", seed.new_features}};
}

std::string drop_reason(const CminSeed& seed) {
  if (seed.covered_by.empty()) return "no features";
  std::string reason = "covered by";
  for (std::size_t i = 0; i < seed.covered_by.size(); ++i)
    reason += (i == 0 ? " " : ", ") + seed.covered_by[i];
  return reason;
}

Json dropped_json(const CminSeed& seed) {
  return {{"path", seed.path},
          {"size", seed.coverage.file_size},
          {"simulated_steps", seed.coverage.simulated_steps},
          {"features", seed.coverage.features},
          {"covered_by", seed.covered_by},
          {"reason", drop_reason(seed)}};
}

std::string counted(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

}  // namespace

std::string cmin_table_json(const CminResult& result) {
  Json kept = Json::array(), dropped = Json::array(), errors = Json::array();
  for (std::size_t k : result.kept) kept.push_back(kept_json(result.seeds[k]));
  for (const CminSeed& seed : result.seeds) {
    if (seed.verdict == CminVerdict::dropped) dropped.push_back(dropped_json(seed));
    if (seed.verdict == CminVerdict::error)
      errors.push_back({{"path", seed.path}, {"error", seed.coverage.error}});
  }
  const Json table = {{"seeds", result.seeds.size()},
                      {"features", result.features},
                      {"kept", std::move(kept)},
                      {"dropped", std::move(dropped)},
                      {"errors", std::move(errors)}};
  return table.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void print_cmin_report(const CminResult& result, const std::string& out_dir, std::ostream& out,
                       std::ostream& err) {
  for (const std::string& note : result.notes) err << "scenfuzz: note: " << note << "\n";
  if (result.problem == CminProblem::output_folder) {
    err << "scenfuzz: error: " << result.message << "\n";
    return;
  }
  std::size_t errors = 0;
  for (const CminSeed& seed : result.seeds)
    if (seed.verdict == CminVerdict::error && !seed.coverage.error.empty()) {
      ++errors;
      if (result.problem != CminProblem::interrupted)
        err << "scenfuzz: warning: " << seed.path << " is left out: " << seed.coverage.error
            << (seed.coverage.error.back() == '\n' ? "" : "\n");
    }
  if (result.problem == CminProblem::interrupted) {
    err << "scenfuzz: interrupted: " << result.covered_now
        << " seeds covered by this run are recorded in '" << out_dir
        << "/cmin.control'; run the same command again to continue\n";
    return;
  }
  for (std::size_t k : result.kept) {
    const CminSeed& seed = result.seeds[k];
    out << "kept     " << seed.path << " -> " << seed.output << ": "
        << counted(seed.coverage.features.size(), "feature") << ", " << seed.new_features.size()
        << " new\n";
  }
  for (const CminSeed& seed : result.seeds) {
    if (seed.verdict == CminVerdict::dropped)
      out << "dropped  " << seed.path << ": " << drop_reason(seed) << "\n";
    if (seed.verdict == CminVerdict::error)
      out << "error    " << seed.path << ": " << first_line(seed.coverage.error) << "\n";
  }
  std::size_t reused = 0;
  for (const CminSeed& seed : result.seeds) reused += seed.reused ? 1 : 0;
  out << "cmin: kept " << result.kept.size() << " of " << result.seeds.size() << " seeds ("
      << result.seeds.size() - result.kept.size() - errors << " dropped, " << errors
      << " with errors), covering " << counted(result.features, "feature") << ", in '" << out_dir
      << "' (the table: cmin.json)";
  if (reused > 0) out << "; " << reused << " seeds' coverage read from cmin.control";
  out << "\n";
  if (result.problem == CminProblem::nothing_covered)
    err << "scenfuzz: error: " << result.message << "\n";
}

int cmin_exit_status(const CminResult& result) {
  return result.problem == CminProblem::none ? kExitSuccess : kExitBadInput;
}

}  // namespace scenfuzz

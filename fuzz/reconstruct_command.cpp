// `scenfuzz reconstruct FILE.acc` (commands.hpp): an accident description's unknowns searched for
// a run that reproduces its collisions, reported and written as a replayable AVUnit scenario with
// its trace and picture.
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/driver_test.hpp"
#include "fuzz/driver_test_report.hpp"
#include "fuzz/options.hpp"
#include "fuzz/reconstruction_scenario.hpp"
#include "fuzz/reconstruction_search.hpp"
#include "fuzz/scenario_language.hpp"
#include "fuzz/significant_digits.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/accident/accident.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "oracle/collision_reconstruction.hpp"
#include "physics/trace/trace_export.hpp"
#include "physics/trace/trace_svg.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;

// What a report prints of a measured number: enough digits to tell runs apart.
std::string shown(double value) { return format_number(round_to_significant(value, 3)); }

std::optional<accident::ScenarioParse> read_accident(const ReconstructCommandOptions& options,
                                                     std::optional<SourceFile>& file,
                                                     std::ostream& err) {
  if (!is_accident_file(options.path)) {
    err << "scenfuzz: error: reconstruct reads an accident description (.acc), not '"
        << options.path << "'\n";
    return std::nullopt;
  }
  file = read_input(options.path, err);
  if (!file) return std::nullopt;
  accident::ScenarioParse parsed = accident::parse_scenario(*file, {options.ego});
  err << format_diagnostics(*file, parsed.diagnostics);
  if (!parsed.ok()) return std::nullopt;
  return parsed;
}

// "truck1's front hit car1's left side at 4.35 s, 0.4 m from the described place".
std::string collision_text(const ExpectedCollision& expected, const CollisionCheck& check,
                           std::span<const double> values) {
  std::string text = expected.striker + "'s " + vehicle_part_words(expected.striker_part) + " on " +
                     expected.victim + "'s " + vehicle_part_words(expected.victim_part) + ": ";
  if (!check.happened)
    return text + "no contact; closest approach " + shown(check.closest_approach) + " m";
  text += "hit at " + shown(check.time) + " s, " + expected.striker + "'s " +
          body_side_words(check.striker_side) + " on " + expected.victim + "'s " +
          body_side_words(check.victim_side);
  if (expected.position) {
    const double dx = check.contact.x - evaluate(expected.position->x, values);
    const double dy = check.contact.y - evaluate(expected.position->y, values);
    text += ", " + shown(std::hypot(dx, dy)) + " m from the described place";
  }
  if (!check.satisfied) text += " (" + check.problem + ")";
  return text;
}

struct Outcome {
  const ReconstructionSearch& search;
  const ReconstructionRun& run;
  std::uint64_t seed = 0;
  std::string replay_text;           // reconstruction.avu
  std::optional<DriverTest> driver;  // when reconstructed
  DriverSeat seat;
};

using NamedText = std::pair<std::string, std::string>;  // a file's name in --out, its content

std::string parameter_text(const ScenarioTemplate& scenario, std::span<const double> values,
                           std::size_t i) {
  const Parameter& parameter = scenario.parameters[i];
  if (parameter.kind == ParameterKind::discrete)
    return parameter.name + " = " + parameter.choices[static_cast<std::size_t>(values[i])];
  return parameter.name + " = " + shown(values[i]) +
         (parameter.unit.empty() ? "" : " " + parameter.unit);
}

std::vector<std::string> report_lines(const ScenarioTemplate& scenario, const Outcome& outcome) {
  std::vector<std::string> lines;
  const std::vector<double>& values = outcome.run.run.values;
  for (std::size_t i = 0; i < scenario.parameters.size(); ++i)
    lines.push_back(parameter_text(scenario, values, i));
  for (std::size_t k = 0; k < scenario.expected_collisions.size(); ++k)
    lines.push_back(
        "collision " + std::to_string(k + 1) + ", " +
        collision_text(scenario.expected_collisions[k], outcome.run.score->collisions[k], values));
  return lines;
}

std::string headline(const std::string& path, const Outcome& outcome) {
  if (outcome.search.reconstructed)
    return "reconstructed " + path + " in " + std::to_string(outcome.search.simulations) +
           " simulations (seed " + std::to_string(outcome.seed) + ")";
  return "not reconstructed " + path + " within " +
         std::to_string(outcome.search.summary.judged + outcome.search.summary.failed) +
         " simulations (seed " + std::to_string(outcome.seed) + "); the closest run, simulation " +
         std::to_string(outcome.search.simulations) + ", misses by " +
         shown(outcome.run.score->robustness) + " m";
}

std::string scenario_text(const ScenarioTemplate& accident, const std::string& path,
                          const Outcome& outcome) {
  const ScenarioTemplate replay =
      replay_scenario(accident, *outcome.run.run.trace, *outcome.run.run.map);
  std::string text = "// " + headline(path, outcome) + ", by scenfuzz reconstruct\n";
  for (const std::string& line : report_lines(accident, outcome)) text += "//   " + line + "\n";
  text += "// The ego, " + accident.ego.name +
          ", starts as it did and is driven where it was going by the system under test; the "
          "other vehicles replay their reconstructed runs.\n";
  return text + avunit::print(replay);
}

// The summary of a reconstruction: its numbers, each described collision as it happened, the
// undescribed ones, and the driver test when there was one.
nlohmann::json summary_json(const ScenarioTemplate& accident, const Outcome& outcome) {
  nlohmann::json summary;
  summary["reconstructed"] = outcome.search.reconstructed;
  summary["simulations"] = outcome.search.simulations;
  summary["simulations_run"] = outcome.search.summary.judged + outcome.search.summary.failed;
  summary["seed"] = outcome.seed;
  summary["robustness"] = outcome.run.score->robustness;
  nlohmann::json parameters = nlohmann::json::object();
  for (std::size_t i = 0; i < accident.parameters.size(); ++i)
    parameters[accident.parameters[i].name] = outcome.run.run.values[i];
  summary["parameters"] = parameters;
  nlohmann::json collisions = nlohmann::json::array();
  for (std::size_t k = 0; k < accident.expected_collisions.size(); ++k) {
    const CollisionCheck& check = outcome.run.score->collisions[k];
    nlohmann::json item = {{"actor", accident.expected_collisions[k].striker},
                           {"victim", accident.expected_collisions[k].victim},
                           {"happened", check.happened},
                           {"as_described", check.satisfied},
                           {"robustness", check.robustness}};
    if (check.happened) {
      item["time"] = check.time;
      item["contact"] = {check.contact.x, check.contact.y};
      item["actor_side"] = body_side_words(check.striker_side);
      item["victim_side"] = body_side_words(check.victim_side);
    }
    if (!check.problem.empty()) item["problem"] = check.problem;
    collisions.push_back(item);
  }
  summary["collisions"] = collisions;
  nlohmann::json undescribed = nlohmann::json::array();
  for (const UndescribedCollision& extra : outcome.run.score->undescribed)
    undescribed.push_back({{"actors", {extra.first, extra.second}}, {"time", extra.time}});
  summary["undescribed_collisions"] = undescribed;
  summary["driver_test"] = nullptr;
  return summary;
}

std::vector<std::string> lane_ids_of(const RoadMap& map) {
  std::vector<std::string> ids;
  for (const Lane& lane : map.lanes()) ids.push_back(lane.id);
  return ids;
}

// The files of the reconstruction itself: its scenario, trace and picture.
std::vector<NamedText> reconstruction_files(const ReconstructCommandOptions& options,
                                            const Outcome& outcome) {
  const Trace& trace = *outcome.run.run.trace;
  TraceSvgOptions picture;
  picture.caption.headline =
      (outcome.search.reconstructed ? "Reconstruction of " : "Closest run to ") +
      fs::path(options.path).filename().string() + ": " +
      (outcome.search.reconstructed ? "every collision as described"
                                    : "misses by " + shown(outcome.run.score->robustness) + " m") +
      " (" + std::to_string(outcome.search.simulations) + " simulations)";
  return {{"reconstruction.avu", outcome.replay_text},
          {"trace.csv", trace_csv(trace, lane_ids_of(*outcome.run.run.map))},
          {"trace.svg", render_trace_svg(*outcome.run.run.map, trace, picture)}};
}

// The driver test's trace and picture, as `scenfuzz run reconstruction.avu` writes them.
std::vector<NamedText> driver_files(const DriverTest& test, const DriverSeat& seat) {
  const Trace& trace = *test.run.trace;
  if (trace.sample_count() == 0) return {};
  TraceSvgOptions picture;
  picture.caption.headline = driver_test_headline(test, seat);
  return {{"driver_trace.csv", trace_csv(trace, lane_ids_of(*test.run.map))},
          {"driver_trace.svg", render_trace_svg(*test.run.map, trace, picture)}};
}

// Writes each file into --out, then the summary naming them; false after an error on `err`.
bool write_outputs(const ReconstructCommandOptions& options, const ScenarioTemplate& accident,
                   const Outcome& outcome, std::ostream& err, std::vector<std::string>& written) {
  std::error_code error;
  fs::create_directories(options.out_dir, error);
  if (error) {
    err << "scenfuzz: error: cannot create '" << options.out_dir << "': " << error.message()
        << "\n";
    return false;
  }
  const fs::path dir = options.out_dir;
  const auto write = [&](const std::string& name, const std::string& content) {
    if (std::string failure = write_file_atomically(dir / name, content); !failure.empty()) {
      err << "scenfuzz: error: " << failure << "\n";
      return false;
    }
    written.push_back((dir / name).string());
    return true;
  };
  for (const auto& [name, content] : reconstruction_files(options, outcome))
    if (!write(name, content)) return false;
  nlohmann::json summary = summary_json(accident, outcome);
  if (outcome.driver) {
    std::vector<std::string> driver_written;
    for (const auto& [name, content] : driver_files(*outcome.driver, outcome.seat)) {
      if (!write(name, content)) return false;
      driver_written.push_back(written.back());
    }
    summary["driver_test"] = driver_test_json(*outcome.driver, outcome.seat, driver_written);
  }
  // The summary names itself among the files written.
  summary["written"] = written;
  summary["written"].push_back((dir / "summary.json").string());
  return write("summary.json", summary.dump(2) + "\n");
}

// The driver under test in the ego's place on the written replay (driver_test.hpp); nullopt
// after an error on `err`: the plugin could not be started, or the replay not be run.
std::optional<DriverTest> test_on_replay(const ReconstructCommandOptions& options,
                                         const std::string& replay_text, std::ostream& err) {
  const SourceFile file((fs::path(options.out_dir) / "reconstruction.avu").string(), replay_text);
  avunit::ParseResult parsed = avunit::parse(file);
  SCENFUZZ_DEMAND(parsed.ok());  // printed by avunit::print, which round-trips
  apply_scenario_overrides(options.simulation, parsed.scenario);
  std::vector<fs::path> map_paths(options.simulation.map_paths.begin(),
                                  options.simulation.map_paths.end());
  DriverTest test =
      test_driver(file, parsed.scenario, map_search_path(map_paths),
                  simulation_options(options.simulation), judge_options(options.simulation));
  if (!test.problem.empty()) {
    err << "scenfuzz: error: the driver could not be tested on the reconstruction: " << test.problem
        << "\n";
    return std::nullopt;
  }
  return test;
}

DriverSeat seat_of(const ReconstructCommandOptions& options, const ScenarioTemplate& accident) {
  return {options.simulation.ego_plugin.empty() ? "the reference driver"
                                                : options.simulation.ego_plugin,
          accident.ego.name};
}

// The search for a reconstruction, with its best run simulated again in full; nullopt after an
// error on `err` (the status in `status`).
std::optional<std::pair<ReconstructionSearch, ReconstructionRun>> reconstruct(
    const ReconstructCommandOptions& options, const ReconstructionEvaluator& evaluator,
    std::ostream& err, int& status) {
  StopSignalGuard stop_signals;
  ReconstructionSearch search;
  try {
    search = search_reconstruction(evaluator, budget_search_options(options),
                                   [] { return StopSignalGuard::stop_requested(); });
  } catch (const std::invalid_argument& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    status = kExitUsage;
    return std::nullopt;
  }
  if (!search.best) {
    err << "scenfuzz: error: no run of '" << options.path
        << "' could be simulated: every point was infeasible or failed\n";
    status = kExitBadInput;
    return std::nullopt;
  }
  ReconstructionRun run = evaluator.reconstruct(search.best->point, search.best->seed);
  return std::make_pair(std::move(search), std::move(run));
}

int exit_status(const Outcome& outcome, const std::string& path, std::ostream& err) {
  if (!outcome.search.reconstructed) {
    err << "scenfuzz: error: '" << path
        << "' was not reconstructed, so no driver was tested on it (a larger --budget or "
           "another --seed may find a reconstruction)\n";
    return kExitBadInput;
  }
  return is_driver_finding(outcome.driver->verdict) ? kExitViolated : kExitSuccess;
}

}  // namespace

int run_reconstruct(const ReconstructCommandOptions& options, std::ostream& out,
                    std::ostream& err) {
  std::optional<SourceFile> file;
  const std::optional<accident::ScenarioParse> parsed = read_accident(options, file, err);
  if (!parsed) return kExitBadInput;
  const ScenarioTemplate& accident = parsed->scenario;
  std::optional<ReconstructionEvaluator> evaluator;
  try {
    std::vector<fs::path> map_paths(options.simulation.map_paths.begin(),
                                    options.simulation.map_paths.end());
    evaluator.emplace(*file, accident, map_search_path(map_paths),
                      simulation_options(options.simulation));
  } catch (const MapError& error) {
    err << "scenfuzz: error: " << error.what() << "\n";
    return kExitBadInput;
  }
  int status = kExitBadInput;
  const auto found = reconstruct(options, *evaluator, err, status);
  if (!found) return status;
  const auto& [search, run] = *found;
  Outcome outcome{search, run, options.seed, "", std::nullopt, seat_of(options, accident)};
  outcome.replay_text = scenario_text(accident, options.path, outcome);
  if (search.reconstructed) {
    outcome.driver = test_on_replay(options, outcome.replay_text, err);
    if (!outcome.driver) return kExitBadInput;
  }
  std::vector<std::string> written;
  if (!write_outputs(options, accident, outcome, err, written)) return kExitBadInput;
  out << headline(options.path, outcome) << "\n";
  for (const std::string& line : report_lines(accident, outcome)) out << "  " << line << "\n";
  if (outcome.driver)
    for (const std::string& line : driver_test_lines(*outcome.driver, outcome.seat))
      out << line << "\n";
  for (const std::string& path : written) out << "wrote " << path << "\n";
  return exit_status(outcome, options.path, err);
}

}  // namespace scenfuzz

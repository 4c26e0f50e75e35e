// minimize_finding (tmin_finding.hpp): the finding's header read back, every candidate printed in
// the finding's language (canonical AVUnit, or WMG SDL level 2 from the finding's syntax tree),
// parsed again and replayed with the search's own evaluator, so that what the reduction keeps is
// exactly what the written file replays.
#include "fuzz/tmin_finding.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/commands.hpp"
#include "fuzz/options.hpp"
#include "fuzz/report_format.hpp"
#include "fuzz/scenario_evaluator.hpp"
#include "fuzz/scenario_language.hpp"
#include "fuzz/tmin.hpp"
#include "fuzz/tmin_wmg.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/number_format.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"
#include "lang/wmg/wmg.hpp"
#include "oracle/failure_mode.hpp"
#include "oracle/robustness.hpp"

namespace scenfuzz {

namespace {

namespace fs = std::filesystem;

// What the finding's header says; a plain concrete file has none of it.
struct FindingHeader {
  std::vector<std::string> replay;  // the replay command's words after `scenfuzz run FILE`
  std::string mode;                 // "failure mode: ..."
  bool has_replay = false;
};

// A command line as a POSIX shell splits it: the quoting shell_quote writes ('...' and '\'').
std::optional<std::vector<std::string>> shell_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(std::exchange(word, {}));
      in_word = false;
    } else if (c == '\'') {
      const std::size_t end = line.find('\'', i + 1);
      if (end == std::string::npos) return std::nullopt;
      word += line.substr(i + 1, end - i - 1);
      in_word = true;
      i = end;
    } else if (c == '\\' && i + 1 < line.size()) {
      word += line[++i];
      in_word = true;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return words;
}

// The header: the comment lines the file starts with.
std::optional<FindingHeader> read_header(const std::string& text, const std::string& comment,
                                         std::string& error) {
  FindingHeader header;
  std::istringstream lines(text);
  const std::string replay_mark = comment + "replay: scenfuzz run ";
  const std::string mode_mark = comment + "failure mode: ";
  for (std::string line; std::getline(lines, line) && line.starts_with(comment.substr(0, 1));) {
    if (line.starts_with(mode_mark)) header.mode = line.substr(mode_mark.size());
    if (!line.starts_with(replay_mark)) continue;
    std::optional<std::vector<std::string>> words = shell_words(line.substr(replay_mark.size()));
    if (!words || words->empty()) {
      error = "its replay line cannot be read: " + line;
      return std::nullopt;
    }
    header.replay.assign(words->begin() + 1, words->end());
    header.has_replay = true;
  }
  return header;
}

// The replay's options, parsed as `scenfuzz run` parses them.
std::optional<RunCommandOptions> replay_options(const std::vector<std::string>& words,
                                                std::string& error) {
  RunCommandOptions options;
  CLI::App app;
  add_run_options(&app, options);
  std::vector<std::string> reversed(words.rbegin(), words.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    error = "its replay line has options 'scenfuzz run' does not take: " + std::string(e.what());
    return std::nullopt;
  }
  if (std::optional<std::string> problem = check_simulation_options(options.simulation)) {
    error = "its replay line's options: " + *problem;
    return std::nullopt;
  }
  return options;
}

// One replay of a scenario as the search judges it.
struct Replay {
  std::string mode;  // the failure-mode signature; empty: it did not fail
  std::string atom;  // the violated atom as the mode names it (an ego failure: empty)
  std::string why;   // why it could not be judged, when it could not
  std::string spec;  // the violated spec's name (an ego failure: empty)
  TminCheck check;   // same_failure left for the caller
};

Replay replay(const SourceFile& file, ScenarioTemplate scenario, const RunCommandOptions& run,
              std::optional<double> duration) {
  SimulationCommandOptions flags = run.simulation;
  if (duration) flags.duration = duration;
  apply_scenario_overrides(flags, scenario);
  Replay result;
  try {
    const std::vector<fs::path> map_paths(flags.map_paths.begin(), flags.map_paths.end());
    ScenarioEvaluator evaluator(file, scenario, map_search_path(map_paths),
                                simulation_options(flags));
    evaluator.set_judge_options(judge_options(flags));
    const ScenarioRun outcome = evaluator.run({}, run.seed);
    result.mode = run_signature(outcome);
    result.why = outcome.infeasible + outcome.failure;
    if (!outcome.trace) return result;
    if (!outcome.trace->time.empty()) result.check.end_time = outcome.trace->time.back();
    if (outcome.trace->ego_failure) result.check.failure_time = outcome.trace->ego_failure->time;
    const std::vector<std::size_t> order = violation_order(outcome.verdicts);
    if (!order.empty()) {
      const SpecVerdict& verdict = outcome.verdicts[order.front()];
      result.spec = verdict.name;
      result.check.failure_time = verdict.time;
      if (outcome.map) result.atom = describe_failure(*outcome.trace, *outcome.map, verdict).atom;
    }
  } catch (const std::exception& error) {
    // A map that cannot be loaded, a spec that cannot be judged: this candidate does not fail.
    result.mode.clear();
    result.why = error.what();
  }
  return result;
}

// A candidate's printed text, parsed again (nullopt when it does not read back).
struct Printed {
  SourceFile file;
  ScenarioTemplate scenario;
};

template <typename Parse>
std::optional<Printed> parse_printed(SourceFile file, const Parse& parse) {
  auto parsed = parse(file);
  if (!parsed.ok() || !parsed.scenario.has_scenario) return std::nullopt;
  return Printed{std::move(file), std::move(parsed.scenario)};
}

// `text` read back in the language it is written in.
std::optional<Printed> parse_printed(const std::string& path, std::string text, bool wmg) {
  SourceFile file(path, std::move(text));
  if (wmg) return parse_printed(std::move(file), [](const SourceFile& f) { return wmg::parse(f); });
  return parse_printed(std::move(file), [](const SourceFile& f) { return avunit::parse(f); });
}

// A replay's mode without the atom it starts with: the finding's own spelling of an atom and
// canonical AVUnit's may differ ("dis_lead > 0.5" and the expression it names), and an atom may
// hold " | " itself.
std::string mode_beyond_atom(const Replay& replay) {
  if (replay.atom.empty() || !replay.mode.starts_with(replay.atom)) return replay.mode;
  return replay.mode.substr(replay.atom.size());
}

// The replay's words for the output: its path, the seed, the finding's other options, and the
// cut duration instead of the finding's.
std::string replay_command(const std::string& out, const RunCommandOptions& run,
                           const std::vector<std::string>& words, std::optional<double> duration) {
  std::string command = "scenfuzz run " + shell_quote(out) + " --seed " + std::to_string(run.seed);
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (words[i] == "--seed" || words[i] == "--duration") {
      ++i;
      continue;
    }
    if (words[i].starts_with("--seed=") || words[i].starts_with("--duration=")) continue;
    command += " " + shell_quote(words[i]);
  }
  if (duration) command += " --duration " + format_number(*duration);
  return command;
}

// What either language's reduction gives: the result printed, its duration, what changed.
struct Reduced {
  std::string text;  // without the output's header
  std::optional<double> duration;
  std::vector<std::string> changes;
  std::size_t actors_removed = 0, waypoints_removed = 0, obstacles_removed = 0;
  std::size_t digits_before = 0, digits_after = 0;
  std::size_t checks = 0;
};

std::string output_header(const std::string& input, const std::string& mode,
                          const Reduced& reduction, const std::string& replay) {
  const std::string comment = comment_prefix(input);
  std::string header = comment + "scenfuzz tmin: " + input + " minimised in " +
                       std::to_string(reduction.checks) + " replays, the same failure\n";
  header += comment + "failure mode: " + mode + "\n";
  if (reduction.changes.empty()) header += comment + "nothing could be removed or changed\n";
  for (const std::string& change : reduction.changes) header += comment + change + "\n";
  return header + comment + "replay: " + replay + "\n";
}

// The input read, parsed and replayed: what the reduction starts from.
struct Start {
  std::optional<SourceFile> file;
  ScenarioTemplate scenario;
  std::optional<wmg::Level2File> tree;  // a WMG SDL file's level-2 syntax tree
  RunCommandOptions run;
  FindingHeader header;
  Replay original;
};

// The finding's header and its replay's options: which scenario of the file it is of, too.
std::string load_header(const std::string& path, Start& start) {
  std::string error;
  std::optional<FindingHeader> header =
      read_header(start.file->text(), comment_prefix(path), error);
  if (!header) return "'" + path + "': " + error;
  start.header = std::move(*header);
  std::optional<RunCommandOptions> run = replay_options(start.header.replay, error);
  if (!run) return "'" + path + "': " + error;
  start.run = std::move(*run);
  return "";
}

std::string load(const std::string& path, Start& start) {
  start.file = read_source_file(path);
  if (!start.file) return "cannot read '" + path + "'";
  if (std::string error = load_header(path, start); !error.empty()) return error;
  ScenarioParse parsed =
      parse_scenario_file(*start.file, avunit::ParseOptions{start.run.choice.scenario, false});
  if (!parsed.ok())
    return "'" + path + "' is not a scenario scenfuzz can read:\n" +
           format_diagnostics(*start.file, parsed.diagnostics);
  if (!parsed.scenario.has_scenario)
    return "'" + path + "' builds no scenario: nothing to minimise";
  if (!parsed.scenario.parameters.empty())
    return "'" + path + "' is a logical scenario with " +
           std::to_string(parsed.scenario.parameters.size()) +
           " parameters; tmin minimises a concrete one (a finding of the search)";
  start.scenario = std::move(parsed.scenario);
  if (is_wmg_file(path)) {
    // WMG SDL is reduced on its level-2 tree (a level-1 file as the level-2 text it stands for):
    // the IR cannot be printed back as WMG SDL.
    const wmg::Level2Text level2 = wmg::level2_text(*start.file);
    wmg::Level2ParseResult tree = wmg::parse_level2(SourceFile(path, level2.text));
    if (!tree.file) return "'" + path + "' has no level-2 text tmin can reduce";
    start.tree = std::move(tree.file);
  }
  start.original = replay(*start.file, start.scenario, start.run, std::nullopt);
  if (start.original.mode.empty() && !start.original.why.empty())
    return "'" + path + "' cannot be replayed and judged: " + start.original.why;
  if (start.original.mode.empty())
    return "'" + path + "' does not fail when replayed with seed " +
           std::to_string(start.run.seed) + ": nothing to minimise";
  if (!start.header.mode.empty() && start.header.mode != start.original.mode)
    return "'" + path + "' no longer fails as its header says (" + start.header.mode +
           "): it replays as " + start.original.mode;
  return "";
}

Reduced reduce_avunit(const Start& start, const TminCheck& first_check,
                      const std::function<TminCheck(std::string, std::optional<double>)>& check) {
  const TminReduction reduction =
      reduce_failing_scenario(TminCandidate{start.scenario, start.run.simulation.duration},
                              first_check, [&](const TminCandidate& candidate) {
                                return check(avunit::print(candidate.scenario), candidate.duration);
                              });
  return Reduced{avunit::print(reduction.result.scenario),
                 reduction.result.duration,
                 reduction.changes,
                 reduction.actors_removed,
                 reduction.waypoints_removed,
                 reduction.obstacles_removed,
                 reduction.digits_before,
                 reduction.digits_after,
                 reduction.checks};
}

Reduced reduce_wmg(const Start& start, const TminCheck& first_check,
                   const std::function<TminCheck(std::string, std::optional<double>)>& check) {
  const WmgTminReduction reduction =
      reduce_failing_wmg(WmgTminCandidate{*start.tree, start.run.simulation.duration}, first_check,
                         [&](const WmgTminCandidate& candidate) {
                           return check(wmg::print_level2(candidate.file), candidate.duration);
                         });
  Reduced reduced{wmg::print_level2(reduction.result.file), reduction.result.duration,
                  reduction.changes};
  reduced.actors_removed = reduction.actors_removed;
  reduced.digits_before = reduction.digits_before;
  reduced.digits_after = reduction.digits_after;
  reduced.checks = reduction.checks;
  return reduced;
}

bool asked_to_stop(const TminOptions& options) {
  return options.interrupted && options.interrupted();
}

TminResult interrupted_result(const std::string& finding_path) {
  TminResult result;
  result.interrupted = true;
  result.error = "the minimisation of '" + finding_path + "' was interrupted";
  return result;
}

}  // namespace

std::string default_minimised_path(const std::string& input) {
  // The output is in the finding's language: <stem>.min.avu or <stem>.min.sdl.
  const fs::path path(input);
  return (path.parent_path() / (path.stem().string() + ".min" + concrete_extension(input)))
      .string();
}

TminResult minimize_finding(const std::string& finding_path, const TminOptions& options) {
  if (asked_to_stop(options)) return interrupted_result(finding_path);
  TminResult result;
  Start start;
  result.error = load(finding_path, start);
  if (!result.ok()) return result;
  result.out_path =
      options.out_path.empty() ? default_minimised_path(finding_path) : options.out_path;
  // `scenfuzz run` reads a file by its extension: the output's must be the finding's language's.
  const bool wmg = start.tree.has_value();
  if (is_wmg_file(result.out_path) != wmg) {
    result.error = "'" + result.out_path + "': the minimised " + finding_path + " is written in " +
                   (wmg ? "WMG SDL" : "AVUnit") + ", so its name must end in " +
                   concrete_extension(finding_path);
    return result;
  }

  // Every candidate is replayed as the text it prints as, so the kept mode is the output's.
  const std::string canonical_text =
      wmg ? wmg::print_level2(*start.tree) : avunit::print(start.scenario);
  std::optional<Printed> canonical = parse_printed(result.out_path, canonical_text, wmg);
  const Replay first =
      canonical ? replay(canonical->file, canonical->scenario, start.run, std::nullopt) : Replay{};
  if (first.mode.empty() || mode_beyond_atom(first) != mode_beyond_atom(start.original) ||
      first.spec != start.original.spec) {
    result.error = "'" + finding_path + "' printed as canonical " +
                   (wmg ? "WMG SDL level 2 " : "AVUnit ") +
                   (first.mode.empty() ? std::string("does not fail") : "fails as " + first.mode) +
                   ", not as " + start.original.mode + ": it cannot be minimised";
    return result;
  }
  result.mode = first.mode;
  const auto still_fails = [&](std::string text, std::optional<double> duration) {
    // Once a stop is asked for, every candidate "passes" without a replay: the reduction then
    // ends in moments, and its result is thrown away below.
    if (asked_to_stop(options)) return TminCheck{};
    std::optional<Printed> printed = parse_printed(result.out_path, std::move(text), wmg);
    if (!printed) return TminCheck{};
    Replay again = replay(printed->file, printed->scenario, start.run, duration);
    again.check.same_failure = again.mode == result.mode;
    return again.check;
  };
  TminCheck first_check = first.check;
  first_check.same_failure = true;
  const Reduced reduction = wmg ? reduce_wmg(start, first_check, still_fails)
                                : reduce_avunit(start, first_check, still_fails);

  if (asked_to_stop(options)) return interrupted_result(finding_path);
  result.replay =
      replay_command(result.out_path, start.run, start.header.replay, reduction.duration);
  const std::string header = output_header(finding_path, result.mode, reduction, result.replay);
  // The written text itself replayed once more: the output must fail as the finding did.
  std::optional<Printed> output = parse_printed(result.out_path, header + reduction.text, wmg);
  const Replay check =
      output ? replay(output->file, output->scenario, start.run, reduction.duration) : Replay{};
  if (check.mode != result.mode) {
    result.error = "the minimised scenario replays as '" + check.mode + "', not as '" +
                   result.mode + "' (please report this)";
    return result;
  }
  result.error = write_file_atomically(result.out_path, output->file.text());
  if (!result.ok()) return result;
  result.changes = reduction.changes;
  result.actors_before = start.scenario.vehicles.size() + start.scenario.pedestrians.size();
  result.actors_removed = reduction.actors_removed;
  result.waypoints_removed = reduction.waypoints_removed;
  result.obstacles_removed = reduction.obstacles_removed;
  result.digits_before = reduction.digits_before;
  result.digits_after = reduction.digits_after;
  result.replays = reduction.checks;
  return result;
}

}  // namespace scenfuzz

// The command-line options of `scenfuzz run` and of the search, declared once in fuzz/options.def:
// the functions that add a group of them to a CLI11 command (each option with its check and its
// help), the bounds the checks enforce, and the checks that concern several options at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fuzz/commands.hpp"
#include "fuzz/search.hpp"
#include "lang/scenario.hpp"
#include "lang/spec.hpp"
#include "oracle/judge.hpp"
#include "physics/simulation/simulation.hpp"
#include "physics/simulation/simulation_limits.hpp"
#include "sampler/mutation_space.hpp"

namespace CLI {
class App;
}

namespace scenfuzz {

// Bounds of the numeric options, so that no value on the command line can exhaust memory, wrap
// around or trip an assertion before any work is done.
// --duration and duration / dt: the simulation's own limits (physics/simulation/simulation_limits).
inline constexpr double kMaxDuration = kMaxScenarioDuration;
inline constexpr double kMaxSimulationSteps = static_cast<double>(kMaxTraceSamples - 1);
inline constexpr double kMaxBudget = 1e9;       // --budget
inline constexpr double kMaxJobs = 1024;        // -j: threads are created up front
inline constexpr double kMaxEgoTimeout = 3600;  // --ego-step-timeout, --ego-start-timeout

// The values an option accepts: numbers (finite) within bounds, or one of some words.
struct OptionCheck {
  double lowest = -std::numeric_limits<double>::infinity();
  bool lowest_included = true;
  double highest = std::numeric_limits<double>::infinity();  // included
  std::vector<std::string> choices;                          // words; empty: any text
};

OptionCheck any_value();
OptionCheck positive(double highest);               // (0, highest]
OptionCheck within(double lowest, double highest);  // [lowest, highest]
OptionCheck one_of(std::vector<std::string> choices);

// A bound as the help and the messages print it: whole numbers in full (1000000000, not 1e+09).
std::string bound_text(double bound);

// What `check` accepts, in words ("> 0 and <= 1", "from 1 to 1024"); empty for any value.
std::string check_text(const OptionCheck& check);

// Adds one option to `app`, bound to `field`: a flag for a bool, a repeatable option for a list,
// and for numbers a parser of its own that rejects what is not a finite number within `check`
// (no wrap-around of "-1" into an unsigned field) with a message naming the option. `shown` is
// the default the help states ("" for the field's initial value).
void add_checked_option(CLI::App* app, const std::string& names, bool& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names, std::string& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names, std::vector<std::string>& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names, double& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names, std::optional<double>& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names, std::uint64_t& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown);
void add_checked_option(CLI::App* app, const std::string& names,
                        std::optional<std::uint64_t>& field, const std::string& value_name,
                        const OptionCheck& check, const std::string& help,
                        const std::string& shown);

// The options of fuzz/options.def of one group, added to `app` and bound to `options`'s fields.
// The simulation's options go under their own heading in the help.
void add_simulation_options(CLI::App* app, SimulationCommandOptions& options);
// `run`'s own options and the simulation's.
void add_run_options(CLI::App* app, RunCommandOptions& options);
// The search's own options, the mutation's and the simulation's.
void add_search_options(CLI::App* app, FuzzCommandOptions& options);
// `reconstruct`'s options: the budget's, its own and the simulation's.
void add_reconstruct_options(CLI::App* app, ReconstructCommandOptions& options);
// -j and --seed of the corpus tools, on `options` (CoverageCommandOptions, CminCommandOptions),
// and the simulation's options.
template <typename CorpusOptions>
void add_corpus_options(CLI::App* app, CorpusOptions& options) {
#define SCENFUZZ_CORPUS_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
  add_simulation_options(app, options.simulation);
}
// --scenario: `run`, the search, `space` and `check`.
void add_scenario_options(CLI::App* app, ScenarioChoiceOptions& options);
// --mutate, for the search and `space`.
void add_mutation_options(CLI::App* app, MutationCommandOptions& options);

// The neighbourhood sizes --mutate asks for, over the defaults; or the first bad --mutate.
struct MutationSizesOrError {
  MutationSizes sizes;
  std::string error;  // non-empty: the message, naming --mutate
};
MutationSizesOrError mutation_sizes(const MutationCommandOptions& options);

// A simulation of `duration` s in steps of `dt` s (both already checked on their own) is at most
// kMaxSimulationSteps long; otherwise the reason, naming --duration and --dt, for an error
// message. `duration_source` says where the duration came from ("--duration 100" or "the
// scenario's duration 100 s").
std::optional<std::string> check_step_count(double duration, double dt,
                                            const std::string& duration_source);

// A warning for every spec that reads further than an explicit --duration (lang/spec_horizon.hpp):
// its verdict may be a time-out. Empty without --duration.
std::vector<std::string> duration_warnings(const SimulationCommandOptions& options,
                                           std::span<const Spec> specs);

// What the simulation is asked for by the command line's options (the seed apart).
SimulationOptions simulation_options(const SimulationCommandOptions& options);

// The search's options the BUDGET rows of fuzz/options.def set, from a command's options (the
// search's, `reconstruct`'s): each row's field has the same name in SearchOptions.
template <typename CommandOptions>
SearchOptions budget_search_options(const CommandOptions& options) {
  SearchOptions search;
#define SCENFUZZ_BUDGET_OPTION(TYPE, FIELD, ...) search.FIELD = options.FIELD;
#include "fuzz/options.def"
  return search;
}

// The scenario as the command line overrides it: --npc-behaviour replaces the scenario's own
// switch, so that setting up the simulation (its warnings included) sees the behaviour it runs.
void apply_scenario_overrides(const SimulationCommandOptions& options, ScenarioTemplate& scenario);

// How the oracle judges collisions by the command line's options (--rss already checked).
JudgeOptions judge_options(const SimulationCommandOptions& options);

// The checks of the simulation options together, once each has passed its own: nullopt, or the
// reason for an error message.
std::optional<std::string> check_simulation_options(const SimulationCommandOptions& options);

}  // namespace scenfuzz

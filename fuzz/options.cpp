// The options of fuzz/options.def as CLI11 options: each parsed and checked the same way wherever
// it appears, with a help text that states its bounds and its default.
#include "fuzz/options.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <system_error>
#include <type_traits>
#include <utility>

#include "lang/number_format.hpp"
#include "lang/spec_horizon.hpp"
#include "physics/simulation/default_duration.hpp"

namespace scenfuzz {

// A size_t field and a uint64_t field are parsed by the same overload.
static_assert(std::is_same_v<std::size_t, std::uint64_t>);

OptionCheck any_value() { return {}; }

OptionCheck positive(double highest) { return {0, false, highest, {}}; }

OptionCheck within(double lowest, double highest) { return {lowest, true, highest, {}}; }

OptionCheck one_of(std::vector<std::string> choices) {
  OptionCheck check;
  check.choices = std::move(choices);
  return check;
}

std::string bound_text(double bound) {
  if (bound == std::floor(bound) && std::fabs(bound) < 1e15)
    return std::to_string(static_cast<long long>(bound));
  return format_number(bound);
}

std::string check_text(const OptionCheck& check) {
  if (!check.choices.empty()) {
    std::string text = "one of";
    for (const std::string& choice : check.choices) text += " " + choice;
    return text;
  }
  const bool bounded_below = std::isfinite(check.lowest);
  const bool bounded_above = std::isfinite(check.highest);
  if (bounded_below && check.lowest_included && bounded_above)
    return "from " + bound_text(check.lowest) + " to " + bound_text(check.highest);
  std::string text;
  if (bounded_below) text = (check.lowest_included ? ">= " : "> ") + bound_text(check.lowest);
  if (bounded_above) text += (text.empty() ? "<= " : " and <= ") + bound_text(check.highest);
  return text;
}

namespace {

const std::string kSimulationGroup = "Simulation options";

// The check's bounds as the help states them, with the value's name: "0 < S <= 1", "N >= 1".
std::string bounds_text(const OptionCheck& check, const std::string& value_name) {
  const bool bounded_below = std::isfinite(check.lowest);
  const bool bounded_above = std::isfinite(check.highest);
  const std::string below = bound_text(check.lowest) + (check.lowest_included ? " <= " : " < ");
  if (bounded_below && bounded_above)
    return below + value_name + " <= " + bound_text(check.highest);
  if (bounded_below)
    return value_name + (check.lowest_included ? " >= " : " > ") + bound_text(check.lowest);
  if (bounded_above) return value_name + " <= " + bound_text(check.highest);
  return "";
}

// "Simulated seconds per step (0 < S <= 1; default 0.05)": the help, the bounds, the default.
std::string help_text(const std::string& help, const OptionCheck& check,
                      const std::string& value_name, const std::string& shown) {
  std::vector<std::string> notes;
  if (check.choices.empty() && !bounds_text(check, value_name).empty())
    notes.push_back(bounds_text(check, value_name));
  if (!shown.empty()) notes.push_back("default " + shown);
  if (notes.empty()) return help;
  return help + " (" + (notes.size() == 1 ? notes[0] : notes[0] + "; " + notes[1]) + ")";
}

bool within_bounds(double value, const OptionCheck& check) {
  const bool above_lowest = check.lowest_included ? value >= check.lowest : value > check.lowest;
  return above_lowest && value <= check.highest;
}

// The message of a rejected value: "--dt: expected a finite number > 0 and <= 1, got '0'".
[[noreturn]] void reject(const std::string& names, const std::string& expected,
                         const std::string& text) {
  throw CLI::ValidationError(names, "expected " + expected + ", got '" + text + "'");
}

// The whole text as a finite double within the check's bounds.
double parse_number(const std::string& names, const OptionCheck& check, const std::string& text) {
  const std::string expected = "a finite number " + check_text(check);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
      !within_bounds(value, check))
    reject(names, expected, text);
  return value;
}

// The whole text as a whole number within the check's bounds; a sign is refused, so "-1" does not
// wrap around to 2^64 - 1.
std::uint64_t parse_count(const std::string& names, const OptionCheck& check,
                          const std::string& text) {
  const std::string bounds = check_text(check);
  const std::string expected = "a whole number " + (bounds.empty() ? ">= 0" : bounds);
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() ||
      !within_bounds(static_cast<double>(value), check))
    reject(names, expected, text);
  return value;
}

// An option with one value, given at most once, parsed into `field` by `parse`.
template <typename Field, typename Parse>
void add_parsed_option(CLI::App* app, const std::string& names, Field& field,
                       const std::string& value_name, const OptionCheck& check,
                       const std::string& help, const std::string& shown, Parse parse) {
  app->add_option_function<std::string>(
         names,
         [&field, names, check, parse](const std::string& text) {
           field = parse(names, check, text);
         },
         help_text(help, check, value_name, shown))
      ->type_name(value_name);
}

template <typename Number>
std::string shown_default(const Number& value, const std::string& shown) {
  return shown.empty() ? bound_text(static_cast<double>(value)) : shown;
}

}  // namespace

void add_checked_option(CLI::App* app, const std::string& names, bool& field,
                        const std::string& /*value_name*/, const OptionCheck& /*check*/,
                        const std::string& help, const std::string& shown) {
  app->add_flag(names, field, help_text(help, {}, "", shown));
}

void add_checked_option(CLI::App* app, const std::string& names, std::string& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown) {
  CLI::Option* option = app->add_option(
      names, field, help_text(help, check, value_name, shown.empty() ? field : shown));
  if (check.choices.empty()) {
    option->type_name(value_name);
    return;
  }
  // The choices name the value ("mid|random"); the check need not list them again.
  std::string choices;
  for (const std::string& choice : check.choices) choices += (choices.empty() ? "" : "|") + choice;
  option->check(CLI::IsMember(check.choices).description(""))->type_name(choices);
}

void add_checked_option(CLI::App* app, const std::string& names, std::vector<std::string>& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown) {
  app->add_option(names, field, help_text(help, check, value_name, shown))
      ->type_name(value_name)
      ->allow_extra_args(false);
}

void add_checked_option(CLI::App* app, const std::string& names, double& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown) {
  add_parsed_option(app, names, field, value_name, check, help, shown_default(field, shown),
                    parse_number);
}

void add_checked_option(CLI::App* app, const std::string& names, std::optional<double>& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown) {
  add_parsed_option(app, names, field, value_name, check, help,
                    field ? shown_default(*field, shown) : shown, parse_number);
}

void add_checked_option(CLI::App* app, const std::string& names, std::uint64_t& field,
                        const std::string& value_name, const OptionCheck& check,
                        const std::string& help, const std::string& shown) {
  add_parsed_option(app, names, field, value_name, check, help, shown_default(field, shown),
                    parse_count);
}

void add_checked_option(CLI::App* app, const std::string& names,
                        std::optional<std::uint64_t>& field, const std::string& value_name,
                        const OptionCheck& check, const std::string& help,
                        const std::string& shown) {
  add_parsed_option(app, names, field, value_name, check, help,
                    field ? shown_default(*field, shown) : shown, parse_count);
}

// Every row of a group becomes one add_checked_option on the struct's field; the struct's
// initial value is the default the help shows.
void add_simulation_options(CLI::App* app, SimulationCommandOptions& options) {
  const std::size_t before = app->get_options().size();
#define SCENFUZZ_SIMULATION_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
  // CLI11 keeps an app's options in the order they were added: those after `before` are ours.
  const std::vector<CLI::Option*> all = app->get_options();
  for (std::size_t i = before; i < all.size(); ++i) all[i]->group(kSimulationGroup);
}

void add_run_options(CLI::App* app, RunCommandOptions& options) {
#define SCENFUZZ_RUN_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
  add_scenario_options(app, options.choice);
  add_simulation_options(app, options.simulation);
}

void add_scenario_options(CLI::App* app, ScenarioChoiceOptions& options) {
#define SCENFUZZ_SCENARIO_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
}

void add_mutation_options(CLI::App* app, MutationCommandOptions& options) {
#define SCENFUZZ_MUTATION_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
}

void add_search_options(CLI::App* app, FuzzCommandOptions& options) {
#define SCENFUZZ_BUDGET_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#define SCENFUZZ_SEARCH_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
  add_scenario_options(app, options.choice);
  add_mutation_options(app, options.mutation);
  add_simulation_options(app, options.simulation);
}

void add_reconstruct_options(CLI::App* app, ReconstructCommandOptions& options) {
#define SCENFUZZ_BUDGET_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#define SCENFUZZ_RECONSTRUCT_OPTION(TYPE, FIELD, DEFAULT, SHOWN, NAMES, VALUE, CHECK, HELP) \
  add_checked_option(app, NAMES, options.FIELD, VALUE, CHECK, HELP, SHOWN);
#include "fuzz/options.def"
  add_simulation_options(app, options.simulation);
}

MutationSizesOrError mutation_sizes(const MutationCommandOptions& options) {
  MutationSizesOrError result;
  for (const std::string& option : options.mutate)
    if (std::optional<std::string> problem = apply_mutation_option(option, result.sizes)) {
      result.error = *problem;
      return result;
    }
  return result;
}

std::optional<std::string> check_step_count(double duration, double dt,
                                            const std::string& duration_source) {
  if (duration / dt <= kMaxSimulationSteps) return std::nullopt;
  return duration_source + " at --dt " + format_number(dt) + " is " +
         bound_text(std::floor(duration / dt)) + " steps, more than the " +
         bound_text(kMaxSimulationSteps) + " a simulation may take; raise --dt or lower " +
         "--duration";
}

std::vector<std::string> duration_warnings(const SimulationCommandOptions& options,
                                           std::span<const Spec> specs) {
  std::vector<std::string> warnings;
  if (!options.duration) return warnings;
  for (const SpecHorizon& short_of : horizons_beyond(specs, *options.duration))
    warnings.push_back("--duration " + format_number(*options.duration) +
                       " is shorter than spec '" + short_of.spec + "' reads (" +
                       format_number(short_of.seconds) +
                       " s): its verdict may be a time-out (docs/search.md)");
  return warnings;
}

SimulationOptions simulation_options(const SimulationCommandOptions& options) {
  SimulationOptions simulation;
  simulation.dt = options.dt;
  simulation.duration = options.duration;
  simulation.stop_at_collision = !options.continue_after_collision;
  simulation.ego_plugin = options.ego_plugin;
  simulation.plugin_step_timeout = options.ego_step_timeout;
  simulation.plugin_start_timeout = options.ego_start_timeout;
  if (options.npc_behaviour == "reactive") simulation.npc_behaviour = NpcBehaviour::reactive;
  if (options.npc_behaviour == "scripted") simulation.npc_behaviour = NpcBehaviour::scripted;
  return simulation;
}

void apply_scenario_overrides(const SimulationCommandOptions& options, ScenarioTemplate& scenario) {
  if (std::optional<NpcBehaviour> behaviour = simulation_options(options).npc_behaviour)
    scenario.npc_behaviour = behaviour;
}

JudgeOptions judge_options(const SimulationCommandOptions& options) {
  JudgeOptions judge;
  judge.all_collisions = options.all_collisions;
  judge.violation_at_zero = options.violation_at_zero;
  if (const RssParametersOrError rss = parse_rss_parameters(options.rss); rss.parameters)
    judge.rss = *rss.parameters;
  return judge;
}

std::optional<std::string> check_simulation_options(const SimulationCommandOptions& options) {
  if (const RssParametersOrError rss = parse_rss_parameters(options.rss); !rss.parameters)
    return "--rss: " + rss.error;
  if (!options.duration) return std::nullopt;
  return check_step_count(*options.duration, options.dt,
                          "--duration " + format_number(*options.duration));
}

}  // namespace scenfuzz

// The steps of the reduction (tmin.hpp), each a short function over a Reducer that holds the
// scenario reduced so far and adopts a candidate only when the predicate says it still fails.
#include "fuzz/tmin.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "fuzz/significant_digits.hpp"
#include "fuzz/tmin_specs.hpp"
#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/walk_values.hpp"

namespace scenfuzz {

namespace {

using Reducer = TminReducer<TminReduction, TminCandidate>;

std::string actor_kind_word(ActorKind kind) {
  switch (kind) {
    case ActorKind::ego: return "ego";
    case ActorKind::vehicle: return "vehicle";
    case ActorKind::pedestrian: return "pedestrian";
    case ActorKind::cyclist: return "cyclist";
  }
  return "actor";
}

// `items` without those `kept` is false for.
template <typename T>
std::vector<T> kept_items(const std::vector<T>& items, const std::vector<bool>& kept,
                          std::size_t first = 0) {
  std::vector<T> result;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (kept[first + i]) result.push_back(items[i]);
  return result;
}

// The scenario's other actors (vehicles, then pedestrians) as one list; the ego is never removed.
void remove_actors(Reducer& reducer) {
  const ScenarioTemplate& start = reducer.reduction.result.scenario;
  const std::vector<Actor> vehicles = start.vehicles, pedestrians = start.pedestrians;
  const auto without = [&](const std::vector<bool>& kept) {
    TminCandidate candidate = reducer.reduction.result;
    candidate.scenario.vehicles = kept_items(vehicles, kept);
    candidate.scenario.pedestrians = kept_items(pedestrians, kept, vehicles.size());
    // The spec atoms that read a removed actor go with it.
    std::set<std::string> removed;
    for (std::size_t i = 0; i < kept.size(); ++i)
      if (!kept[i])
        removed.insert(i < vehicles.size() ? vehicles[i].name
                                           : pedestrians[i - vehicles.size()].name);
    candidate.scenario.specs = specs_without_actors(candidate.scenario.specs, removed);
    return candidate;
  };
  const std::vector<bool> kept = reduce_list(
      vehicles.size() + pedestrians.size(),
      [&](const std::vector<bool>& trial) { return reducer.adopt_if_failing(without(trial)); });
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i]) continue;
    const Actor& actor = i < vehicles.size() ? vehicles[i] : pedestrians[i - vehicles.size()];
    reducer.reduction.changes.push_back("removed " + actor_kind_word(actor.kind) + " " +
                                        actor.name);
    ++reducer.reduction.actors_removed;
  }
}

// The waypoints of one actor (vehicles[index] or, past them, pedestrians[...]).
Actor& actor_at(ScenarioTemplate& scenario, std::size_t index) {
  return index < scenario.vehicles.size() ? scenario.vehicles[index]
                                          : scenario.pedestrians[index - scenario.vehicles.size()];
}

void remove_waypoints(Reducer& reducer) {
  ScenarioTemplate& scenario = reducer.reduction.result.scenario;
  const std::size_t actors = scenario.vehicles.size() + scenario.pedestrians.size();
  for (std::size_t a = 0; a < actors; ++a) {
    const Actor actor = actor_at(reducer.reduction.result.scenario, a);
    if (actor.motion.kind != MotionKind::waypoints || actor.motion.states.empty()) continue;
    const std::vector<bool> kept =
        reduce_list(actor.motion.states.size(), [&](const std::vector<bool>& trial) {
          TminCandidate candidate = reducer.reduction.result;
          actor_at(candidate.scenario, a).motion.states = kept_items(actor.motion.states, trial);
          return reducer.adopt_if_failing(std::move(candidate));
        });
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (kept[i]) continue;
      reducer.reduction.changes.push_back("removed waypoint " + std::to_string(i + 1) + " of " +
                                          actor.name);
      ++reducer.reduction.waypoints_removed;
    }
  }
}

void remove_obstacles(Reducer& reducer) {
  const std::vector<Obstacle> obstacles = reducer.reduction.result.scenario.obstacles;
  const std::vector<bool> kept = reduce_list(obstacles.size(), [&](const std::vector<bool>& trial) {
    TminCandidate candidate = reducer.reduction.result;
    candidate.scenario.obstacles = kept_items(obstacles, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i]) continue;
    reducer.reduction.changes.push_back("removed obstacle " + obstacles[i].name);
    ++reducer.reduction.obstacles_removed;
  }
}

std::string weather_text(const WeatherComponent& component) {
  const std::string intensity =
      is_constant(component.intensity) ? " " + format_number(component.intensity.constant) : "";
  return component.kind + intensity;
}

// Dry and clear: no weather component at all; else as few as keep the failure.
void neutral_weather(Reducer& reducer) {
  const std::optional<Environment>& environment = reducer.reduction.result.scenario.environment;
  if (!environment || environment->weather.empty()) return;
  const std::vector<WeatherComponent> weather = environment->weather;
  const std::vector<bool> kept = reduce_list(weather.size(), [&](const std::vector<bool>& trial) {
    TminCandidate candidate = reducer.reduction.result;
    candidate.scenario.environment->weather = kept_items(weather, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (!kept[i])
      reducer.reduction.changes.push_back("removed weather " + weather_text(weather[i]));
}

void noon(Reducer& reducer) {
  const std::optional<Environment>& environment = reducer.reduction.result.scenario.environment;
  if (!environment || !environment->time_of_day) return;
  const Value& time = *environment->time_of_day;
  if (is_constant(time) && time.constant == kNoonSeconds) return;
  TminCandidate candidate = reducer.reduction.result;
  candidate.scenario.environment->time_of_day = constant_value(kNoonSeconds, time.location);
  const std::string was = is_constant(time) ? format_time_of_day(time.constant) : "computed";
  if (reducer.adopt_if_failing(std::move(candidate)))
    reducer.reduction.changes.push_back("time of day " + was + " -> 12:00");
}

// Each number of the scenario to the fewest significant digits that keep the failure.
void round_numbers(Reducer& reducer) {
  std::vector<double> numbers = scenario_numbers(reducer.reduction.result.scenario);
  reducer.reduction.digits_before = total_digits(numbers);
  reducer.reduction.numbers_rounded = round_each(numbers, [&](const std::vector<double>& trial) {
    TminCandidate candidate = reducer.reduction.result;
    set_scenario_numbers(candidate.scenario, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  reducer.reduction.digits_after = total_digits(numbers);
  if (reducer.reduction.numbers_rounded > 0)
    reducer.reduction.changes.push_back(
        "rounded " + std::to_string(reducer.reduction.numbers_rounded) + " of " +
        std::to_string(numbers.size()) +
        " numbers: " + std::to_string(reducer.reduction.digits_before) + " -> " +
        std::to_string(reducer.reduction.digits_after) + " significant digits");
}

void cut_the_duration(Reducer& reducer) {
  const std::optional<double> cut = cut_duration(reducer.check);
  if (!cut) return;
  TminCandidate candidate = reducer.reduction.result;
  candidate.duration = *cut;
  const double ended = reducer.check.end_time;
  if (reducer.adopt_if_failing(std::move(candidate)))
    reducer.reduction.changes.push_back("duration cut to " + format_number(*cut) +
                                        " s (the run went on to " +
                                        format_number(std::round(ended * 100) / 100) + " s)");
}

// Calls `visit` on every constant inside `value` (arithmetic that was not folded included).
template <typename Visit>
void visit_constants(Value& value, const Visit& visit) {
  if (value.op == ValueOp::constant) visit(value.constant);
  for (Value& operand : value.operands) visit_constants(operand, visit);
}

// The walk scenario_numbers and set_scenario_numbers share: the specs, events and end conditions
// are set aside while it runs, and so is the time of day (noon, or a time that matters, is not
// made a rounder number of seconds: 43200 s is 4e4 s to one digit, 11:06:40).
template <typename Visit>
void walk_numbers(ScenarioTemplate& scenario, const Visit& visit) {
  std::vector<Spec> specs = std::exchange(scenario.specs, {});
  std::vector<ScenarioEvent> events = std::exchange(scenario.events, {});
  std::vector<Formula> end_conditions = std::exchange(scenario.end_conditions, {});
  std::optional<Value> time_of_day;
  if (scenario.environment) time_of_day = std::exchange(scenario.environment->time_of_day, {});
  for_each_value(scenario, [&](Value& value, const std::string&, const std::string&) {
    visit_constants(value, visit);
  });
  scenario.specs = std::move(specs);
  scenario.events = std::move(events);
  scenario.end_conditions = std::move(end_conditions);
  if (scenario.environment) scenario.environment->time_of_day = std::move(time_of_day);
}

}  // namespace

std::vector<bool> reduce_list(std::size_t count,
                              const std::function<bool(const std::vector<bool>&)>& fails_with) {
  std::vector<bool> kept(count, true);
  for (std::size_t chunk = (count + 1) / 2; chunk >= 1; chunk = (chunk + 1) / 2) {
    std::vector<std::size_t> alive;
    for (std::size_t i = 0; i < count; ++i)
      if (kept[i]) alive.push_back(i);
    for (std::size_t first = 0; first < alive.size(); first += chunk) {
      std::vector<bool> trial = kept;
      for (std::size_t j = first; j < std::min(first + chunk, alive.size()); ++j)
        trial[alive[j]] = false;
      if (fails_with(trial)) kept = std::move(trial);
    }
    if (chunk == 1) break;
  }
  return kept;
}

std::size_t round_each(std::vector<double>& numbers,
                       const std::function<bool(const std::vector<double>&)>& fails_with) {
  std::size_t rounded = 0;
  for (std::size_t i = 0; i < numbers.size(); ++i) {
    const double original = numbers[i];
    const int digits = significant_digits(original);
    int fewest = 1, enough = digits;
    while (fewest < enough) {
      const int middle = (fewest + enough) / 2;
      std::vector<double> trial = numbers;
      trial[i] = round_to_significant(original, middle);
      if (fails_with(trial)) {
        enough = middle;
        numbers = std::move(trial);
      } else {
        fewest = middle + 1;
      }
    }
    if (enough < digits) ++rounded;
  }
  return rounded;
}

std::size_t total_digits(const std::vector<double>& numbers) {
  std::size_t digits = 0;
  for (double number : numbers) digits += static_cast<std::size_t>(significant_digits(number));
  return digits;
}

std::optional<double> cut_duration(const TminCheck& check) {
  if (!std::isfinite(check.failure_time) || !std::isfinite(check.end_time)) return std::nullopt;
  const double cut = std::ceil(check.failure_time + kDurationMargin);
  if (cut >= check.end_time) return std::nullopt;
  return cut;
}

std::vector<double> scenario_numbers(const ScenarioTemplate& scenario) {
  ScenarioTemplate copy = scenario;
  std::vector<double> numbers;
  walk_numbers(copy, [&](double& number) { numbers.push_back(number); });
  return numbers;
}

void set_scenario_numbers(ScenarioTemplate& scenario, const std::vector<double>& numbers) {
  std::size_t next = 0;
  walk_numbers(scenario, [&](double& number) {
    if (next < numbers.size()) number = numbers[next];
    ++next;
  });
}

TminReduction reduce_failing_scenario(TminCandidate start, const TminCheck& start_check,
                                      const TminPredicate& still_fails) {
  SCENFUZZ_DEMAND(start_check.same_failure);
  TminReduction reduction;
  reduction.result = std::move(start);
  Reducer reducer{reduction, still_fails, start_check};
  remove_actors(reducer);
  remove_waypoints(reducer);
  remove_obstacles(reducer);
  neutral_weather(reducer);
  noon(reducer);
  round_numbers(reducer);
  cut_the_duration(reducer);
  return reduction;
}

}  // namespace scenfuzz

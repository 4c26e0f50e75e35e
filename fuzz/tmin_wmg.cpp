// The steps of the WMG SDL reduction (tmin_wmg.hpp), each a short function over a Reducer that
// holds the file reduced so far and adopts a candidate only when the predicate says it still
// fails; the list and digit searches are tmin.hpp's.
#include "fuzz/tmin_wmg.hpp"

#include <cmath>
#include <set>
#include <utility>

#include "lang/demand.hpp"
#include "lang/number_format.hpp"
#include "lang/wmg/reduce.hpp"

namespace scenfuzz {

namespace {

using Reducer = TminReducer<WmgTminReduction, WmgTminCandidate>;

// "vehicle", "pedestrian" or "cyclist": how the file initialises `actor`.
std::string actor_type_word(const wmg::Level2File& file, const std::string& actor) {
  for (const wmg::RelativeActorInit& init : file.dynamics.initialisation.relative) {
    if (init.actor.name != actor) continue;
    switch (init.type.value) {
      case wmg::ActorType::vehicle: return "vehicle";
      case wmg::ActorType::pedestrian: return "pedestrian";
      case wmg::ActorType::cyclist: return "cyclist";
    }
  }
  return "actor";
}

void remove_actors(Reducer& reducer) {
  const wmg::Level2File start = reducer.reduction.result.file;
  const std::vector<std::string> actors = wmg::other_actors(start);
  reduce_list(actors.size(), [&](const std::vector<bool>& trial) {
    WmgTminCandidate candidate = reducer.reduction.result;
    candidate.file = start;
    wmg::remove_actors(candidate.file, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  // Those placed relative to a removed actor went with it: the kept list does not say them all.
  const std::vector<std::string> left = wmg::other_actors(reducer.reduction.result.file);
  const std::set<std::string> kept(left.begin(), left.end());
  for (const std::string& actor : actors) {
    if (kept.contains(actor)) continue;
    reducer.reduction.changes.push_back("removed " + actor_type_word(start, actor) + " " + actor);
    ++reducer.reduction.actors_removed;
  }
}

void remove_phases(Reducer& reducer) {
  const wmg::Level2File start = reducer.reduction.result.file;
  const std::vector<wmg::PhaseName> phases = wmg::manoeuvre_phases(start);
  const std::vector<bool> kept = reduce_list(phases.size(), [&](const std::vector<bool>& trial) {
    WmgTminCandidate candidate = reducer.reduction.result;
    candidate.file = start;
    wmg::remove_phases(candidate.file, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (kept[i]) continue;
    reducer.reduction.changes.push_back("removed phase " + std::to_string(phases[i].number) +
                                        " of " + phases[i].actor);
    ++reducer.reduction.phases_removed;
  }
}

// Dry, calm and clear: every weather component neutral; else as few as keep the failure.
void neutral_weather(Reducer& reducer) {
  const wmg::Level2File start = reducer.reduction.result.file;
  const std::vector<std::string> components = wmg::weather_components(start);
  const auto dropped = [&](const std::vector<bool>& kept) {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < components.size(); ++i)
      if (!kept[i]) names.push_back(components[i]);
    return names;
  };
  const std::vector<bool> kept =
      reduce_list(components.size(), [&](const std::vector<bool>& trial) {
        WmgTminCandidate candidate = reducer.reduction.result;
        candidate.file = start;
        wmg::neutral_weather(candidate.file, dropped(trial));
        return reducer.adopt_if_failing(std::move(candidate));
      });
  for (const std::string& component : dropped(kept))
    reducer.reduction.changes.push_back("removed weather " + component);
}

void noon(Reducer& reducer) {
  const std::optional<wmg::NumberRange>& time =
      reducer.reduction.result.file.environment.time_of_day;
  if (!time) return;  // "Any": nothing to set
  const std::string was = time->is_range ? "a range" : format_time_of_day(time->low);
  WmgTminCandidate candidate = reducer.reduction.result;
  if (!wmg::set_time_of_day(candidate.file, kNoonSeconds)) return;
  if (reducer.adopt_if_failing(std::move(candidate)))
    reducer.reduction.changes.push_back("time of day " + was + " -> 12:00");
}

void round_numbers(Reducer& reducer) {
  WmgTminReduction& reduction = reducer.reduction;
  std::vector<double> numbers = wmg::file_numbers(reduction.result.file);
  reduction.digits_before = total_digits(numbers);
  reduction.numbers_rounded = round_each(numbers, [&](const std::vector<double>& trial) {
    WmgTminCandidate candidate = reduction.result;
    wmg::set_file_numbers(candidate.file, trial);
    return reducer.adopt_if_failing(std::move(candidate));
  });
  reduction.digits_after = total_digits(numbers);
  if (reduction.numbers_rounded > 0)
    reduction.changes.push_back("rounded " + std::to_string(reduction.numbers_rounded) + " of " +
                                std::to_string(numbers.size()) +
                                " numbers: " + std::to_string(reduction.digits_before) + " -> " +
                                std::to_string(reduction.digits_after) + " significant digits");
}

void cut_the_duration(Reducer& reducer) {
  const std::optional<double> cut = cut_duration(reducer.check);
  if (!cut) return;
  WmgTminCandidate candidate = reducer.reduction.result;
  candidate.duration = *cut;
  const double ended = reducer.check.end_time;
  if (reducer.adopt_if_failing(std::move(candidate)))
    reducer.reduction.changes.push_back("duration cut to " + format_number(*cut) +
                                        " s (the run went on to " +
                                        format_number(std::round(ended * 100) / 100) + " s)");
}

}  // namespace

WmgTminReduction reduce_failing_wmg(WmgTminCandidate start, const TminCheck& start_check,
                                    const WmgTminPredicate& still_fails) {
  SCENFUZZ_DEMAND(start_check.same_failure);
  WmgTminReduction reduction;
  reduction.result = std::move(start);
  Reducer reducer{reduction, still_fails, start_check};
  remove_actors(reducer);
  remove_phases(reducer);
  neutral_weather(reducer);
  noon(reducer);
  round_numbers(reducer);
  cut_the_duration(reducer);
  return reduction;
}

}  // namespace scenfuzz

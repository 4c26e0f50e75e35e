// The level-2 tree edits of reduce.hpp: removing actors and what names them, removing phases,
// neutral weather and time of day, and the walk over the written numbers.
#include "lang/wmg/reduce.hpp"

#include <algorithm>
#include <set>
#include <utility>
#include <variant>

#include "lang/demand.hpp"
#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {

namespace {

using Names = std::set<std::string>;

// The actors asked for, and those placed relative to any of them (in initialisation order a
// reference comes before the actors placed relative to it, so one pass finds them all).
Names with_dependants(const Initialisation& initialisation, Names removed) {
  for (const RelativeActorInit& init : initialisation.relative)
    if (removed.contains(init.reference.name)) removed.insert(init.actor.name);
  return removed;
}

struct NamesAnyOf {
  const Names& names;
  bool operator()(const TimerConstraint&) const { return false; }
  bool operator()(const CollisionCondition&) const { return false; }
  bool operator()(const OffsetConstraint& c) const {
    return names.contains(c.actor.name) || names.contains(c.reference.name);
  }
  bool operator()(const LaneConstraint& c) const {
    return names.contains(c.actor.name) ||
           (c.placement && names.contains(c.placement->reference.name));
  }
  bool operator()(const ActorCondition& c) const { return names.contains(c.actor.name); }
  bool operator()(const TrafficLightCondition&) const { return false; }
};

template <typename T, typename Predicate>
void erase_where(std::vector<T>& items, const Predicate& predicate) {
  items.erase(std::remove_if(items.begin(), items.end(), predicate), items.end());
}

bool phase_names_any(const ManoeuvrePhase& phase, const Names& names) {
  return (phase.agent.agent && names.contains(phase.agent.agent->name)) ||
         names.contains(phase.relative.reference.name);
}

// The smallest WHEN ... DO the grammar allows (it wants at least one): the ego driving itself.
Ssms ego_autonomous(const std::string& ego) {
  Ssms ssms;
  ActorCondition condition;
  condition.actor.name = ego;
  condition.observed.text = "Going Ahead";
  ssms.conditions.push_back(condition);
  ssms.autonomous = true;
  return ssms;
}

// Phases numbered 1, 2, ... as the parser demands; empty sequences and SSMS without a trigger or
// anything to do removed (the last one replaced by the ego's `DO: AUTO`).
void tidy_sequences(Dynamics& dynamics) {
  const std::string ego = ego_name(dynamics);
  for (Ssms& ssms : dynamics.sequences) {
    for (ManoeuvreSequence& sequence : ssms.sequences)
      for (std::size_t i = 0; i < sequence.phases.size(); ++i)
        sequence.phases[i].number.value = static_cast<std::int64_t>(i + 1);
    erase_where(ssms.sequences, [](const ManoeuvreSequence& s) { return s.phases.empty(); });
  }
  erase_where(dynamics.sequences, [](const Ssms& ssms) {
    return ssms.conditions.empty() || (!ssms.autonomous && ssms.sequences.empty());
  });
  if (dynamics.sequences.empty()) dynamics.sequences.push_back(ego_autonomous(ego));
}

void remove_from_sequences(Dynamics& dynamics, const Names& names) {
  const NamesAnyOf mentions{names};
  for (Ssms& ssms : dynamics.sequences) {
    erase_where(ssms.conditions, [&](const WhenCondition& c) { return std::visit(mentions, c); });
    erase_where(ssms.sequences,
                [&](const ManoeuvreSequence& s) { return names.contains(s.actor.name); });
    for (ManoeuvreSequence& sequence : ssms.sequences) {
      erase_where(sequence.phases,
                  [&](const ManoeuvrePhase& phase) { return phase_names_any(phase, names); });
      // The phase itself does not name the actor: it only stops holding on it.
      for (ManoeuvrePhase& phase : sequence.phases)
        if (phase.while_constraint && std::visit(mentions, *phase.while_constraint))
          phase.while_constraint.reset();
    }
  }
  tidy_sequences(dynamics);
}

bool is_zero(const NumberRange& range) { return !range.is_range && range.low == 0; }

NumberRange lone(double value) {
  NumberRange range;
  range.low = range.high = value;
  return range;
}

// Calls `visit` on every NumberRange of each section the numbers walk covers.
template <typename Visit>
void walk_junction(Junction& junction, const Visit& visit) {
  for (NumberRange& angle : junction.angles) visit(angle);
  for (std::optional<NumberRange>* size :
       {&junction.dimensions.width, &junction.dimensions.depth, &junction.dimensions.diameter})
    if (*size) visit(**size);
}

template <typename Visit>
void walk_road(Road& road, const Visit& visit) {
  if (road.speed_limit) visit(*road.speed_limit);
  if (road.curvature_radius)
    for (SegmentRange& segment : road.curvature_radius->segments)
      if (segment.range) visit(*segment.range);
  for (SpecialRoadStructure& structure : road.special_structures)
    visit(structure.distance_from_start);
  for (FixedRoadStructure& structure : road.fixed_structures)
    if (structure.street_lights) {
      visit(structure.street_lights->spacing);
      visit(structure.street_lights->height);
    }
  for (RoadSign& sign : road.road_signs) visit(sign.distance_from_start);
  visit(road.length);
  if (road.lane_width.whole_road) visit(*road.lane_width.whole_road);
  for (SegmentRange& segment : road.lane_width.segments)
    if (segment.range) visit(*segment.range);
}

template <typename Visit>
struct ConstraintNumbers {
  const Visit& visit;
  void operator()(TimerConstraint& c) const { visit(c.value); }
  void operator()(OffsetConstraint& c) const { visit(c.value); }
  void operator()(LaneConstraint& c) const {
    if (!c.placement) return;
    for (OffsetRelation& offset : c.placement->offsets) visit(offset.offset);
    if (c.placement->relative_heading) visit(*c.placement->relative_heading);
  }
};

template <typename Visit>
void walk_initialisation(Initialisation& initialisation, const Visit& visit) {
  AbsoluteActorInit& first = initialisation.first;
  if (first.position) {
    visit(first.position->x);
    visit(first.position->y);
  }
  if (first.heading) visit(*first.heading);
  for (RelativeActorInit& init : initialisation.relative) {
    for (OffsetRelation& offset : init.offsets) visit(offset.offset);
    visit(init.relative_heading);
  }
  for (TimerInit& timer : initialisation.timers) visit(timer.value);
}

template <typename Visit>
void walk_ssms(Ssms& ssms, const Visit& visit) {
  for (WhenCondition& condition : ssms.conditions)
    if (auto* actor = std::get_if<ActorCondition>(&condition); actor && actor->speed)
      visit(*actor->speed);
  for (ManoeuvreSequence& sequence : ssms.sequences)
    for (ManoeuvrePhase& phase : sequence.phases) {
      visit(phase.agent.first);
      visit(phase.agent.second);
      visit(phase.relative.distance);
      if (phase.while_constraint)
        std::visit(ConstraintNumbers<Visit>{visit}, *phase.while_constraint);
    }
}

template <typename Visit>
void walk_environment(Environment& environment, const Visit& visit) {
  if (environment.wind) visit(*environment.wind);
  visit(environment.cloudiness);
  visit(environment.rainfall.intensity);
  if (environment.snowfall) visit(environment.snowfall->visibility);
  if (environment.light_source_position) visit(environment.light_source_position->elevation);
}

template <typename Visit>
void walk_numbers(Level2File& file, const Visit& visit) {
  for (Junction& junction : file.scenery.junctions) walk_junction(junction, visit);
  for (Road& road : file.scenery.roads) walk_road(road, visit);
  walk_initialisation(file.dynamics.initialisation, visit);
  for (Ssms& ssms : file.dynamics.sequences) walk_ssms(ssms, visit);
  walk_environment(file.environment, visit);
  if (file.traffic) {
    for (Centroid& centroid : file.traffic->centroids) visit(centroid.distance);
    for (TrafficFlow& flow : file.traffic->flows) {
      visit(flow.first);
      visit(flow.second);
    }
  }
}

}  // namespace

std::vector<std::string> other_actors(const Level2File& file) {
  const std::string ego = ego_name(file.dynamics);
  std::vector<std::string> names;
  for (const RelativeActorInit& init : file.dynamics.initialisation.relative)
    if (init.actor.name != ego) names.push_back(init.actor.name);
  return names;
}

std::vector<std::string> remove_actors(Level2File& file, const std::vector<bool>& kept) {
  const std::vector<std::string> actors = other_actors(file);
  SCENFUZZ_DEMAND(kept.size() == actors.size());
  Names asked;
  for (std::size_t i = 0; i < actors.size(); ++i)
    if (!kept[i]) asked.insert(actors[i]);
  Dynamics& dynamics = file.dynamics;
  const Names removed = with_dependants(dynamics.initialisation, asked);
  erase_where(dynamics.initialisation.relative,
              [&](const RelativeActorInit& init) { return removed.contains(init.actor.name); });
  remove_from_sequences(dynamics, removed);
  erase_where(dynamics.end_conditions,
              [&](const EndCondition& c) { return std::visit(NamesAnyOf{removed}, c); });
  std::vector<std::string> dependants;
  for (const std::string& name : removed)
    if (!asked.contains(name)) dependants.push_back(name);
  return dependants;
}

std::vector<PhaseName> manoeuvre_phases(const Level2File& file) {
  std::vector<PhaseName> phases;
  for (const Ssms& ssms : file.dynamics.sequences)
    for (const ManoeuvreSequence& sequence : ssms.sequences)
      for (const ManoeuvrePhase& phase : sequence.phases)
        phases.push_back(PhaseName{sequence.actor.name, phase.number.value});
  return phases;
}

void remove_phases(Level2File& file, const std::vector<bool>& kept) {
  std::size_t next = 0;
  for (Ssms& ssms : file.dynamics.sequences)
    for (ManoeuvreSequence& sequence : ssms.sequences)
      erase_where(sequence.phases, [&](const ManoeuvrePhase&) {
        SCENFUZZ_DEMAND(next < kept.size());
        return !kept[next++];
      });
  SCENFUZZ_DEMAND(next == kept.size());
  tidy_sequences(file.dynamics);
}

std::vector<std::string> weather_components(const Level2File& file) {
  const Environment& environment = file.environment;
  std::vector<std::string> components;
  if (environment.wind) components.push_back("wind");
  if (!is_zero(environment.cloudiness)) components.push_back("cloudiness");
  if (environment.particulates && environment.particulates->text != "None")
    components.push_back("particulates");
  if (!is_zero(environment.rainfall.intensity)) components.push_back("rainfall");
  if (environment.snowfall) components.push_back("snowfall");
  return components;
}

void neutral_weather(Level2File& file, const std::vector<std::string>& components) {
  Environment& environment = file.environment;
  for (const std::string& component : components) {
    if (component == "wind") environment.wind.reset();
    if (component == "cloudiness") environment.cloudiness = lone(0);
    if (component == "particulates") environment.particulates.reset();
    if (component == "snowfall") environment.snowfall.reset();
    if (component == "rainfall") {
      environment.rainfall.type = Label{"Light Rain", false, {}};
      environment.rainfall.intensity = lone(0);
    }
  }
}

bool set_time_of_day(Level2File& file, double seconds) {
  std::optional<NumberRange>& time = file.environment.time_of_day;
  if (time && !time->is_range && time->low == seconds) return false;
  time = lone(seconds);
  return true;
}

std::vector<double> file_numbers(const Level2File& file) {
  Level2File copy = file;
  std::vector<double> numbers;
  walk_numbers(copy, [&](NumberRange& range) { numbers.push_back(range.low); });
  return numbers;
}

void set_file_numbers(Level2File& file, const std::vector<double>& numbers) {
  std::size_t next = 0;
  walk_numbers(file, [&](NumberRange& range) {
    if (next < numbers.size()) range = lone(numbers[next]);
    ++next;
  });
}

}  // namespace scenfuzz::wmg

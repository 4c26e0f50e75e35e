// CH-Scenario events as triggered behaviour (translation.hpp; docs/ch-scenario.md, "Events"):
// `when GUARD do ACTION` becomes manoeuvre phases of the road user the action moves, each started
// when the guard holds; an event that fires with a probability between 0 and 1 gets a search
// parameter choosing whether it fires, so that the search explores both outcomes and a finding
// can say how likely the outcomes it needed are.
#include <algorithm>
#include <array>

#include "lang/chs/predicates.hpp"
#include "lang/chs/translation.hpp"
#include "lang/chs/vocabulary.hpp"
#include "lang/demand.hpp"

namespace scenfuzz::chs {

namespace {

constexpr double kKilometresPerHour = 1 / 3.6;
constexpr double kDriveOffSpeed = 30;  // km/h: a vehicle written without a speed drives off so
constexpr double kWalkOffSpeed = 5;    // km/h: likewise a pedestrian
constexpr double kSpeedStep = 10;      // km/h: what `speed++` and `speed--` change
constexpr const char* kActions =
    "scenfuzz reads the actions parked = false / true, speed = N (km/h), speed++, speed--, "
    "position++ (a lane to the left) and position-- (to the right), each possibly after a road "
    "user's name (van_parked = false), and no other";
// The timer that `time` and `wait` read: seconds since the start.
constexpr const char* kClock = "time";

// The roles a name ends in: `first_car_parked` is the role `parked` of first_car.
enum class Role { parked, speed, distance, position, clock, none };

Role role_of(const std::string& word) {
  if (word == "parked" || word == "stopped" || word == "stop" || word == "stationary")
    return Role::parked;
  if (word == "speed" || word == "velocity") return Role::speed;
  if (word == "dist" || word == "distance") return Role::distance;
  if (word == "position" || word == "lane") return Role::position;
  if (word == "time" || word == "wait" || word == "t" || word == "waiting") return Role::clock;
  return Role::none;
}

bool names_the_ego(const std::string& key) {
  return key == "ego" || key == "currentvehicle" || key == "hostvehicle" ||
         key == "subjectvehicle" || key == "egovehicle";
}

// A name split into the road user it prefixes (empty: none) and its role.
struct RoleName {
  std::string actor_key;  // joined words
  Role role = Role::none;
};

RoleName split_name(const std::string& name) {
  std::vector<std::string> words = words_of(name);
  if (words.empty()) return {};
  RoleName split{"", role_of(words.back())};
  words.pop_back();
  for (const std::string& word : words) split.actor_key += word;
  if (split.role == Role::none) split.actor_key = joined_words(name);
  return split;
}

class EventTranslator {
 public:
  explicit EventTranslator(Translation& translation)
      : t_(translation), scenario_(translation.scenario), diagnostics_(translation.diagnostics) {}

  void constraint(const Constraint& constraint) {
    const std::size_t count = constraint.events.size();
    for (std::size_t i = 0; i < count; ++i) {
      const std::string name =
          constraint.name.text + ".event" + (count == 1 ? "" : std::to_string(i + 1));
      event(constraint, constraint.events[i], name);
    }
  }

 private:
  // A phase of the road user named, before it is known that the whole event translates.
  struct PendingPhase {
    std::string actor;
    ManoeuvrePhase phase;
  };

  void event(const Constraint& constraint, const Event& event, const std::string& name) {
    if (event.probability.value == 0) return;  // it never fires
    subject_ = default_subject(constraint);
    left_out_ = false;
    std::vector<PendingPhase> phases;
    for (const Statement& statement : event.action) {
      auto phase = action(statement);
      if (!phase) return leave_out(statement.location);
      phases.push_back(std::move(*phase));
    }
    auto guard = PredicateTranslator(diagnostics_, [&](const std::string& text, SourceLocation at) {
                   return guard_name(text, at);
                 }).translate(event.guard);
    if (!guard) {
      if (left_out_) leave_out(event.guard.location);
      return;
    }
    if (event.probability.value < 1) *guard = fires_only_if_chosen(std::move(*guard), event, name);
    start_phases(std::move(phases), *guard);
  }

  void leave_out(SourceLocation at) {
    diagnostics_.warning(at,
                         "this event is left out (docs/ch-scenario.md, \"Events\", lists what "
                         "scenfuzz reads)");
  }

  // The first related name that is a road user scenfuzz drives: not the ego, nor the road edge.
  std::string default_subject(const Constraint& constraint) {
    for (const Text& related : constraint.related)
      if (const Actor* actor = find_actor(joined_words(related.text));
          actor && actor->kind != ActorKind::ego)
        return actor->name;
    return "";
  }

  const Actor* find_actor(const std::string& key) {
    if (names_the_ego(key)) return &scenario_.ego;
    if (key == "forwardvehicle" || key == "frontvehicle") return forward_vehicle();
    if (joined_words(scenario_.ego.name) == key) return &scenario_.ego;
    for (const auto* actors : {&scenario_.vehicles, &scenario_.pedestrians})
      for (const Actor& actor : *actors)
        if (joined_words(actor.name) == key) return &actor;
    return nullptr;
  }

  // The first vehicle whose track does not place it behind the ego or oncoming.
  const Actor* forward_vehicle() {
    for (const Actor& vehicle : scenario_.vehicles) {
      const DynamicEntity* entity = dynamic_entity(vehicle.name);
      const TrackPlace place = entity ? read_track(entity->track.text).place : TrackPlace::ahead;
      if (place != TrackPlace::behind && place != TrackPlace::oncoming) return &vehicle;
    }
    return nullptr;
  }

  const DynamicEntity* dynamic_entity(const std::string& name) const {
    for (const DynamicEntity& entity : t_.file.dynamic_entities)
      if (entity.name.text == name) return &entity;
    return nullptr;
  }

  // The road user a name's prefix names, else the event's subject.
  const Actor* actor_of(const RoleName& name) {
    if (!name.actor_key.empty()) return find_actor(name.actor_key);
    return subject_.empty() ? nullptr : find_actor(joined_words(subject_));
  }

  std::optional<Meaning> guard_name(const std::string& text, SourceLocation at) {
    const RoleName name = split_name(text);
    if (name.role == Role::clock && name.actor_key.empty()) return clock(at);
    const Actor* actor = actor_of(name);
    if (!actor && name.role == Role::speed && name.actor_key.empty()) actor = &scenario_.ego;
    if (actor) {
      SpecTerm who = word_term(actor->name, at);
      switch (name.role) {
        case Role::parked:
          return comparison(CompareOp::equal, signal_term("manoeuvre", at, {who}),
                            word_term("Stopped", at), at);
        case Role::speed:  // km/h, as the file's speeds
          return product_term(signal_term("speed", at, {who}), number_term(3.6, at), at);
        case Role::distance: {
          // Between the road user and the ego, however it is named: how far it is ahead.
          const Actor* other = actor->kind == ActorKind::ego && !subject_.empty()
                                   ? find_actor(joined_words(subject_))
                                   : actor;
          if (other->kind == ActorKind::ego) break;
          return signal_term("longitudinal_offset", at,
                             {word_term(other->name, at), word_term(scenario_.ego.name, at)});
        }
        default: break;
      }
    }
    diagnostics_.warning(at, "scenfuzz reads no '" + text +
                                 "' in a guard: time, wait, speed, dist, parked, each "
                                 "possibly after a road user's name (first_car_parked)");
    left_out_ = true;
    return std::nullopt;
  }

  SpecTerm clock(SourceLocation at) {
    const bool added = std::any_of(scenario_.timers.begin(), scenario_.timers.end(),
                                   [](const NamedValue& timer) { return timer.name == kClock; });
    if (!added) scenario_.timers.push_back({kClock, constant_value(0), {}});
    return signal_term("timer", at, {word_term(kClock, at)});
  }

  std::optional<PendingPhase> action(const Statement& statement) {
    const RoleName name = split_name(statement.target.text);
    if (name.role == Role::none || name.role == Role::clock || name.role == Role::distance) {
      diagnostics_.warning(statement.location, kActions);
      return std::nullopt;
    }
    const Actor* actor = actor_of(name);
    if (!actor || actor->kind == ActorKind::ego) {
      std::string why =
          actor ? "the ego is driven by the system under test, not by events"
          : name.actor_key.empty()
              ? "the constraint relates with no road user scenfuzz drives (the ego is driven by "
                "the system under test), so '" +
                    statement.target.text + "' moves nobody"
              : "'" + statement.target.text + "' names no road user of the file";
      diagnostics_.warning(statement.location, why);
      return std::nullopt;
    }
    auto manoeuvre = manoeuvre_of(statement, name.role, *actor);
    if (!manoeuvre) return std::nullopt;
    manoeuvre->location = statement.location;
    return PendingPhase{actor->name, std::move(*manoeuvre)};
  }

  // The written speed of a road user in km/h: what it drives off at.
  double written_speed(const Actor& actor) const {
    const DynamicEntity* entity = dynamic_entity(actor.name);
    if (entity && entity->speed.value > 0) return entity->speed.value;
    return actor.kind == ActorKind::pedestrian ? kWalkOffSpeed : kDriveOffSpeed;
  }

  static ManoeuvrePhase phase(const char* manoeuvre, std::optional<double> kilometres_per_hour,
                              SourceLocation at) {
    ManoeuvrePhase phase;
    phase.manoeuvre = manoeuvre;
    if (kilometres_per_hour)
      phase.parameters.push_back(
          {"speed", constant_value(std::max(0.0, *kilometres_per_hour) * kKilometresPerHour), at});
    return phase;
  }

  std::optional<ManoeuvrePhase> manoeuvre_of(const Statement& statement, Role role,
                                             const Actor& actor) {
    const SourceLocation at = statement.location;
    const bool walker = actor.kind == ActorKind::pedestrian;
    const auto assigned = assigned_value(statement);
    const bool increment = statement.kind == Statement::Kind::increment;
    switch (role) {
      case Role::parked:
        if (!assigned) break;
        if (*assigned != 0) return phase("Stop", std::nullopt, at);
        return phase(walker ? "Walk_Cross" : "Drive", written_speed(actor), at);
      case Role::speed:
        if (walker && !assigned) break;
        if (assigned) return phase(walker ? "Walk_Cross" : "Drive", *assigned, at);
        return phase("Drive", written_speed(actor) + (increment ? kSpeedStep : -kSpeedStep), at);
      case Role::position:
        if (walker || assigned) break;
        return phase(increment ? "LaneChangeLeft" : "LaneChangeRight", std::nullopt, at);
      default: break;
    }
    diagnostics_.warning(at, std::string(kActions) + " (of " + actor.name + ")");
    return std::nullopt;
  }

  // `= true`, `= false`, `= 30`: the value as a number (true 1, false 0); none for ++ and --, and
  // for any other expression.
  static std::optional<double> assigned_value(const Statement& statement) {
    if (statement.kind != Statement::Kind::assign) return std::nullopt;
    const Expression& value = statement.value;
    if (value.kind == Expression::Kind::boolean) return value.boolean ? 1 : 0;
    if (value.kind == Expression::Kind::number) return value.number;
    return std::nullopt;
  }

  // guard && (the event's outcome parameter chooses "fires").
  Formula fires_only_if_chosen(Formula guard, const Event& event, const std::string& name) {
    Parameter outcome;
    outcome.name = name;
    outcome.kind = ParameterKind::discrete;
    outcome.upper = 1;
    outcome.choices = {"does not fire", "fires"};
    outcome.location = event.probability.location;
    outcome.event_outcome = true;
    const int index = static_cast<int>(scenario_.parameters.size());
    scenario_.parameters.push_back(std::move(outcome));
    SpecTerm chosen;
    chosen.kind = TermKind::number;
    chosen.value = parameter_value(index, event.probability.location);
    chosen.location = event.probability.location;
    const SourceLocation at = event.location;
    return combined(FormulaKind::conjunction, std::move(guard),
                    comparison(CompareOp::equal, std::move(chosen), number_term(1, at), at), at);
  }

  // Each road user's phases of the event start together, when the guard holds; a road user's
  // further phases of the same action follow its first.
  void start_phases(std::vector<PendingPhase> phases, const Formula& guard) {
    std::vector<std::string> started;
    for (PendingPhase& pending : phases) {
      Actor* actor = mutable_actor(pending.actor);
      if (std::find(started.begin(), started.end(), pending.actor) == started.end()) {
        pending.phase.start_when = guard;
        started.push_back(pending.actor);
      }
      actor->motion.kind = MotionKind::manoeuvres;
      actor->motion.phases.push_back(std::move(pending.phase));
    }
  }

  Actor* mutable_actor(const std::string& name) {
    for (auto* actors : {&scenario_.vehicles, &scenario_.pedestrians})
      for (Actor& actor : *actors)
        if (actor.name == name) return &actor;
    SCENFUZZ_DEMAND(false);
    return nullptr;
  }

  Translation& t_;
  ScenarioTemplate& scenario_;
  Diagnostics& diagnostics_;
  std::string subject_;    // the road user the event's unprefixed names mean
  bool left_out_ = false;  // a guard name was not read (warned of)
};

}  // namespace

void translate_events(Translation& translation) {
  EventTranslator translator(translation);
  for (const Constraint& constraint : translation.file.constraints)
    translator.constraint(constraint);
}

}  // namespace scenfuzz::chs

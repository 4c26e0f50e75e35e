// Level 1 to level 2, the dynamics: where the actors start (the ego absolutely, the others
// relative to it), each PHASES group as a WHEN ... DO ... with one manoeuvre sequence per actor,
// and the end: a global timer and the table's scenario duration, or a collision.
#include <algorithm>

#include "lang/wmg/level1_convert_parts.hpp"
#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::detail {

namespace {

Identifier id(std::string name, SourceLocation where = {}) {
  return Identifier{std::move(name), where};
}

LaneName lane_of(const ActorPlan& actor, SourceLocation where = {}) {
  return LaneName{id(actor.road, where), id(actor.lane, where), where};
}

bool on_the_left(RelativeLocation location) {
  return location == RelativeLocation::front_side_left || location == RelativeLocation::side_left ||
         location == RelativeLocation::rear_side_left;
}

RelativeLocation relative_location(std::string_view code) {
  const std::vector<std::string>& codes = vocabulary::relative_location().phrases;
  for (std::size_t i = 0; i < codes.size(); ++i)
    if (codes[i] == code) return static_cast<RelativeLocation>(i);
  return RelativeLocation::front;
}

constexpr std::string_view kClock = "Clock";

class DynamicsConverter {
 public:
  DynamicsConverter(const ConversionPlan& plan, Diagnostics& diagnostics)
      : plan_(plan), diagnostics_(diagnostics) {}

  Dynamics run() {
    Dynamics dynamics;
    dynamics.initialisation = initialisation();
    for (const Level1Ssms& ssms : plan_.file->sequences) {
      const PhaseGroup* previous = nullptr;
      for (const PhaseGroup& group : ssms.groups) {
        dynamics.sequences.push_back(convert_group(group, previous));
        previous = &group;
      }
    }
    const QualitativeDefault& duration = setting("scenario duration");
    dynamics.end_conditions.push_back(
        TimerConstraint{id(std::string(kClock)),
                        Located<Comparison>{Comparison::greater_equal, {}},
                        NumberRange{duration.low, duration.low, false, {}},
                        {}});
    dynamics.end_conditions.push_back(CollisionCondition{});
    return dynamics;
  }

 private:
  Initialisation initialisation() {
    Initialisation init;
    const ActorPlan& ego = plan_.ego();
    init.first.type = Located<ActorType>{ego.type, ego.name.location};
    init.first.actor = ego.name;
    init.first.lane = lane_of(ego, ego.name.location);
    init.first.heading = table_range(setting("ego heading"), ego.name.location);
    init.first.location = ego.name.location;
    for (std::size_t i = 1; i < plan_.actors.size(); ++i)
      init.relative.push_back(relative_init(plan_.actors[i]));
    // The clock the end condition reads starts with the scenario.
    init.timers.push_back(TimerInit{
        Located<TimerScope>{TimerScope::global, {}}, id(std::string(kClock)), NumberRange{}, {}});
    return init;
  }

  RelativeActorInit relative_init(const ActorPlan& actor) {
    SourceLocation where = actor.name.location;
    RelativeActorInit init;
    init.type = Located<ActorType>{actor.type, where};
    init.actor = actor.name;
    init.lane = lane_of(actor, where);
    auto offset = [&](PositionRelation relation, std::string_view gap) {
      return OffsetRelation{Located<PositionRelation>{relation, where},
                            table_range(setting(gap), where), where};
    };
    std::string_view heading = "heading on the same road";
    if (actor.type == ActorType::pedestrian) {
      init.offsets.push_back(offset(PositionRelation::longitudinal, "pedestrian gap"));
      init.offsets.push_back(offset(PositionRelation::lateral, "pedestrian lateral offset"));
      heading = "pedestrian heading";
    } else if (actor.road != plan_.ego().road) {
      init.offsets.push_back(offset(PositionRelation::longitudinal, "gap on another road"));
      heading = "heading on another road";
    } else if (actor.lane_number != plan_.ego().lane_number) {
      init.offsets.push_back(offset(PositionRelation::longitudinal, "gap in the next lane"));
    } else {
      init.offsets.push_back(offset(PositionRelation::longitudinal, "gap in the same lane"));
    }
    init.relative_position = Located<RelativeLocation>{actor.relative_position, where};
    init.relative_heading = table_range(setting(heading), where);
    // A pedestrian on the ego's left faces across the road to the right: the range mirrored.
    if (actor.type == ActorType::pedestrian && on_the_left(actor.relative_position))
      init.relative_heading = {-init.relative_heading.high, -init.relative_heading.low,
                               init.relative_heading.is_range, init.relative_heading.location};
    init.reference = plan_.ego().name;
    init.location = where;
    return init;
  }

  // The actor a phase is measured against: the first actor its places name, else the ego, else
  // (for the ego's own phases) the first other actor.
  const ActorPlan& reference_of(const std::string& actor, const Level1Manoeuvre& manoeuvre) {
    for (const ManoeuvrePlace& place : manoeuvre.places)
      if (place.target && place.target->name != actor)
        if (const ActorPlan* named = plan_.actor(place.target->name)) return *named;
    if (plan_.ego().name.name != actor || plan_.actors.size() == 1) return plan_.ego();
    return plan_.actors[1];
  }

  // The level-2 manoeuvre type: the table's kind of the action, completed by the direction of
  // the first place (Towards, Away, Cross) or, for cut-ins and cut-outs, by the lanes.
  std::string manoeuvre_type(const ActorPlan* actor, const ActorPlan& reference,
                             const Level1Manoeuvre& manoeuvre) {
    std::string kind(default_for(Quality::manoeuvre_kind, manoeuvre.action.text, "drives").label);
    std::string relation = "no place";
    for (const ManoeuvrePlace& place : manoeuvre.places)
      if (place.relation) {
        relation = place.relation->text;
        break;
      }
    std::string direction(default_for(Quality::place_direction, relation, "no place").label);
    std::int64_t lane = actor ? actor->lane_number : 1;
    const RoadPlan* road = actor ? plan_.road(actor->road) : nullptr;
    bool same_road = actor && actor->road == reference.road && actor->lane_number > 0 &&
                     reference.lane_number > 0;
    if (kind == "CutIn") {
      if (!same_road || lane == reference.lane_number) return "Drive_CutIn";
      return lane > reference.lane_number ? "LaneChangeRight_CutIn" : "LaneChangeLeft_CutIn";
    }
    if (kind == "CutOut") {
      if (!road || road->lane_count < 2) return "Drive_CutOut";
      return lane < road->lane_count ? "LaneChangeLeft_CutOut" : "LaneChangeRight_CutOut";
    }
    if (kind == "Stop" || kind == "Stopped") return kind;
    bool on_foot = kind == "Walk" || kind == "Run" || kind == "Slide";
    if (!on_foot && direction == "Cross") direction = "Towards";
    return kind + "_" + direction;
  }

  static std::string kind_of(const std::string& type) { return type.substr(0, type.find('_')); }

  NumberRange phase_speed(const ActorPlan* actor, const std::string& kind,
                          const Level1Manoeuvre& manoeuvre) {
    SourceLocation where = manoeuvre.action.location;
    if (const QualitativeDefault* own = find_default(Quality::actor_speed, kind))
      return table_range(*own, where);
    if (actor && actor->type == ActorType::pedestrian)
      return table_range(default_for(Quality::actor_speed, "pedestrian", "pedestrian"), where);
    if (actor && actor->type == ActorType::cyclist)
      return table_range(default_for(Quality::actor_speed, "cyclist", "cyclist"), where);
    std::string change = manoeuvre.speed_change ? manoeuvre.speed_change->text : "not said";
    const RoadPlan* road = actor ? plan_.road(actor->road) : nullptr;
    return speed_range(default_for(Quality::speed_change, change, "not said"),
                       road ? road->speed_limit : 0.0, where);
  }

  ManoeuvrePhase convert_phase(const PhaseClause& clause, std::int64_t number) {
    const ActorPlan* actor = plan_.actor(clause.actor.name);
    const ActorPlan& reference = reference_of(clause.actor.name, clause.manoeuvre);
    SourceLocation where = clause.manoeuvre.location;
    std::string type = manoeuvre_type(actor, reference, clause.manoeuvre);
    std::string kind = kind_of(type);
    std::string table_kind(
        default_for(Quality::manoeuvre_kind, clause.manoeuvre.action.text, "drives").label);
    ManoeuvrePhase phase;
    phase.number = WholeNumber{number, where};
    phase.type = table_label(type, clause.manoeuvre.action.location);
    phase.agent.first = phase_speed(actor, kind, clause.manoeuvre);
    phase.agent.second =
        table_range(default_for(Quality::phase_duration, table_kind, "Drive"), where);
    phase.agent.location = where;
    phase.relative.reference = reference.name;
    phase.relative.distance =
        table_range(default_for(Quality::phase_gap, table_kind, "Drive"), where);
    RelativeLocation position = RelativeLocation::front;
    if (clause.manoeuvre.position)
      position = relative_location(
          default_for(Quality::relative_position, clause.manoeuvre.position->text, "front").label);
    else if (kind == "Walk" || kind == "Run" || kind == "Slide")
      position = RelativeLocation::front_side_left;
    else if (actor && actor->road != reference.road)
      position = RelativeLocation::front_side_right;
    phase.relative.relative_location = Located<RelativeLocation>{position, where};
    phase.relative.location = where;
    phase.location = clause.location;
    return phase;
  }

  // What a WHEN condition observes an actor doing, from the level-2 type its manoeuvre becomes.
  Label observed(const std::string& actor_name, const Level1Manoeuvre& manoeuvre) {
    const ActorPlan* actor = plan_.actor(actor_name);
    std::string type = manoeuvre_type(actor, reference_of(actor_name, manoeuvre), manoeuvre);
    return table_label(default_for(Quality::observed_manoeuvre, kind_of(type), "Drive").label,
                       manoeuvre.action.location);
  }

  ActorCondition actor_condition(const ActorClause& clause) {
    ActorCondition condition;
    const ActorPlan* actor = plan_.actor(clause.actor.name);
    condition.actor = clause.actor;
    condition.observed = observed(clause.actor.name, clause.manoeuvre);
    for (const ManoeuvrePlace& place : clause.manoeuvre.places)
      if (place.target && plan_.junctions.count(place.target->name)) {
        condition.in_element = *place.target;
        break;
      }
    if (!condition.in_element && actor) condition.in_lane = lane_of(*actor, clause.actor.location);
    bool moving = condition.observed.text != "Stopped";
    if (moving && actor && actor->type == ActorType::vehicle)
      condition.speed = phase_speed(actor, "", clause.manoeuvre);
    condition.location = clause.location;
    return condition;
  }

  // The lights a "the traffic light ahead of X" condition watches: those of X's road, of the
  // road X, or of every road of the junction X.
  TrafficLightCondition light_condition(const TrafficLightClause& clause) {
    TrafficLightCondition condition;
    SourceLocation where = clause.reference.location;
    const std::string& reference = clause.reference.name;
    if (auto junction = plan_.junctions.find(reference); junction != plan_.junctions.end()) {
      for (const Identifier& road : junction->second->roads)
        condition.lights.push_back(id(traffic_light_name(road.name), where));
    } else {
      const ActorPlan* actor = plan_.actor(reference);
      std::string road = actor ? actor->road : reference;
      condition.lights.push_back(id(traffic_light_name(road), where));
      const RoadPlan* road_plan = plan_.road(road);
      if (!road_plan || road_plan->junctions.empty())
        diagnostics_.warning(where, "road " + road +
                                        " meets no junction, so level 2 has no traffic light "
                                        "for it; the condition names " +
                                        traffic_light_name(road) + " all the same");
    }
    if (condition.lights.empty()) condition.lights.push_back(id("TL", where));
    condition.colour = clause.colour;
    condition.location = clause.location;
    return condition;
  }

  Ssms convert_group(const PhaseGroup& group, const PhaseGroup* previous) {
    Ssms ssms;
    for (const Level1Condition& condition : group.conditions) {
      if (const auto* actor = std::get_if<ActorClause>(&condition))
        ssms.conditions.emplace_back(actor_condition(*actor));
      else
        ssms.conditions.emplace_back(light_condition(std::get<TrafficLightClause>(condition)));
    }
    if (ssms.conditions.empty() && previous && !previous->phases.empty()) {
      // "Next, ..." with no conditions: it starts once the previous group's last phase is under
      // way, observed as a condition on that phase's actor.
      const PhaseClause& last = previous->phases.back();
      ActorClause clause{last.actor, last.manoeuvre, last.location};
      ssms.conditions.emplace_back(actor_condition(clause));
    }
    if (ssms.conditions.empty()) {
      ActorClause clause{plan_.ego().name, {}, {}};
      clause.manoeuvre.action.text = "drives";
      ssms.conditions.emplace_back(actor_condition(clause));
    }
    for (const PhaseClause& phase : group.phases) {
      auto sequence = std::find_if(ssms.sequences.begin(), ssms.sequences.end(),
                                   [&](const ManoeuvreSequence& existing) {
                                     return existing.actor.name == phase.actor.name;
                                   });
      if (sequence == ssms.sequences.end()) {
        ssms.sequences.push_back(ManoeuvreSequence{phase.actor, {}, phase.location});
        sequence = ssms.sequences.end() - 1;
      }
      sequence->phases.push_back(
          convert_phase(phase, static_cast<std::int64_t>(sequence->phases.size()) + 1));
    }
    ssms.location = group.location;
    return ssms;
  }

  const ConversionPlan& plan_;
  Diagnostics& diagnostics_;
};

}  // namespace

Dynamics convert_dynamics(const ConversionPlan& plan, Diagnostics& diagnostics) {
  return DynamicsConverter(plan, diagnostics).run();
}

}  // namespace scenfuzz::wmg::detail

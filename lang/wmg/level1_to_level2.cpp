// Level 1 to level 2, top level: resolve the names (the plan), then build each level-2 section.
#include "lang/wmg/level1_to_level2.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lang/wmg/level1_convert_parts.hpp"
#include "lang/wmg/level1_phrases.hpp"

namespace scenfuzz::wmg {

namespace detail {

const RoadPlan* ConversionPlan::road(const std::string& name) const {
  auto found = road_index.find(name);
  return found == road_index.end() ? nullptr : &roads[found->second];
}

const ActorPlan* ConversionPlan::actor(const std::string& name) const {
  auto found = actor_index.find(name);
  return found == actor_index.end() ? nullptr : &actors[found->second];
}

std::string traffic_light_name(const std::string& road) {
  return "TL" + (road.empty() ? road : road.substr(1));
}

NumberRange table_range(const QualitativeDefault& row, SourceLocation where) {
  return NumberRange{row.low, row.high, row.low != row.high, where};
}

NumberRange speed_range(const QualitativeDefault& fraction, double limit, SourceLocation where) {
  double low = std::round(fraction.low * limit);
  double high = std::round(fraction.high * limit);
  return NumberRange{low, high, low != high, where};
}

Label table_label(std::string_view text, SourceLocation where) {
  return Label{std::string(text), false, where};
}

Label converted_label(const Label& level1, Quality quality, std::string_view fallback) {
  if (level1.is_string) return level1;
  return table_label(default_for(quality, level1.text, fallback).label, level1.location);
}

namespace {

// The singular road type that keys the table: "motorways" is "motorway"; a STRING gets the
// numbers of the setting's road type.
std::string road_type_words(const Label& road_type) {
  if (road_type.is_string) return std::string(setting("road type given as a name").label);
  const std::vector<std::string>& phrases = level1_phrases::road_type().phrases;
  constexpr std::size_t kSingulars = 5;  // the list is five singulars, then their plurals
  for (std::size_t i = 0; i < phrases.size(); ++i)
    if (phrases[i] == road_type.text) return phrases[i % kSingulars];
  return std::string(setting("road type given as a name").label);
}

void plan_roads(const Level1File& file, ConversionPlan& plan) {
  for (const RoadSentence& sentence : file.roads)
    for (const Identifier& id : sentence.roads) {
      RoadPlan road;
      road.id = id;
      road.sentence = &sentence;
      road.type_words = road_type_words(sentence.road_type);
      road.lane_count = static_cast<std::int64_t>(
          default_for(Quality::lane_count, road.type_words, "minor road").low);
      road.speed_limit = default_for(Quality::speed_limit, road.type_words, "minor road").low;
      road.length = table_range(default_for(Quality::road_length, road.type_words, "minor road"),
                                sentence.road_type.location);
      plan.road_index[id.name] = plan.roads.size();
      plan.roads.push_back(road);
    }
  for (const RoadFeatureSentence& sentence : file.road_features)
    for (const Identifier& id : sentence.roads)
      if (auto found = plan.road_index.find(id.name); found != plan.road_index.end())
        for (const Label& feature : sentence.features)
          plan.roads[found->second].features.push_back(feature);
  for (const JunctionSentence& junction : file.junctions) {
    plan.junctions[junction.id.name] = &junction;
    for (const Identifier& id : junction.roads)
      if (auto found = plan.road_index.find(id.name); found != plan.road_index.end()) {
        std::vector<std::string>& at = plan.roads[found->second].junctions;
        if (std::find(at.begin(), at.end(), junction.id.name) == at.end())
          at.push_back(junction.id.name);
      }
  }
}

std::string first_manoeuvre_kind(const Level1File& file, const std::string& actor) {
  for (const Level1Ssms& ssms : file.sequences)
    for (const PhaseGroup& group : ssms.groups)
      for (const PhaseClause& phase : group.phases)
        if (phase.actor.name == actor)
          return std::string(
              default_for(Quality::manoeuvre_kind, phase.manoeuvre.action.text, "drives").label);
  return "";
}

// The ego starts in the first lane of its road; a vehicle that cuts in starts in the next lane
// (level 2 numbers lanes from the right, as the corpus: L2 is left of L1), any other vehicle on
// the ego's road ahead in the ego's lane, pedestrians on the pavement (P1), actors on other roads
// in their road's first lane.
void place_actor(const ConversionPlan& plan, ActorPlan& actor, bool is_ego) {
  const RoadPlan* road = plan.road(actor.road);
  std::int64_t lanes = road ? road->lane_count : 1;
  if (actor.type == ActorType::pedestrian) {
    actor.lane = "P1";
    actor.lane_number = 0;
    actor.relative_position = RelativeLocation::front_side_left;
    return;
  }
  actor.lane_number = 1;
  actor.relative_position = RelativeLocation::front;
  if (!is_ego && actor.road != plan.ego().road) {
    actor.relative_position = RelativeLocation::front_side_right;
  } else if (!is_ego && actor.first_manoeuvre_kind == "CutIn" && lanes >= 2) {
    actor.lane_number = 2;
    actor.relative_position = RelativeLocation::front_side_left;
  }
  actor.lane = "L" + std::to_string(actor.lane_number);
}

void plan_actors(const Level1File& file, ConversionPlan& plan) {
  std::map<std::string, std::string> places;
  for (const ActorLocation& location : file.locations)
    places[location.actor.name] = location.place.name;
  std::vector<ActorPlan> declared;
  for (const ActorSentence& sentence : file.actors)
    for (const Identifier& name : sentence.names) {
      ActorPlan actor;
      actor.name = name;
      actor.type = sentence.type.value;
      std::string place = places[name.name];
      auto junction = plan.junctions.find(place);
      actor.road = junction != plan.junctions.end() && !junction->second->roads.empty()
                       ? junction->second->roads.front().name
                       : place;
      actor.first_manoeuvre_kind = first_manoeuvre_kind(file, name.name);
      declared.push_back(actor);
    }
  // parse_level1 never yields a file without actors (the grammar asks for one or more), and
  // level 2 cannot be written without one: a caller that built such a tree has a bug.
  if (declared.empty())
    throw std::logic_error("level1_to_level2 needs a file with at least one actor");
  std::string ego = file.sequences.empty() ? "" : file.sequences.front().autonomous_actor.name;
  std::stable_partition(declared.begin(), declared.end(),
                        [&](const ActorPlan& actor) { return actor.name.name == ego; });
  for (ActorPlan& actor : declared) {
    plan.actor_index[actor.name.name] = plan.actors.size();
    plan.actors.push_back(actor);
  }
  for (std::size_t i = 0; i < plan.actors.size(); ++i) place_actor(plan, plan.actors[i], i == 0);
}

void signalise(ConversionPlan& plan, const std::string& road) {
  if (const RoadPlan* found = plan.road(road))
    plan.signalised_junctions.insert(found->junctions.begin(), found->junctions.end());
}

// A junction has traffic lights when one of its roads has them, or when a WHEN condition
// watches a light there.
void plan_traffic_lights(const Level1File& file, ConversionPlan& plan) {
  for (const RoadPlan& road : plan.roads)
    for (const Label& feature : road.features)
      if (!feature.is_string && feature.text == "traffic lights") signalise(plan, road.id.name);
  for (const Level1Ssms& ssms : file.sequences)
    for (const PhaseGroup& group : ssms.groups)
      for (const Level1Condition& condition : group.conditions)
        if (const auto* light = std::get_if<TrafficLightClause>(&condition)) {
          const std::string& reference = light->reference.name;
          if (plan.junctions.count(reference)) plan.signalised_junctions.insert(reference);
          if (const ActorPlan* actor = plan.actor(reference)) signalise(plan, actor->road);
          signalise(plan, reference);
        }
}

Header convert_header(const Level1Header& header) {
  Header result;
  result.version = header.version;
  result.authors.push_back(header.author ? *header.author
                                         : Text{std::string(setting("author").label), {}});
  result.location = header.location;
  return result;
}

}  // namespace

ConversionPlan plan_conversion(const Level1File& file) {
  ConversionPlan plan;
  plan.file = &file;
  plan_roads(file, plan);
  plan_actors(file, plan);
  plan_traffic_lights(file, plan);
  return plan;
}

}  // namespace detail

Level2File level1_to_level2(const Level1File& file, Diagnostics& diagnostics) {
  detail::ConversionPlan plan = detail::plan_conversion(file);
  Level2File result;
  result.header = detail::convert_header(file.header);
  result.scenery = detail::convert_scenery(plan);
  result.dynamics = detail::convert_dynamics(plan, diagnostics);
  result.environment = detail::convert_environment(file);
  result.traffic = detail::convert_traffic(plan);
  return result;
}

}  // namespace scenfuzz::wmg

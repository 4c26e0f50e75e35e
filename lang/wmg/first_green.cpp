// Which direction of a signalised crossroads has the first green. The file gives no signal
// timing, and the generator's fixed plan gives the south and north arms the first 25 s: an ego
// on the west arm would wait at red through a whole 25 s run while its WHEN `[TL1] is [Green]`
// never held (corpora/wmg/signalised_junction.sdl did). So the plan starts as the file's first
// light condition describes, else with the ego's own approach green (docs/wmg-semantics.md).
#include <string>
#include <variant>

#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {
namespace {

// Whether a signal (`light_west`) or lane (`east_in_0`) of the crossroads map is on its west or
// east arm.
bool east_west(const std::string& map_id) {
  return map_id.find("west") != std::string::npos || map_id.find("east") != std::string::npos;
}

// The first WHEN condition naming a light of the junction: whether its direction is green.
const TrafficLightCondition* first_light_condition(const Dynamics& dynamics,
                                                   const Translation& translation) {
  for (const Ssms& ssms : dynamics.sequences)
    for (const WhenCondition& condition : ssms.conditions)
      if (const auto* light = std::get_if<TrafficLightCondition>(&condition))
        if (!light->lights.empty() && translation.traffic_lights.contains(light->lights[0].name))
          return light;
  return nullptr;
}

}  // namespace

void choose_first_green(const Dynamics& dynamics, Translation& translation) {
  MapReference& map = translation.scenario.map;
  if (map.name != "crossroads") return;
  bool first = false;  // east_west_first
  SourceLocation where = map.location;
  if (const TrafficLightCondition* condition = first_light_condition(dynamics, translation)) {
    // Green or amber: that light's approach goes first; red: the crossing one.
    const bool named_east_west =
        east_west(translation.traffic_lights.at(condition->lights[0].name));
    first = condition->colour.value == TrafficLightColour::red ? !named_east_west : named_east_west;
    where = condition->location;
  } else {
    first = east_west(translation.scenario.ego.initial.position.lane);
  }
  map.parameters.push_back(
      NamedValue{"east_west_first", constant_value(first ? 1.0 : 0.0, where), where});
}

}  // namespace scenfuzz::wmg

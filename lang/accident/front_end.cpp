// The accident front end (accident.hpp): parse, then translate the parts in order.
#include "lang/accident/accident.hpp"
#include "lang/accident/parser.hpp"
#include "lang/accident/translation.hpp"

namespace scenfuzz::accident {

namespace {

// Simulated long enough for a vehicle starting at the far end of the start distances at a crawl
// to be overtaken by the events: the collisions happen well inside it or not at all.
constexpr double kDuration = 30;

bool is_vehicle(const File& file, const std::string& name) {
  for (const Vehicle& vehicle : file.vehicles)
    if (vehicle.id.text == name) return true;
  return false;
}

// The ego: as asked, else the first collision's victim if it is a vehicle, else its actor.
std::string choose_ego(const File& file, const TranslateOptions& options,
                       Diagnostics& diagnostics) {
  if (!options.ego.empty()) {
    if (is_vehicle(file, options.ego)) return options.ego;
    std::string names;
    for (const Vehicle& vehicle : file.vehicles)
      names += (names.empty() ? "" : ", ") + vehicle.id.text;
    diagnostics.error(file.dynamic_at, "--ego names '" + options.ego +
                                           "', which is no VEHICLE of this description (" + names +
                                           ")");
    return {};
  }
  const Collision& first = file.collisions.front();
  return is_vehicle(file, first.victim.id.text) ? first.victim.id.text : first.actor.id.text;
}

ScenarioTemplate translate(const File& file, const TranslateOptions& options,
                           Diagnostics& diagnostics) {
  Translation translation(file, diagnostics);
  ScenarioTemplate& scenario = translation.scenario;
  scenario.language = SourceLanguage::accident;
  scenario.has_scenario = true;
  scenario.scenario_name = "accident";
  scenario.trace_name = "trace";
  // Every vehicle drives as described, without heeding the others: that is how it crashed.
  scenario.npc_behaviour = NpcBehaviour::scripted;
  scenario.duration = constant_value(kDuration);
  translation.ego = choose_ego(file, options, diagnostics);
  if (translation.ego.empty()) return scenario;
  translate_scene(translation);
  translate_vehicles(translation);
  translate_collisions(translation);
  return std::move(translation.scenario);
}

}  // namespace

int add_parameter(ScenarioTemplate& scenario, Parameter parameter) {
  scenario.parameters.push_back(std::move(parameter));
  return static_cast<int>(scenario.parameters.size()) - 1;
}

ScenarioParse parse_scenario(const SourceFile& file, const TranslateOptions& options) {
  ScenarioParse result;
  result.scenario.language = SourceLanguage::accident;
  ParseResult parsed = parse(file);
  result.diagnostics = std::move(parsed.diagnostics);
  if (!parsed.file) return result;
  result.scenario = translate(*parsed.file, options, result.diagnostics);
  return result;
}

}  // namespace scenfuzz::accident

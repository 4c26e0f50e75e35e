// The CH-Scenario translation's driver (translation.hpp): the parts in the order they depend on
// each other (entities need the map's roads; disasters, specs and events the road users).
#include "lang/chs/translation.hpp"

namespace scenfuzz::chs {

Value located(const Number& number, double scale) {
  return constant_value(number.value * scale, number.location);
}

ScenarioTemplate translate(const File& file, Diagnostics& diagnostics) {
  Translation translation(file, diagnostics);
  ScenarioTemplate& scenario = translation.scenario;
  scenario.language = SourceLanguage::ch_scenario;
  scenario.has_scenario = true;
  scenario.scenario_name = "scenario";
  scenario.trace_name = "trace";
  translate_map(translation);
  translate_entities(translation);
  translate_environment(translation);
  translate_specs(translation);
  translate_events(translation);
  return std::move(translation.scenario);
}

}  // namespace scenfuzz::chs

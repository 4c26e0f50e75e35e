// Level 1 to level 2, the environment: the time of day, the light, the sky and the weather
// features of the environment sentence, each the range the defaults table gives it.
#include "lang/wmg/level1_convert_parts.hpp"
#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::detail {

namespace {

const EnvironmentFeature* feature_of(const EnvironmentSentence& sentence,
                                     EnvironmentFeatureKind kind) {
  const EnvironmentFeature* found = nullptr;
  for (const EnvironmentFeature& feature : sentence.features)
    if (feature.kind == kind) found = &feature;  // the last one written wins
  return found;
}

}  // namespace

std::string surface_weather(const Level1File& file) {
  if (feature_of(file.environment, EnvironmentFeatureKind::snowfall)) return "snow";
  if (feature_of(file.environment, EnvironmentFeatureKind::rainfall)) return "rain";
  return "dry";
}

Environment convert_environment(const Level1File& file) {
  const EnvironmentSentence& sentence = file.environment;
  Environment environment;
  environment.id = Identifier{"Weather1", sentence.location};
  if (const EnvironmentFeature* wind = feature_of(sentence, EnvironmentFeatureKind::wind))
    environment.wind = table_range(default_for(Quality::wind, wind->phrase.text, "a light breeze"),
                                   wind->location);
  if (sentence.cloud && !sentence.cloud->is_string)
    environment.cloudiness =
        table_range(default_for(Quality::cloudiness, sentence.cloud->text, "cloudiness not said"),
                    sentence.cloud->location);
  else
    environment.cloudiness = table_range(setting("cloudiness not said"), sentence.location);
  if (const EnvironmentFeature* particulates =
          feature_of(sentence, EnvironmentFeatureKind::particulates))
    environment.particulates =
        converted_label(particulates->phrase, Quality::particulates, "no particulates");
  if (const EnvironmentFeature* rain = feature_of(sentence, EnvironmentFeatureKind::rainfall)) {
    const QualitativeDefault& row = default_for(Quality::rainfall, rain->phrase.text, "light rain");
    environment.rainfall = Rainfall{table_label(row.label, rain->location),
                                    table_range(row, rain->location), rain->location};
  } else {
    const QualitativeDefault& dry = setting("rainfall not said");
    environment.rainfall = Rainfall{table_label(dry.label, sentence.location),
                                    table_range(dry, sentence.location), sentence.location};
  }
  if (const EnvironmentFeature* snow = feature_of(sentence, EnvironmentFeatureKind::snowfall)) {
    const QualitativeDefault& row = default_for(Quality::snowfall, snow->phrase.text, "light snow");
    environment.snowfall = Snowfall{table_label(row.label, snow->location),
                                    table_range(row, snow->location), snow->location};
  }
  environment.time_of_day =
      table_range(default_for(Quality::time_of_day, sentence.time_of_day.text, "day"),
                  sentence.time_of_day.location);
  bool night = sentence.time_of_day.text == "night";
  const QualitativeDefault& light =
      default_for(night ? Quality::night_light : Quality::daylight, sentence.light.text, "light");
  environment.illumination = table_label(light.label, sentence.light.location);
  environment.light_source = table_label(
      default_for(Quality::light_source, light.label, "Day").label, sentence.light.location);
  if (light.has_range) {
    const QualitativeDefault& sun = setting("sun position");
    RelativeLocation position = RelativeLocation::front;
    const std::vector<std::string>& codes = vocabulary::relative_location().phrases;
    for (std::size_t i = 0; i < codes.size(); ++i)
      if (codes[i] == sun.label) position = static_cast<RelativeLocation>(i);
    environment.light_source_position = LightSourcePosition{
        table_range(light, sentence.light.location),
        Located<RelativeLocation>{position, sentence.light.location}, sentence.light.location};
  }
  environment.location = sentence.location;
  return environment;
}

}  // namespace scenfuzz::wmg::detail

// ENVIRONMENT_ELEMENTS to weather components in [0, 1] and the time of day (docs/wmg-semantics.md,
// "Environment"), and the traffic model's flows to background traffic that the simulator drives.
#include <string>

#include "lang/wmg/scenario_translation.hpp"

namespace scenfuzz::wmg {

namespace {

constexpr double kKilometresPerHour = 3.6;
// The contract's scales: the rainfall, wind and visibility that count as full intensity.
constexpr double kFullRain = 50.0;           // mm/h
constexpr double kFullWind = 100.0;          // km/h
constexpr double kClearVisibility = 1000.0;  // m
constexpr double kOktas = 8.0;

void add_weather(Translation& translation, const std::string& kind, Value intensity,
                 std::optional<WeatherLevel> level, SourceLocation location) {
  translation.scenario.environment->weather.push_back(
      WeatherComponent{kind, std::move(intensity), level, location});
}

// The IR has no `min`: a range reaching past full intensity cannot be clamped, so the intensity
// grows past 1 there, and the user is told.
void warn_past_full(Translation& translation, const NumberRange& range, double full,
                    const std::string& what) {
  if (range.high > full)
    translation.diagnostics.warning(
        range.location,
        what + " above " + std::to_string(static_cast<int>(full)) + " gives an intensity above 1");
}

void add_attribute(Translation& translation, const std::string& key, const Label& label) {
  translation.scenario.environment->attributes.push_back(
      Attribute{key, label.text, label.location});
}

std::optional<WeatherLevel> snow_level(const std::string& type) {
  if (type == "Light Snow") return WeatherLevel::light;
  if (type == "Moderate Snow") return WeatherLevel::middle;
  if (type == "Heavy Snow") return WeatherLevel::heavy;
  return std::nullopt;
}

double snow_intensity(WeatherLevel level) {
  switch (level) {
    case WeatherLevel::light: return 0.3;
    case WeatherLevel::middle: return 0.6;
    case WeatherLevel::heavy: return 0.9;
  }
  return 0.3;
}

// The simulator spawns a flow's vehicles at its rate and speed: neither may be negative, the
// vehicles must move, and more than one vehicle a second per lane is not traffic.
void check_flow(const TrafficFlow& flow, Translation& translation) {
  constexpr double kMostVehiclesPerHour = 3600.0;
  const std::string name = "traffic flow '" + flow.id.name + "'";
  if (flow.first.low < 0.0)
    translation.diagnostics.error(flow.first.location,
                                  "the rate of " + name + " cannot be negative");
  else if (flow.first.high > kMostVehiclesPerHour)
    translation.diagnostics.error(flow.first.location,
                                  "the rate of " + name +
                                      " cannot be above 3600 vehicles per hour (one vehicle per "
                                      "second per lane)");
  if (flow.second.low <= 0.0)
    translation.diagnostics.error(flow.second.location, "the speed of " + name +
                                                            " must be above 0 km/h (its "
                                                            "vehicles must move)");
}

}  // namespace

void translate_environment(const Environment& environment, Translation& translation) {
  translation.scenario.environment = scenfuzz::Environment{};
  translation.scenario.environment->location = environment.location;
  if (environment.wind) {
    warn_past_full(translation, *environment.wind, kFullWind, "wind");
    add_weather(translation, "wind",
                translation.number(*environment.wind, "environment.wind", "km/h", kFullWind),
                std::nullopt, environment.wind->location);
  }
  add_weather(translation, "cloudiness",
              translation.number(environment.cloudiness, "environment.cloudiness", "oktas", kOktas),
              std::nullopt, environment.cloudiness.location);
  if (environment.particulates) {
    if (environment.particulates->text == "Mist and Fog")
      add_weather(translation, "fog", constant_value(0.5), std::nullopt,
                  environment.particulates->location);
    else
      add_attribute(translation, "particulates", *environment.particulates);
  }
  const Rainfall& rain = environment.rainfall;
  warn_past_full(translation, rain.intensity, kFullRain, "rainfall");
  add_attribute(translation, "rainfall", rain.type);
  add_weather(translation, "rain",
              translation.number(rain.intensity, "environment.rainfall", "mm/h", kFullRain),
              std::nullopt, rain.location);
  if (environment.snowfall) {
    const Snowfall& snow = *environment.snowfall;
    const std::optional<WeatherLevel> level = snow_level(snow.type.text);
    add_weather(translation, "snow",
                constant_value(snow_intensity(level.value_or(WeatherLevel::light))), level,
                snow.location);
    warn_past_full(translation, snow.visibility, kClearVisibility, "snowfall visibility");
    Value visibility = translation.number(snow.visibility, "environment.snowfall.visibility", "m",
                                          kClearVisibility);
    add_weather(
        translation, "fog",
        binary_value(ValueOp::subtract, constant_value(1.0), visibility, snow.visibility.location),
        std::nullopt, snow.location);
  }
  if (environment.time_of_day)
    translation.scenario.environment->time_of_day =
        translation.number(*environment.time_of_day, "environment.time_of_day", "time of day");
  add_attribute(translation, "illumination", environment.illumination);
  add_attribute(translation, "light_source", environment.light_source);
  if (environment.light_source_position) {
    const LightSourcePosition& position = *environment.light_source_position;
    translation.number(position.elevation, "environment.light_elevation", "deg", 1.0,
                       ParameterKind::angle);
    translation.scenario.environment->attributes.push_back(Attribute{
        "light_position", sector_text(position.position.value), position.position.location});
  }
  if (environment.connectivity && !environment.connectivity->none) {
    const Connectivity& connectivity = *environment.connectivity;
    if (connectivity.link) add_attribute(translation, "communication", *connectivity.link);
    if (connectivity.technology) add_attribute(translation, "technology", *connectivity.technology);
    if (connectivity.positioning)
      add_attribute(translation, "positioning", *connectivity.positioning);
  }
}

// A flow's destination: at a junction traffic bound for another road leaves the junction on it,
// by the lane written where the connections make it an out lane (lane_directions.cpp), else by
// the arm's out lane of the same number. A
// flow to its own origin (level 1's "traffic on R1") has no destination: it drives on along the
// lanes' successors.
std::string destination_lane_id(const TrafficFlow& flow, Translation& translation) {
  if (flow.destination_lane.road.name == flow.source_lane.road.name &&
      flow.destination_lane.lane.name == flow.source_lane.lane.name) {
    translation.lane_id(flow.destination_lane);  // still checked
    return "";
  }
  std::string id = translation.lane_id(flow.destination_lane).value_or("");
  const std::string::size_type in = id.rfind("_in_");
  if (in != std::string::npos) id.replace(in, 4, "_out_");
  return id;
}

void translate_traffic(const TrafficModel& traffic, Translation& translation) {
  for (const Centroid& centroid : traffic.centroids) {
    if (!translation.roads.contains(centroid.road.name))
      translation.diagnostics.error(centroid.road.location,
                                    "unknown road '" + centroid.road.name + "'");
    translation.number(centroid.distance, "traffic." + centroid.id.name + ".distance", "m");
  }
  for (const TrafficFlow& flow : traffic.flows) {
    check_flow(flow, translation);
    scenfuzz::TrafficFlow result;
    result.name = flow.id.name;
    result.location = flow.location;
    result.source_lane = translation.lane_id(flow.source_lane).value_or("");
    result.destination_lane = destination_lane_id(flow, translation);
    const std::string prefix = "traffic." + flow.id.name + ".";
    result.rate = translation.number(flow.first, prefix + "rate", "veh/h");
    result.speed = translation.number(flow.second, prefix + "speed", "km/h", kKilometresPerHour);
    translation.scenario.traffic.flows.push_back(std::move(result));
  }
}

}  // namespace scenfuzz::wmg

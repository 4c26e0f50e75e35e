// CH-Scenario weather, natural disasters and special high-risk conditions (translation.hpp;
// docs/ch-scenario.md, "Weather and disasters"). The simulation knows rain, fog, snow, wetness and
// the time of day: precipitation is rain, the visibility's shortfall is fog, and each disaster
// sets a floor under them; a geological disaster puts an obstacle in the ego's lane ahead. The
// special high-risk conditions lower the speed limit (translate_map.cpp) and the road's friction.
#include <algorithm>

#include "lang/chs/translation.hpp"

namespace scenfuzz::chs {

namespace {

// Floors the meteorological disasters set under rain and fog (fog 1 is the least visibility
// the perception model knows: 15 % of the clear-day range).
struct DisasterWeather {
  double rain = 0, fog = 0;
};

DisasterWeather disaster_weather(const NaturalDisaster& d) {
  DisasterWeather floor;
  auto raise = [&](const Flag& flag, double rain, double fog) {
    if (!flag.value) return;
    floor.rain = std::max(floor.rain, rain);
    floor.fog = std::max(floor.fog, fog);
  };
  raise(d.rainstorm, 1.0, 0.3);
  raise(d.typhoon, 0.9, 0.5);
  raise(d.sandstorm, 0, 0.9);
  raise(d.tornado, 0.5, 0.6);
  return floor;
}

// The written value as a located component, unless the disaster's floor is higher (then the
// floor holds and the written number has no effect, so it is not a place to mutate).
WeatherComponent component(const std::string& kind, double written, const Number& at,
                           double floor) {
  if (floor > written) return {kind, constant_value(floor), std::nullopt, at.location};
  return {kind, constant_value(written, at.location), std::nullopt, at.location};
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// The `H:MM` or `HH:MM:SS` in a timestamp (`2022 年 1 月 30 日 17:30:42`), in seconds since
// midnight, located at its own text.
std::optional<Value> time_of_day(const Text& timestamp) {
  const std::string& text = timestamp.text;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!is_digit(text[i]) || (i > 0 && is_digit(text[i - 1]))) continue;
    std::size_t j = i;
    while (j < text.size() && is_digit(text[j])) ++j;
    if (j - i > 2 || j + 2 >= text.size() || text[j] != ':' || !is_digit(text[j + 1]) ||
        !is_digit(text[j + 2]))
      continue;
    const int hours = std::stoi(text.substr(i, j - i));
    const int minutes = std::stoi(text.substr(j + 1, 2));
    std::size_t end = j + 3;
    int seconds = 0;
    if (end + 2 < text.size() && text[end] == ':' && is_digit(text[end + 1]) &&
        is_digit(text[end + 2])) {
      seconds = std::stoi(text.substr(end + 1, 2));
      end += 3;
    }
    if (hours > 23 || minutes > 59 || seconds > 59) return std::nullopt;
    SourceLocation at = timestamp.location;
    std::uint32_t characters = 0;  // columns count UTF-8 code points
    for (std::size_t k = 0; k < i; ++k)
      if ((static_cast<unsigned char>(text[k]) & 0xC0) != 0x80) ++characters;
    at.column += characters;
    at.offset += static_cast<std::uint32_t>(i);
    at.length = static_cast<std::uint32_t>(end - i);
    return constant_value(hours * 3600.0 + minutes * 60.0 + seconds, at);
  }
  return std::nullopt;
}

// The road's grip as a share of dry asphalt's (docs/ch-scenario.md, "Road friction"): the least
// any of the file's conditions leaves; none on a dry, sound road.
std::optional<double> road_friction(const File& file) {
  const SpecialHighRisk& h = file.high_risk;
  double friction = 1 - 0.3 * file.weather.wetness.value;  // wet asphalt: about 0.7 of dry
  if (h.wade.value) friction = std::min(friction, 0.5);
  if (h.muddy.value || file.disaster.debris_flow.value) friction = std::min(friction, 0.4);
  if (h.ice_road.value) friction = std::min(friction, 0.2);
  if (friction >= 1) return std::nullopt;
  return friction;
}

// A geological disaster in the ego's lane ahead: its name, length along the lane and height.
struct Blockage {
  const char* name;
  double length, height;
};

void geological_disasters(Translation& translation) {
  const NaturalDisaster& d = translation.file.disaster;
  constexpr double kAhead = 120;  // m from the ego's start
  // Fallen from the kerb side, it leaves room on the lane's left to pass in the other lane.
  constexpr double kWidth = 2.5, kTowardsKerb = -0.75;
  for (auto [flag, blockage] : {std::pair{&d.landslide, Blockage{"landslide", 6, 2}},
                                std::pair{&d.debris_flow, Blockage{"debris_flow", 10, 1}},
                                std::pair{&d.collapse, Blockage{"collapse", 15, 0.5}}}) {
    if (!flag->value) continue;
    Obstacle obstacle;
    obstacle.name = blockage.name;
    obstacle.position.kind = PositionKind::relative;
    obstacle.position.reference = translation.scenario.ego.name;
    obstacle.position.s = constant_value(kAhead);
    obstacle.position.relative_location = "F";
    obstacle.position.lateral = constant_value(kTowardsKerb);
    obstacle.position.location = flag->location;
    obstacle.shape = Shape{
        ShapeKind::box,
        {constant_value(blockage.length), constant_value(kWidth), constant_value(blockage.height)},
        flag->location};
    obstacle.location = flag->location;
    translation.scenario.obstacles.push_back(std::move(obstacle));
  }
}

}  // namespace

void translate_environment(Translation& translation) {
  const File& file = translation.file;
  Environment environment;
  const Weather& w = file.weather;
  environment.location = w.location;
  const DisasterWeather floor = disaster_weather(file.disaster);
  environment.weather.push_back(
      component("rain", w.precipitation.value, w.precipitation, floor.rain));
  environment.weather.push_back(component("fog", 1 - w.visibility.value, w.visibility, floor.fog));
  environment.weather.push_back(component("wetness", w.wetness.value, w.wetness, 0));
  environment.weather.push_back(component("cloudiness", w.cloudiness.value, w.cloudiness, 0));
  for (const DynamicEntity& entity : file.dynamic_entities)
    if (auto time = time_of_day(entity.timestamp)) {
      environment.time_of_day = std::move(time);
      break;
    }
  if (const auto friction = road_friction(file))
    environment.road_friction = constant_value(*friction);
  translation.scenario.environment = std::move(environment);
  if (!translation.scenario.ego.name.empty()) geological_disasters(translation);
}

}  // namespace scenfuzz::chs

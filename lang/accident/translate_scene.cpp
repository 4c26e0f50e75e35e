// The static part (translation.hpp; docs/accident.md, "What a description means"): the road kind
// as a built-in map, with two lanes each way when a vehicle changes lanes and one otherwise; trees
// as obstacles; lights as the crossroad's signals set to their colour; stop signs and level
// crossings where they are written.
#include <cmath>

#include "lang/accident/translation.hpp"

namespace scenfuzz::accident {

namespace {

// A roadside tree's trunk, as a cylinder.
constexpr double kTrunkRadius = 0.3;
constexpr double kTreeHeight = 6;

bool changes_lanes(const File& file) {
  for (const Vehicle& vehicle : file.vehicles)
    for (const Event& event : vehicle.chain)
      if (event.kind.value == EventKind::change_lane_left ||
          event.kind.value == EventKind::change_lane_right)
        return true;
  return false;
}

Position map_position(const SceneLayout& layout, const Point& point) {
  const PlanePoint on_map = layout.on_map({point.x, point.y});
  Position position;
  position.kind = PositionKind::coordinate;
  position.x = constant_value(on_map.x, point.x_at);
  position.y = constant_value(on_map.y, point.y_at);
  position.location = point.location;
  return position;
}

void translate_map(Translation& translation) {
  const File& file = translation.file;
  translation.layout = scene_layout(file.road.kind.value, changes_lanes(file) ? 2 : 1);
  MapReference& map = translation.scenario.map;
  map.name = translation.layout.map;
  map.location = file.road.location;
  for (const auto& [name, value] : translation.layout.parameters)
    map.parameters.push_back({name, constant_value(value), file.road.location});
}

void translate_trees(Translation& translation) {
  for (const Tree& tree : translation.file.trees) {
    Obstacle obstacle;
    obstacle.name = tree.id.text;
    obstacle.position = map_position(translation.layout, tree.coords);
    // AVUnit's cylinder has three dimensions, the third unused (docs/simulation.md).
    obstacle.shape = Shape{ShapeKind::cylinder,
                           {constant_value(kTrunkRadius), constant_value(kTreeHeight),
                            constant_value(kTrunkRadius)},
                           tree.location};
    obstacle.location = tree.location;
    translation.scenario.obstacles.push_back(std::move(obstacle));
  }
}

// The crossroad's arm a light stands on: the one its position lies along.
std::string arm_of(const Point& point) {
  if (std::abs(point.x) > std::abs(point.y)) return point.x > 0 ? "east" : "west";
  return point.y > 0 ? "north" : "south";
}

// A light is the signal of the crossroad's arm it stands on, showing its colour from the start;
// the built-in crossroads' signals then run their plan on. Other roads have no signals.
void translate_lights(Translation& translation) {
  for (const Light& light : translation.file.lights) {
    if (translation.file.road.kind.value != RoadKind::crossroad) {
      translation.diagnostics.warning(
          light.location, "light '" + light.id.text +
                              "' is left out: only a crossroad has traffic lights in scenfuzz");
      continue;
    }
    if (light.colour.value == Colour::inactive) {
      translation.diagnostics.warning(
          light.colour.location, "light '" + light.id.text +
                                     "' is inactive, but the crossroad's signals always run their "
                                     "plan: its colour is left to the plan");
      continue;
    }
    TrafficLightSetting setting;
    setting.id = "light_" + arm_of(light.coords);
    setting.color = light.colour.value == Colour::red     ? "red"
                    : light.colour.value == Colour::green ? "green"
                                                          : "yellow";
    setting.location = light.location;
    translation.scenario.traffic.lights.push_back(std::move(setting));
  }
}

}  // namespace

void translate_scene(Translation& translation) {
  translate_map(translation);
  translate_trees(translation);
  translate_lights(translation);
  for (const StopSign& sign : translation.file.stop_signs)
    translation.scenario.traffic.stop_signs.push_back(
        map_position(translation.layout, sign.coords));
  for (const LevelCrossing& crossing : translation.file.crossings)
    translation.scenario.traffic.level_crossings.push_back(
        map_position(translation.layout, crossing.coords));
}

}  // namespace scenfuzz::accident

#include "lang/wmg/level1_phrases.hpp"

namespace scenfuzz::wmg::level1_phrases {

const Vocabulary& time_of_day() {
  static const Vocabulary v{"time of day", {"day", "night"}, false, {}};
  return v;
}

const Vocabulary& light_condition() {
  static const Vocabulary v{"light condition", {"light", "bright", "dark"}, false, {}};
  return v;
}

const Vocabulary& cloud_condition() {
  static const Vocabulary v{
      "cloud condition",
      {"lightly cloud covered", "partly cloudy", "cloudy", "cloud covered", "overcast", "clear"},
      true,
      {}};
  return v;
}

const Vocabulary& particulates() {
  static const Vocabulary v{"particulates",
                            {"marine particulates", "mist and fog", "dust and sand",
                             "smoke and pollution", "volcanic ash", "no particulates"},
                            false,
                            {}};
  return v;
}

const Vocabulary& snowfall() {
  static const Vocabulary v{"snowfall", {"light snow", "moderate snow", "heavy snow"}, false, {}};
  return v;
}

const Vocabulary& wind() {
  static const Vocabulary v{
      "wind", {"a light breeze", "a moderate breeze", "a heavy breeze"}, false, {}};
  return v;
}

const Vocabulary& rainfall() {
  static const Vocabulary v{"rainfall", {"light rain", "moderate rain", "heavy rain"}, false, {}};
  return v;
}

const Vocabulary& junction_type() {
  static const Vocabulary v{
      "junction type",
      {"T-Junction", "Y-Junction", "staggered junction", "staggered", "crossroad",
       "grade separated junction", "normal roundabout", "large roundabout", "double roundabout",
       "compact roundabout", "mini roundabout"},
      true,
      {}};
  return v;
}

const Vocabulary& connection_type() {
  static const Vocabulary v{
      "connection type",
      {"straight ahead", "turning right", "turning left", "to the left", "to the right"},
      false,
      {}};
  return v;
}

const Vocabulary& horizontal_geometry() {
  static const Vocabulary v{"horizontal geometry", {"straight", "curved"}, true, {}};
  return v;
}

const Vocabulary& road_type() {
  static const Vocabulary v{
      "road type",
      {"motorway", "radial road", "distributor road", "minor road", "parking zone", "motorways",
       "radial roads", "distributor roads", "minor roads", "parking zones"},
      true,
      {}};
  return v;
}

const Vocabulary& road_feature() {
  static const Vocabulary v{"road feature",
                            {"broken lane markings", "solid lane markings",
                             "temporary lane markings", "pedestrian crossing", "trees", "buildings",
                             "solid barriers", "street lights", "traffic lights"},
                            true,
                            {}};
  return v;
}

const Vocabulary& traffic_amount() {
  static const Vocabulary v{
      "amount of traffic", {"no", "light", "some", "moderate", "heavy", "a lot of"}, false, {}};
  return v;
}

const Vocabulary& actor_type() {
  static const Vocabulary v{
      "actor type",
      {"vehicle", "pedestrian", "cyclist", "vehicles", "pedestrians", "cyclists"},
      false,
      {}};
  return v;
}

const Vocabulary& traffic_light_colour() {
  static const Vocabulary v{"traffic light colour", {"green", "amber", "red"}, false, {}};
  return v;
}

const Vocabulary& action() {
  static const Vocabulary v{
      "manoeuvre",
      {"is driving", "is cutting in", "is cutting out", "is stopped", "drives", "cuts in",
       "cuts out", "stops", "changes lane right", "changes lane left", "turns right", "turns left",
       "reverses", "collides", "walks", "runs", "slides", "cutting in", "cutting out"},
      false,
      {}};
  return v;
}

const Vocabulary& relation() {
  static const Vocabulary v{
      "place",
      {"towards", "ahead of", "across", "in front of", "behind", "from", "with", "ahead", "away"},
      false,
      {}};
  return v;
}

const Vocabulary& preposition() {
  static const Vocabulary v{"preposition", {"near", "on", "onto", "into"}, false, {}};
  return v;
}

const Vocabulary& relative_position() {
  static const Vocabulary v{
      "relative position",
      {"front", "rear", "left", "front left", "rear left", "right", "front right", "rear right"},
      false,
      {}};
  return v;
}

const Vocabulary& speed_change() {
  static const Vocabulary v{
      "speed condition",
      {"accelerating", "speeding up", "at constant speed", "decelerating", "slowing down"},
      false,
      {}};
  return v;
}

}  // namespace scenfuzz::wmg::level1_phrases

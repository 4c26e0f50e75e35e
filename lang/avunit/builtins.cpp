#include "lang/avunit/builtins.hpp"

#include <algorithm>
#include <array>

namespace scenfuzz::avunit {

namespace {

constexpr std::array kFunctions = {std::string_view("dis"), std::string_view("vel"),
                                   std::string_view("spd"), std::string_view("acc"),
                                   std::string_view("diff")};

constexpr std::array<std::string_view, 18> kFlags = {"highBeamOn",
                                                     "lowBeamOn",
                                                     "hornOn",
                                                     "fogLightOn",
                                                     "warningFlashOn",
                                                     "wiperOn",
                                                     "engineOn",
                                                     "manualIntervention",
                                                     "isLaneChanging",
                                                     "isOverTaking",
                                                     "isTurningAround",
                                                     "honkingAllowed",
                                                     "streetLightOn",
                                                     "PriorityNPCAhead",
                                                     "PriorityPedsAhead",
                                                     "isTrafficJam",
                                                     "trafficLightAhead.isBlinking",
                                                     "trafficLightAhead.direction.isBlinking"};

constexpr std::array<std::string_view, 8> kDistancePredicates = {
    "crosswalkAhead",       "junctionAhead", "stopSignAhead", "stoplineAhead",
    "specialLocationAhead", "NPCAhead",      "NearestNPC",    "NPCOpposite"};

constexpr std::array<std::string_view, 23> kValueSignals = {"speed",
                                                            "acc",
                                                            "brake",
                                                            "gear",
                                                            "direction",
                                                            "turnSignal",
                                                            "currentLane.number",
                                                            "currentLane.direction",
                                                            "speedLimit.upperLimit",
                                                            "speedLimit.lowerLimit",
                                                            "trafficLightAhead.color",
                                                            "trafficLightAhead.direction.color",
                                                            "signalAhead",
                                                            "specialLocationAhead.type",
                                                            "NPCAhead.speed",
                                                            "NearestNPC.speed",
                                                            "NPCOpposite.speed",
                                                            "Time",
                                                            "rain",
                                                            "fog",
                                                            "snow",
                                                            "visibility",
                                                            "wetness"};

constexpr std::array<std::string_view, 5> kColors = {"red", "green", "blue", "black", "white"};
constexpr std::array<std::string_view, 7> kVehicleKinds = {
    "car", "bus", "Van", "truck", "bicycle", "motorbicycle", "tricycle"};
constexpr std::array<std::string_view, 4> kShapes = {"sphere", "box", "cone", "cylinder"};
constexpr std::array<std::string_view, 6> kWeatherKinds = {"sunny", "rain",    "snow",
                                                           "fog",   "wetness", "cloudiness"};
constexpr std::array<std::string_view, 3> kWeatherLevels = {"light", "middle", "heavy"};
constexpr std::array<std::string_view, 7> kEnumerationWords = {"red",     "yellow", "green", "off",
                                                               "forward", "left",   "right"};
constexpr std::array<std::string_view, 6> kWaypointFunctions = {"Waypoint", "waypoint", "W",
                                                                "WP",       "w",        "wp"};

constexpr std::array<std::string_view, 7> kTraceColumns = {
    "x", "y", "heading", "speed", "acceleration", "yaw_rate", "s"};

template <std::size_t N>
bool contains(const std::array<std::string_view, N>& words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

}  // namespace

SignalClass signal_class(std::string_view name) {
  if (contains(kFunctions, name)) return SignalClass::function;
  if (contains(kFlags, name)) return SignalClass::flag;
  if (contains(kDistancePredicates, name)) return SignalClass::distance_predicate;
  if (contains(kValueSignals, name)) return SignalClass::value;
  return SignalClass::none;
}

bool is_trace_column(std::string_view name) { return contains(kTraceColumns, name); }

std::string trace_column_list() {
  std::string list;
  for (std::string_view column : kTraceColumns) (list += list.empty() ? "" : ", ") += column;
  return list;
}

bool is_color_word(std::string_view word) { return contains(kColors, word); }
bool is_vehicle_kind_word(std::string_view word) { return contains(kVehicleKinds, word); }
bool is_shape_word(std::string_view word) { return contains(kShapes, word); }
bool is_weather_kind(std::string_view word) { return contains(kWeatherKinds, word); }
bool is_weather_level(std::string_view word) { return contains(kWeatherLevels, word); }
bool is_enumeration_word(std::string_view word) { return contains(kEnumerationWords, word); }
bool is_waypoint_function(std::string_view name) { return contains(kWaypointFunctions, name); }
// `U` and `u` are the older scenest grammar's short forms (../shared/grammars/scenest.txt).
bool is_uniform_function(std::string_view name) {
  return name == "uniform" || name == "Uniform" || name == "U" || name == "u";
}
bool is_motion_function(std::string_view name) {
  return is_waypoint_function(name) || is_uniform_function(name) || name == "Random";
}

double weather_level_intensity(std::string_view level) {
  if (level == "light") return 0.1;
  if (level == "middle") return 0.5;
  return 0.8;
}

std::vector<std::string_view> builtin_names() {
  std::vector<std::string_view> names = {
      "AV",    "Vehicle",      "Pedestrian",  "Obstacle", "Environment",  "load",
      "range", "EXE",          "IMU",         "ENU",      "WGS84",        "EGO",
      "pi",    "uniform",      "Waypoint",    "Random",   "Intersection", "SpeedLimit",
      "Flow",  "NPCBehaviour", "TrafficLight"};
  names.insert(names.end(), kFunctions.begin(), kFunctions.end());
  names.insert(names.end(), kFlags.begin(), kFlags.end());
  names.insert(names.end(), kDistancePredicates.begin(), kDistancePredicates.end());
  names.insert(names.end(), kValueSignals.begin(), kValueSignals.end());
  names.insert(names.end(), kColors.begin(), kColors.end());
  names.insert(names.end(), kVehicleKinds.begin(), kVehicleKinds.end());
  names.insert(names.end(), kShapes.begin(), kShapes.end());
  names.insert(names.end(), kWeatherLevels.begin(), kWeatherLevels.end());
  names.insert(names.end(), kEnumerationWords.begin(), kEnumerationWords.end());
  return names;
}

}  // namespace scenfuzz::avunit

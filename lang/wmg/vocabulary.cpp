#include "lang/wmg/vocabulary.hpp"

#include <algorithm>
#include <cctype>

#include "lang/edit_distance.hpp"

namespace scenfuzz::wmg {

namespace vocabulary {

const Vocabulary& extension() {
  static const Vocabulary v{"extension", {"None"}, true, {}};
  return v;
}

const Vocabulary& npc_behaviour() {
  static const Vocabulary v{"NPC behaviour", {"Reactive", "Scripted"}, false, {}};
  return v;
}

const Vocabulary& junction_type() {
  static const Vocabulary v{"junction type",
                            {"T-Junction", "Y-Junction", "Staggered", "Crossroads",
                             "Grade Separated", "Normal roundabout", "Large roundabout",
                             "Double roundabout", "Compact roundabout", "Mini roundabout"},
                            true,
                            {}};
  return v;
}

const Vocabulary& connection_control() {
  static const Vocabulary v{"connection control", {"Traffic light", "Give way", "No"}, true, {}};
  return v;
}

const Vocabulary& junction_road_sign() {
  static const Vocabulary v{
      "road sign", {"Traffic Light", "Warning", "Give way", "Stop"}, true, {}};
  return v;
}

const Vocabulary& traffic_light_type() {
  static const Vocabulary v{
      "traffic light type", {"With pedestrian crossing", "Without pedestrian crossing"}, true, {}};
  return v;
}

const Vocabulary& road_type() {
  static const Vocabulary v{
      "road type",
      {"Motorway", "Radial road", "Distributor road", "Minor road", "Parking"},
      true,
      {}};
  return v;
}

const Vocabulary& zone_type() {
  static const Vocabulary v{"zone", {"N/A"}, true, {}};
  return v;
}

const Vocabulary& environment_type() {
  static const Vocabulary v{"environment type", {"Urban", "Rural"}, true, {}};
  return v;
}

const Vocabulary& traffic_direction() {
  static const Vocabulary v{"traffic direction", {"Left-handed", "Right-handed"}, true, {}};
  return v;
}

const Vocabulary& lane_type() {
  static const Vocabulary v{"lane type", {"Traffic lane"}, true, {}};
  return v;
}

const Vocabulary& lane_marking() {
  static const Vocabulary v{"lane marking", {"Broken line", "Solid line"}, true, {}};
  return v;
}

const Vocabulary& surface_type() {
  static const Vocabulary v{"surface type", {"Loose", "Segmented", "Uniform"}, true, {}};
  return v;
}

const Vocabulary& surface_condition() {
  static const Vocabulary v{"surface condition",
                            {"Dry", "Wet", "Snow", "Contaminated", "Icy", "Mirage", "Flooded"},
                            true,
                            {}};
  return v;
}

const Vocabulary& surface_feature() {
  static const Vocabulary v{
      "surface feature", {"Cracks", "Potholes", "Ruts", "Swells", "N/A"}, true, {}};
  return v;
}

const Vocabulary& horizontal_geometry() {
  static const Vocabulary v{"horizontal geometry", {"Straight", "Curved"}, true, {}};
  return v;
}

const Vocabulary& vertical_geometry() {
  static const Vocabulary v{
      "vertical geometry", {"Up-slope", "Down-slope", "Level plane"}, true, {}};
  return v;
}

const Vocabulary& transverse_geometry() {
  static const Vocabulary v{"transverse geometry", {"Divided", "Undivided", "Pavement"}, true, {}};
  return v;
}

const Vocabulary& banking_angle() {
  static const Vocabulary v{"banking angle",
                            {"Level Plane", "Left Bank - Shallow", "Left Bank - Deep",
                             "Right Bank - Shallow", "Right Bank - Deep"},
                            false,
                            {}};
  return v;
}

const Vocabulary& roadside_feature() {
  static const Vocabulary v{"roadside feature", {"No"}, true, {}};
  return v;
}

const Vocabulary& edge_feature() {
  static const Vocabulary v{"roadway edge feature",
                            {"Shoulder (grass)", "Solid barriers", "Temporary line markers",
                             "Pavement", "Line markers", "Shoulder (paved or gravel)"},
                            true,
                            {}};
  return v;
}

const Vocabulary& special_structure() {
  static const Vocabulary v{"special road structure",
                            {"Bridge", "Tunnel", "Rail crossing", "Automated barrier",
                             "Pedestrian crossing", "Toll plaza", "Speed bump"},
                            true,
                            {}};
  return v;
}

const Vocabulary& fixed_structure() {
  static const Vocabulary v{"fixed road structure",
                            {"Street lights", "Vegetation", "Street furniture", "Buildings"},
                            true,
                            {}};
  return v;
}

const Vocabulary& temporary_structure() {
  static const Vocabulary v{
      "temporary road structure",
      {"Accident site", "Road works", "Construction site detour", "Refuse collection", "Flood"},
      true,
      {}};
  return v;
}

const Vocabulary& road_sign() {
  static const Vocabulary v{"road sign", {"Speed limit"}, true, {}};
  return v;
}

const Vocabulary& actor_type() {
  static const Vocabulary v{"actor type", {"Vehicle", "Pedestrian", "Cyclist"}, false, {}};
  return v;
}

const Vocabulary& relative_location() {
  static const Vocabulary v{
      "relative location", {"F", "FSR", "SR", "RSR", "R", "RSL", "SL", "FSL"}, false, {}};
  return v;
}

const Vocabulary& position_relation() {
  static const Vocabulary v{"position relation", {"Lateral", "Longitudinal"}, false, {}};
  return v;
}

const Vocabulary& timer_scope() {
  static const Vocabulary v{"timer", {"Global timer", "Local timer"}, false, {}};
  return v;
}

const Vocabulary& observed_manoeuvre() {
  static const Vocabulary v{"observed manoeuvre",
                            {"Going Ahead", "Stopped", "LaneChangeRight", "LaneChangeLeft",
                             "TurnRight", "TurnLeft", "Reverse"},
                            true,
                            {}};
  return v;
}

const Vocabulary& traffic_light_colour() {
  static const Vocabulary v{"traffic light colour", {"Green", "Amber", "Red"}, false, {}};
  return v;
}

const Vocabulary& manoeuvre_type() {
  static const Vocabulary v{"manoeuvre type",
                            {"Drive_CutIn",
                             "Drive_CutOut",
                             "Drive_Towards",
                             "Drive_Away",
                             "Stop",
                             "Stopped",
                             "LaneChangeRight_CutIn",
                             "LaneChangeRight_CutOut",
                             "LaneChangeRight_Towards",
                             "LaneChangeRight_Away",
                             "LaneChangeLeft_CutIn",
                             "LaneChangeLeft_CutOut",
                             "LaneChangeLeft_Towards",
                             "LaneChangeLeft_Away",
                             "TurnRight_CutIn",
                             "TurnRight_CutOut",
                             "TurnRight_Towards",
                             "TurnRight_Away",
                             "TurnLeft_CutIn",
                             "TurnLeft_CutOut",
                             "TurnLeft_Towards",
                             "TurnLeft_Away",
                             "Reverse_CutIn",
                             "Reverse_CutOut",
                             "Reverse_Towards",
                             "Reverse_Away",
                             "Misc_CutIn",
                             "Misc_CutOut",
                             "Misc_Towards",
                             "Misc_Away",
                             "Collide_CutIn",
                             "Collide_CutOut",
                             "Collide_Towards",
                             "Collide_Away",
                             "Walk_Towards",
                             "Walk_Cross",
                             "Walk_Away",
                             "Run_Towards",
                             "Run_Cross",
                             "Run_Away",
                             "Slide_Towards",
                             "Slide_Cross",
                             "Slide_Away"},
                            false,
                            {{"Misc_Cutout", "Misc_CutOut"}, {"Collide_Cutout", "Collide_CutOut"}}};
  return v;
}

const Vocabulary& particulates() {
  static const Vocabulary v{
      "particulates type",
      {"Marine", "Mist and Fog", "Sand and Dust", "Smoke and Pollution", "Volcanic Ash", "None"},
      false,
      {}};
  return v;
}

const Vocabulary& rainfall() {
  static const Vocabulary v{
      "rainfall type", {"Light Rain", "Moderate Rain", "Heavy Rain"}, false, {}};
  return v;
}

const Vocabulary& snowfall() {
  static const Vocabulary v{
      "snowfall type", {"Light Snow", "Moderate Snow", "Heavy Snow"}, false, {}};
  return v;
}

const Vocabulary& light_type() {
  static const Vocabulary v{
      "illumination", {"Day", "Night Lit", "Night Dark", "Artificial"}, false, {}};
  return v;
}

const Vocabulary& light_source() {
  static const Vocabulary v{"light source", {"Sun", "Headlamp", "Street Lighting"}, true, {}};
  return v;
}

const Vocabulary& communication_link() {
  static const Vocabulary v{"communication link", {"V2V", "V2I"}, false, {}};
  return v;
}

const Vocabulary& v2v_technology() {
  static const Vocabulary v{"V2V technology", {"Cellular", "Satellite", "WiFi"}, false, {}};
  return v;
}

const Vocabulary& v2i_technology() {
  static const Vocabulary v{
      "V2I technology", {"Cellular", "Satellite", "WiFi", "GLOSA"}, false, {}};
  return v;
}

const Vocabulary& positioning() {
  static const Vocabulary v{"positioning system", {"Galileo", "GLONASS", "GPS"}, false, {}};
  return v;
}

}  // namespace vocabulary

std::vector<std::string> phrase_pieces(std::string_view phrase) {
  std::vector<std::string> pieces;
  auto is_word_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  for (std::size_t i = 0; i < phrase.size();) {
    if (phrase[i] == ' ') {
      ++i;
    } else if (is_word_char(phrase[i])) {
      std::size_t start = i;
      while (i < phrase.size() && is_word_char(phrase[i])) ++i;
      pieces.emplace_back(phrase.substr(start, i - start));
    } else {
      pieces.emplace_back(1, phrase[i]);
      ++i;
    }
  }
  return pieces;
}

namespace {

std::string lower(std::string_view text) {
  std::string result(text);
  for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return result;
}

}  // namespace

std::optional<std::string> closest_spelling(const std::vector<std::string>& candidates,
                                            std::string_view written) {
  // Case-insensitive distance first, so that `Drive_Cutin` finds `Drive_CutIn`; long inputs are
  // not words anyone misspelt, and comparing them would only cost time.
  if (written.empty() || written.size() > 64) return std::nullopt;
  std::string key = lower(written);
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const std::string& candidate : candidates) {
    std::size_t distance = edit_distance(key, lower(candidate));
    if (!best || distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  std::size_t tolerance = std::max<std::size_t>(2, key.size() / 3);
  if (best && best_distance <= tolerance && *best != written) return best;
  return std::nullopt;
}

}  // namespace scenfuzz::wmg

// The one table that gives level-1 words their level-2 meaning: for each qualitative word
// ("heavy rain", "a lot of", "curved", "motorway", "cuts in") the level-2 enumeration value it
// becomes and/or the range of numbers it stands for, and, for everything level 2 needs that
// level 1 does not say, a documented default (a "setting" row). docs/wmg-sdl.md ("Level 1 and
// its default ranges") prints this table. Units are the corpus's: metres, km/h, degrees, seconds,
// mm/h of rain, oktas of cloud.
#pragma once

#include <span>
#include <string_view>

namespace scenfuzz::wmg {

// Which level-2 value a row sets; `words` is the level-1 phrase it applies to.
enum class Quality {
  time_of_day,           // seconds since midnight
  daylight,              // light condition by day: illumination, sun elevation (degrees)
  night_light,           // light condition at night: illumination
  light_source,          // illumination (level-2 word) -> light source
  cloudiness,            // oktas
  rainfall,              // rainfall type, mm/h
  snowfall,              // snowfall type, visibility (m)
  wind,                  // km/h
  particulates,          // particulates type
  surface_condition,     // weather ("rain", "snow", "dry") -> surface condition
  junction_type,         // junction type
  junction_size,         // "Width and depth" or "Diameter" (m)
  junction_angle,        // degrees between neighbouring roads
  junction_control,      // connection control
  road_type,             // road type (singular level-1 words)
  road_environment,      // Urban or Rural
  road_division,         // transverse geometry
  speed_limit,           // km/h
  lane_count,            // lanes
  lane_width,            // m
  road_length,           // m
  curvature_radius,      // m, for curved roads
  horizontal_geometry,   // horizontal road geometry
  lane_marking_feature,  // road feature -> lane markings
  edge_feature,          // road feature -> roadway edge feature
  fixed_feature,         // road feature -> fixed road structure
  special_feature,       // road feature -> special road structure
  traffic_flow,          // vehicles per hour per lane
  traffic_speed,         // fraction of the speed limit
  manoeuvre_kind,        // DOES_SOMETHING -> kind of manoeuvre (the level-2 type's first part)
  place_direction,       // REL_ACTION_LOCATION -> Towards, Away or Cross
  observed_manoeuvre,    // kind of manoeuvre -> what a WHEN condition observes
  phase_duration,        // kind of manoeuvre -> s (a phase's second agent parameter)
  phase_gap,             // kind of manoeuvre -> m to the reference actor
  speed_change,          // REL_SPEED_CONDITION -> fraction of the speed limit
  actor_speed,           // manoeuvres and actors that keep their own speed -> km/h
  relative_position,     // REL_POSITION -> relative location
  setting,               // something level 1 never says; `words` names it
};

struct QualitativeDefault {
  Quality quality;
  std::string_view words;  // the level-1 phrase, or the name of a setting
  std::string_view label;  // the level-2 value it becomes; empty when only a range
  bool has_range = false;
  double low = 0.0;  // the range it stands for, when has_range
  double high = 0.0;
  std::string_view unit;
  std::string_view reason;  // why these values
};

std::span<const QualitativeDefault> qualitative_defaults();

// The row for `words`; the row for `fallback` when there is none (a STRING the table cannot
// know). Every fallback the conversion uses is in the table, so the result is never null there.
const QualitativeDefault* find_default(Quality quality, std::string_view words);
const QualitativeDefault& default_for(Quality quality, std::string_view words,
                                      std::string_view fallback);
const QualitativeDefault& setting(std::string_view name);

}  // namespace scenfuzz::wmg

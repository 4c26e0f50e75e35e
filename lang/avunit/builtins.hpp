// The words AVUnit and scenest give a meaning without a definition: signal functions, scenest's
// traffic-law signals (reference/scenest-law-signals.md), and the enumeration words.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace scenfuzz::avunit {

enum class SignalClass {
  none,
  function,            // dis vel spd acc diff: two arguments
  flag,                // a boolean signal: `hornOn`
  distance_predicate,  // true within a distance: `stoplineAhead(2)`
  value,               // a numeric or enumerated signal: `speed`, `trafficLightAhead.color`
};

// `name` may be dotted: "trafficLightAhead.color".
SignalClass signal_class(std::string_view name);

// The numeric columns of a trace projection: `trace[ego].speed`, `npc_truth.x`.
bool is_trace_column(std::string_view name);  // x y heading speed acceleration yaw_rate s
std::string trace_column_list();              // "x, y, heading, ..." for messages

bool is_color_word(std::string_view word);         // red green blue black white
bool is_vehicle_kind_word(std::string_view word);  // car bus Van truck bicycle ...
bool is_shape_word(std::string_view word);         // sphere box cone cylinder
bool is_weather_kind(std::string_view word);       // sunny rain snow fog wetness cloudiness
bool is_weather_level(std::string_view word);      // light middle heavy
bool is_enumeration_word(std::string_view word);   // red yellow green off forward left right
bool is_motion_function(std::string_view name);    // uniform, Waypoint, W, ..., Random
bool is_waypoint_function(std::string_view name);
bool is_uniform_function(std::string_view name);

// The intensity a weather level stands for (LawBreaker's values).
double weather_level_intensity(std::string_view level);

// Every name a user could have meant, for "did you mean" suggestions.
std::vector<std::string_view> builtin_names();

}  // namespace scenfuzz::avunit

// The environment (ENVIRONMENT_ELEMENTS) and the optional traffic model (TRAFFIC_MODEL) of a
// level-2 file.
#pragma once

#include <optional>
#include <vector>

#include "lang/wmg/dynamic_syntax.hpp"
#include "lang/wmg/syntax_values.hpp"

namespace scenfuzz::wmg {

// "Rainfall [Moderate Rain: 2 to 8]".
struct Rainfall {
  Label type;
  NumberRange intensity;
  SourceLocation location;
  bool operator==(const Rainfall&) const = default;
};

// "Snowfall [Light Snow (visibility: 100 to 500)]".
struct Snowfall {
  Label type;
  NumberRange visibility;
  SourceLocation location;
  bool operator==(const Snowfall&) const = default;
};

// "at [10 to 40] degree elevation AND [F] position" after the light source.
struct LightSourcePosition {
  NumberRange elevation;
  Located<RelativeLocation> position;
  SourceLocation location;
  bool operator==(const LightSourcePosition&) const = default;
};

// CONNECTIVITY_TYPE: "None" (none set), or "Communication: V2V: WiFi, Positioning: GPS".
struct Connectivity {
  bool none = false;
  std::optional<Label> link;         // "V2V" or "V2I"
  std::optional<Label> technology;   // "Cellular", "Satellite", "WiFi", "GLOSA"
  std::optional<Label> positioning;  // "Galileo", "GLONASS", "GPS"
  SourceLocation location;
  bool operator==(const Connectivity&) const = default;
};

struct Environment {
  Identifier id;
  std::optional<NumberRange> wind;
  NumberRange cloudiness;
  std::optional<Label> particulates;
  Rainfall rainfall;
  std::optional<Snowfall> snowfall;
  // Seconds since midnight, from TIME_RANGE `08:00 to 18:00` (or one time); empty for "Any".
  std::optional<NumberRange> time_of_day;
  Label illumination;
  Label light_source;
  std::optional<LightSourcePosition> light_source_position;
  std::optional<Connectivity> connectivity;
  SourceLocation location;
  bool operator==(const Environment&) const = default;
};

// TRAFFIC_INIT_PARAMS: "CENTROID [C1] in [R1] at [50 to 100] to [J1]".
struct Centroid {
  Identifier id;
  Identifier road;
  NumberRange distance;
  Identifier reference;
  SourceLocation location;
  bool operator==(const Centroid&) const = default;
};

// TRAFFIC_ELEMENT: "TRAFFIC [F1]: [C1: R1.L1, C2: R2.L1] at [300 to 900, 40 to 60]". The
// grammar names neither range; the translation gives them their meaning.
struct TrafficFlow {
  Identifier id;
  Identifier source;
  LaneName source_lane;
  Identifier destination;
  LaneName destination_lane;
  NumberRange first;
  NumberRange second;
  SourceLocation location;
  bool operator==(const TrafficFlow&) const = default;
};

struct TrafficModel {
  std::vector<Centroid> centroids;
  std::vector<TrafficFlow> flows;
  SourceLocation location;
  bool operator==(const TrafficModel&) const = default;
};

}  // namespace scenfuzz::wmg

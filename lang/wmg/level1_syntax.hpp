// The syntax tree of a WMG SDL level-1 file: the controlled English sentences of chapter 1 of the
// WMG SDL syntax document, as read in docs/wmg-sdl.md ("Level 1 and its default ranges"). Every
// enumeration word is kept as a Label in its level-1 spelling ("heavy rain", "a lot of",
// "cuts in"); level1_to_level2 gives it its level-2 meaning. Equality is structural, as for
// level 2.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "lang/wmg/dynamic_syntax.hpp"
#include "lang/wmg/syntax.hpp"
#include "lang/wmg/syntax_values.hpp"

namespace scenfuzz::wmg {

struct Level1Header {
  Version version;
  std::optional<Text> author;
  SourceLocation location;
  bool operator==(const Level1Header&) const = default;
};

enum class EnvironmentFeatureKind { particulates, snowfall, wind, rainfall };

// One ADDITIONAL_ENV_FEATURES: "heavy rain", "a light breeze", "mist and fog".
struct EnvironmentFeature {
  EnvironmentFeatureKind kind = EnvironmentFeatureKind::rainfall;
  Label phrase;
  SourceLocation location;
  bool operator==(const EnvironmentFeature&) const = default;
};

// "During the day, there is a bright, partly cloudy sky, with heavy rain and a light breeze."
struct EnvironmentSentence {
  Label time_of_day;           // "day" or "night"
  Label light;                 // "light", "bright" or "dark"
  std::optional<Label> cloud;  // a CLOUD_CONDITION phrase or a STRING
  std::vector<EnvironmentFeature> features;
  SourceLocation location;
  bool operator==(const EnvironmentSentence&) const = default;
};

// "R1 to R3 is straight ahead."
struct ConnectionSentence {
  Identifier from;
  Identifier to;
  Label connection;  // "straight ahead", "turning left", ...
  SourceLocation location;
  bool operator==(const ConnectionSentence&) const = default;
};

// "There is a crossroad, J1, which has connections with R1, R2, R3 and R4." and the connection
// sentences that follow it.
struct JunctionSentence {
  Label type;  // "crossroad", "mini roundabout", ... or a STRING
  Identifier id;
  std::vector<Identifier> roads;
  std::vector<ConnectionSentence> connections;
  SourceLocation location;
  bool operator==(const JunctionSentence&) const = default;
};

// "R1 is a curved, motorway with a lot of traffic." or "R2 and R3 are straight, minor roads."
struct RoadSentence {
  std::vector<Identifier> roads;
  Label horizontal_geometry;     // "straight", "curved" or a STRING
  Label road_type;               // "motorway", "minor roads", ... or a STRING
  std::optional<Label> traffic;  // "no", "light", "some", "moderate", "heavy", "a lot of"
  SourceLocation location;
  bool operator==(const RoadSentence&) const = default;
};

// "Also, R1 has street lights and trees." / "Also, R1 and R2 have traffic lights."
struct RoadFeatureSentence {
  std::vector<Identifier> roads;
  std::vector<Label> features;  // ROAD_FEATURE phrases or STRINGs
  SourceLocation location;
  bool operator==(const RoadFeatureSentence&) const = default;
};

// "There are 2 vehicles, Car1 and Car2."
struct ActorSentence {
  WholeNumber count;
  Located<ActorType> type;
  std::vector<Identifier> names;
  SourceLocation location;
  bool operator==(const ActorSentence&) const = default;
};

// "Ego is in R1": a road or a junction.
struct ActorLocation {
  Identifier actor;
  Identifier place;
  SourceLocation location;
  bool operator==(const ActorLocation&) const = default;
};

// Where a manoeuvre goes: "towards J1", "in front of Ego", "onto R2", "away". At least one of
// relation and preposition is set; target is the road, junction or actor named, if any.
struct ManoeuvrePlace {
  std::optional<Label> relation;     // REL_ACTION_LOCATION: "towards", "in front of", ...
  std::optional<Label> preposition;  // POSITIONAL_PREPOSITION: "near", "on", "onto", "into"
  std::optional<Identifier> target;
  SourceLocation location;
  bool operator==(const ManoeuvrePlace&) const = default;
};

// MANOEUVRE_SEQUENCE: "cuts in, decelerating, in front of Ego at its front left".
struct Level1Manoeuvre {
  Label action;                       // DOES_SOMETHING: "cuts in", "is driving", "walks", ...
  std::optional<Label> speed_change;  // REL_SPEED_CONDITION: "decelerating", ...
  std::vector<ManoeuvrePlace> places;
  std::optional<Label> position;  // REL_POSITION after "at its": "front left", ...
  SourceLocation location;
  bool operator==(const Level1Manoeuvre&) const = default;
};

// "Car1 is driving towards J1" as a WHEN condition.
struct ActorClause {
  Identifier actor;
  Level1Manoeuvre manoeuvre;
  SourceLocation location;
  bool operator==(const ActorClause&) const = default;
};

// "the traffic light ahead of Ego is red".
struct TrafficLightClause {
  Label relation;
  Identifier reference;
  Located<TrafficLightColour> colour;
  SourceLocation location;
  bool operator==(const TrafficLightClause&) const = default;
};

using Level1Condition = std::variant<ActorClause, TrafficLightClause>;

// One phase: "Car1 cuts in", ", then decelerates", ". And Car2 stops". `actor` is the actor
// written, or the previous phase's actor when none is written (actor_written false).
struct PhaseClause {
  Identifier actor;
  bool actor_written = true;
  Level1Manoeuvre manoeuvre;
  SourceLocation location;
  bool operator==(const PhaseClause&) const = default;
};

// PHASES: the WHEN conditions and the phases they start. Every group after the first is
// introduced by "Also," or "Next," (trigger), with "when" or "as" before its conditions, or
// with no conditions at all ("Next, Car1 stops.": it follows the previous group).
struct PhaseGroup {
  std::optional<Label> trigger;       // "Also" or "Next"; empty for the first group
  std::optional<Label> trigger_word;  // "when" or "as"
  std::vector<Level1Condition> conditions;
  std::vector<PhaseClause> phases;
  SourceLocation location;
  bool operator==(const PhaseGroup&) const = default;
};

// SSMS: "When ... . Ego operates autonomously."
struct Level1Ssms {
  std::vector<PhaseGroup> groups;
  Identifier autonomous_actor;
  SourceLocation location;
  bool operator==(const Level1Ssms&) const = default;
};

struct Level1File {
  Level1Header header;
  EnvironmentSentence environment;
  std::vector<JunctionSentence> junctions;  // empty for "There is no junction present."
  std::vector<RoadSentence> roads;
  std::vector<RoadFeatureSentence> road_features;
  std::vector<ActorSentence> actors;
  std::vector<ActorLocation> locations;
  std::vector<Level1Ssms> sequences;
  bool operator==(const Level1File&) const = default;
};

}  // namespace scenfuzz::wmg

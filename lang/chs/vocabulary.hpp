// The words scenfuzz reads in a CH-Scenario file's free text (docs/ch-scenario.md, "Free text"):
// what an entity is from its name and overview, and what a dynamic entity's `track` says about
// its direction and manoeuvre. The text is matched a word at a time, without case; what no rule
// reads is returned, for the translation to warn of.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace scenfuzz::chs {

// The lower-case ASCII words of a text ("People's" -> "people", "s"); other characters separate.
std::vector<std::string> words_of(std::string_view text);

enum class EntityClass { vehicle, pedestrian, cyclist, obstacle, traffic_light, unknown };

struct EntityWords {
  EntityClass kind = EntityClass::unknown;
  std::string model;   // a general actor kind the simulation knows: car, van, bus, truck, ...
  std::string colour;  // a traffic light's: red, yellow, green; empty when not said
};

// What an entity is, from the words of its name and overview (the first word a rule knows wins,
// name before overview).
EntityWords classify_entity(std::string_view name, std::string_view overview);

enum class TrackPlace { none, ahead, behind, oncoming, crossing };
enum class TrackManoeuvre {
  follow,
  stop,
  change_left,
  change_right,
  overtake,
  turn_left,
  turn_right
};

struct TrackReading {
  std::optional<double> heading;  // a compass word: radians counter-clockwise from east
  TrackPlace place = TrackPlace::none;
  TrackManoeuvre manoeuvre = TrackManoeuvre::follow;
  std::vector<std::string> unread;  // words no rule reads ("hospital")
};

TrackReading read_track(std::string_view text);

}  // namespace scenfuzz::chs

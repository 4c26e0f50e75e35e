// CH-Scenario syntax tree to scenario IR (internal to the CH-Scenario front end): the state one
// translation shares between its parts, and one function per part, each in its own file. What
// each construct means is the contract in docs/ch-scenario.md, "What a file means".
#pragma once

#include <optional>
#include <string>

#include "lang/chs/road_stations.hpp"
#include "lang/chs/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::chs {

// Where the ego starts when the file does not say: on a road of the network, in the lane next to
// the centre line of one half, at arc length `s` of the centre line.
struct EgoPlace {
  const Road* road = nullptr;
  bool forward = true;  // in the point order (the right half)
  double s = 0;
};

struct Translation {
  Translation(const File& file_, Diagnostics& diagnostics_)
      : file(file_), diagnostics(diagnostics_) {}

  const File& file;
  Diagnostics& diagnostics;
  ScenarioTemplate scenario;
  std::optional<EgoPlace> ego_place;  // none when the ego's position is written
};

// A constant Value located at a written number, in SI: `number.value * scale`.
Value located(const Number& number, double scale = 1.0);

// The map: a named one, or the blank map's roads as outlines the map layer builds lanes from.
void translate_map(Translation& translation);
// Dynamic and static entities: the ego, the other actors, obstacles.
void translate_entities(Translation& translation);
// Weather, natural disasters, special high-risk conditions and the time of day.
void translate_environment(Translation& translation);
// Safety protocols as specs; constraints' related names checked.
void translate_specs(Translation& translation);
// Events as manoeuvre phases started by their guards, a parameter for each one's outcome.
void translate_events(Translation& translation);

// The whole file. The file must have read without an error.
ScenarioTemplate translate(const File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::chs

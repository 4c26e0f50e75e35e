// Accident syntax tree to scenario IR (internal to the accident front end): the state one
// translation shares between its parts, and one function per part, each in its own file.
#pragma once

#include <string>

#include "lang/accident/accident.hpp"
#include "lang/accident/scene_layout.hpp"
#include "lang/accident/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::accident {

struct Translation {
  Translation(const File& file_, Diagnostics& diagnostics_)
      : file(file_), diagnostics(diagnostics_) {}

  const File& file;
  Diagnostics& diagnostics;
  SceneLayout layout;
  std::string ego;  // the vehicle that is the ego
  ScenarioTemplate scenario;
};

// A search parameter of the template, added; its index.
int add_parameter(ScenarioTemplate& scenario, Parameter parameter);

// The road as a built-in map, and the trees, lights, level crossings and stop signs on it.
void translate_scene(Translation& translation);
// Every vehicle as an actor driving its chain of events; the unknowns as parameters.
void translate_vehicles(Translation& translation);
// The collisions, as the scenario's expected collisions.
void translate_collisions(Translation& translation);

}  // namespace scenfuzz::accident

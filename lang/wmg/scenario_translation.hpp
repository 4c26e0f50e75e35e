// Level-2 syntax tree to scenario IR (internal to the WMG front end): the shared state of one
// translation and the translation of each section, one file per section. What the IR shapes and
// names mean is the contract in docs/wmg-semantics.md.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg {

// How the lanes `Rn.Lk` of one road are named in the built-in map the scenery becomes.
struct RoadLanes {
  std::string lane_prefix;         // lane k is `<lane_prefix><k-1>`: "east_", "fwd_", "west_in_"
  int traffic_lanes = 0;           // lanes L1..Ln the map generates for this road
  std::set<std::string> declared;  // lane names written in "Number of lanes [n] as [...]"
  // `Rn.Lk` to its map lane where the junction's connections say which way each lane runs
  // (lane_directions.cpp); empty elsewhere, where lane k is `<lane_prefix><k-1>`.
  std::map<std::string, std::string> ids;

  // Every lane the map generates for the road: a junction arm's in and out lanes.
  std::vector<std::string> map_lanes() const;
};

// One translation in progress: the template being built, its diagnostics, and the names the
// sections declare for the others to check (roads, actors, timers, traffic lights).
struct Translation {
  explicit Translation(Diagnostics& diagnostics_) : diagnostics(diagnostics_) {}

  ScenarioTemplate scenario;
  Diagnostics& diagnostics;
  std::map<std::string, RoadLanes> roads;
  std::map<std::string, ActorKind> actors;  // every initialised actor, the ego included
  std::set<std::string> timers;
  std::set<std::string> local_timers;  // those declared `Local timer`
  // A junction's light (`TL1`) to the map's signal controlling its approach (`light_west`).
  std::map<std::string, std::string> traffic_lights;
  std::set<std::string> elements;  // junction and structure ids an actor can be "in"

  // The Value a written number stands for, divided by `divisor` to make it SI: a constant for a
  // lone number, else a new parameter `name` over [low, high] in the file's `unit`, located at
  // the range's text (a finding replaces exactly that text).
  Value number(const NumberRange& range, const std::string& name, const std::string& unit,
               double divisor = 1.0, ParameterKind kind = ParameterKind::continuous);
  // The map's lane id for `Rn.Lk`, or nullopt after an error naming the lane.
  std::optional<std::string> lane_id(const LaneName& lane);
  // True when `actor` is initialised; else reports that it is referenced but not initialised.
  bool check_actor(const Identifier& actor);
};

// The scenery: the built-in map, its parameters, the lane naming, the junction's traffic lights.
// `initialisation` says where actors stand relative to each other, which places a junction's
// roads among its arms where the angles leave a choice (junction_arms.hpp).
void translate_scenery(const Scenery& scenery, const Initialisation& initialisation,
                       Translation& translation);
// Initialisation, manoeuvre sequences, timers and end conditions: the actors and their motion.
void translate_dynamics(const Dynamics& dynamics, Translation& translation);
// Weather, time of day, light and connectivity.
void translate_environment(const Environment& environment, Translation& translation);
// A signalised crossroads' first green: the approach of the first light a WHEN names green (the
// crossing one for red), else the ego's.
void choose_first_green(const Dynamics& dynamics, Translation& translation);
// The ego's destination: the first lane connection written from its lane, when the junction has
// one (WMG gives the ego no other).
void choose_ego_exit(const Scenery& scenery, const Dynamics& dynamics, Translation& translation);
// Names each traffic lane of a junction's roads (`roads[i]` on arm `arms[i]`, null for a road the
// scenery lacks) as an in or out lane of its arm by the junction's lane connections, and returns
// the lanes each way the map needs.
int name_junction_lanes(const Junction& junction, const std::vector<const Road*>& roads,
                        const std::vector<std::string>& arms, Translation& translation);
// Background traffic flows.
void translate_traffic(const TrafficModel& traffic, Translation& translation);

// The conditions of WHEN, WHILE and END as formulas over the signals of the contract. A WHEN's
// `at a speed of` also lands in `speeds` (actor name to m/s): the speed that actor starts with.
Formula when_formula(const std::vector<WhenCondition>& conditions, const std::string& prefix,
                     Translation& translation, std::map<std::string, Value>& speeds);
// `actor`: whose phase the WHILE holds; a local timer in it counts from that actor's phase 1.
Formula while_formula(const WhileConstraint& constraint, const std::string& prefix,
                      Translation& translation, const std::string& actor);
Formula end_formula(const EndCondition& condition, const std::string& prefix,
                    Translation& translation);

// The ego: the actor whose condition guards a `DO: AUTO`, else the first initialised.
std::string ego_name(const Dynamics& dynamics);

// The sector as written: F, FSR, SR, RSR, R, RSL, SL, FSL.
std::string sector_text(RelativeLocation location);

// The whole level-2 file as a template (SourceLanguage::wmg_sdl).
ScenarioTemplate translate_level2(const Level2File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::wmg

// The pieces of the level-1 to level-2 conversion (internal to the WMG front end): the plan that
// resolves names (which road each actor is on, which lane, which junctions have traffic lights)
// and one function per level-2 section.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/wmg/level1_defaults.hpp"
#include "lang/wmg/level1_syntax.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg::detail {

// One road of the level-1 file and the numbers its road type stands for.
struct RoadPlan {
  Identifier id;
  const RoadSentence* sentence = nullptr;
  std::string type_words;  // the singular level-1 road type that keys the table ("motorway")
  std::int64_t lane_count = 1;
  double speed_limit = 0.0;
  NumberRange length;
  std::vector<Label> features;
  std::vector<std::string> junctions;  // the junctions it connects to, in order
};

// One actor: where it starts and how it stands to the ego.
struct ActorPlan {
  Identifier name;
  ActorType type = ActorType::vehicle;
  std::string road;
  std::string lane;  // "L1", "L2", "P1"
  std::int64_t lane_number = 1;
  RelativeLocation relative_position = RelativeLocation::front;
  std::string first_manoeuvre_kind;  // the table's kind of its first phase, "" when it has none
};

struct ConversionPlan {
  const Level1File* file = nullptr;
  std::vector<RoadPlan> roads;
  std::map<std::string, std::size_t> road_index;
  std::map<std::string, const JunctionSentence*> junctions;
  std::set<std::string> signalised_junctions;
  std::vector<ActorPlan> actors;  // the ego first
  std::map<std::string, std::size_t> actor_index;

  const RoadPlan* road(const std::string& name) const;
  const ActorPlan* actor(const std::string& name) const;
  const ActorPlan& ego() const { return actors.front(); }
};

// ---- level1_to_level2.cpp ----
ConversionPlan plan_conversion(const Level1File& file);
// The level-2 traffic light that controls a road's entry to its junction: TL1 for R1.
std::string traffic_light_name(const std::string& road);
// A range from the table, at the level-1 words' place in the file.
NumberRange table_range(const QualitativeDefault& row, SourceLocation where = {});
// `fraction` of `limit`, in whole km/h.
NumberRange speed_range(const QualitativeDefault& fraction, double limit, SourceLocation where);
Label table_label(std::string_view text, SourceLocation where = {});
// A level-1 label as level 2 writes it: the table's word, or the STRING as it was written.
Label converted_label(const Label& level1, Quality quality, std::string_view fallback);

// ---- level1_convert_scenery.cpp ----
Scenery convert_scenery(const ConversionPlan& plan);
std::optional<TrafficModel> convert_traffic(const ConversionPlan& plan);

// ---- level1_convert_dynamics.cpp ----
Dynamics convert_dynamics(const ConversionPlan& plan, Diagnostics& diagnostics);

// ---- level1_convert_environment.cpp ----
Environment convert_environment(const Level1File& file);
// "rain", "snow" or "dry": what the weather does to the road surface.
std::string surface_weather(const Level1File& file);

}  // namespace scenfuzz::wmg::detail

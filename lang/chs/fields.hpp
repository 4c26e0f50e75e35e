// What each part of a CH-Scenario entity module may hold: the section headers, and the keys of
// the weather, disasters, high-risk conditions, blank map, roads and entities, each with its
// value's kind and range (docs/ch-scenario.md lists them).
#pragma once

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "lang/chs/syntax.hpp"
#include "lang/chs/values.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::chs {

enum class Header {
  road_network,
  weather,
  disaster,  // NaturalDisaster and its MeteorologicalDisaster, GeologicalDisaster
  high_risk,
  entities,
  static_entity,   // StaticEntity, StaticEntity1, ...
  dynamic_entity,  // DynamicEntity, DynamicEntity1, ...
  constraints,     // the specification module
};

// The header a whole line (normalised) is, if it is one.
std::optional<Header> header_of(const std::string& key);

// A weather, disaster or high-risk key, wherever it is written (their names are unique): true when
// `key` is one (read, or reported).
bool read_global(const std::string& key, SourceLocation key_at, const Value& value, File& file,
                 std::set<std::string>& seen, Diagnostics& diagnostics);

// `length:` or `width:` of a blank map.
bool read_blank_map(const std::string& key, SourceLocation key_at, const Value& value,
                    MapSource& map, std::set<std::string>& seen, Diagnostics& diagnostics);

// The polyline of `road` a key names (left boundary, centre line(s), road lines, right boundary).
std::vector<Point>* boundary_of(Road& road, const std::string& key);

enum class EntityKind { undecided, static_entity, dynamic_entity };

// An entity being read: its kind comes from its header, or else from its first key other than
// its name (`overview` is a static entity's, the others a dynamic one's).
struct PendingEntity {
  EntityKind kind = EntityKind::undecided;
  bool open = false, named = false;
  StaticEntity static_entity;
  DynamicEntity dynamic_entity;
  std::set<std::string> keys;
  SourceLocation location;
};

void read_entity_key(PendingEntity& entity, const std::string& key, SourceLocation key_at,
                     std::string_view written, const Value& value, Diagnostics& diagnostics);

// "unknown key 'x' in the weather; did you mean 'y'?"
std::string unknown_key_message(std::string_view written, const std::string& key,
                                const std::string& where);

// What the file as a whole must hold: a map, roads on a blank map only and well formed, unique
// names of roads, entities and constraints, a speed for every dynamic entity.
void check_whole_file(const File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::chs

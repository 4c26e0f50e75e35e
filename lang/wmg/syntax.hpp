// The syntax tree of a WMG SDL level-2 file: plain structs that mirror the grammar (chapter 2 of
// the WMG SDL syntax document, as read in docs/wmg-sdl.md). Equality is structural: locations
// always compare equal, so a printed and re-parsed tree equals the original.
#pragma once

#include <optional>
#include <vector>

#include "lang/wmg/dynamic_syntax.hpp"
#include "lang/wmg/environment_syntax.hpp"
#include "lang/wmg/scenery_syntax.hpp"
#include "lang/wmg/syntax_values.hpp"

namespace scenfuzz::wmg {

// VERSION: INT.INT
struct Version {
  WholeNumber major_part;
  WholeNumber minor_part;
  SourceLocation location;
  bool operator==(const Version&) const = default;
};

// scenfuzz's header extension `NPC BEHAVIOUR: Reactive | Scripted` (docs/wmg-sdl.md): how the
// NPCs drive. In the order of vocabulary::npc_behaviour().
enum class NpcBehaviourWord { reactive, scripted };

struct Header {
  Version version;
  std::vector<Text> authors;
  std::optional<Label> extension;  // "None" or a STRING
  std::optional<Located<NpcBehaviourWord>> npc_behaviour;
  SourceLocation location;
  bool operator==(const Header&) const = default;
};

struct Level2File {
  Header header;
  Scenery scenery;
  Dynamics dynamics;
  std::optional<Text> internal_elements;
  Environment environment;
  std::optional<TrafficModel> traffic;
  bool operator==(const Level2File&) const = default;
};

}  // namespace scenfuzz::wmg

// The enumerations of WMG SDL level 2: for each, the phrases the grammar lists (canonical
// spelling, case-sensitive, possibly several words), whether a STRING may stand in for them, and
// the spellings we also accept. The parser matches them; the printer writes the canonical text.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace scenfuzz::wmg {

struct Vocabulary {
  std::string what;                  // how a value is named in messages: "road type"
  std::vector<std::string> phrases;  // canonical spellings, in the grammar's order
  bool allows_string = false;        // a quoted STRING may stand for a value not listed
  // Other spellings the grammar document itself uses (written, canonical).
  std::vector<std::pair<std::string, std::string>> aliases;
};

namespace vocabulary {
const Vocabulary& extension();
const Vocabulary& npc_behaviour();  // scenfuzz's header extension: Reactive, Scripted
const Vocabulary& junction_type();
const Vocabulary& connection_control();
const Vocabulary& junction_road_sign();
const Vocabulary& traffic_light_type();
const Vocabulary& road_type();
const Vocabulary& zone_type();
const Vocabulary& environment_type();
const Vocabulary& traffic_direction();
const Vocabulary& lane_type();
const Vocabulary& lane_marking();
const Vocabulary& surface_type();
const Vocabulary& surface_condition();
const Vocabulary& surface_feature();
const Vocabulary& horizontal_geometry();
const Vocabulary& vertical_geometry();
const Vocabulary& transverse_geometry();
const Vocabulary& banking_angle();
const Vocabulary& roadside_feature();
const Vocabulary& edge_feature();
const Vocabulary& special_structure();
const Vocabulary& fixed_structure();
const Vocabulary& temporary_structure();
const Vocabulary& road_sign();
const Vocabulary& actor_type();
const Vocabulary& relative_location();
const Vocabulary& position_relation();
const Vocabulary& timer_scope();
const Vocabulary& observed_manoeuvre();
const Vocabulary& traffic_light_colour();
const Vocabulary& manoeuvre_type();
const Vocabulary& particulates();
const Vocabulary& rainfall();
const Vocabulary& snowfall();
const Vocabulary& light_type();
const Vocabulary& light_source();
const Vocabulary& communication_link();
const Vocabulary& v2v_technology();
const Vocabulary& v2i_technology();
const Vocabulary& positioning();
}  // namespace vocabulary

// The token texts a phrase consists of: "T-Junction" is T, -, Junction; "N/A" is N, /, A.
std::vector<std::string> phrase_pieces(std::string_view phrase);

// The candidate closest to `written` (ignoring case first), if it is close enough to be a likely
// misspelling.
std::optional<std::string> closest_spelling(const std::vector<std::string>& candidates,
                                            std::string_view written);

}  // namespace scenfuzz::wmg

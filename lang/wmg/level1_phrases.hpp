// The word lists of WMG SDL level 1 (chapter 1 of the syntax document): for each enumeration the
// phrases the grammar lists, case-sensitive, possibly several words, in the grammar's order, and
// whether a quoted STRING may stand in for them. The level-1 parser matches them; the defaults
// table (level1_defaults.hpp) gives each its level-2 meaning.
#pragma once

#include "lang/wmg/vocabulary.hpp"

namespace scenfuzz::wmg::level1_phrases {

const Vocabulary& time_of_day();
const Vocabulary& light_condition();
const Vocabulary& cloud_condition();
const Vocabulary& particulates();
const Vocabulary& snowfall();
const Vocabulary& wind();
const Vocabulary& rainfall();
const Vocabulary& junction_type();
const Vocabulary& connection_type();
const Vocabulary& horizontal_geometry();
const Vocabulary& road_type();
const Vocabulary& road_feature();
const Vocabulary& traffic_amount();
const Vocabulary& actor_type();
const Vocabulary& traffic_light_colour();
const Vocabulary& action();
const Vocabulary& relation();
const Vocabulary& preposition();
const Vocabulary& relative_position();
const Vocabulary& speed_change();

}  // namespace scenfuzz::wmg::level1_phrases

// Level 1 to level 2: the logical scenario a level-1 file describes. Every qualitative word
// becomes the range the defaults table (level1_defaults.hpp) gives it, and everything level 2
// needs but level 1 does not say gets the table's documented default. The result prints with
// print_level2 and parses back with parse_level2 without diagnostics.
#pragma once

#include "lang/diagnostic.hpp"
#include "lang/wmg/level1_syntax.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg {

// `file` must come from parse_level1 without errors (its names are then all declared). Things
// level 2 cannot say exactly are reported as warnings in `diagnostics`; there are no errors.
Level2File level1_to_level2(const Level1File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::wmg

// Prints a level-2 syntax tree as canonical WMG SDL level-2 text: one keyword layout, canonical
// enumeration spellings, numbers in the shortest decimal text that reads back to the same value.
// parse_level2(print_level2(tree)) gives a tree equal to `tree`.
#pragma once

#include <string>

#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg {

std::string print_level2(const Level2File& file);

// The text of one value as the printer writes it: `20 to 40.5`, or `30` for a lone number.
std::string range_text(const NumberRange& range);

}  // namespace scenfuzz::wmg

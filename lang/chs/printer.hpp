// A CH-Scenario syntax tree as text in the layout docs/ch-scenario.md describes: reading the text
// gives the same tree (chs_fuzzer checks it). Findings will be written back with it.
#pragma once

#include <string>

#include "lang/chs/syntax.hpp"

namespace scenfuzz::chs {

std::string print(const File& file);

}  // namespace scenfuzz::chs

// An accident syntax tree as text in the canonical layout of docs/accident.md: the grammar's
// order of parts and objects, upper-case keywords, lower-case values, one property a line (a
// leaf object on one line), numbers in the shortest form that reads back exactly. Reading the
// text gives an equal tree (acc_fuzzer checks it); findings will be written back with it.
#pragma once

#include <string>

#include "lang/accident/syntax.hpp"

namespace scenfuzz::accident {

std::string print(const File& file);

}  // namespace scenfuzz::accident

// How far apart two spellings are, for "did you mean ...?" suggestions in every front end.
#pragma once

#include <cstddef>
#include <string_view>

namespace scenfuzz {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions
// that turn `a` into `b` (bytes, case-sensitive).
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace scenfuzz

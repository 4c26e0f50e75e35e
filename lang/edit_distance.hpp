// How far apart two spellings are, for "did you mean ...?" suggestions in every front end.
#pragma once

#include <cstddef>
#include <string_view>

namespace scenfuzz {

// Levenshtein distance: the fewest single-character insertions, deletions and substitutions
// that turn `a` into `b` (bytes, case-sensitive).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The same when it is at most `limit`, and otherwise limit + 1, found without filling the whole
// table: a suggestion weighed against every name of a big file must not cost a full table each.
std::size_t edit_distance_within(std::string_view a, std::string_view b, std::size_t limit);

}  // namespace scenfuzz

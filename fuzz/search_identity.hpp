// What makes a search the search it is: the scenario's exact text, the strategy, seed, budget,
// targets and every simulation option. Written as search.json when a search starts; --resume
// continues only a search with the same identity, since anything else would replay the journal
// into different results.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "fuzz/commands.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {

nlohmann::json search_identity(const FuzzCommandOptions& options, const SourceFile& file);

// Empty when `stored` (read from search.json) and `now` are the same search, else a message
// naming the first difference ("the seed was 1, now 2").
std::string identity_difference(const nlohmann::json& stored, const nlohmann::json& now);

}  // namespace scenfuzz

// The behaviour coverage a search reached, as summary.json reports it (docs/coverage.md,
// "The search's coverage"): the union of its evaluations' features, which does not depend on the
// order they arrive in, so it is the same for any -j and after --resume.
#pragma once

#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace scenfuzz {

// The families of docs/coverage.md's grammar, in its order: the feature's first dotted part.
inline constexpr const char* kCoverageFamilies[] = {"ego",     "road",  "interaction",
                                                    "weather", "light", "law"};

// {"features": N, "names": [sorted], "by_family": {family: count}} with every family listed.
nlohmann::json coverage_summary_json(const std::set<std::string>& features);

}  // namespace scenfuzz

// Turns parsed statements into a ScenarioTemplate: evaluates assignments in order (a name must be
// defined before it is used), folds constants, makes every `range(...)` a search parameter, builds
// the executed scenario and its specifications, and names each parameter by where it sits.
#pragma once

#include <optional>
#include <vector>

#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

ScenarioTemplate elaborate(const std::vector<Statement>& statements, SourceLanguage language,
                           Diagnostics& diagnostics);

// A lone formula: AVUnit's formula syntax where a name that is neither a built-in nor defined is
// a signal of that name (dotted names too: `ego.speed`), and such a signal alone is a flag.
std::optional<Formula> elaborate_lone_formula(const Syntax& syntax, Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit

// Turns parsed statements into a ScenarioTemplate: evaluates assignments in order (a name must be
// defined before it is used), folds constants, makes every `range(...)` a search parameter, builds
// the executed scenario and its specifications, and names each parameter by where it sits.
#pragma once

#include <vector>

#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

ScenarioTemplate elaborate(const std::vector<Statement>& statements, SourceLanguage language,
                           Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit

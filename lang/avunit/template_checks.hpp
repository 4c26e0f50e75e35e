// What is checked and settled once the elaborator has assembled a template: that headings and
// specs name actors of their own scenario, and the parameters' names and order. Apart from the
// elaborator, which is about evaluating a file's statements.
#pragma once

#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

// Headings related to actors and specs reading actors need those actors in the scenario; an
// error for each that does not.
void check_references(const ScenarioTemplate& scenario, Diagnostics& diagnostics);

// Marks in `read` (one flag per parameter) the parameters the scenario reads.
void mark_read_parameters(ScenarioTemplate& scenario, std::vector<bool>& read);

// Names each parameter after the first slot that reads it, orders the parameters by that walk,
// and drops those nothing reads, with a warning unless `read_elsewhere` (another of the file's
// scenarios reads it).
void name_parameters(ScenarioTemplate& scenario, const std::vector<bool>& read_elsewhere,
                     Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit

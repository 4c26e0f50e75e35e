// What a `.acc` file must hold beyond its syntax: IDs unique across trees, lights and vehicles;
// each collision's actor a vehicle and its victim a vehicle, tree or light, not the actor itself;
// each start or end sign a light or tree. Separate from the parser so that a reference is checked
// against every declaration, wherever in the file it was written.
#pragma once

#include "lang/accident/syntax.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz::accident {

// Duplicate IDs (reported at the second); IDs not read (empty) are left out.
void check_ids(const File& file, Diagnostics& diagnostics);
// Every name used against the IDs declared: only meaningful when every declaration was read.
void check_references(const File& file, Diagnostics& diagnostics);

}  // namespace scenfuzz::accident

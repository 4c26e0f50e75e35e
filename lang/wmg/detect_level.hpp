// Which level of WMG SDL a `.sdl` file is written in: both levels share the extension, and only
// level 2 has the section keyword SCENERY ELEMENTS at the start of a line.
#pragma once

#include "lang/source_file.hpp"

namespace scenfuzz::wmg {

// 2 when a line starts (after blanks) with "SCENERY ELEMENTS" (the two words separated by blanks),
// outside a comment; 1 otherwise.
int detect_wmg_level(const SourceFile& file);

}  // namespace scenfuzz::wmg

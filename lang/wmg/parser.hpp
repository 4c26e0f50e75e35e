// The WMG SDL level-2 front end's parser: text to syntax tree (lang/wmg/syntax.hpp). The grammar
// and how scenfuzz reads the grammar document's ambiguities are in docs/wmg-sdl.md.
#pragma once

#include <optional>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/syntax.hpp"

namespace scenfuzz::wmg {

struct Level2ParseResult {
  std::optional<Level2File> file;  // set only when there is no error
  Diagnostics diagnostics;
};

// Never throws. A mistake in one road, junction, manoeuvre phase or section is reported and the
// parser resumes at the next one, so one run reports several independent errors (up to the
// Diagnostics limit).
Level2ParseResult parse_level2(const SourceFile& file);

}  // namespace scenfuzz::wmg

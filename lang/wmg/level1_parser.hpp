// The WMG SDL level-1 front end's parser: controlled English sentences to a syntax tree
// (lang/wmg/level1_syntax.hpp). The sentences, and how scenfuzz reads the grammar document's
// ambiguities, are in docs/wmg-sdl.md ("Level 1 and its default ranges").
#pragma once

#include <optional>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/level1_syntax.hpp"

namespace scenfuzz::wmg {

struct Level1ParseResult {
  std::optional<Level1File> file;  // set only when there is no error
  Diagnostics diagnostics;
};

// Never throws. A mistake in one sentence is reported and the parser resumes at the next one;
// after the sentences are read, every name is checked: actors, roads and junctions must be
// declared before a sentence can refer to them.
Level1ParseResult parse_level1(const SourceFile& file);

}  // namespace scenfuzz::wmg

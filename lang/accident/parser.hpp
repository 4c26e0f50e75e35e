// Reads a `.acc` file, the accident formalism of CarSim (docs/accident.md): a STATIC, a DYNAMIC
// and an ACCIDENT part, each a bracket of objects that are brackets of `KEYWORD = value;`
// properties. Every mistake is a diagnostic at its file:line:column with what was expected, and
// the parse goes on at the end of the property, the bracket's `]` or the next keyword, so
// independent mistakes are all reported. Never throws on user input.
#pragma once

#include <optional>

#include "lang/accident/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::accident {

struct ParseResult {
  std::optional<File> file;  // none when there were errors
  Diagnostics diagnostics;
};

ParseResult parse(const SourceFile& source);

}  // namespace scenfuzz::accident

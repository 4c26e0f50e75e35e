// Reads a CH-Scenario file (docs/ch-scenario.md), its scenario entity module and its
// specification module: a line-oriented layout of section headers, `key: value` lines, road
// polylines and constraints, as the grammar's concrete examples are laid out. Every mistake is a
// diagnostic at its file:line:column, and the parse goes on at the next line, so independent
// mistakes are all reported.
#pragma once

#include <optional>

#include "lang/chs/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::chs {

struct ParseResult {
  std::optional<File> file;  // none when there were errors
  Diagnostics diagnostics;
};

ParseResult parse(const SourceFile& source);

}  // namespace scenfuzz::chs

// The WMG SDL front end as the rest of scenfuzz sees it: a `.sdl` file (level 1 or level 2) read
// into a ScenarioTemplate, and a concrete scenario printed back as WMG SDL. The meaning of every
// construct is the contract in docs/wmg-semantics.md.
#pragma once

#include <span>
#include <string>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::wmg {

struct ParseResult {
  ScenarioTemplate scenario;  // complete only when there are no errors
  Diagnostics diagnostics;

  bool ok() const { return !diagnostics.has_errors(); }
};

// Detects the level; a level-1 file is parsed, converted to level 2 and then translated. Never
// throws on bad input: every problem is a diagnostic pointing into `file`.
ParseResult parse(const SourceFile& file);

// A concrete scenario as WMG SDL level 2: for a level-2 file, the user's own text with every range
// replaced by the value chosen for its parameter (`parameter_values[i]` for
// `scenario.parameters[i]`); for a level-1 file (which has no numbers to replace), the level-2
// text it converts to, with its ranges replaced. `scenario` must come from parse(file).
std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values);

// The level-2 text a file stands for: a level-1 file converted, a level-2 file printed
// canonically. Errors leave the text empty.
struct Level2Text {
  std::string text;
  Diagnostics diagnostics;
};
Level2Text level2_text(const SourceFile& file);

}  // namespace scenfuzz::wmg

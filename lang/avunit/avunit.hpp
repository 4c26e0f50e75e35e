// The AVUnit front end (also reads scenest, which shares AVUnit's scenario part): parse a file into
// a ScenarioTemplate, and print a template back as AVUnit.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::avunit {

struct ParseResult {
  ScenarioTemplate scenario;  // complete only when there are no errors
  Diagnostics diagnostics;
  // The scenarios the file executes (`Trace t = EXE(NAME);`), each once, in file order; when it
  // executes none, those it creates. `scenario` is the chosen one of them.
  std::vector<std::string> scenarios;

  bool ok() const { return !diagnostics.has_errors(); }
};

// Which of a file's scenarios to build (lang/avunit/scenario_choice.hpp).
struct ParseOptions {
  // The scenario `--scenario NAME` names; empty: the file must execute only one.
  std::string scenario;
  // Several scenarios without a name are fine (`scenfuzz check`): every one is checked, the first
  // is built, and a note lists them.
  bool survey = false;
};

// Parses and resolves a whole file. Never throws on bad input: every problem is a diagnostic.
ParseResult parse(const SourceFile& file, const ParseOptions& options = {});

struct FormulaParseResult {
  std::optional<Formula> formula;  // set when there are no errors
  Diagnostics diagnostics;
};

// A whole file that is one STL formula in AVUnit's syntax (`scenfuzz stl --spec`): names that are
// not AVUnit built-ins are signals of that name (`x`, `ego.speed`), for the caller to resolve.
FormulaParseResult parse_formula(const SourceFile& file);

// Canonical AVUnit for a template: parse(print(t)) gives back a template equal to t.
std::string print(const ScenarioTemplate& scenario);

// `formula` (spec's own or one derived from it, such as a law's sub-violation) in AVUnit's
// syntax, its trace projections named after spec's trace: what reports show of a formula.
std::string print_formula(const ScenarioTemplate& scenario, const Spec& spec,
                          const Formula& formula);

// The user's own file with every range replaced by the value chosen for its parameter
// (`parameter_values[i]` for `scenario.parameters[i]`): a concrete, replayable scenario, after
// `//` lines naming each dimension's value (one inside an expression by the value of what the
// user wrote and where its draw came from, lang/parameter_provenance.hpp).
std::string print_concrete(const SourceFile& file, const ScenarioTemplate& scenario,
                           std::span<const double> parameter_values);

}  // namespace scenfuzz::avunit

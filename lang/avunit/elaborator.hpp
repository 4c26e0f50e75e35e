// Turns parsed statements into a ScenarioTemplate: evaluates assignments in order (a name must be
// defined before it is used), folds constants, makes every `range(...)` a search parameter, builds
// the executed scenario and its specifications, and names each parameter by where it sits.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/scenario_choice.hpp"
#include "lang/avunit/syntax.hpp"
#include "lang/diagnostic.hpp"
#include "lang/scenario.hpp"

namespace scenfuzz::avunit {

class Elaborator;

// Elaborates statements one at a time, as the parser gives them, so that a big file's syntax
// trees need not all be held at once: only what its names are bound to.
class StatementElaborator {
 public:
  // `request` chooses the scenario the template is built from when the file has several.
  StatementElaborator(SourceLanguage language, Diagnostics& diagnostics,
                      ScenarioRequest request = {});
  ~StatementElaborator();
  StatementElaborator(const StatementElaborator&) = delete;
  StatementElaborator& operator=(const StatementElaborator&) = delete;

  void add(const Statement& statement);
  // The template of all the statements added.
  ScenarioTemplate finish();
  // After finish: the names of the scenarios the file executes (or, executing none, creates).
  const std::vector<std::string>& scenario_names() const;

 private:
  std::unique_ptr<Elaborator> elaborator_;
};

// A lone formula: AVUnit's formula syntax where a name that is neither a built-in nor defined is
// a signal of that name (dotted names too: `ego.speed`), and such a signal alone is a flag.
std::optional<Formula> elaborate_lone_formula(const Syntax& syntax, Diagnostics& diagnostics);

}  // namespace scenfuzz::avunit

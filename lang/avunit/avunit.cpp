#include "lang/avunit/avunit.hpp"

#include "lang/avunit/elaborator.hpp"
#include "lang/avunit/lexer.hpp"
#include "lang/avunit/parser.hpp"

namespace scenfuzz::avunit {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

ParseResult parse(const SourceFile& file, const ParseOptions& options) {
  ParseResult result;
  SourceLanguage language =
      ends_with(file.path(), ".scenest") ? SourceLanguage::scenest : SourceLanguage::avunit;
  // Each statement is elaborated as soon as it is parsed, and its tokens and syntax then let go:
  // memory grows with what the file's names are bound to, not with its text.
  TokenReader reader(file, result.diagnostics);
  StatementElaborator elaborator(language, result.diagnostics,
                                 ScenarioRequest{options.scenario, options.survey});
  parse_statements(reader, result.diagnostics,
                   [&](const Statement& statement) { elaborator.add(statement); });
  result.scenario = elaborator.finish();
  result.scenarios = elaborator.scenario_names();
  return result;
}

FormulaParseResult parse_formula(const SourceFile& file) {
  FormulaParseResult result;
  std::vector<Token> tokens = tokenize(file, result.diagnostics);
  if (result.diagnostics.has_errors()) return result;
  std::optional<Syntax> syntax = parse_lone_expression(tokens, result.diagnostics);
  if (!syntax) return result;
  result.formula = elaborate_lone_formula(*syntax, result.diagnostics);
  return result;
}

}  // namespace scenfuzz::avunit

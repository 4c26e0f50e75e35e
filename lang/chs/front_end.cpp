// The CH-Scenario front end (chs.hpp): read the file, then translate it when it read cleanly.
#include "lang/chs/chs.hpp"
#include "lang/chs/parser.hpp"
#include "lang/chs/translation.hpp"

namespace scenfuzz::chs {

ScenarioParse parse_scenario(const SourceFile& file) {
  ScenarioParse result;
  result.scenario.language = SourceLanguage::ch_scenario;
  ParseResult parsed = parse(file);
  result.diagnostics = std::move(parsed.diagnostics);
  if (!parsed.file) return result;
  result.scenario = translate(*parsed.file, result.diagnostics);
  return result;
}

}  // namespace scenfuzz::chs

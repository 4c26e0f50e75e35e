// `scenfuzz convert --to sdl2 FILE`: a WMG SDL file as level-2 text.
#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "lang/diagnostic.hpp"
#include "lang/wmg/wmg.hpp"

namespace scenfuzz {

int run_convert(const std::string& path, std::ostream& out, std::ostream& err) {
  std::optional<SourceFile> file = read_input(path, err);
  if (!file) return kExitBadInput;
  const wmg::Level2Text converted = wmg::level2_text(*file);
  err << format_diagnostics(*file, converted.diagnostics);
  if (converted.diagnostics.has_errors()) return kExitBadInput;
  out << converted.text;
  return kExitSuccess;
}

}  // namespace scenfuzz

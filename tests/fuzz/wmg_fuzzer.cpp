// libFuzzer harness for the WMG SDL front end, both levels. For any input bytes: detecting the
// level, parsing and formatting the diagnostics must not crash, leak or hang. A level-2 file that
// parses cleanly must survive the printer: print_level2(t) parses again without diagnostics, to
// an equal tree. A level-1 file that parses cleanly must convert: level1_to_level2 printed with
// print_level2 parses back without diagnostics, to an equal tree.
// Built by scripts/fuzz.sh (SCENFUZZ_FUZZ=ON, clang, ASan + UBSan).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"
#include "lang/wmg/detect_level.hpp"
#include "lang/wmg/level1_parser.hpp"
#include "lang/wmg/level1_to_level2.hpp"
#include "lang/wmg/parser.hpp"
#include "lang/wmg/syntax_printer.hpp"

namespace {

using namespace scenfuzz;

// The level-2 text `tree` prints to must read back as `tree`; `what` says where it came from.
void expect_prints_back(const wmg::Level2File& tree, const char* what) {
  const SourceFile printed("printed.sdl", wmg::print_level2(tree));
  const wmg::Level2ParseResult reparsed = wmg::parse_level2(printed);
  if (!reparsed.file || !reparsed.diagnostics.all().empty()) {
    std::fprintf(stderr, "print_level2(%s) does not parse cleanly:\n%s\n--- printed ---\n%s\n",
                 what, format_diagnostics(printed, reparsed.diagnostics).c_str(),
                 printed.text().c_str());
    __builtin_trap();
  }
  if (!(*reparsed.file == tree)) {
    std::fprintf(stderr, "parse_level2(print_level2(%s)) != %s\n--- printed ---\n%s\n", what, what,
                 printed.text().c_str());
    __builtin_trap();
  }
}

void check_level2(const SourceFile& file) {
  const wmg::Level2ParseResult parsed = wmg::parse_level2(file);
  const std::string messages = format_diagnostics(file, parsed.diagnostics);
  if (parsed.file) expect_prints_back(*parsed.file, "the parsed tree");
}

void check_level1(const SourceFile& file) {
  const wmg::Level1ParseResult parsed = wmg::parse_level1(file);
  const std::string messages = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.file) return;
  Diagnostics conversion;
  const wmg::Level2File converted = wmg::level1_to_level2(*parsed.file, conversion);
  const std::string warnings = format_diagnostics(file, conversion);
  if (conversion.has_errors()) {
    std::fprintf(stderr, "level1_to_level2 reported errors on a clean level-1 file:\n%s\n",
                 warnings.c_str());
    __builtin_trap();
  }
  expect_prints_back(converted, "level1_to_level2(the parsed file)");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const SourceFile file("fuzz.sdl", std::string(reinterpret_cast<const char*>(data), size));
  if (wmg::detect_wmg_level(file) == 2)
    check_level2(file);
  else
    check_level1(file);
  return 0;
}

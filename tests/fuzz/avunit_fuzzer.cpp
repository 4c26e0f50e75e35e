// libFuzzer harness for the AVUnit front end. For any input bytes: parsing and formatting the
// diagnostics must not crash, leak or hang; and a file that parses cleanly must survive the
// printer: print(parse(f)) parses again without errors, to the same template.
// Built by scripts/fuzz.sh (SCENFUZZ_FUZZ=ON, clang, ASan + UBSan).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace scenfuzz;
  const SourceFile file("fuzz.avu", std::string(reinterpret_cast<const char*>(data), size));
  const avunit::ParseResult parsed = avunit::parse(file);
  const std::string messages = format_diagnostics(file, parsed.diagnostics);
  if (!parsed.ok()) return 0;

  const SourceFile printed("printed.avu", avunit::print(parsed.scenario));
  const avunit::ParseResult reparsed = avunit::parse(printed);
  if (!reparsed.ok()) {
    std::fprintf(stderr, "print(parse(f)) does not parse:\n%s\n--- printed ---\n%s\n",
                 format_diagnostics(printed, reparsed.diagnostics).c_str(), printed.text().c_str());
    __builtin_trap();
  }
  if (!(reparsed.scenario == parsed.scenario)) {
    std::fprintf(stderr, "parse(print(t)) != t\n--- printed ---\n%s\n", printed.text().c_str());
    __builtin_trap();
  }
  return 0;
}

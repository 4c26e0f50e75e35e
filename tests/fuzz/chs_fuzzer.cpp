// libFuzzer harness for the CH-Scenario front end. For any input bytes: parsing and formatting
// the diagnostics must not crash, leak or hang; a parse gives a file exactly when it reports no
// error; every diagnostic and every located value lies within the input; a file that parses
// prints to text that parses, without a diagnostic, to an equal tree.
// Built by scripts/fuzz.sh (SCENFUZZ_FUZZ=ON, clang, ASan + UBSan).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "lang/chs/parser.hpp"
#include "lang/chs/printer.hpp"
#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace {

using namespace scenfuzz;

void expect_within(const SourceFile& source, const SourceLocation& where, const char* what) {
  if (!where.known()) return;
  if (where.line > source.line_count() || where.end_offset() > source.text().size()) {
    std::fprintf(stderr, "%s at %u:%u (bytes %u+%u) lies outside the %zu-byte input\n", what,
                 where.line, where.column, where.offset, where.length, source.text().size());
    __builtin_trap();
  }
}

void expect_values_within(const SourceFile& source, const chs::File& file) {
  for (const chs::Road& road : file.roads) {
    expect_within(source, road.name.location, "a road's name");
    for (const auto* points : {&road.left_boundary, &road.centre_lines, &road.right_boundary})
      for (const chs::Point& point : *points) expect_within(source, point.location, "a point");
  }
  for (const chs::DynamicEntity& entity : file.dynamic_entities) {
    expect_within(source, entity.name.location, "an entity's name");
    expect_within(source, entity.speed.location, "a speed");
  }
  for (const chs::Constraint& constraint : file.constraints)
    for (const chs::Event& event : constraint.events) {
      expect_within(source, event.guard.location, "a guard");
      for (const chs::Statement& statement : event.action)
        expect_within(source, statement.location, "a statement");
    }
}

void expect_prints_back(const chs::File& file) {
  const SourceFile printed("printed.chs", chs::print(file));
  const chs::ParseResult reparsed = chs::parse(printed);
  if (!reparsed.file || !reparsed.diagnostics.all().empty()) {
    std::fprintf(stderr, "print(file) does not parse cleanly:\n%s\n--- printed ---\n%s\n",
                 format_diagnostics(printed, reparsed.diagnostics).c_str(), printed.text().c_str());
    __builtin_trap();
  }
  if (!(*reparsed.file == file)) {
    std::fprintf(stderr, "parse(print(file)) != file\n--- printed ---\n%s\n",
                 printed.text().c_str());
    __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const SourceFile source("fuzz.chs", std::string(reinterpret_cast<const char*>(data), size));
  const chs::ParseResult result = chs::parse(source);
  (void)format_diagnostics(source, result.diagnostics);
  for (const Diagnostic& diagnostic : result.diagnostics.all())
    expect_within(source, diagnostic.location, "a diagnostic");
  if (result.file.has_value() == result.diagnostics.has_errors()) {
    std::fprintf(stderr, "a parse %s a file but %s errors\n", result.file ? "gave" : "did not give",
                 result.diagnostics.has_errors() ? "reported" : "reported no");
    __builtin_trap();
  }
  if (result.file) {
    expect_values_within(source, *result.file);
    expect_prints_back(*result.file);
  }
  return 0;
}

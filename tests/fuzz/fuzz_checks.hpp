// Checks every front end's libFuzzer harness makes of a parse, whatever the language: a value or a
// diagnostic lies within the input, and a parse gives a file exactly when it reports no error.
// A failed check prints why and traps, which libFuzzer reports as a crash with the input.
#pragma once

#include <cstdio>

#include "lang/diagnostic.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz::fuzz_checks {

inline void expect_within(const SourceFile& source, const SourceLocation& where, const char* what) {
  if (!where.known()) return;
  if (where.line > source.line_count() || where.end_offset() > source.text().size()) {
    std::fprintf(stderr, "%s at %u:%u (bytes %u+%u) lies outside the %zu-byte input\n", what,
                 where.line, where.column, where.offset, where.length, source.text().size());
    __builtin_trap();
  }
}

// Formatting the diagnostics must not crash; each lies within the input; there is a file
// (`has_file`) exactly when there is no error.
inline void expect_consistent_parse(const SourceFile& source, const Diagnostics& diagnostics,
                                    bool has_file) {
  (void)format_diagnostics(source, diagnostics);
  for (const Diagnostic& diagnostic : diagnostics.all())
    expect_within(source, diagnostic.location, "a diagnostic");
  if (has_file == diagnostics.has_errors()) {
    std::fprintf(stderr, "a parse %s a file but %s errors\n", has_file ? "gave" : "did not give",
                 diagnostics.has_errors() ? "reported" : "reported no");
    __builtin_trap();
  }
}

}  // namespace scenfuzz::fuzz_checks

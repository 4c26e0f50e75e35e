// Shared by the malformed-input suites of every front end: running a parse in a forked child so
// that a crash fails one case instead of the whole binary, picking the errors out of the
// diagnostics, editing a valid base text, and the shape of one "one mistake, one first error"
// case.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"

namespace scenfuzz::test {

// How many failures the running test has recorded so far.
inline int failed_parts() {
  const ::testing::TestResult* result =
      ::testing::UnitTest::GetInstance()->current_test_info()->result();
  int failed = 0;
  for (int i = 0; i < result->total_part_count(); ++i)
    if (result->GetTestPartResult(i).failed()) ++failed;
  return failed;
}

// Runs `parse(text)` for every text in a forked child and expects it to come back: a crash
// (stack overflow, bad optional access, ...) fails this expectation only, and the caller then
// skips parsing in-process. Returns whether the child survived.
template <typename Parse>
bool parse_survives(const std::vector<std::string>& texts, const std::string& label, Parse parse) {
  const int before = failed_parts();
  EXPECT_EXIT(
      {
        for (const std::string& text : texts) parse(text);
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "")
      << "parse crashed on " << label;
  return failed_parts() == before;
}

inline std::vector<const Diagnostic*> errors_of(const Diagnostics& diagnostics) {
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : diagnostics.all())
    if (d.severity == Severity::error) errors.push_back(&d);
  return errors;
}

inline std::vector<std::uint32_t> error_lines(const Diagnostics& diagnostics) {
  std::vector<std::uint32_t> lines;
  for (const Diagnostic* d : errors_of(diagnostics)) lines.push_back(d->location.line);
  return lines;
}

// `text` with the first `from` replaced by `to`; `from` must occur.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("'" + from + "' is not in the base text");
  return text.replace(at, from.size(), to);
}

// One mistake in an otherwise valid file, and where and what its first error must be.
struct MalformedCase {
  std::string name;
  std::string text;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string message;  // a distinctive part of the first error's message
};

inline std::ostream& operator<<(std::ostream& out, const MalformedCase& c) { return out << c.name; }

// The first error by place in the file is the case's: at its line and column, saying its message.
// `shown` is the diagnostics as a user sees them, for the failure message.
inline void expect_first_error(const MalformedCase& c, const Diagnostics& diagnostics,
                               const std::string& shown) {
  const std::vector<const Diagnostic*> errors = errors_of(diagnostics);
  ASSERT_FALSE(errors.empty()) << c.name;
  const Diagnostic* first = errors.front();
  for (const Diagnostic* d : errors)
    if (d->location.line < first->location.line ||
        (d->location.line == first->location.line && d->location.column < first->location.column))
      first = d;
  EXPECT_EQ(first->location.line, c.line) << shown;
  EXPECT_EQ(first->location.column, c.column) << shown;
  EXPECT_THAT(first->message, ::testing::HasSubstr(c.message)) << shown;
}

}  // namespace scenfuzz::test

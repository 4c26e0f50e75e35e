// Messages about a user's file: `file:line:column: error: ...`, the line, and a caret under the
// place. Every front end reports through a Diagnostics list; nothing throws on bad input.
#pragma once

#include <string>
#include <vector>

#include "lang/source_file.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz {

enum class Severity { error, warning, note };

struct Diagnostic {
  Severity severity = Severity::error;
  SourceLocation location;
  std::string message;
};

class Diagnostics {
 public:
  void error(SourceLocation where, std::string message);
  void warning(SourceLocation where, std::string message);
  void note(SourceLocation where, std::string message);

  const std::vector<Diagnostic>& all() const { return items_; }
  std::size_t error_count() const { return errors_; }
  bool has_errors() const { return errors_ > 0; }
  // A file this broken gets no more messages: the first ones are the useful ones.
  bool too_many_errors() const { return errors_ >= kErrorLimit; }

  static constexpr std::size_t kErrorLimit = 25;

 private:
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
};

// `path:line:column: error: message`, then the source line and a caret line.
std::string format_diagnostic(const SourceFile& file, const Diagnostic& diagnostic);
std::string format_diagnostics(const SourceFile& file, const Diagnostics& diagnostics);

}  // namespace scenfuzz

// `scenfuzz check FILE...`: parse files and report what is wrong with them.
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "fuzz/cli.hpp"
#include "fuzz/commands.hpp"
#include "lang/avunit/avunit.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz {

std::optional<SourceFile> read_input(const std::string& path, std::ostream& err) {
  errno = 0;
  std::optional<SourceFile> file = read_source_file(path);
  if (!file) {
    const int error = errno;
    err << "scenfuzz: error: cannot read '" << path
        << "': " << (error != 0 ? std::strerror(error) : "read failed") << "\n";
  }
  return file;
}

int run_check(const std::vector<std::string>& paths, std::ostream& err) {
  bool failed = false;
  for (const std::string& path : paths) {
    std::optional<SourceFile> file = read_input(path, err);
    if (!file) {
      failed = true;
      continue;
    }
    const avunit::ParseResult result = avunit::parse(*file);
    err << format_diagnostics(*file, result.diagnostics);
    if (!result.ok()) failed = true;
  }
  return failed ? kExitBadInput : kExitSuccess;
}

}  // namespace scenfuzz

// The subcommands behind the command line, callable without it (tests, other front ends).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lang/source_file.hpp"

namespace scenfuzz {

// `scenfuzz check FILE...`: parses every file, printing its diagnostics (warnings too) to `err`.
// Returns kExitSuccess when no file has errors, kExitBadInput otherwise; every file is checked.
int run_check(const std::vector<std::string>& paths, std::ostream& err);

// `scenfuzz space FILE [--json]`: prints the file's parameter space to `out` as an aligned table,
// or as JSON. Diagnostics go to `err`; a file with errors gives kExitBadInput and no space.
int run_space(const std::string& path, bool json, std::ostream& out, std::ostream& err);

// Reads a scenario file, or prints `scenfuzz: error: cannot read 'path': <reason>` to `err`.
std::optional<SourceFile> read_input(const std::string& path, std::ostream& err);

}  // namespace scenfuzz

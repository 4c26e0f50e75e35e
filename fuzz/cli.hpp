// The scenfuzz command line: parses the arguments with CLI11 and runs one subcommand.
#pragma once

#include <iostream>

namespace scenfuzz {

// Exit codes of every subcommand.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitViolated = 1;  // a spec is violated (run, stl) / findings (the search)
inline constexpr int kExitUsage = 2;     // bad command line
inline constexpr int kExitBadInput = 2;  // a scenario or map file cannot be read or has errors
inline constexpr int kExitInternal = 3;  // a bug: an unexpected exception

// Runs `scenfuzz` with the given arguments; output goes to `out`, messages to `err`.
int run_cli(int argc, const char* const* argv, std::ostream& out = std::cout,
            std::ostream& err = std::cerr);

}  // namespace scenfuzz

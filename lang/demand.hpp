// Always-on checks of scenfuzz's own invariants, as Drake's DRAKE_DEMAND: a failed one is a bug in
// scenfuzz, reported with its place and the condition, then abort(), in every build type (unlike
// assert, which a release build drops). User input is never checked with it: bad input gets a
// diagnostic naming file:line:column or the option.
#pragma once

namespace scenfuzz {

[[noreturn]] void demand_failed(const char* condition, const char* file, int line);

}  // namespace scenfuzz

#define SCENFUZZ_DEMAND(condition) \
  ((condition) ? static_cast<void>(0) : ::scenfuzz::demand_failed(#condition, __FILE__, __LINE__))

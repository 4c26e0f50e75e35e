// What cmin tells: OUT_DIR/cmin.json (every seed: kept with what it covers, dropped with the kept
// seeds that cover its features or "no features", or its error), the summary printed at the end,
// and the exit status.
#pragma once

#include <ostream>
#include <string>

#include "fuzz/corpus_minimize.hpp"

namespace scenfuzz {

inline constexpr const char* kCminTableFileName = "cmin.json";

// The text of cmin.json. It depends only on the seeds and their coverage: a run resumed after a
// kill writes the same table as an uninterrupted one.
std::string cmin_table_json(const CminResult& result);

// A line per seed on `out` (kept, dropped and why, error), then the totals; errors in full and
// problems on `err`.
void print_cmin_report(const CminResult& result, const std::string& out_dir, std::ostream& out,
                       std::ostream& err);

// kExitSuccess, or kExitBadInput when OUT_DIR cannot be used, no seed could be covered or the
// run was interrupted before the end (DESIGN.md, "Exit statuses").
int cmin_exit_status(const CminResult& result);

}  // namespace scenfuzz

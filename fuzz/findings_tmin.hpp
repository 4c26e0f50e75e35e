// --tmin: the findings of a search (or the new failure modes of a campaign's search) minimised
// after it, several at once, each as `scenfuzz tmin` would (fuzz/tmin_finding.hpp). A finding
// that cannot be minimised is reported with its reason, never an error of the caller: a WMG
// finding, or one that does not fail again on replay, still is a finding.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace scenfuzz {

// One finding to minimise and where its minimised scenario goes.
struct TminJob {
  std::string finding_file;
  std::string out_path;  // empty: beside the finding, <stem>.min.avu
};

// What became of one TminJob.
struct TminJobResult {
  std::string minimised_file;  // written (or found in place); empty: none
  std::string reason;          // why there is none
  bool interrupted = false;    // a stop came first: a later run may minimise it
  bool reused = false;         // found in place from an earlier run, not minimised again
};

// Minimises every job on `jobs` threads (0: all cores), results in the jobs' order; the files
// written are the same for any `jobs`. A job whose output exists already is taken as done (a
// resumed search: outputs are written atomically, and removed when their finding changes).
// `interrupted` is asked before every replay; once it says true the jobs left are not started
// and those running stop without writing.
std::vector<TminJobResult> minimise_findings(const std::vector<TminJob>& jobs, std::size_t threads,
                                             const std::function<bool()>& interrupted);

}  // namespace scenfuzz

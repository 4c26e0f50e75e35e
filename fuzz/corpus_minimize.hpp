// `scenfuzz cmin IN... -o OUT_DIR` without the command line: the smallest subset of a corpus's
// seeds that keeps the corpus's behaviour coverage (fuzz/set_cover.hpp), its files copied
// unchanged into OUT_DIR with a table (cmin.json) of what each kept seed covers and why each
// other seed was dropped. Coverage is computed in parallel and recorded in OUT_DIR's control file
// (fuzz/cmin_control_file.hpp) as it comes, so an interrupted or killed run is resumed by running
// it again. The coverage function is a parameter: the command passes cover_seed, tests plant
// coverage.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "fuzz/seed_coverage.hpp"

namespace scenfuzz {

// What one seed covers; called from several threads at once, it never throws (an error is in
// the result's `error`).
using CoverFunction = std::function<SeedCoverage(const std::string& path)>;

struct CminOptions {
  std::vector<std::string> inputs;  // IN...: scenario files and folders of them
  std::string out_dir;              // -o
  std::size_t jobs = 0;             // -j: seeds covered at once; 0: one per core
  // What the coverage depends on besides the seeds' bytes (the simulation options, the version):
  // records made under another identity are not reused.
  std::string identity;
};

enum class CminVerdict { kept, dropped, error };

struct CminSeed {
  std::string path;    // as its input entry was expanded ("corpus/sub/a.avu")
  std::string output;  // where a kept seed is copied, relative to OUT_DIR ("sub/a.avu")
  std::string hash;    // content hash of its bytes; empty when they cannot be read
  SeedCoverage coverage;
  CminVerdict verdict = CminVerdict::error;
  std::vector<std::string> new_features;  // kept: the features it was the first to cover
  std::vector<std::string> covered_by;    // dropped: the kept seeds that cover its features
  bool reused = false;                    // its coverage was read from the control file
};

enum class CminProblem {
  none,
  output_folder,    // OUT_DIR is not usable (not ours, inside an input, cannot be written)
  interrupted,      // a stop was asked for before every seed was covered
  nothing_covered,  // no seed could be covered
};

struct CminResult {
  std::vector<CminSeed> seeds;    // every seed (and every input that named none), input order
  std::vector<std::size_t> kept;  // indices into `seeds`, in the order the cover chose them
  std::size_t features = 0;       // the corpus's features: the union over the seeds
  std::size_t covered_now = 0;    // seeds covered by this run (the others were reused)
  CminProblem problem = CminProblem::none;
  std::string message;             // what the problem is
  std::vector<std::string> notes;  // worth saying, not wrong ("the control file was made with...")
};

// Minimises the corpus. `stop_requested` is asked between seeds; once it says yes, the seeds in
// flight are finished and recorded and the result is `interrupted`, with no other output.
CminResult minimize_corpus(const CminOptions& options, const CoverFunction& cover,
                           const std::function<bool()>& stop_requested = {});

}  // namespace scenfuzz

// cmin's control file (OUT_DIR/cmin.control), after libFuzzer's merge control file: every seed's
// coverage is appended as one line the moment it is computed, so a run killed (even by kill -9)
// loses at most the seeds in flight, and the next run with the same OUT_DIR reads the lines back
// instead of simulating again. The format (JSON Lines) is in docs/search.md, "Corpus
// minimisation (cmin)".
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "fuzz/seed_coverage.hpp"

namespace scenfuzz {

inline constexpr const char* kCminControlFileName = "cmin.control";

// One seed's coverage as recorded: valid for the seed while its bytes hash to `hash`.
struct CminRecord {
  std::string hash;       // the seed's content hash (16 hex digits)
  SeedCoverage coverage;  // its path names the seed
};

struct CminControlContents {
  bool existed = false;  // there was a control file
  // Its header named other coverage options (or none could be read): its records are not used.
  bool other_identity = false;
  std::map<std::string, CminRecord> records;  // by seed path; a later line for a path wins
  std::size_t unreadable_lines = 0;           // a line cut short by a kill, and the like
};

// The header line of a control file for coverage options `identity`, newline included.
std::string cmin_control_header(const std::string& identity);

// A record as one line, newline included.
std::string cmin_control_line(const CminRecord& record);

// The records of the control file at `path` made with `identity`. Lines that do not parse (the
// last one after a kill -9) are skipped and counted; a missing file has no records.
CminControlContents read_cmin_control(const std::filesystem::path& path,
                                      const std::string& identity);

// Appends lines to a control file, one write(2) each, from any thread: a line is in the file
// (the kernel's page cache, which outlives the process) once `append` returns.
class CminControlAppender {
 public:
  CminControlAppender() = default;
  ~CminControlAppender();
  CminControlAppender(const CminControlAppender&) = delete;
  CminControlAppender& operator=(const CminControlAppender&) = delete;

  // Opens `path` for appending; an empty string, else why it cannot be.
  std::string open(const std::filesystem::path& path);
  // Appends `line`; an empty string, else why it could not be written.
  std::string append(const std::string& line);

 private:
  std::mutex mutex_;
  std::filesystem::path path_;
  int descriptor_ = -1;
};

}  // namespace scenfuzz

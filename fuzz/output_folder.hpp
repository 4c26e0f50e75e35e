// A search's output folder, claimed by one process at a time: a lock (folder_lock.hpp, on
// DIR/.lock),
// what an earlier search left there, and the temporary files a killed run may have left behind.
#pragma once

#include <filesystem>
#include <string>

#include "fuzz/folder_lock.hpp"

namespace scenfuzz {

// Holds the lock on an output folder while it lives.
class OutputFolderLock {
 public:
  // Creates `dir` if needed and locks it. Returns an error message (empty on success): the
  // folder cannot be created, or another process holds it ("... process 1234 ...").
  std::string acquire(const std::filesystem::path& dir);

  bool held() const { return lock_.held(); }

 private:
  FolderLock lock_;
};

// Whether `dir` holds (part of) an earlier search: its journal, summary or findings.
bool holds_search(const std::filesystem::path& dir);

// Removes what a search writes into `dir` (findings/, evaluations.csv, summary.json,
// search.json) and nothing else. Returns an error message, empty on success.
std::string remove_search(const std::filesystem::path& dir);

// Removes the temporary files (NAME.tmp.PID) of atomic writes that a killed run left in `dir`
// and `dir`/findings. Call with the folder's lock held.
void remove_temporary_files(const std::filesystem::path& dir);

}  // namespace scenfuzz

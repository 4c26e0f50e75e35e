// A search's output folder, claimed by one process at a time: a lock (flock on DIR/.lock, which
// names the process holding it; the kernel releases it when that process dies, even by kill -9),
// what an earlier search left there, and the temporary files a killed run may have left behind.
#pragma once

#include <filesystem>
#include <string>

namespace scenfuzz {

// Holds the lock on an output folder while it lives.
class OutputFolderLock {
 public:
  OutputFolderLock() = default;
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;
  OutputFolderLock(OutputFolderLock&& other) noexcept;
  OutputFolderLock& operator=(OutputFolderLock&& other) noexcept;

  // Creates `dir` if needed and locks it. Returns an error message (empty on success): the
  // folder cannot be created, or another process holds it ("... process 1234 ...").
  std::string acquire(const std::filesystem::path& dir);

  bool held() const { return descriptor_ >= 0; }

 private:
  int descriptor_ = -1;
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

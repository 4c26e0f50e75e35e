// A folder claimed by one process at a time: an exclusive flock on a lock file in it, which also
// names the holder (process, host, since when) for the message the next claimant gets. The kernel
// releases a flock when its process dies, even by kill -9, so a killed run never leaves a stale
// lock behind. A flock belongs to one open file: a second acquire in the same process is refused
// too. The search's output folder (output_folder.hpp) and a campaign (campaign/campaign_lock.hpp)
// are claimed this way.
#pragma once

#include <filesystem>
#include <string>

namespace scenfuzz {

// Why a folder could not be claimed: `busy` when another process holds it (`holder` names it),
// else `error` says what failed (the folder or the lock file cannot be made).
struct FolderLockRefusal {
  bool busy = false;
  std::string holder;
  std::string error;
};

class FolderLock {
 public:
  FolderLock() = default;
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;
  FolderLock(FolderLock&& other) noexcept;
  FolderLock& operator=(FolderLock&& other) noexcept;

  // Creates `dir` if needed and locks `dir`/`file_name`. True on success; otherwise `refusal`
  // says why.
  bool acquire(const std::filesystem::path& dir, const std::string& file_name,
               FolderLockRefusal& refusal);

  bool held() const { return descriptor_ >= 0; }

 private:
  int descriptor_ = -1;
};

}  // namespace scenfuzz

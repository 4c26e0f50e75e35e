// One `campaign run` per campaign folder at a time: the folder lock (fuzz/folder_lock.hpp) on
// DIR/campaign.lock, whose holder (process, host, since when) a second run's message names.
#pragma once

#include <filesystem>
#include <string>

#include "fuzz/folder_lock.hpp"

namespace scenfuzz {

class CampaignLock {
 public:
  // Locks the campaign folder `dir` (created if missing). Empty on success; otherwise why not,
  // naming the holder when another run has it.
  std::string acquire(const std::filesystem::path& dir);

  bool held() const { return lock_.held(); }

 private:
  FolderLock lock_;
};

}  // namespace scenfuzz

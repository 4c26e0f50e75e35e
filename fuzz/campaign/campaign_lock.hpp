// One `campaign run` per campaign folder at a time: an exclusive flock on DIR/campaign.lock, which
// also names the holder (process, host, since when) for the message a second run gets. The kernel
// releases a flock when its process dies, even by kill -9, so a killed run never leaves a stale
// lock behind for the next run to trip over. A flock belongs to one open file: a second acquire
// in the same process is refused too.
#pragma once

#include <filesystem>
#include <string>

namespace scenfuzz {

class CampaignLock {
 public:
  CampaignLock() = default;
  ~CampaignLock();
  CampaignLock(const CampaignLock&) = delete;
  CampaignLock& operator=(const CampaignLock&) = delete;
  CampaignLock(CampaignLock&& other) noexcept;
  CampaignLock& operator=(CampaignLock&& other) noexcept;

  // Locks the campaign folder `dir` (created if missing). Empty on success; otherwise why not,
  // naming the holder when another run has it.
  std::string acquire(const std::filesystem::path& dir);

  bool held() const { return descriptor_ >= 0; }

 private:
  int descriptor_ = -1;
};

}  // namespace scenfuzz

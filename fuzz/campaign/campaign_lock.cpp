// CampaignLock: the folder lock, and the message a second run gets.
#include "fuzz/campaign/campaign_lock.hpp"

namespace scenfuzz {

std::string CampaignLock::acquire(const std::filesystem::path& dir) {
  FolderLockRefusal refusal;
  if (lock_.acquire(dir, "campaign.lock", refusal)) return {};
  if (!refusal.busy) return refusal.error;
  return "the campaign '" + dir.string() + "' is in use by another run (" + refusal.holder +
         "); wait for it to end, or stop it";
}

}  // namespace scenfuzz

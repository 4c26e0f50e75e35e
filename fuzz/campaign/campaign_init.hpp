// `scenfuzz campaign init DIR FILES...`: starts a campaign folder with a commented campaign.toml
// listing the given seed files and folders, which parse_campaign_config accepts as written.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace scenfuzz {

struct CampaignInitOptions {
  std::string dir;                 // DIR: the campaign folder, created if missing
  std::vector<std::string> files;  // FILES: seed scenario files and folders, as the user named them
};

// The commented campaign.toml of a campaign called `name` whose `seeds` are `seed_entries`
// (relative to its folder); `example_file`, one of the files they stand for, is the path of the
// commented-out [[seed]] example.
std::string campaign_toml_text(const std::string& name,
                               const std::vector<std::string>& seed_entries,
                               const std::string& example_file);

// Writes DIR/campaign.toml (atomically) and says so on `out`. kExitBadInput, with the reason on
// `err`, when DIR/campaign.toml already exists (it is never overwritten), a FILE does not exist
// or is not a scenario file or folder, or DIR cannot be written.
int run_campaign_init(const CampaignInitOptions& options, std::ostream& out, std::ostream& err);

}  // namespace scenfuzz

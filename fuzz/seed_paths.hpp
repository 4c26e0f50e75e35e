// Seed entries on disk (a campaign's `seeds`, the corpus arguments of the search, `coverage` and
// `cmin`): a scenario file stands for itself, a folder for every scenario file under it (.avu,
// .scenest, .sdl, at any depth, sorted), so a corpus folder is one entry and files added to it
// join the next run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace scenfuzz {

// Whether `path` is named like a scenario file: .avu, .scenest or .sdl.
bool is_scenario_file_name(const std::filesystem::path& path);

struct SeedExpansion {
  // Relative to the campaign folder, lexically normalised, generic form ("corpora/a.avu").
  std::vector<std::string> files;
  std::string error;  // empty on success; else what is wrong with the entry
};

// The scenario files `entry` (relative to `campaign_folder`, or absolute) stands for. An error
// when it does not exist, is a file not named like a scenario, or is a folder without one.
SeedExpansion expand_seed_entry(const std::filesystem::path& campaign_folder,
                                const std::string& entry);

// `path` lexically normalised in generic form, as seed files are named ("a/./b/../c.avu" is
// "a/c.avu"), for comparing a [[seed]] path with the expanded files.
std::string seed_key(const std::string& path);

}  // namespace scenfuzz

// What a campaign folder's campaign.toml says: its name, the seed scenarios (files and folders,
// expanded), the ego under test, the budget and the search options, with per-seed overrides.
// Parsing never throws on bad input: every problem is a diagnostic naming file:line:column and
// what was expected. docs/campaigns.md describes every key.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lang/diagnostic.hpp"
#include "lang/source_location.hpp"

namespace scenfuzz {

// The search options every seed gets unless its [[seed]] table overrides them.
struct CampaignSearchDefaults {
  std::string algorithm = "ga";     // as --algo: ga, random, halton, lhs, nlopt:NAME
  std::uint64_t seed = 0;           // as --seed
  std::size_t jobs = 0;             // as -j; 0 means all cores
  std::vector<std::string> mutate;  // as --mutate: how concrete seeds are mutated (checked)
  bool tmin = false;                // as --tmin: each new failure mode's finding minimised
};

// A [[seed]] table: options for one seed file.
struct CampaignSeedOverride {
  std::string path;  // relative to the campaign folder, normalised like CampaignConfig::seed_files
  double budget_share = 1;               // weight of its share of the budget; every other seed: 1
  std::optional<std::string> algorithm;  // instead of [search] algo
  std::string scenario;  // as --scenario: which of the file's scenarios it is (empty: its only one)
  SourceLocation location;  // of its `path` value
};

struct CampaignConfig {
  std::filesystem::path folder;  // the campaign folder: where campaign.toml is
  std::string name;              // [campaign] name
  // `seeds` as written, and the scenario files they stand for: relative to `folder`, in generic
  // form ("corpora/avunit/a.avu"), each once, in the order of `seeds` and sorted within a folder.
  std::vector<std::string> seed_entries;
  std::vector<std::string> seed_files;
  std::string ego_plugin;   // [ego] plugin, relative to `folder` as written; empty: the reference
                            // driver
  std::string ego_version;  // [ego] version; required with a plugin, "reference" without
  std::optional<std::uint64_t> budget_simulations;   // [budget] simulations, > 0
  std::optional<double> budget_wall_seconds;         // [budget] wall_seconds, > 0 and finite
  CampaignSearchDefaults search;                     // [search]
  std::vector<CampaignSeedOverride> seed_overrides;  // [[seed]], in file order
  std::vector<std::string> map_paths;                // map_paths, relative to `folder` as written
};

struct CampaignConfigResult {
  std::optional<CampaignConfig> config;  // set when there is no error
  Diagnostics diagnostics;               // errors and warnings, against the file's text
};

// The ego version campaign.toml implies when it names no plugin.
inline constexpr const char* kReferenceEgoVersion = "reference";

// Parses campaign.toml's `text`; `path` names the file in messages, and its folder is the
// campaign folder that seed paths are relative to (they are looked up on disk: a path that does
// not exist is an error).
CampaignConfigResult parse_campaign_config(const std::string& text, const std::string& path);

}  // namespace scenfuzz

// Builds small but real campaigns for the report's tests: a search run by the scenfuzz executable
// into the campaign's folder layout (searches/run-<id>/round-1/<seed>-0/), its evaluations and
// findings read back from what it wrote, and each finding's scenario and picture copied into
// modes/<content hash>.<ext> as the campaign run does, then recorded through CampaignDb.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/content_hash.hpp"
#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {

// What one search found, as the campaign records it.
struct CampaignSearchResult {
  std::vector<CampaignEvaluation> evaluations;
  std::vector<FailureModeRecord> modes;
};

// The column `name` of a CSV header row, or -1.
inline int csv_column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return static_cast<int>(i);
  return -1;
}

// evaluations.csv as the campaign's compact records: the robustness of `spec` (the search's only
// target), and whether the evaluation violated anything.
inline std::vector<CampaignEvaluation> read_evaluations(const std::filesystem::path& folder,
                                                        const std::string& spec) {
  const auto rows = read_csv(slurp(folder / "evaluations.csv"));
  EXPECT_FALSE(rows.empty()) << folder;
  if (rows.empty()) return {};
  const int robustness = csv_column(rows[0], "robustness." + spec);
  const int violated = csv_column(rows[0], "violated");
  EXPECT_GE(robustness, 0);
  EXPECT_GE(violated, 0);
  std::vector<CampaignEvaluation> records;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    CampaignEvaluation record;
    record.index = static_cast<std::int64_t>(i - 1);
    const std::string& value = rows[i].at(static_cast<std::size_t>(robustness));
    if (!value.empty()) record.robustness = std::stod(value);
    record.finding = !rows[i].at(static_cast<std::size_t>(violated)).empty();
    records.push_back(record);
  }
  return records;
}

// Copies `file` to modes/<content hash><extension> in `campaign` (its picture, when there is one,
// beside it as .svg); returns the scenario's path relative to the campaign folder.
inline std::string copy_into_modes(const std::filesystem::path& campaign,
                                   const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  const std::string hash = content_hash(slurp(file));
  fs::create_directories(campaign / "modes");
  const std::string relative = "modes/" + hash + file.extension().string();
  fs::copy_file(file, campaign / relative, fs::copy_options::overwrite_existing);
  fs::path picture = file;
  picture.replace_extension(".svg");
  if (fs::exists(picture))
    fs::copy_file(picture, campaign / "modes" / (hash + ".svg"),
                  fs::copy_options::overwrite_existing);
  return relative;
}

// The failure modes summary.json lists, their responsibility from evaluations.csv.
inline std::vector<FailureModeRecord> read_failure_modes(const std::filesystem::path& campaign,
                                                         const std::filesystem::path& folder,
                                                         std::int64_t seed_id) {
  const nlohmann::json summary = nlohmann::json::parse(slurp(folder / "summary.json"));
  const auto rows = read_csv(slurp(folder / "evaluations.csv"));
  const int responsibility = csv_column(rows.at(0), "responsibility");
  std::vector<FailureModeRecord> modes;
  for (const nlohmann::json& finding : summary.at("findings")) {
    FailureModeRecord mode;
    mode.seed_id = seed_id;
    mode.signature = finding.at("mode").get<std::string>();
    mode.spec = finding.at("spec").get<std::string>();
    const auto row = finding.at("evaluation").get<std::size_t>() + 1;
    mode.responsibility = rows.at(row).at(static_cast<std::size_t>(responsibility));
    mode.scenario_file = copy_into_modes(campaign, finding.at("file").get<std::string>());
    mode.replay_command = "scenfuzz run " + mode.scenario_file;
    modes.push_back(mode);
  }
  return modes;
}

// A fixture that searches seeds with the real executable and records them in a campaign.
class ReportCampaignTest : public CommandTest {
 protected:
  // Searches `seed` (a path relative to the campaign folder `campaign`) for `spec` with `budget`
  // simulations and search seed `search_seed`, in run `run_id`; records the search, its
  // evaluations and its failure modes in `db`. Returns what it recorded.
  CampaignSearchResult search(CampaignDb& db, const std::filesystem::path& campaign,
                              std::int64_t run_id, std::int64_t seed_id, const std::string& seed,
                              const std::string& spec, int budget, int search_seed) {
    const std::string folder_name =
        "searches/run-" + std::to_string(run_id) + "/round-1/" + std::to_string(seed_id) + "-0";
    const std::filesystem::path folder = campaign / folder_name;
    // --all-collisions: the pedestrian running into the ego's side counts, a mode more to report.
    const Outcome run =
        scenfuzz({"--budget", std::to_string(budget), "--seed", std::to_string(search_seed),
                  "--spec", spec, "-j", "1", "--quiet", "--all-collisions", "--out",
                  folder.string(), (campaign / seed).string()});
    EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 1) << run.err;
    CampaignSearchResult result;
    result.evaluations = read_evaluations(folder, spec);
    result.modes = read_failure_modes(campaign, folder, seed_id);
    SearchRecord record;
    record.run_id = run_id;
    record.seed_id = seed_id;
    record.algorithm = "ga";
    record.budget = static_cast<std::uint64_t>(budget);
    record.output_folder = folder_name;
    record.spec = spec;
    // With the coverage its summary.json reports, as the campaign records it.
    const std::vector<std::string> coverage = nlohmann::json::parse(slurp(folder / "summary.json"))
                                                  .at("coverage")
                                                  .at("names")
                                                  .get<std::vector<std::string>>();
    db.record_search_result(record, result.evaluations, {}, coverage);
    for (const FailureModeRecord& mode : result.modes) db.upsert_failure_mode(run_id, mode);
    return result;
  }
};

}  // namespace scenfuzz::test

// What the campaign-run tests share: a small campaign over three corpus seeds that need no Apollo
// map (a few seconds per run), and a canonical dump of a campaign's database — every table's rows
// in key order, times left out — with the list of its DIR/modes files (and the content of the
// minimised ones), for comparing the outcome of two runs (-j 1 against -j 2, killed against
// uninterrupted).
#pragma once

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"
#include "fuzz/content_hash.hpp"
#include "tests/fuzz/command_runner.hpp"

namespace scenfuzz::test {

// The seeds of the small campaign: 1, 2 and 2 specs.
inline std::vector<std::string> small_campaign_seeds() {
  return {source_file("corpora/avunit/cut_in_straight.avu"),
          source_file("corpora/avunit/pedestrian_step_out.avu"),
          source_file("corpora/avunit/lead_vehicle_hard_brake.avu")};
}

// campaign.toml of a campaign over `seeds` with `budget` (the [budget] table's lines).
inline std::string campaign_toml(const std::vector<std::string>& seeds, const std::string& budget,
                                 const std::string& more = "") {
  std::string text = "seeds = [";
  for (std::size_t i = 0; i < seeds.size(); ++i) text += (i ? ", \"" : "\"") + seeds[i] + "\"";
  return text + "]\n\n[budget]\n" + budget + "\n\n[search]\nseed = 7\n" + more;
}

inline std::string text_of(const std::optional<double>& value) {
  if (!value) return "NULL";
  std::ostringstream text;
  text.precision(17);
  text << *value;
  return text.str();
}

// The campaign's database and modes/ as text, times left out. Opens (and so locks) the campaign.
inline std::string canonical_dump(const std::filesystem::path& dir) {
  CampaignDbOpening opening = CampaignDb::open(dir);
  if (!opening.db) return "cannot open: " + opening.error;
  CampaignDb& db = *opening.db;
  std::ostringstream dump;
  for (const CampaignRun& run : db.list_runs())
    dump << "run " << run.id << " " << run.ego_version << (run.ended.empty() ? " open" : " ended")
         << "\n";
  for (const CampaignSeed& seed : db.list_seeds())
    dump << "seed " << seed.id << " " << seed.path << " " << seed.content_hash << "\n";
  for (const CampaignSearch& search : db.list_searches()) {
    const SearchRecord& r = search.record;
    dump << "search " << search.id << " run " << r.run_id << " seed " << r.seed_id << " "
         << r.algorithm << " budget " << r.budget << " " << status_name(r.status) << " "
         << r.output_folder << " round " << r.round << " spec " << r.spec_index << " " << r.spec
         << " seed " << r.search_seed << " spent " << r.simulations << " new " << r.new_modes
         << " best " << text_of(r.best_robustness) << "\n";
    for (const CampaignEvaluation& e : db.list_evaluations(search.id))
      dump << "  " << e.index << " " << text_of(e.robustness) << " " << e.finding << "\n";
    for (const std::string& feature : db.list_coverage(search.id))
      dump << "  covers " << feature << "\n";
  }
  for (const CampaignFailureMode& mode : db.list_failure_modes())
    dump << "mode " << mode.id << " seed " << mode.record.seed_id << " " << mode.record.signature
         << " | " << mode.record.spec << " " << mode.record.responsibility << " "
         << mode.record.scenario_file << " " << mode.record.replay_command << " first "
         << mode.first_seen_run << " last " << mode.last_seen_run << " " << status_name(mode.status)
         << "\n";
  for (const CampaignReplay& replay : db.list_replays())
    dump << "replay " << replay.run_id << " " << replay.failure_mode_id << " " << replay.tried
         << " " << replay.failing << " " << replay.verdict << "\n";
  std::vector<std::string> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "modes", error))
    files.push_back(entry.path().filename().string());
  std::sort(files.begin(), files.end());
  // The other files are named by the hash of their content; a minimised one ([search] tmin) is
  // not, so its content is compared too.
  for (const std::string& file : files) {
    dump << "file " << file;
    if (file.ends_with(".min.avu")) dump << " " << content_hash(slurp(dir / "modes" / file));
    dump << "\n";
  }
  return dump.str();
}

// Where two dumps differ first: the line of each (a dump runs to thousands of lines).
inline std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream left(a), right(b);
  std::string x, y;
  for (int line = 1;; ++line) {
    const bool more_left = static_cast<bool>(std::getline(left, x));
    const bool more_right = static_cast<bool>(std::getline(right, y));
    if (!more_left && !more_right) return "no difference";
    if (x != y || more_left != more_right)
      return "line " + std::to_string(line) + ":\n  " + (more_left ? x : "(end)") + "\n  " +
             (more_right ? y : "(end)");
  }
}

}  // namespace scenfuzz::test

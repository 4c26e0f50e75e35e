// What `scenfuzz campaign report` shows, loaded from the campaign database once into plain
// structs: the runs, each seed's searches and best robustness as simulations were spent, the
// failure modes with their pictures, and per run how many modes were new, failing, fixed,
// regressed and flaky. The page (campaign_report_html.hpp) and its charts (campaign_report_svg.hpp)
// only read these.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign/campaign_db.hpp"

namespace scenfuzz {

// One run and what it did to the failure modes: each mode this run learnt about (a search of
// the run found it, or its regression replay gave a verdict) counted once, by the status the run
// left it in. Exact: replayed from the replays table (the verdict per mode per run) and the
// sightings table (the modes each search found), in run order, by the rules the database moves
// statuses by.
struct ReportRun {
  CampaignRun run;
  std::size_t searches = 0;
  std::size_t simulations = 0;       // evaluations recorded by its searches
  std::size_t modes_first_seen = 0;  // new: first found in this run
  // Failing in this run: new, still failing (found again, or failing every replay seed) or
  // regressed.
  std::size_t modes_seen = 0;
  std::size_t fixed = 0;      // its replay failed on no seed, and no search of it found the mode
  std::size_t regressed = 0;  // fixed before, failing again in this run
  std::size_t flaky = 0;      // its replay failed on some seeds only, and no search found it
};

// A point of a seed's chart: after `simulations` simulations of the seed (over all its searches,
// in order), the lowest robustness so far was `best`. One point per change.
struct BestSoFar {
  std::size_t simulations = 0;
  double best = 0;  // may be -infinity (the database keeps infinities)

  bool operator==(const BestSoFar&) const = default;
};

// Where a run's searches of a seed began, counted in the seed's simulations: the chart marks it.
struct RunStart {
  std::int64_t run_id = 0;
  std::size_t simulations = 0;
};

struct ReportSeed {
  CampaignSeed seed;
  std::size_t searches = 0;
  std::size_t simulations = 0;
  std::size_t judged = 0;  // simulations with a robustness
  std::vector<BestSoFar> best;
  std::vector<RunStart> run_starts;
  std::size_t failure_modes = 0;
  // Behaviour-coverage features (docs/coverage.md) its searches reached together.
  std::size_t features = 0;
};

struct ReportFailureMode {
  CampaignFailureMode mode;
  std::string seed_path;  // empty when the seed is not in the database (read mid-change)
  std::string first_seen_started, last_seen_started;  // the runs' start times
  // modes/<hash>.svg beside the scenario file, relative to the campaign folder; empty when the
  // finding had no picture.
  std::string picture;
  // modes/<hash>.min.avu ([search] tmin), relative to the campaign folder; empty when there is
  // none.
  std::string minimised;
};

struct ReportData {
  std::string name;  // the campaign's
  std::vector<ReportRun> runs;
  std::vector<ReportSeed> seeds;
  std::vector<ReportFailureMode> failure_modes;
  std::size_t corpus_features = 0;  // the union over every seed's searches
};

// Everything the report shows, from `db`; `dir` is the campaign folder, where the pictures are
// looked for. Tolerates a database read while a run writes it (rows that refer to rows it has
// not read yet are shown without them).
ReportData load_report_data(CampaignDb& db, const std::filesystem::path& dir,
                            const std::string& name);

// The best-so-far steps of a sequence of robustness values (nullopt: not judged, still counted).
std::vector<BestSoFar> best_so_far(const std::vector<std::optional<double>>& robustness);

}  // namespace scenfuzz

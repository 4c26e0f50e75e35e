// run_corpus_search: expand and check the seeds, split the budget, search each seed in its own
// folder, then write corpus.json.
#include "fuzz/corpus_search.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <system_error>

#include "fuzz/atomic_file.hpp"
#include "fuzz/cli.hpp"
#include "fuzz/seed_paths.hpp"
#include "fuzz/stop_signals.hpp"
#include "lang/demand.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

struct CorpusSeed {
  std::string path;
  std::string folder;  // under --out
  std::size_t budget = 0;
  int exit_status = kExitSuccess;
  std::size_t findings = 0;
};

// The scenario files `entries` stand for, each once, in order; empty after errors on `err`.
std::vector<std::string> expand_entries(const std::vector<std::string>& entries,
                                        std::ostream& err) {
  std::vector<std::string> files;
  std::set<std::string> seen;
  bool ok = true;
  for (const std::string& entry : entries) {
    const SeedExpansion expansion = expand_seed_entry(fs::current_path(), entry);
    if (!expansion.error.empty()) {
      err << "scenfuzz: error: " << expansion.error << "\n";
      ok = false;
    }
    for (const std::string& file : expansion.files)
      if (seen.insert(file).second) files.push_back(file);
  }
  if (!ok) files.clear();
  return files;
}

// Every seed parses and builds a scenario (diagnostics on `err`); false if any does not.
bool check_seeds(const std::vector<std::string>& files, std::ostream& err) {
  bool ok = true;
  for (const std::string& file : files) ok = read_scenario(file, "search", err).has_value() && ok;
  return ok;
}

// How many findings a seed's search kept, from its summary.json (0 when there is none).
std::size_t findings_in(const fs::path& folder) {
  std::ifstream in(folder / "summary.json");
  if (!in) return 0;
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.contains("findings")) return 0;
  return summary.at("findings").size();
}

int search_seed(const FuzzCommandOptions& options, CorpusSeed& seed, std::size_t seed_count,
                std::ostream& out, std::ostream& err) {
  FuzzCommandOptions own = options;
  own.path = seed.path;
  own.budget = seed.budget;
  own.out_dir = (fs::path(options.out_dir) / seed.folder).string();
  if (options.time_limit > 0) own.time_limit = options.time_limit / static_cast<double>(seed_count);
  if (options.json)
    out << nlohmann::json{{"event", "seed"},
                          {"path", seed.path},
                          {"budget", seed.budget},
                          {"out", own.out_dir}}
               .dump()
        << "\n";
  else if (!options.quiet)
    out << "== " << seed.path << " (" << seed.budget << " simulations, " << own.out_dir << ")\n";
  seed.exit_status = run_fuzz(own, out, err);
  seed.findings = findings_in(own.out_dir);
  return seed.exit_status;
}

std::string corpus_json(const FuzzCommandOptions& options, const std::vector<CorpusSeed>& seeds) {
  nlohmann::ordered_json document;
  document["budget"] = options.budget;
  document["seed"] = options.seed;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const CorpusSeed& seed : seeds)
    list.push_back({{"path", seed.path},
                    {"folder", seed.folder},
                    {"budget", seed.budget},
                    {"exit_status", seed.exit_status},
                    {"findings", seed.findings}});
  document["seeds"] = std::move(list);
  return document.dump(2) + "\n";
}

int corpus_exit_status(const std::vector<CorpusSeed>& seeds) {
  int status = kExitSuccess;
  for (const CorpusSeed& seed : seeds) {
    if (seed.exit_status != kExitSuccess && seed.exit_status != kExitViolated)
      return seed.exit_status;
    if (seed.exit_status == kExitViolated) status = kExitViolated;
  }
  return status;
}

}  // namespace

bool is_corpus_search(const std::vector<std::string>& entries) {
  if (entries.size() != 1) return entries.size() > 1;
  std::error_code error;
  return fs::is_directory(entries.front(), error);
}

std::vector<std::size_t> corpus_budget_shares(std::size_t budget, std::size_t seeds) {
  SCENFUZZ_DEMAND(seeds > 0 && budget >= seeds);
  std::vector<std::size_t> shares(seeds, budget / seeds);
  for (std::size_t i = 0; i < budget % seeds; ++i) ++shares[i];
  return shares;
}

std::vector<std::string> corpus_folder_names(const std::vector<std::string>& seed_files) {
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (const std::string& file : seed_files) {
    const std::string stem = fs::path(file).stem().string();
    std::string name = stem;
    for (int n = 2; !taken.insert(name).second; ++n) name = stem + "-" + std::to_string(n);
    names.push_back(name);
  }
  return names;
}

int run_corpus_search(const FuzzCommandOptions& options, const std::vector<std::string>& entries,
                      std::ostream& out, std::ostream& err) {
  // A name is one file's: the seeds of a corpus name their scenarios differently.
  if (!options.choice.scenario.empty()) {
    err << "scenfuzz: error: --scenario chooses a scenario of one FILE, not of a corpus\n";
    return kExitUsage;
  }
  const std::vector<std::string> files = expand_entries(entries, err);
  if (files.empty() || !check_seeds(files, err)) {
    err << "scenfuzz: error: nothing was searched: fix the corpus first\n";
    return kExitBadInput;
  }
  if (options.budget < files.size()) {
    err << "scenfuzz: error: --budget " << options.budget
        << " is less than one simulation for each of the " << files.size() << " seeds\n";
    return kExitUsage;
  }
  const std::vector<std::size_t> shares = corpus_budget_shares(options.budget, files.size());
  const std::vector<std::string> folders = corpus_folder_names(files);
  std::vector<CorpusSeed> seeds;
  for (std::size_t i = 0; i < files.size(); ++i) seeds.push_back({files[i], folders[i], shares[i]});
  std::size_t searched = 0;
  {
    // Held between the seeds' own guards, so that a stop asked for between two searches counts.
    StopSignalGuard guard;
    for (; searched < seeds.size() && !StopSignalGuard::stop_requested(); ++searched)
      search_seed(options, seeds[searched], seeds.size(), out, err);
  }
  seeds.resize(searched);
  if (searched < files.size())
    err << "scenfuzz: note: stopped after " << searched << " of " << files.size()
        << " seeds; rerun with --resume to continue\n";
  const fs::path summary = fs::path(options.out_dir) / "corpus.json";
  if (std::string failure = write_file_atomically(summary, corpus_json(options, seeds));
      !failure.empty()) {
    err << "scenfuzz: error: " << failure << "\n";
    return kExitBadInput;
  }
  if (!options.quiet && !options.json) {
    std::size_t findings = 0, failing = 0;
    for (const CorpusSeed& seed : seeds) {
      findings += seed.findings;
      failing += seed.findings > 0 ? 1 : 0;
    }
    out << "corpus: " << findings << (findings == 1 ? " finding" : " findings") << " in " << failing
        << " of " << seeds.size() << " seeds; wrote " << summary.string() << "\n";
  }
  return corpus_exit_status(seeds);
}

}  // namespace scenfuzz

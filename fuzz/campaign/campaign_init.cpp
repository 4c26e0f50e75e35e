// run_campaign_init: checks the FILES, writes the starting campaign.toml and reads it back with
// parse_campaign_config before writing it, so init never leaves a file that `campaign run` rejects.
#include "fuzz/campaign/campaign_init.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "fuzz/atomic_file.hpp"
#include "fuzz/campaign/campaign_config.hpp"
#include "fuzz/seed_paths.hpp"
#include "fuzz/cli.hpp"
#include "lang/diagnostic.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (byte < 0x20 || byte == 0x7F) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04X", static_cast<unsigned>(byte));
      quoted += escape;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

// Whether `a` and `b` (absolute) share more than the root: the campaign and its seeds live in one
// tree (a repository), so a relative path keeps working when the tree moves.
bool share_a_folder(const fs::path& a, const fs::path& b) {
  auto a_part = a.begin(), b_part = b.begin();
  std::size_t shared = 0;
  for (; a_part != a.end() && b_part != b.end() && *a_part == *b_part; ++a_part, ++b_part) ++shared;
  return shared > 1;  // more than "/"
}

// `file` as the campaign folder `dir` sees it: relative to it when they share a folder besides
// the root, else absolute; a folder with a trailing '/'.
std::string entry_for(const fs::path& dir, const std::string& file) {
  std::error_code error;
  const fs::path target = fs::absolute(file, error).lexically_normal();
  const fs::path folder = fs::absolute(dir, error).lexically_normal();
  fs::path relative = share_a_folder(target, folder) ? target.lexically_relative(folder) : target;
  if (relative.empty()) relative = target;
  std::string entry = relative.generic_string();
  if (fs::is_directory(file, error) && !entry.ends_with('/')) entry += '/';
  return entry;
}

// Empty when `file` can be a seed; else why not.
std::string seed_problem(const std::string& file) {
  std::error_code error;
  if (!fs::exists(file, error)) return "'" + file + "' does not exist";
  return expand_seed_entry(fs::current_path(error), file).error;
}

std::string folder_name(const fs::path& dir) {
  std::error_code error;
  fs::path absolute = fs::absolute(dir, error).lexically_normal();
  if (!absolute.has_filename()) absolute = absolute.parent_path();
  return absolute.filename().string();
}

}  // namespace

std::string campaign_toml_text(const std::string& name,
                               const std::vector<std::string>& seed_entries,
                               const std::string& example_file) {
  std::string seeds;
  for (const std::string& entry : seed_entries) seeds += "  " + toml_string(entry) + ",\n";
  return "# A scenfuzz falsification campaign (docs/campaigns.md describes every key). Paths are\n"
         "# relative to this folder.\n"
         "\n"
         "# The seed scenarios: files (.avu, .scenest, .sdl) and folders, which stand for every\n"
         "# scenario file under them. An edited seed file counts as a new seed.\n"
         "seeds = [\n" +
         seeds +
         "]\n"
         "\n"
         "# Folders to look for Apollo maps in, before SCENFUZZ_MAP_PATH and corpora/maps.\n"
         "# map_paths = [\"maps/\"]\n"
         "\n"
         "[campaign]\n"
         "name = " +
         toml_string(name) +
         "\n"
         "\n"
         "[ego]\n"
         "# The ego under test: a shared library (docs/ego-plugin.md) and a version you set, such\n"
         "# as its git hash, which tells one night's ego from the next. Without a plugin, the\n"
         "# reference driver drives (version \"reference\").\n"
         "# plugin = \"build/libmy_driver.so\"\n"
         "# version = \"0123abc\"\n"
         "\n"
         "[budget]\n"
         "# Each run's budget, shared over all seeds: simulations, wall-clock seconds, or both\n"
         "# (the run stops at the first one spent).\n"
         "simulations = 5000\n"
         "# wall_seconds = 3600\n"
         "\n"
         "[search]\n"
         "# Every seed's search, as scenfuzz's --algo, --seed and -j: ga, random, halton, lhs or\n"
         "# nlopt:NAME; the seed of every random choice; worker threads (0: all cores).\n"
         "algo = \"ga\"\n"
         "seed = 0\n"
         "jobs = 0\n"
         "\n"
         "# One [[seed]] table per seed file whose search differs: path is one of the files\n"
         "# `seeds` stands for; budget_share weighs its share of the budget (1 without one).\n"
         "# [[seed]]\n"
         "# path = " +
         toml_string(example_file) +
         "\n"
         "# budget_share = 2.0\n"
         "# algo = \"nlopt:GN_ISRES\"\n";
}

int run_campaign_init(const CampaignInitOptions& options, std::ostream& out, std::ostream& err) {
  const fs::path dir = options.dir;
  const fs::path target = dir / "campaign.toml";
  std::error_code error;
  if (fs::symlink_status(target, error).type() != fs::file_type::not_found) {
    err << "scenfuzz: error: '" << target.string()
        << "' already exists; campaign init never overwrites it (edit it, or remove it to start "
           "again)\n";
    return kExitBadInput;
  }
  if (options.files.empty()) {
    err << "scenfuzz: error: campaign init needs at least one seed scenario file or folder\n";
    return kExitUsage;
  }
  std::vector<std::string> entries;
  for (const std::string& file : options.files) {
    if (const std::string problem = seed_problem(file); !problem.empty()) {
      err << "scenfuzz: error: " << problem << "\n";
      return kExitBadInput;
    }
    entries.push_back(entry_for(dir, file));
  }
  fs::create_directories(dir, error);
  if (error) {
    err << "scenfuzz: error: cannot create '" << dir.string() << "': " << error.message() << "\n";
    return kExitBadInput;
  }
  std::string text = campaign_toml_text(folder_name(dir), entries, entries.front());
  // Read back before writing: a path that TOML or the seed rules cannot take is caught here.
  const CampaignConfigResult parsed = parse_campaign_config(text, target.string());
  if (!parsed.config) {
    err << format_diagnostics(SourceFile(target.string(), text), parsed.diagnostics)
        << "scenfuzz: error: campaign init could not write a campaign.toml for these files\n";
    return kExitBadInput;
  }
  // The [[seed]] example names a file, not a folder; only a comment changes.
  text = campaign_toml_text(folder_name(dir), entries, parsed.config->seed_files.front());
  if (const std::string problem = write_file_atomically(target, text); !problem.empty()) {
    err << "scenfuzz: error: " << problem << "\n";
    return kExitBadInput;
  }
  out << "scenfuzz: wrote " << target.string() << " (" << parsed.config->seed_files.size()
      << " seed scenario" << (parsed.config->seed_files.size() == 1 ? "" : "s")
      << "); edit it to set the ego under test and the budget\n";
  return kExitSuccess;
}

}  // namespace scenfuzz

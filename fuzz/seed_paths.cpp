// expand_seed_entry: a stat, then a sorted recursive walk for folders.
#include "fuzz/seed_paths.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <system_error>

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 3> kScenarioExtensions = {".avu", ".scenest", ".sdl"};

// Every scenario file under `folder` (shown as `shown_folder`), sorted by name.
SeedExpansion expand_folder(const fs::path& folder, const fs::path& shown_folder,
                            const std::string& entry) {
  SeedExpansion expansion;
  std::error_code error;
  fs::recursive_directory_iterator walk(folder, error), end;
  for (; !error && walk != end; walk.increment(error)) {
    const fs::directory_entry& item = *walk;
    std::error_code type_error;
    if (!item.is_regular_file(type_error) || !is_scenario_file_name(item.path())) continue;
    const fs::path inside = item.path().lexically_relative(folder);
    expansion.files.push_back((shown_folder / inside).lexically_normal().generic_string());
  }
  if (error) {
    expansion.files.clear();
    expansion.error = "cannot read the folder '" + entry + "': " + error.message();
    return expansion;
  }
  std::sort(expansion.files.begin(), expansion.files.end());
  if (expansion.files.empty())
    expansion.error = "the folder '" + entry + "' holds no scenario file (.avu, .scenest, .sdl)";
  return expansion;
}

}  // namespace

bool is_scenario_file_name(const fs::path& path) {
  const std::string extension = path.extension().string();
  return std::find(kScenarioExtensions.begin(), kScenarioExtensions.end(), extension) !=
         kScenarioExtensions.end();
}

std::string seed_key(const std::string& path) {
  return fs::path(path).lexically_normal().generic_string();
}

SeedExpansion expand_seed_entry(const fs::path& campaign_folder, const std::string& entry) {
  SeedExpansion expansion;
  const fs::path written(entry);
  const fs::path on_disk = written.is_absolute() ? written : campaign_folder / written;
  std::error_code error;
  const fs::file_status status = fs::status(on_disk, error);
  if (status.type() == fs::file_type::not_found) {
    expansion.error = "'" + entry +
                      "' does not exist (seed paths are relative to the campaign "
                      "folder, '" +
                      campaign_folder.generic_string() + "')";
    return expansion;
  }
  if (error) {
    expansion.error = "cannot read '" + entry + "': " + error.message();
    return expansion;
  }
  if (fs::is_directory(status)) return expand_folder(on_disk, written, entry);
  if (!is_scenario_file_name(written)) {
    expansion.error = "'" + entry +
                      "' is not a scenario file: expected a .avu, .scenest or "
                      ".sdl file, or a folder of them";
    return expansion;
  }
  expansion.files.push_back(seed_key(entry));
  return expansion;
}

}  // namespace scenfuzz

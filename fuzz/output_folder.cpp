// The output folder's lock, what an earlier search left in it, and a killed run's temporary files.
#include "fuzz/output_folder.hpp"

#include <string_view>
#include <system_error>

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kSearchFiles[] = {"evaluations.csv", "summary.json", "search.json"};

bool is_temporary(const fs::path& path) {
  return path.filename().string().find(".tmp.") != std::string::npos;
}

}  // namespace

std::string OutputFolderLock::acquire(const fs::path& dir) {
  FolderLockRefusal refusal;
  if (lock_.acquire(dir, ".lock", refusal)) return {};
  if (!refusal.busy) return refusal.error;
  return "'" + dir.string() + "' is in use by another search (" + refusal.holder +
         "); wait for it to end, or write into another folder with --out DIR";
}

bool holds_search(const fs::path& dir) {
  std::error_code error;
  for (std::string_view name : kSearchFiles)
    if (fs::exists(dir / name, error)) return true;
  return fs::is_directory(dir / "findings", error) &&
         fs::directory_iterator(dir / "findings", error) != fs::directory_iterator();
}

std::string remove_search(const fs::path& dir) {
  std::error_code error;
  fs::remove_all(dir / "findings", error);
  if (error) return "cannot remove '" + (dir / "findings").string() + "': " + error.message();
  for (std::string_view name : kSearchFiles) {
    fs::remove(dir / name, error);
    if (error) return "cannot remove '" + (dir / name).string() + "': " + error.message();
  }
  return {};
}

void remove_temporary_files(const fs::path& dir) {
  for (const fs::path& folder : {dir, dir / "findings"}) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) continue;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
      if (entry.is_regular_file(error) && is_temporary(entry.path()))
        fs::remove(entry.path(), error);
  }
}

}  // namespace scenfuzz

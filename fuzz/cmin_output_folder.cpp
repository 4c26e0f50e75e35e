// claim_cmin_output_folder and remove_stale_cmin_files.
#include "fuzz/cmin_output_folder.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "fuzz/cmin_control_file.hpp"
#include "fuzz/seed_paths.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// Whether `folder` is `path` or one of its ancestors (both absolute and normal).
bool contains(const fs::path& folder, const fs::path& path) {
  auto [end, unused] = std::mismatch(folder.begin(), folder.end(), path.begin(), path.end());
  return end == folder.end() || (std::next(end) == folder.end() && end->empty());
}

fs::path absolute_normal(const fs::path& path) {
  std::error_code error;
  fs::path result = fs::weakly_canonical(fs::absolute(path, error), error);
  if (error) result = fs::absolute(path, error).lexically_normal();
  return result;
}

// Why `out_dir` would overlap one of `inputs`, or an empty string.
std::string overlap(const fs::path& out_dir, const std::vector<std::string>& inputs) {
  const fs::path out = absolute_normal(out_dir);
  for (const std::string& input : inputs) {
    const fs::path in = absolute_normal(input);
    if (contains(in, out))
      return "the output folder '" + out_dir.string() + "' is inside the input '" + input +
             "': its copies would be seeds of the next run";
    if (contains(out, in))
      return "the input '" + input + "' is inside the output folder '" + out_dir.string() +
             "', which cmin rewrites";
  }
  return {};
}

// Whether `out_dir` may be written: missing, empty, or made by cmin (its control file or lock).
std::string not_ours(const fs::path& out_dir) {
  std::error_code error;
  const fs::file_status status = fs::status(out_dir, error);
  if (status.type() == fs::file_type::not_found) return {};
  if (!fs::is_directory(status))
    return "the output folder '" + out_dir.string() + "' exists and is not a folder";
  if (fs::exists(out_dir / kCminControlFileName) || fs::exists(out_dir / kCminLockFileName))
    return {};
  if (fs::is_empty(out_dir, error) || error) return {};
  return "the output folder '" + out_dir.string() +
         "' is not empty and was not made by cmin: give a new or empty folder";
}

// A temporary file of write_file_atomically: "<name>.tmp.<process id>".
bool is_atomic_leftover(const fs::path& path) {
  const std::string name = path.filename().string();
  const std::size_t at = name.rfind(".tmp.");
  if (at == std::string::npos || at + 5 == name.size()) return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(at + 5), name.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

std::string claim_cmin_output_folder(const fs::path& out_dir,
                                     const std::vector<std::string>& inputs, FolderLock& lock) {
  if (std::string why = overlap(out_dir, inputs); !why.empty()) return why;
  if (std::string why = not_ours(out_dir); !why.empty()) return why;
  FolderLockRefusal refusal;
  if (lock.acquire(out_dir, kCminLockFileName, refusal)) return {};
  if (refusal.busy)
    return "the output folder '" + out_dir.string() + "' is in use by another run (" +
           refusal.holder + ")";
  return refusal.error;
}

std::string remove_stale_cmin_files(const fs::path& out_dir, const std::set<std::string>& kept) {
  std::vector<fs::path> stale;
  std::error_code error;
  for (fs::recursive_directory_iterator walk(out_dir, error), end; !error && walk != end;
       walk.increment(error)) {
    std::error_code type_error;
    if (!walk->is_regular_file(type_error)) continue;
    const fs::path& path = walk->path();
    const std::string relative = path.lexically_relative(out_dir).generic_string();
    if ((is_scenario_file_name(path) && kept.count(relative) == 0) || is_atomic_leftover(path))
      stale.push_back(path);
  }
  if (error) return "cannot read the folder '" + out_dir.string() + "': " + error.message();
  for (const fs::path& path : stale) {
    fs::remove(path, error);
    if (error) return "cannot remove '" + path.string() + "': " + error.message();
  }
  return {};
}

}  // namespace scenfuzz

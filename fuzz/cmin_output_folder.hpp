// cmin's OUT_DIR: claimed by one run at a time, only ever a folder cmin made (a new or empty one
// the first time), never an input or inside one (the kept copies would become seeds of the next
// run), and left holding exactly the kept seeds: copies an earlier result kept that this one
// does not, and temporary files a killed run left, are removed.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "fuzz/folder_lock.hpp"

namespace scenfuzz {

inline constexpr const char* kCminLockFileName = "cmin.lock";

// Claims `out_dir` for a run over the seed entries `inputs`, creating it if needed; an empty
// string, else why it cannot be used (another run holds it, it is not cmin's, it overlaps an
// input, it cannot be made).
std::string claim_cmin_output_folder(const std::filesystem::path& out_dir,
                                     const std::vector<std::string>& inputs, FolderLock& lock);

// Removes the scenario files under `out_dir` that are not in `kept` (paths relative to it,
// generic form) and the temporary files of atomic writes a kill left; an empty string, else
// what could not be removed.
std::string remove_stale_cmin_files(const std::filesystem::path& out_dir,
                                    const std::set<std::string>& kept);

}  // namespace scenfuzz

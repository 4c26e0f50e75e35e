// The representative files of a campaign's failure modes, DIR/modes/<content hash>.<ext>: a
// finding's concrete scenario, copied and named by the content hash of its text, with the files
// the search wrote beside it (its picture .svg, its trace .csv, an ego failure's
// .observation.json) under the same hash. Content-addressed, so copying twice is harmless and a
// killed copy is simply made again; each file appears whole (written atomically).
#pragma once

#include <filesystem>
#include <string>

namespace scenfuzz {

// The sidecar suffixes copied with a finding's scenario file, in the order they are copied.
inline constexpr const char* kModeSidecars[] = {".svg", ".csv", ".observation.json"};

struct ModeFiles {
  std::string scenario_file;  // "modes/<hash>.<ext>", relative to the campaign folder
  std::string error;          // why the copy failed; empty on success
};

// Copies the finding scenario file `finding` (and its sidecars, when they exist) into
// `campaign_folder`/modes/.
ModeFiles copy_mode_files(const std::filesystem::path& campaign_folder,
                          const std::filesystem::path& finding);

// Where [search] tmin puts the minimised scenario of a mode whose representative is
// `scenario_file` ("modes/<hash>.<ext>"): beside it, "modes/<hash>.min.avu" (".min.sdl").
std::string minimised_mode_file(const std::string& scenario_file);

// Reads the file at `path` whole into `text`; false when it cannot be read.
bool read_whole_file(const std::filesystem::path& path, std::string& text);

// Removes the temporary files of atomic writes a killed run left in DIR/modes/.
void remove_mode_temporaries(const std::filesystem::path& campaign_folder);

}  // namespace scenfuzz

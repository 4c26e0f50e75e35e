// copy_mode_files: content-addressed copies of a finding's files into DIR/modes/.
#include "fuzz/campaign/mode_files.hpp"

#include <fstream>
#include <sstream>

#include "fuzz/atomic_file.hpp"
#include "fuzz/content_hash.hpp"
#include "fuzz/output_folder.hpp"
#include "fuzz/tmin_finding.hpp"

namespace scenfuzz {

namespace fs = std::filesystem;

namespace {

// Writes `text` to `target` unless it is there already (same name, same content by
// construction); an error message or empty.
std::string place(const fs::path& target, const std::string& text) {
  std::error_code error;
  if (fs::exists(target, error)) return "";
  return write_file_atomically(target, text);
}

}  // namespace

ModeFiles copy_mode_files(const fs::path& campaign_folder, const fs::path& finding) {
  ModeFiles files;
  std::string text;
  if (!read_whole_file(finding, text)) {
    files.error = "cannot read the finding '" + finding.string() + "'";
    return files;
  }
  const std::string hash = content_hash(text);
  const fs::path modes = campaign_folder / "modes";
  std::error_code error;
  fs::create_directories(modes, error);
  // The sidecars first, the scenario last: its presence means the mode's files are whole.
  const std::string stem = finding.stem().string();
  for (const char* suffix : kModeSidecars) {
    const fs::path sidecar = finding.parent_path() / (stem + suffix);
    std::string content;
    if (!fs::exists(sidecar, error) || !read_whole_file(sidecar, content)) continue;
    if (std::string failure = place(modes / (hash + suffix), content); !failure.empty()) {
      files.error = failure;
      return files;
    }
  }
  const std::string name = hash + finding.extension().string();
  if (std::string failure = place(modes / name, text); !failure.empty()) {
    files.error = failure;
    return files;
  }
  files.scenario_file = "modes/" + name;
  return files;
}

std::string minimised_mode_file(const std::string& scenario_file) {
  return fs::path(default_minimised_path(scenario_file)).generic_string();
}

bool read_whole_file(const fs::path& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  text = bytes.str();
  return static_cast<bool>(in) || in.eof();
}

void remove_mode_temporaries(const fs::path& campaign_folder) {
  // remove_temporary_files cleans a folder and its findings/; modes/ has none of its own.
  remove_temporary_files(campaign_folder / "modes");
}

}  // namespace scenfuzz

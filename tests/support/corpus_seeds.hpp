// The corpus seeds the tests run over: every AVUnit and WMG SDL file in corpora/avunit,
// corpora/wmg and corpora/benchmarks, parsed, and the map search path that finds their maps
// (the shared Apollo maps when present).
#pragma once

#include <algorithm>
#include <filesystem>
#include <optional>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/map_source.hpp"
#include "shared_dir.hpp"

namespace scenfuzz::test {

inline std::vector<std::filesystem::path> corpus_seeds() {
  std::vector<std::filesystem::path> files;
  for (const char* folder : {"avunit", "wmg", "benchmarks"})
    for (const auto& entry : std::filesystem::directory_iterator(
             std::filesystem::path(SCENFUZZ_SOURCE_DIR) / "corpora" / folder))
      if (entry.path().extension() == ".avu" || entry.path().extension() == ".sdl")
        files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The seed's scenario, or nullopt when it has errors.
inline std::optional<ScenarioTemplate> parse_seed(const SourceFile& file) {
  if (file.path().ends_with(".sdl")) {
    wmg::ParseResult parsed = wmg::parse(file);
    if (parsed.diagnostics.has_errors()) return std::nullopt;
    return std::move(parsed.scenario);
  }
  avunit::ParseResult parsed = avunit::parse(file);
  if (!parsed.ok()) return std::nullopt;
  return std::move(parsed.scenario);
}

inline MapSearchPath corpus_map_search_path() {
  std::vector<std::filesystem::path> folders;
  if (have_shared_dir()) folders.push_back(shared_dir() / "maps" / "apollo");
  return map_search_path(folders);
}

}  // namespace scenfuzz::test

// The corpus seeds the tests run over: every AVUnit and WMG SDL file in corpora/avunit,
// corpora/wmg and corpora/benchmarks, parsed, and the map search path that finds their maps
// (the shared Apollo maps when present).
#pragma once

#include <algorithm>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lang/avunit/avunit.hpp"
#include "lang/wmg/wmg.hpp"
#include "physics/map/map_source.hpp"
#include "physics/simulation/simulation.hpp"
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

// A seed simulated at `values` with seed 1: its map and trace, or why not.
struct SeedRun {
  std::optional<RoadMap> map;
  std::optional<Trace> trace;
  bool map_missing = false;  // its map could not be loaded (it is in the shared folder)
  std::string error;         // the map's error, or the set-up's diagnostics
};

inline SeedRun simulate_seed(const SourceFile& file, const ScenarioTemplate& scenario,
                             const std::vector<double>& values) {
  SeedRun run;
  try {
    run.map.emplace(load_scenario_map(scenario.map, corpus_map_search_path(), values));
  } catch (const MapError& error) {
    run.map_missing = true;
    run.error = error.what();
    return run;
  }
  Diagnostics diagnostics;
  auto setup = prepare_simulation(scenario, values, *run.map, 1, diagnostics);
  if (!setup) {
    run.error = format_diagnostics(file, diagnostics);
    return run;
  }
  run.trace = simulate(*run.map, *setup, {});
  return run;
}

}  // namespace scenfuzz::test

// The subcommands behind the command line, callable without it (tests, other front ends).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lang/scenario.hpp"
#include "lang/source_file.hpp"

namespace scenfuzz {

// Which of a file's scenarios a command uses (`--scenario`), as fuzz/options.def declares it.
struct ScenarioChoiceOptions {
#define SCENFUZZ_SCENARIO_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
};

// `scenfuzz check FILE...`: parses every file, printing its diagnostics (warnings too) to `err`.
// Returns kExitSuccess when no file has errors, kExitBadInput otherwise; every file is checked.
// A file executing several scenarios checks each and notes them; `choice` names one that must
// exist.
int run_check(const std::vector<std::string>& paths, const ScenarioChoiceOptions& choice,
              std::ostream& err);

struct MapCommandOptions {
  std::string name;                    // built-in map (with ?parameters), Apollo map name or file
  std::vector<std::string> map_paths;  // --map-path, in order
  std::string svg_path;                // --svg: draw the map there
  bool labels = false;                 // --labels: lane ids in the drawing
  bool json = false;                   // --json: the summary and every lane as JSON
  bool list = false;                   // --list: the built-in maps and their parameters
};

// `scenfuzz map NAME|FILE`: loads a map and prints a summary (or JSON) to `out`; draws it with
// --svg. A map that cannot be found or read gives kExitBadInput with the reason on `err`.
int run_map(const MapCommandOptions& options, std::ostream& out, std::ostream& err);

// The options of every simulation, which `run` and the search share. The fields, their defaults
// and what they mean are declared in fuzz/options.def, with the command-line options.
struct SimulationCommandOptions {
#define SCENFUZZ_SIMULATION_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
};

struct RunCommandOptions {
  std::string path;  // FILE
#define SCENFUZZ_RUN_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
  SimulationCommandOptions simulation;
  ScenarioChoiceOptions choice;
};

// `scenfuzz run FILE`: simulates the scenario (a logical one at the point --at chooses), prints
// what happened to `out` and writes the trace and a picture into the output folder.
int run_run(const RunCommandOptions& options, std::ostream& out, std::ostream& err);

// `scenfuzz convert --to sdl2 FILE`: prints the WMG SDL level-2 text of a level-1 file (a level-2
// file canonically) to `out`. kExitSuccess, or kExitBadInput with the diagnostics on `err`.
int run_convert(const std::string& path, std::ostream& out, std::ostream& err);

struct StlCommandOptions {
  std::string spec;        // --spec: one STL formula in AVUnit's syntax
  std::string trace_path;  // --trace: a CSV log with a `time` column
  bool signal = false;     // --signal: the robustness at every sample, as CSV
};

// `scenfuzz stl`: prints the formula's robustness on the CSV log at its first sample (or, with
// --signal, `time,robustness` for every sample) to `out`; for a violated formula, a note on `err`
// naming the responsible atom and time. Returns kExitSuccess when the robustness is >= 0,
// kExitViolated when < 0, kExitBadInput for a bad formula or log (diagnostics on `err`).
int run_stl(const StlCommandOptions& options, std::ostream& out, std::ostream& err);

// Reads a scenario file, or prints `scenfuzz: error: cannot read 'path': <reason>` to `err`.
std::optional<SourceFile> read_input(const std::string& path, std::ostream& err);

// A scenario file a command runs, read and parsed.
struct ScenarioFile {
  SourceFile file;
  ScenarioTemplate scenario;
};

// Reads and parses `path` (its scenario `choice` names, when it has several), printing its
// diagnostics to `err`; nullopt (with an error on `err`) when it cannot be read, has errors, or
// builds no scenario ("nothing to <purpose>").
std::optional<ScenarioFile> read_scenario(const std::string& path, const std::string& purpose,
                                          std::ostream& err,
                                          const ScenarioChoiceOptions& choice = {});

// How a concrete scenario's values are mutated (sampler/mutation_space.hpp), as fuzz/options.def
// declares it.
struct MutationCommandOptions {
#define SCENFUZZ_MUTATION_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
};

struct FuzzCommandOptions {
  std::string path;  // FILE
#define SCENFUZZ_BUDGET_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#define SCENFUZZ_SEARCH_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
  SimulationCommandOptions simulation;
  MutationCommandOptions mutation;
  ScenarioChoiceOptions choice;
};

// `scenfuzz space FILE [--json] [--mutate KIND=SIZE]`: prints the file's parameter space to `out`
// as an aligned table, or as JSON; a concrete file's derived space, marked as derived. Diagnostics
// go to `err`; a file with errors gives kExitBadInput and no space.
int run_space(const std::string& path, bool json, const MutationCommandOptions& mutation,
              const ScenarioChoiceOptions& choice, std::ostream& out, std::ostream& err);

// `scenfuzz [options] FILE`: searches the scenario's parameter space and writes every finding.
// Exit status kExitSuccess (no finding), kExitViolated (findings), kExitBadInput / kExitUsage.
int run_fuzz(const FuzzCommandOptions& options, std::ostream& out, std::ostream& err);

struct ReconstructCommandOptions {
  std::string path;  // FILE.acc
#define SCENFUZZ_BUDGET_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#define SCENFUZZ_RECONSTRUCT_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
  SimulationCommandOptions simulation;
};

// `scenfuzz reconstruct FILE.acc`: searches the accident's unknowns (speeds, start distances,
// event timings) for a run in which the described collisions happen as described, and writes it
// as a concrete AVUnit scenario with its trace and picture into --out. kExitSuccess when
// reconstructed, kExitViolated when the budget ran out first (the closest run is reported and
// written), kExitBadInput / kExitUsage for a bad file or option.
int run_reconstruct(const ReconstructCommandOptions& options, std::ostream& out, std::ostream& err);

struct TminCommandOptions {
  std::string path;      // FINDING: a finding of the search, or a plain concrete scenario
  std::string out_path;  // -o; empty: beside it, <name>.min.avu
};

// `scenfuzz tmin FINDING [-o OUT]`: reduces the failing scenario while the same failure mode
// persists (fuzz/tmin_finding.hpp) and writes it; what changed and the replay command go to
// `out`. kExitSuccess when written; kExitBadInput (message on `err`) for a file that cannot be
// read, is not a concrete scenario or does not fail the same way when replayed.
int run_tmin(const TminCommandOptions& options, std::ostream& out, std::ostream& err);

struct CoverageCommandOptions {
  std::vector<std::string> paths;  // FILE|DIR...: scenario files, folders of them
  bool json = false;               // --json
#define SCENFUZZ_CORPUS_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
  SimulationCommandOptions simulation;
};

// `scenfuzz coverage FILE|DIR...`: the behaviour-coverage features (docs/coverage.md) the corpus
// covers and which seeds cover each, as a table or JSON on `out`; seeds that cannot be covered
// are listed with their errors and never stop the run. The same output for any -j. kExitSuccess
// when at least one seed was covered, kExitBadInput when none could be.
int run_coverage(const CoverageCommandOptions& options, std::ostream& out, std::ostream& err);

enum class BenchKind { falsification, chasing_cars, parallel };

struct BenchCommandOptions {
  BenchKind kind = BenchKind::falsification;
  std::optional<std::size_t> budget;    // --budget: 500 (falsification), 1500 (cc), 200 (parallel)
  std::vector<std::string> algorithms;  // --algos / --algo; empty: the bench's default
  std::size_t seeds = 20;               // falsification: --seeds, runs with seeds 1..N
  bool first_finding_only = false;      // falsification: --first-only, each run stops there
  std::size_t runs = 10;                // cc: --runs, runs with seeds 1..N per requirement
  std::vector<std::string> requirements;  // cc: --requirements; empty: CC1..CC5, CCx
  std::size_t segments = 20;              // cc: --segments, input segments of 100 / N s
  std::size_t jobs = 0;                   // -j: searches at once (falsification, cc); 0 = cores
  std::vector<std::string> scenarios;     // falsification, parallel; empty: the bundled choice
};

// `scenfuzz bench falsification|cc|parallel`: measures the search and prints aligned tables to
// `out` (progress to `err` on a terminal only). kExitSuccess, kExitUsage for bad arguments,
// kExitBadInput for a scenario that cannot be read.
int run_bench(const BenchCommandOptions& options, std::ostream& out, std::ostream& err);

struct CminCommandOptions {
  std::vector<std::string> inputs;  // IN...: scenario files and folders of them
  std::string out_dir;              // -o: where the kept seeds, cmin.json and cmin.control go
#define SCENFUZZ_CORPUS_OPTION(TYPE, FIELD, DEFAULT, ...) TYPE FIELD = DEFAULT;
#include "fuzz/options.def"
  SimulationCommandOptions simulation;
};

// `scenfuzz cmin IN... -o OUT_DIR`: copies the smallest subset of the seeds that keeps their
// behaviour coverage into OUT_DIR (fuzz/corpus_minimize.hpp), with cmin.json saying why each seed
// was kept or dropped; resumable after a kill from OUT_DIR/cmin.control. kExitSuccess, or
// kExitBadInput when OUT_DIR cannot be used, no seed could be covered or it was interrupted.
int run_cmin(const CminCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace scenfuzz
